// RbsmPhys: the joint between two RBSM blocks: Kawai springs, Mohr-Coulomb strength and the state
// of every integration point.
#pragma once
#include <core/IPhys.hpp>
#include <pkg/rbsm/kernel/IntegrationRule.hpp>
#include <pkg/rbsm/kernel/HeapValue.hpp>
#include <pkg/rbsm/kernel/MohrCoulombJoint.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>

namespace yade {

class RbsmPhys : public IPhys {
public:
	/// The state of one integration point: the law's (rbsm::JointPointState: shear traction, intact,
	/// slipping, open) and the normal traction it found.
	struct Point {
		rbsm::JointPointState joint;
		Real                  normalTraction = 0;
	};
	/// A joint's points live in the joint itself up to kInlinePoints (Ig2's default nIP = 2: one block of
	/// memory with the joint, no other), and all in one heap block of their own beyond (nIP 3..8), so a
	/// scene pays only for the points it asked for.
	static constexpr int kInlinePoints = 2;
	/// The points beyond kInlinePoints: one heap block, copied with the joint (MemoryOrder.cpp copies
	/// joints to lay them out in loop order).
	struct MorePoints {
		std::unique_ptr<Point[]> data;
		int                      size = 0;
		MorePoints()                  = default;
		MorePoints(const MorePoints& o)
		        : data(o.size ? new Point[o.size] : nullptr)
		        , size(o.size)
		{
			std::copy_n(o.data.get(), size, data.get());
		}
		MorePoints& operator=(const MorePoints& o)
		{
			MorePoints c(o);
			std::swap(data, c.data);
			std::swap(size, c.size);
			return *this;
		}
		void reset(int n)
		{
			data.reset(n ? new Point[n] : nullptr);
			size = n;
		}
	};
	std::array<Point, kInlinePoints> inlinePoints {};
	MorePoints                       morePoints; ///< all the points when there are more than kInlinePoints
	int                              nPoints = 0; ///< how many points (the geometry's nIP)
	/// The dashpots' forces at each point (normal, shear) [N] as applied at the last step: the law counts the second
	/// half of their work at the next step, with the velocity they acted at (O.trackEnergy and damping only;
	/// saved as dashpotForces).
	struct DashpotForces {
		std::array<Real, 2 * rbsm::kMaxIntegrationPoints> f {};
	};
	rbsm::HeapValue<DashpotForces> lastDashpots;
	Point*                           pointData() { return morePoints.data ? morePoints.data.get() : inlinePoints.data(); }
	const Point*                     pointData() const { return morePoints.data ? morePoints.data.get() : inlinePoints.data(); }
	Point&                           point(int k) { return pointData()[k]; }
	const Point&                     point(int k) const { return pointData()[k]; }

	//! Sets up n points, all intact or all broken (Ip2, when the joint forms).
	void initPoints(int n, bool intact)
	{
		if (n < 0 || n > rbsm::kMaxIntegrationPoints) throw std::invalid_argument("RbsmPhys: 0..8 integration points (got " + std::to_string(n) + ")");
		nPoints = n;
		inlinePoints.fill(Point {});
		morePoints.reset(n > kInlinePoints ? n : 0);
		for (int k = 0; k < n; k++)
			point(k).joint.intact = intact;
	}
	//! Breaks the joint at every integration point (no cohesion, no tension): a pre-existing crack.
	void breakJoint()
	{
		welded = false;
		for (int k = 0; k < nPoints; k++)
			point(k).joint.intact = false;
	}
	template <class F> int countPoints(F f) const
	{
		int c = 0;
		for (int k = 0; k < nPoints; k++)
			c += f(point(k).joint) ? 1 : 0;
		return c;
	}
	int nIntact() const { return countPoints([](const rbsm::JointPointState& j) { return j.intact; }); }
	int nSlipping() const { return countPoints([](const rbsm::JointPointState& j) { return j.slipping; }); }
	int nOpen() const { return countPoints([](const rbsm::JointPointState& j) { return j.open; }); }
	// Python's per-point lists (defined with the functor, Ip2_RbsmMat_RbsmMat_RbsmPhys.cpp)
	boost::python::list pyIntact() const;
	boost::python::list pySlipping() const;
	boost::python::list pyOpen() const;
	std::vector<Real>   pyShearTraction() const;
	void                pySetShearTraction(const std::vector<Real>& tau);
	std::vector<Real>   pyNormalTraction() const;
	//! Counts the joints whose kn, ks were set from Python (assignment; also updateAttrs and a
	//! constructor, which may set them; not O.load): RbsmTimeStepper makes a full estimate at its
	//! next step when it changed (a stiffer joint). Strengths do not count: they leave the step alone,
	//! and scripts set them mid-run (a full estimate there would change the steps a run takes).
	static inline std::atomic<long> edits { 0 };
	//! A joint value is finite and >= 0, else std::invalid_argument naming it (ValueError in Python).
	static void checkValue(const char* name, Real v);
	//! Python's setter of a strength: checked, nothing else (no postLoad, no edit counted).
	template <Real RbsmPhys::*Member> static void setStrength(RbsmPhys& p, Real v);
	template <Real RbsmPhys::*Member> static Real getValue(const RbsmPhys& p) { return p.*Member; }
	// Saving: the points go through the hidden attributes shearTraction ... open (the names and
	// types of the per-point attributes of earlier versions), filled only around a save or load.
	void preSave(RbsmPhys&);
	void postSave(RbsmPhys&);
	void postLoad(RbsmPhys&);
	using Flags = std::vector<unsigned char>; // per-point booleans as saved
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmPhys, IPhys,
		"Joint of the Rigid-Bodies-Spring Model between two blocks: normal and shear springs per unit area "
		"(λ = diag(kn, ks)·δ, seed paper eq. 10), Mohr-Coulomb strength (eq. 11), and the state of each integration point. "
		"Tractions are positive in compression (normal) and along the contact tangent (shear, traction on body 2). "
		"Strength values may be changed per interaction, e.g. to model a pre-existing crack (:yref:`breakJoint<RbsmPhys.breakJoint>`).",
		((Real, kn, 0, Attr::triggerPostLoad, "Normal spring stiffness per unit area [Pa/m] (Kawai: E′/(h1+h2)); finite, >= 0. A change makes RbsmTimeStepper estimate the step again before the next step moves anything."))
		((Real, ks, 0, Attr::triggerPostLoad, "Shear spring stiffness per unit area [Pa/m] (Kawai: 2G/(h1+h2)); finite, >= 0 (a change: as kn)."))
		((Real, cohesion, 0, , "Cohesion c of the joint while intact [Pa]; finite, >= 0."))
		((Real, tanPhi, 0, , "tan φ of the joint friction angle; finite, >= 0."))
		((Real, tensileStrength, 0, , "Tensile strength σt of the joint while intact [Pa]; finite, >= 0."))
		((bool, ductile, false, , "Slip keeps the cohesion (perfectly plastic); only tension breaks the joint (:yref:`RbsmMat.ductile`)."))
		((bool, welded, false, , "The joint is a cut of a continuum between two deformable blocks (:yref:`RbsmMat.deformable`), not a discontinuity: its springs are elastic penalty springs that do not break (tension unlimited) and slip only between plastic blocks (:yref:`weldYields<RbsmPhys.weldYields>`; otherwise shear is unlimited too and the strengths above are not used). Made so by Ip2 for the joints of deformable blocks bonded at the first step (setCohesionNow); breakJoint, and yade_rbsm.slope.set_joint_strength along a joint, make it a Mohr-Coulomb joint."))
		((bool, weldYields, false, , "A welded joint between two plastic blocks (:yref:`RbsmMat.plastic`) carries no more shear than the material it cuts: |τ| ≤ max(c + σn tan φ, 0) at its points, perfectly plastic (slip keeps the cohesion), as no plane of a Mohr-Coulomb continuum carries more. Its tension stays unlimited: the tension cut-off is the blocks' (a weld opened in tension would be followed as material points that no longer meet). Set by Ip2 when the joint is made, from :yref:`RbsmMat.weldYields`; False: elastic and unlimited."))
		((Real, weldBreakStrain, 0, , "A welded joint becomes a Mohr-Coulomb joint (welded False) when both its blocks' plasticShear exceed this; 0: never. From the materials' :yref:`RbsmMat.weldBreakStrain` (the larger, if both give one)."))
		((Real, linearShare, 1, Attr::triggerPostLoad, "Welded joints: the share of kn, ks that resists the linear part of the jump along the joint (its bending), the whole of them resisting its mean: Kawai's springs of the two materials over the penalty ones (1/penalty), set by Ip2. A jump penalised in full at every point of every edge over-constrains the blocks' constant strains, which then lock in any field but a uniform one (tests/deformable/test_disc.py). In (0, 1]; 1: every point alike (the other joints). The point tractions are those applied."))
		((bool, water, false, , "The joint takes the pore pressure of the law's phreatic surface (:yref:`Law2_RbsmGeom_RbsmPhys_MohrCoulomb.phreatic`; yade_rbsm.slope.set_water sets it on the joint sets' joints)."))
		((Real, waterForce, 0, Attr::readonly, "Force of the water in the joint at the last step, Σ u_k a_k [N] (pushing its blocks apart)."))
		((Real, dampingCoefficient, 0, Attr::readonly, "Viscous traction per relative velocity [Pa·s/m] (from the law's dampingRatio; saved, so that RbsmTimeStepper.estimate() of a loaded scene is right before its first step)."))
		((Real, normalForce, 0, Attr::readonly, "Resultant normal force of the joint [N] (> 0 compression), Σ σn_k a_k."))
		((Real, shearForce, 0, Attr::readonly, "Resultant shear force of the joint [N] along the contact tangent, Σ τ_k a_k."))
		((Real, strength, 0, Attr::readonly, "Shear strength of the joint at the current normal stress, Σ (c_k + σn_k tanφ) a_k [N] (c_k = 0 where broken)."))
		((Real, plasticDissipation, 0, Attr::readonly, "Energy dissipated by slip on this joint since it formed [J]."))
		((Real, bondedLength, -1, Attr::readonly, "Length of contact segment that is bonded [m] (cohesive joints): while the joint has never slipped (plasticDissipation = 0), the segment's length less the blocks' tangential travel since the joint formed (tangentialTravel): a face bonded across a small misfit bonds as it closes, a corner bonded at a point and slid along a face does not; after a slip it only shrinks with the segment. Cohesion and tensile strength of the intact points act over this length, spread over the segment. -1: not yet met (a scene saved before this attribute starts from its next step)."))
		((Real, tangentialTravel, 0, Attr::readonly, "Relative tangential displacement of the blocks at the middle of the segment since the joint formed [m] (cohesive joints; bondedLength)."))
		((Real, contactLength, 0, Attr::readonly, "Length of the contact segment at the last step of the law [m]: where a frictional contact grows, the new part carries no shear yet, so the shear tractions of its broken points are scaled by old/new length (without it a rocking or tipping block gained energy from tractions spread over a growing area)."))
		((std::vector<Real>, shearTraction, , Attr::hidden, "Saved form of the shear traction τ_k of each point [Pa] (see the property of that name)."))
		((std::vector<Real>, normalTraction, , Attr::hidden, "Saved form of the normal traction σn_k of each point [Pa]."))
		((Flags, intact, , Attr::hidden, "Saved form of intactPoints."))
		((Flags, slipping, , Attr::hidden, "Saved form of slippingPoints."))
		((Flags, open, , Attr::hidden, "Saved form of openPoints."))
		((std::vector<Real>, dashpotForces, , Attr::hidden, "Saved form of the dashpots' forces of the last step (normal, shear of each point) [N], whose work the law counts in part at the next step (O.trackEnergy with contact damping); empty when none.")),
		/*ctor*/ createIndex();,
		/*py*/
		// (the strengths again, with a checked setter: these replace the attributes' own properties)
		.add_property("cohesion", &RbsmPhys::getValue<&RbsmPhys::cohesion>, &RbsmPhys::setStrength<&RbsmPhys::cohesion>, "Cohesion c of the joint while intact [Pa]; finite, >= 0.")
		.add_property("tanPhi", &RbsmPhys::getValue<&RbsmPhys::tanPhi>, &RbsmPhys::setStrength<&RbsmPhys::tanPhi>, "tan φ of the joint friction angle; finite, >= 0.")
		.add_property("tensileStrength", &RbsmPhys::getValue<&RbsmPhys::tensileStrength>, &RbsmPhys::setStrength<&RbsmPhys::tensileStrength>, "Tensile strength σt of the joint while intact [Pa]; finite, >= 0.")
		.add_property("shearTraction", &RbsmPhys::pyShearTraction, &RbsmPhys::pySetShearTraction, "Shear traction τ_k at each integration point [Pa] (incremental elastic, returned to the Mohr-Coulomb surface on slip); may be set, one value per point.")
		.add_property("normalTraction", &RbsmPhys::pyNormalTraction, "Normal traction σn_k at each integration point [Pa] (> 0 compression).")
		.add_property("intactPoints", &RbsmPhys::pyIntact, "Per integration point: joint still intact (cohesion and tensile strength active).")
		.add_property("slippingPoints", &RbsmPhys::pySlipping, "Per integration point: slipping on the Mohr-Coulomb surface this step.")
		.add_property("openPoints", &RbsmPhys::pyOpen, "Per integration point: broken and open.")
		.add_property("nIntact", &RbsmPhys::nIntact, "Number of intact integration points.")
		.add_property("nSlipping", &RbsmPhys::nSlipping, "Number of slipping integration points.")
		.add_property("nOpen", &RbsmPhys::nOpen, "Number of open integration points.")
		.def("breakJoint", &RbsmPhys::breakJoint, "Break the joint at all integration points (cohesion and tensile strength lost; a welded joint becomes a Mohr-Coulomb one), e.g. a pre-existing crack.")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RbsmPhys, IPhys);
};
REGISTER_SERIALIZABLE(RbsmPhys);

template <Real RbsmPhys::*Member> void RbsmPhys::setStrength(RbsmPhys& p, Real v)
{
	checkValue(Member == &RbsmPhys::cohesion ? "cohesion" : Member == &RbsmPhys::tanPhi ? "tanPhi" : "tensileStrength", v);
	p.*Member = v;
}

} // namespace yade
