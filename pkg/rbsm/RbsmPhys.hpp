// RbsmPhys: the joint between two RBSM blocks: Kawai springs, Mohr-Coulomb strength and the state
// of every integration point.
#pragma once
#include <core/IPhys.hpp>

namespace yade {

class RbsmPhys : public IPhys {
public:
	//! Breaks the joint at every integration point (no cohesion, no tension): a pre-existing crack.
	void breakJoint()
	{
		for (auto&& ok : intact)
			ok = false;
	}
	using Flags = std::vector<unsigned char>; // per-point booleans; not std::vector<bool>, whose bit access costs in the law's loop
	int countTrue(const Flags& v) const { return int(std::count_if(v.begin(), v.end(), [](unsigned char b) { return b != 0; })); }
	int nIntact() const { return countTrue(intact); }
	int nSlipping() const { return countTrue(slipping); }
	int nOpen() const { return countTrue(open); }
	//! Per-point flags as Python lists of bool.
	boost::python::list pyIntact() const { return toList(intact); }
	boost::python::list pySlipping() const { return toList(slipping); }
	boost::python::list pyOpen() const { return toList(open); }
	static boost::python::list toList(const Flags& v)
	{
		boost::python::list l;
		for (unsigned char b : v)
			l.append(b != 0);
		return l;
	}
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmPhys, IPhys,
		"Joint of the Rigid-Bodies-Spring Model between two blocks: normal and shear springs per unit area "
		"(λ = diag(kn, ks)·δ, seed paper eq. 10), Mohr-Coulomb strength (eq. 11), and the state of each integration point. "
		"Tractions are positive in compression (normal) and along the contact tangent (shear, traction on body 2). "
		"Strength values may be changed per interaction, e.g. to model a pre-existing crack (:yref:`breakJoint<RbsmPhys.breakJoint>`).",
		((Real, kn, 0, , "Normal spring stiffness per unit area [Pa/m] (Kawai: E′/(h1+h2))."))
		((Real, ks, 0, , "Shear spring stiffness per unit area [Pa/m] (Kawai: 2G/(h1+h2))."))
		((Real, cohesion, 0, , "Cohesion c of the joint while intact [Pa]."))
		((Real, tanPhi, 0, , "tan φ of the joint friction angle."))
		((Real, tensileStrength, 0, , "Tensile strength σt of the joint while intact [Pa]."))
		((Real, dampingCoefficient, 0, Attr::readonly, "Viscous traction per relative velocity [Pa·s/m] (from the law's dampingRatio; saved, so that RbsmTimeStepper.estimate() of a loaded scene is right before its first step)."))
		((std::vector<Real>, shearTraction, , , "Shear traction τ_k at each integration point [Pa] (incremental elastic, returned to the Mohr-Coulomb surface on slip)."))
		((std::vector<Real>, normalTraction, , Attr::readonly, "Normal traction σn_k at each integration point [Pa] (> 0 compression)."))
		((Flags, intact, , Attr::hidden, "Whether point k still has cohesion and tensile strength."))
		((Flags, slipping, , Attr::hidden, "Whether point k is on the Mohr-Coulomb surface (slipping) this step."))
		((Flags, open, , Attr::hidden, "Whether point k is broken and open (carries nothing)."))
		((Real, normalForce, 0, Attr::readonly, "Resultant normal force of the joint [N] (> 0 compression), Σ σn_k a_k."))
		((Real, shearForce, 0, Attr::readonly, "Resultant shear force of the joint [N] along the contact tangent, Σ τ_k a_k."))
		((Real, strength, 0, Attr::readonly, "Shear strength of the joint at the current normal stress, Σ (c_k + σn_k tanφ) a_k [N] (c_k = 0 where broken)."))
		((Real, plasticDissipation, 0, Attr::readonly, "Energy dissipated by slip on this joint since it formed [J].")),
		/*ctor*/ createIndex();,
		/*py*/
		.add_property("intactPoints", &RbsmPhys::pyIntact, "Per integration point: joint still intact (cohesion and tensile strength active).")
		.add_property("slippingPoints", &RbsmPhys::pySlipping, "Per integration point: slipping on the Mohr-Coulomb surface this step.")
		.add_property("openPoints", &RbsmPhys::pyOpen, "Per integration point: broken and open.")
		.add_property("nIntact", &RbsmPhys::nIntact, "Number of intact integration points.")
		.add_property("nSlipping", &RbsmPhys::nSlipping, "Number of slipping integration points.")
		.add_property("nOpen", &RbsmPhys::nOpen, "Number of open integration points.")
		.def("breakJoint", &RbsmPhys::breakJoint, "Break the joint at all integration points (cohesion and tensile strength lost), e.g. a pre-existing crack.")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RbsmPhys, IPhys);
};
REGISTER_SERIALIZABLE(RbsmPhys);

} // namespace yade
