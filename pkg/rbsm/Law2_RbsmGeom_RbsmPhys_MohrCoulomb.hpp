// Law2_RbsmGeom_RbsmPhys_MohrCoulomb: forces of the RBSM joint springs with Mohr-Coulomb slip.
#pragma once
#include <core/Dispatching.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>
#include <pkg/rbsm/kernel/Hydrostatic.hpp>

namespace yade {

class Law2_RbsmGeom_RbsmPhys_MohrCoulomb : public LawFunctor {
public:
	bool go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I) override;
	//! The joint's load on the strain of its deformable blocks (RbsmGeom.strainSides), from its force on body 2 and Σ s_k f_k.
	void addStrainLoads(const Interaction& I, const RbsmGeom& g, const Vector2r& force, const Vector2r& firstMoment);
	//! Checks the attributes when they are set (raises ValueError in Python, before any step).
	void postLoad(Law2_RbsmGeom_RbsmPhys_MohrCoulomb&)
	{
		if (!(std::isfinite(dampingRatio) && dampingRatio >= 0))
			throw std::invalid_argument("Law2_RbsmGeom_RbsmPhys_MohrCoulomb.dampingRatio: must be a finite number >= 0 (got " + std::to_string(dampingRatio) + ")");
		rbsm::checkWaterTable("Law2_RbsmGeom_RbsmPhys_MohrCoulomb", phreatic, waterUnitWeight);
	}
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Law2_RbsmGeom_RbsmPhys_MohrCoulomb, LawFunctor,
		"Contact law of the Rigid-Bodies-Spring Model (seed paper eq. 10-11). At each integration point k of the joint:\n\n"
		"* σn = kn·δn (δn total overlap from the geometry, > 0 compression) and τ ← τ − ks·Δus (incremental shear);\n"
		"* tension cut-off: an intact point with σn < −σt breaks irreversibly (c, σt → 0) and opens; a broken point with "
		"δn ≤ 0 is open and carries nothing;\n"
		"* Mohr-Coulomb: |τ| ≤ c + σn tanφ; beyond it an intact point breaks (c → 0) and τ returns to ±σn tanφ (slip);\n"
		"* a frictional joint (no intact point left, or c = σt = 0) slips as a whole, by Coulomb's law for its "
		"resultant |Σ τ_k a_k| ≤ tanφ Σ σn_k a_k, with the same plastic slip at every point: two rigid blocks slide by the "
		"same amount all along their joint.\n\n"
		"The tractions, times the tributary area w_k·ℓ·thickness, give a force and a moment on each block (force on body 2 "
		"= Σ (σn n + τ t) a_k, opposite on body 1). With O.trackEnergy: 'elastPotential' (spring energy), 'plastDissip' "
		"(friction's work on the plastic slip), 'jointRelease' (spring energy lost without friction work: points that open or break, "
		"contact length that goes, the rest of a return to the friction surface) and 'viscDamp' if dampingRatio > 0, so that "
		"with NewtonIntegrator's 'kinetic' and 'gravWork' O.energy.total() stays constant. A joint that is open everywhere and separated is removed.\n\n"
		"Water (UDEC's hydrostatic joint pressure): with a :yref:`phreatic<Law2_RbsmGeom_RbsmPhys_MohrCoulomb.phreatic>` surface, each "
		"point of a joint that takes water (:yref:`RbsmPhys.water`, or every joint with :yref:`waterAll<Law2_RbsmGeom_RbsmPhys_MohrCoulomb.waterAll>`) "
		"below it has the pore pressure u = γw·(h(x) − y), which pushes the two blocks apart with u·a_k; the springs carry the "
		"effective stress, so the strength is c + σn′ tanφ with σn′ = σn − u. The water stays as given (no flow); its work on the blocks is O.energy's waterWork. "
		"With :yref:`openWater<Law2_RbsmGeom_RbsmPhys_MohrCoulomb.openWater>` the blocks stand in open water: the pressure on their faces is "
		":yref:`OpenWaterPressure`'s (the whole boundary below the water table, buoyancy included), so a wet joint adds none of its own, and a "
		"dry contact below the water table is pressed shut by the water around its blocks (its faces' pressure taken off them).",
		((std::vector<Vector2r>, phreatic, , Attr::triggerPostLoad, "The phreatic surface (water table) [m], a polyline of strictly increasing x in the blocks' plane, continued level beyond its ends; empty (default): no water, no cost."))
		((Real, waterUnitWeight, 9810, Attr::triggerPostLoad, "Unit weight of the water γw [N/m³]."))
		((bool, waterAll, false, , "Every joint takes water (UDEC: every contact), not only those with RbsmPhys.water."))
		((bool, openWater, false, , "The blocks stand in open water (a reservoir, a submerged toe): :yref:`OpenWaterPressure` puts the water's pressure on the faces of every block, and the joints add only what the faces' pressure leaves out (a dry contact: pressed shut). yade_rbsm.slope.set_water(open_water=True) sets both."))
		((Real, dampingRatio, 0, Attr::triggerPostLoad, "Viscous contact damping as a fraction of critical damping of the joint (normal and shear), ξ; 0 disables it (no cost). The shear dashpot acts while the joint sticks, and spring and dashpot together stay within the Mohr-Coulomb strength of the springs' normal force: the dashpot damps, it adds no friction. A point that is not bonded is damped over the part of the step it was in contact: closing by more than its overlap δ in the step, at δ/dt (a landing's first push does not depend on where in the step the contact began; docs/manual/guide/model.md)."))
		((int, plastDissipIx, -1, (Attr::hidden | Attr::noSave), "Index of plastDissip in O.energy."))
		((int, elastPotentialIx, -1, (Attr::hidden | Attr::noSave), "Index of elastPotential in O.energy."))
		((int, waterWorkIx, -1, (Attr::hidden | Attr::noSave), "Index of waterWork in O.energy."))
		((int, viscDampIx, -1, (Attr::hidden | Attr::noSave), "Index of viscDamp in O.energy."))
		((int, jointReleaseIx, -1, (Attr::hidden | Attr::noSave), "Index of jointRelease in O.energy.")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(RbsmGeom, RbsmPhys);

private:
	//! The step of one joint; Strain: a joint of a deformable block (RbsmGeom.strainSides) or a welded one.
	template <bool Strain> bool joint(RbsmGeom& g, RbsmPhys& p, Interaction* I);
	bool deformableJoint(RbsmGeom& g, RbsmPhys& p, Interaction* I);
	DEFINE_FUNCTOR_ORDER_2D(RbsmGeom, RbsmPhys);
};
REGISTER_SERIALIZABLE(Law2_RbsmGeom_RbsmPhys_MohrCoulomb);

} // namespace yade
