// RbsmMat: material of RBSM blocks and of the joints between them.
#pragma once
#include <core/Material.hpp>

namespace yade {

class RbsmMat : public Material {
public:
	//! Checks every value; throws std::invalid_argument naming the attribute and the problem.
	void postLoad(RbsmMat&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmMat, Material,
		"Material of Rigid-Bodies-Spring Model blocks (Kawai 1977): elastic constants of the blocks, which set the "
		"stiffness of the joint springs (see :yref:`Ip2_RbsmMat_RbsmMat_RbsmPhys`), and the Mohr-Coulomb strength of "
		"the joints: f = τ² − (c + σn·tanφ)² with σn > 0 in compression (the seed paper's eq. 11 with its tension-positive σ). "
		"Units SI: Pa, kg/m³, radians. As for YADE's materials, a value changed mid-run acts where it is read: a joint "
		"takes its springs and strength when it is made (change RbsmPhys of the existing ones), a block its mass when "
		"it is built (change State.mass).",
		((Real, young, 1e9, Attr::triggerPostLoad, "Young's modulus E of the blocks [Pa]."))
		((Real, poisson, 0.2, Attr::triggerPostLoad, "Poisson's ratio ν of the blocks [-]; in (−1, 0.5)."))
		((bool, planeStrain, true, Attr::triggerPostLoad,
			"2D state used by Kawai's spring formulas: plane strain (True, slopes and long structures) or plane stress (False, thin plates)."))
		((Real, frictionAngle, 0.5, Attr::triggerPostLoad, "Joint friction angle φ [rad], in [0, π/2)."))
		((Real, cohesion, 0, Attr::triggerPostLoad, "Cohesion c of intact joints [Pa] (≥ 0); lost when the joint breaks."))
		((Real, tensileStrength, 0, Attr::triggerPostLoad, "Tensile strength σt of intact joints [Pa] (≥ 0); lost when the joint breaks."))
		((bool, ductile, false, ,
			"Joints keep their cohesion while they slip (perfectly plastic Mohr-Coulomb, the continuum model of strength-reduction FEM and of limit equilibrium); only tension breaks them. "
			"False (default, Kawai's RBSM and the seed): a point loses its cohesion at its first slip (brittle). A joint is ductile if both its materials are."))
		((Real, jointKn, 0, Attr::triggerPostLoad,
			"Normal stiffness per unit area of the joints of these blocks [Pa/m], as rock engineers give a joint set's kn; 0 (default): Kawai's E′/(h1+h2) from young and poisson. "
			"Between two materials that both give it, the smaller; if only one does, its value. Also used for joints with walls and facets, and by RbsmTimeStepper's first-contact bound."))
		((Real, jointKs, 0, Attr::triggerPostLoad,
			"Shear stiffness per unit area of the joints of these blocks [Pa/m]; 0 (default): Kawai's 2G/(h1+h2). Combined as jointKn."))
		((bool, deformable, false, ,
			"Blocks of this material carry a constant strain besides their rigid motion (the seed's eq. 4; :yref:`DeformableState`): their "
			"elasticity is the block's own (young, poisson, planeStrain), so the joints of two such blocks made at the first step of an "
			"assembly (:yref:`Ip2_RbsmMat_RbsmMat_RbsmPhys.setCohesionNow`, as the builders do) are *welded* (:yref:`RbsmPhys.welded`: stiff "
			"elastic springs that do not break and slip only with :yref:`weldYields<RbsmMat.weldYields>`, the cuts of a continuum), while joints made later, broken ones and the builders' "
			"joint sets and traces keep the Mohr-Coulomb law. Rigid blocks (False, default) are Kawai's. Read when a block is built "
			"(newAssocState) and when a joint is made; needs :yref:`BlockStrainIntegrator` in O.engines (yade_rbsm.engines() adds it when a material is deformable)."))
		((bool, plastic, false, ,
			"Deformable blocks of this material yield (issue 39): their stress D(ε − εᵖ) is held within Mohr-Coulomb with a tension cut-off, "
			"of the same cohesion, frictionAngle and tensileStrength as the joints (the cut-off at most the apex c cot φ), by FLAC's explicit return "
			"map at every step (:yref:`BlockStrainIntegrator`), so that a shear band can run through blocks; the plastic strain and the yield state "
			"are kept in :yref:`DeformableState`. The out-of-plane stress is taken as the intermediate one. Strength reduction reduces the blocks' "
			"strength with the joints'. False (default): elastic blocks. Read at every step; ignored for rigid blocks."))
		((Real, dilatancy, 0, Attr::triggerPostLoad,
			"Dilatancy angle ψ of plastic blocks [rad], in [0, π/2); used as min(ψ, frictionAngle). 0 (default, as Griffiths & Lane's strength reduction): "
			"plastic flow keeps the block's area."))
		((Real, weldBreakStrain, 0, Attr::triggerPostLoad,
			"Plastic deformable blocks: a welded joint between two blocks whose :yref:`plasticShear<DeformableState.plasticShear>` both exceed this "
			"becomes a Mohr-Coulomb joint of the material's strength (a crack of the continuum, along which a failed mass can slide and run out); "
			"the criterion is the blocks' plastic shear because it is what a shear band accumulates and a uniformly stressed block does not localise "
			"(≥ 0; 0, default: welded joints stay welded). Read when a joint is made (:yref:`RbsmPhys.weldBreakStrain`)."))
		((bool, weldYields, false, ,
			"Plastic deformable blocks: their welded joints carry no more shear than the material they cut, |τ| ≤ max(c + σn tan φ, 0), "
			"perfectly plastic (:yref:`RbsmPhys.weldYields`; tension stays the blocks' to cut off). Elastic welds (False, default) can carry "
			"many times that where a rigid boundary's corner concentrates the strain (60 × c beside a strip footing's edges, +9.7 % on "
			"Prandtl's load; True: +3.7 %, tests/deformable/test_footing.py); slipping welds make a slope's strength reduction converge slower "
			"near its limit (docs/manual/guide/deformable.md). A joint yields if both its materials say so. Read when a joint is made."))
		((Real, penalty, 100, Attr::triggerPostLoad,
			"Deformable blocks: the stiffness of their joints' springs as a multiple of Kawai's (≥ 1): Kawai's h/E′ is the compliance "
			"of a rigid block's half, which a deformable block carries in itself, so its side of a joint adds h/(penalty·E′). Larger is "
			"closer to a continuum across welded joints (a Voronoi plate is softer than the material by about 1/penalty: −9 %, −3.2 %, −0.9 % at 10, 30, 100, tests/deformable/test_patch.py) and costs √penalty in time step.")),
		/*ctor*/ createIndex(); density = 2600;,
		/*py*/ .add_property("density", boost::python::make_getter(&Material::density, boost::python::return_value_policy<boost::python::return_by_value>()),
			&detail::setThenPostLoad<RbsmMat, Material, Real, &Material::density>,
			"Density of the blocks [kg/m³] (> 0); checked when set, like the attributes above (Material's own density is not).")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RbsmMat, Material);
	//! A deformable material's blocks get a DeformableState (YADE's utils and the plugin's builders ask the material).
	shared_ptr<State> newAssocState() const override;
	bool              stateTypeOk(State* s) const override;
};
REGISTER_SERIALIZABLE(RbsmMat);

} // namespace yade
