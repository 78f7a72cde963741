// RbsmGeom: geometry of an edge-to-edge contact between two Polygon2D blocks.
#pragma once
#include <core/IGeom.hpp>
#include <core/State.hpp>
#include <pkg/rbsm/BlockStateCheck.hpp>
#include <pkg/rbsm/kernel/ContactMemory.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/FrozenContact.hpp>
#include <pkg/rbsm/kernel/HeapValue.hpp>
#include <pkg/rbsm/kernel/IntegrationRule.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>
#include <pkg/rbsm/kernel/Pose2.hpp>
#include <pkg/rbsm/kernel/SegmentKinematics.hpp>

namespace yade {

/* The contact line is an edge of one block (the reference edge); the other block's facing edge is
 * clipped to it, giving a segment p0-p1 of length ℓ on the reference line. Along it, the joint
 * springs sit at integration points x_k = p0 + s_k (p1 - p0) (Gauss-Legendre s_k, weights w_k, the
 * rule of nIP points). Both blocks being rigid, the relative displacement of block 2 with respect
 * to block 1 (the seed's eq. (8)-(9)) is linear along the segment (rbsm::SegmentKinematics), so the
 * geometry stores its values at the ends and the law samples them at the points:
 *   δn(s) = (1 − s) d0 + s d1      normal overlap, total, from the geometry: > 0 penetration [m]
 *   v(s)  = v0 + s (ω2 − ω1) ẑ × (p1 − p0)   velocity of block 2 relative to block 1 [m/s]
 *   Δus(s) = v(s)·t dt             tangential increment of the step; the shear spring is tracked
 *                                  incrementally (RbsmPhys), so it follows the contact as it rotates
 *                                  and translates.
 * The per-point values are Python properties (deltaN, shearIncrement, normalVelocity, shearVelocity),
 * computed when asked: no per-point arrays live in the contact.
 * Convention (YADE's): the normal n points from body 1 to body 2, t = (-n.y, n.x). */
class RbsmGeom : public IGeom {
public:
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmGeom, IGeom,
		"Edge-to-edge contact of two :yref:`Polygon2D` blocks (RBSM): contact segment, frame and, at each integration "
		"point, normal overlap and tangential displacement increment (seed paper eq. 8-9). Created by "
		":yref:`Ig2_Polygon2D_Polygon2D_RbsmGeom`.",
		((std::vector<Real>, frozenState, , Attr::hidden, "The frozen contact (rbsm::FrozenContact, see frozenSteps) packed for saving; empty when there is none."))
		((std::vector<Real>, strainsMadeState, , Attr::hidden, "The deformable blocks' strains when the joint was made (6 numbers, see strainSides) for saving; empty when there are none."))
		((Vector2r, normal, Vector2r::Zero(), Attr::readonly, "Unit normal of the contact line, from body 1 to body 2."))
		((Vector2r, p0, Vector2r::Zero(), Attr::readonly, "Start of the contact segment on the reference line [m]."))
		((Vector2r, p1, Vector2r::Zero(), Attr::readonly, "End of the contact segment (p0→p1 along the tangent) [m]."))
		((Real, d0, 0, (Attr::readonly | Attr::noSave), "Normal overlap at p0 [m] (> 0 penetration, < 0 gap); the overlap is linear along the segment, δn(s) = (1 − s) d0 + s d1."))
		((Real, d1, 0, (Attr::readonly | Attr::noSave), "Normal overlap at p1 [m]."))
		((Vector2r, relativeVelocity, Vector2r::Zero(), (Attr::readonly | Attr::noSave), "Velocity of block 2's material point at p0 relative to block 1's [m/s]."))
		((Real, relativeAngularVelocity, 0, (Attr::readonly | Attr::noSave), "ω2 − ω1 [rad/s]; with relativeVelocity the relative velocity anywhere on the segment, v(s) = v0 + s (ω2 − ω1) ẑ × (p1 − p0)."))
		((Real, length, 0, Attr::readonly, "Contact length ℓ = |p1 − p0| [m]."))
		((Real, thickness, 1, Attr::readonly, "Out-of-plane thickness of the joint [m]: the smaller of the two blocks' thickness."))
		((Real, reducedMass, 0, Attr::readonly, "m1·m2/(m1+m2) of the two blocks [kg] (a fixed block counts as infinite mass); used by contact damping."))
		((Vector2r, centroid1, Vector2r::Zero(), (Attr::readonly | Attr::noSave), "Centroid of block 1 at this step [m]."))
		((Vector2r, centroid2, Vector2r::Zero(), (Attr::readonly | Attr::noSave), "Centroid of block 2 at this step [m]."))
		((Real, separation, 0, Attr::readonly, "Largest separation between the blocks (separating-axis search) [m]; < 0 when they overlap. In a step with frozen kinematics (Ig2's updateTolerance) minus the larger overlap at the segment's ends."))
		((Real, h1, 0, Attr::readonly, "Distance from block 1's centroid to the contact line [m] (Kawai's h1)."))
		((Real, h2, 0, Attr::readonly, "Distance from block 2's centroid to the contact line [m] (Kawai's h2)."))
		((int, refBody, 0, Attr::readonly, "Which block holds the reference edge (1 or 2); kept from step to step unless another edge is clearly better."))
		((int, refEdge, -1, Attr::readonly, "Index of the reference edge (vertex i → i+1) on that block."))
		((int, incEdge, -1, Attr::readonly, "Index of the incident edge (the other block's edge that faces the reference edge, vertex i → i+1) at the last exact update; -1 if unknown."))
		((int, nIP, 0, Attr::readonly, "Number of integration points along the contact (Gauss-Legendre rule of :yref:`positions<RbsmGeom.positions>` and :yref:`weights<RbsmGeom.weights>`), from :yref:`Ig2_Polygon2D_Polygon2D_RbsmGeom.nIP` when the contact was made."))
		((int, frozenSteps, 0, Attr::readonly, "Steps since the contact geometry was last computed exactly (0: exact at this step). Above 0 only with :yref:`Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance` > 0, while the joint is followed as material points, and for a welded joint (:yref:`RbsmPhys.welded`), which is followed so from its first step after welding for as long as it is welded."))
		((bool, lost, false, (Attr::readonly | Attr::noSave), "The blocks of this joint no longer face each other within reach (the facing edge clipped away, or separated beyond what intact springs can hold): the law breaks every point and removes the joint."))
		((int, strainSides, 0, Attr::readonly, "Which blocks of the joint are deformable (:yref:`DeformableState`): 1 block 1, 2 block 2, 3 both, 0 none; read when the joint is made (and by :yref:`BlockStrainIntegrator` when deformable blocks appear). Their strain's displacement is in deltaN and the velocities, and the joint's tractions load it.")),
		/*ctor*/ createIndex();,
		/*py*/ .def("point", &RbsmGeom::point, "World position of integration point k [m].")
		.add_property("contactPoint", &RbsmGeom::contactPoint, "Middle of the contact segment, (p0 + p1)/2 at z = 0 [m]: the contact point of YADE's sphere contacts (ScGeom.contactPoint), so that YADE's tools reading it (export.VTKExporter.exportContactPoints) work on joints.")
		.add_property("tangent", &RbsmGeom::tangent, "Unit tangent t = (-n.y, n.x) of the contact line (p0→p1 runs along it).")
		.add_property("positions", &RbsmGeom::pyPositions, "Parametric positions s_k in [0, 1] of the integration points along p0→p1.")
		.add_property("weights", &RbsmGeom::pyWeights, "Integration weights w_k (sum 1); the tributary area of point k is w_k·ℓ·thickness.")
		.add_property("deltaN", &RbsmGeom::pyDeltaN, "Normal overlap δn_k at each integration point [m] (> 0 penetration).")
		.add_property("normalVelocity", &RbsmGeom::pyNormalVelocity, "Relative normal velocity at each point [m/s] (> 0 closing).")
		.add_property("shearVelocity", &RbsmGeom::pyShearVelocity, "Relative tangential velocity at each point [m/s].")
		.add_property("shearIncrement", &RbsmGeom::pyShearIncrement, "Tangential relative displacement Δus_k of a step at each point [m]: shearVelocity × O.dt.")
	);
	// clang-format on
	// The attributes are ordered by use: what the geometry functor writes and the law reads at every
	// step is contiguous (fewer cache lines per contact), the saved-only frozenState first.
	Vector2r tangent() const { return Vector2r(-normal.y(), normal.x()); }
	Vector3r contactPoint() const { return Vector3r(0.5 * (p0.x() + p1.x()), 0.5 * (p0.y() + p1.y()), 0); }
	/// The rule of the nIP points (shared, static; null while nIP = 0).
	const rbsm::IntegrationRule* rule = nullptr;
	void                         setIntegrationPoints(int n)
	{
		rule = &rbsm::integrationRule(n); // throws std::invalid_argument outside 1..8
		nIP  = n;
	}
	int nPoints() const { return rule ? rule->n : 0; }
	/// The relative motion along the segment, for the law to sample at its points (Strain false: the law's
	/// step of a joint between rigid blocks, which knows there is no strain to add).
	template <bool Strain = true> rbsm::SegmentKinematics kinematics() const
	{
		const Vector2r          seg = p1 - p0;
		rbsm::SegmentKinematics k { d0, d1, relativeVelocity, relativeAngularVelocity * Vector2r(-seg.y(), seg.x()) };
		if (Strain && strainSides) k.dvds += strainSlope; // (deformable blocks only: a rigid joint's sum is untouched)
		return k;
	}
	Vector2r point(int k) const;
	/// Deformable blocks (strainSides): their strain's displacement B(r)ε since the contact was frozen, and its
	/// rate, added to the overlap at the segment's ends and to the relative velocity along it (linear in s, as
	/// the rigid motion's); a contact found on the strained shapes (onStrainedShapes) takes the rate only.
	void addStrainMotion(const State& state1, const State& state2);
	/// This step's contact was found on the deformable blocks' strained shapes (set by Ig2 at every step).
	bool onStrainedShapes = false;
	/// The strain rates' part of the change of the relative velocity from p0 to p1 [m/s] (addStrainMotion).
	Vector2r strainSlope = Vector2r::Zero();
	/// The deformable blocks' strains when the contact was last frozen (strainSides; on the heap: a rigid joint
	/// carries one pointer): a frozen step follows material points of the shapes strained then, and adds the
	/// strain since. An exact step finds the contact on the strained shapes themselves (Ig2).
	struct StrainsMade {
		Vector3r block1 = Vector3r::Zero(), block2 = Vector3r::Zero();
	};
	rbsm::HeapValue<StrainsMade> strainsMade;
	/// Records the strains of the joint's deformable blocks now (when it is frozen, made, or its blocks become deformable).
	void recordStrainsMade(const State& state1, const State& state2);
	/// The step's contact c (rbsm::EdgeContact, in block 1's frame frame1, exact or frozen) written to
	/// the world frame, with the centroids, Kawai's h1 and h2 and the relative motion along the segment
	/// (the fields kinematics() reads back for the law); the joint is not lost.
	/// (Inline, below: it runs for every contact at every step, from Ig2_Polygon2D_Polygon2D_RbsmGeom.cpp.)
	void update(const rbsm::EdgeContact& c, const rbsm::Pose2& frame1, const State& state1, const State& state2);
	/// After an exact update c at the relative pose rel (block 2 in block 1's frame): freezes it when
	/// keepFrozen (Ig2's updateTolerance > 0), frozenSteps back to 0. (Inline, below: every exact step.)
	void exactAt(const rbsm::EdgeContact& c, const rbsm::Pose2& rel, bool keepFrozen);
	/// frozen = rbsm::freezeContact(c, rel) (out of line: rare, and large for the callers of exactAt).
	void freeze(const rbsm::EdgeContact& c, const rbsm::Pose2& rel);
	/// frozen = f if f is valid, else none.
	void holdFrozen(const rbsm::FrozenContact& f);
	/// The blocks no longer face each other within reach: handed to the law as lost (it ends the joint).
	void markLost(Real separationNow);
	// Python's per-point lists
	std::vector<Real> pyPositions() const;
	std::vector<Real> pyWeights() const;
	std::vector<Real> pyDeltaN() const;
	std::vector<Real> pyNormalVelocity() const;
	std::vector<Real> pyShearVelocity() const;
	std::vector<Real> pyShearIncrement() const;
	/// The contact as material points at its last exact update (Ig2's updateTolerance > 0 only;
	/// rbsm::FrozenContact), on the heap from the first freeze: where updateTolerance is 0 a joint
	/// carries one pointer, not the 136 bytes (every byte of a joint streams at every step at 10⁵ blocks).
	/// Held only while valid (holdFrozen). Saved through frozenState, so that a loaded scene continues
	/// like the uninterrupted run.
	rbsm::HeapValue<rbsm::FrozenContact> frozen;
	/// Polygon2D.revision of the two blocks when the joint was made (not saved: 0 after a load, like
	/// the shapes'); Ig2 makes the joint anew when a block has been reshaped since.
	long shapeRevision1 = 0, shapeRevision2 = 0;
	/// What the last full separating-axis search of this contact found (rbsm::SearchMemory): lets the
	/// next steps skip the search while it provably would choose the same edge. Not saved: after a
	/// load the first step searches in full, with the same result.
	rbsm::SearchMemory searchMemory;
	/// Drops what the joint remembers of the blocks' old shapes (edge numbers, search memory, frozen
	/// contact) and records the new revisions.
	void forgetShapes(long revision1, long revision2)
	{
		searchMemory   = rbsm::SearchMemory();
		frozen.reset();
		refBody        = 0;
		refEdge        = -1;
		frozenSteps    = 0;
		shapeRevision1 = revision1;
		shapeRevision2 = revision2;
	}
	/// m1·m2/(m1+m2), a fixed block (or one without a positive mass) counting as infinite mass.
	static Real reducedMassOf(const State& a, const State& b)
	{
		auto       infinite = [](const State& s) { return fixedBlock(s) || !(s.mass > 0); };
		const bool fa = infinite(a), fb = infinite(b);
		if (fa && fb) return 0;
		if (fa) return b.mass;
		if (fb) return a.mass;
		return a.mass * b.mass / (a.mass + b.mass);
	}
	void                preSave(RbsmGeom&);
	void                postLoad(RbsmGeom&);
	REGISTER_CLASS_INDEX(RbsmGeom, IGeom);
};
REGISTER_SERIALIZABLE(RbsmGeom);

inline void RbsmGeom::update(const rbsm::EdgeContact& c, const rbsm::Pose2& frame1, const State& state1, const State& state2)
{
	// Computed into locals, stored at the end: for the compiler a store to a member could alias c or
	// the states, which it would then load again after every store.
	// Back to the world frame: x ↦ x1 + R(θ1) x for points, R(θ1) for directions.
	const Vector2r n = frame1.rotate(c.normal), a = frame1.apply(c.p0), b = frame1.apply(c.p1);
	const Vector2r c1 = state1.pos.head<2>(), c2 = state2.pos.head<2>();
	const Real     w1 = state1.angVel.z(), w2 = state2.angVel.z();
	// The relative motion along the segment, which the law samples at its points (kinematics()):
	// block 2's velocity relative to block 1's at p0, v2 + ω2 × (p0 − c2) − v1 − ω1 × (p0 − c1).
	const rbsm::SegmentKinematics k = rbsm::segmentKinematics(c.d0, c.d1, a, b, c1, state1.vel.head<2>(), w1, c2, state2.vel.head<2>(), w2);
	if (c.incEdge >= 0) incEdge = c.incEdge; // (a frozen step keeps the last exact one)
	lost                    = false;
	normal                  = n;
	p0                      = a;
	p1                      = b;
	length                  = c.length;
	separation              = c.separation;
	refBody                 = c.refBody;
	refEdge                 = c.refEdge;
	centroid1               = c1;
	centroid2               = c2;
	h1                      = rbsm::distanceToLine(c1, a, n);
	h2                      = rbsm::distanceToLine(c2, a, n);
	d0                      = k.d0;
	d1                      = k.d1;
	relativeVelocity        = k.v0;
	relativeAngularVelocity = w2 - w1;
}

inline void RbsmGeom::exactAt(const rbsm::EdgeContact& c, const rbsm::Pose2& rel, bool keepFrozen)
{
	if (keepFrozen) freeze(c, rel);
	else frozen.reset();
	frozenSteps = 0;
}

} // namespace yade
