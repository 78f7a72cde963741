// RbsmGeom: geometry of an edge-to-edge contact between two Polygon2D blocks.
#pragma once
#include <core/IGeom.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/FrozenContact.hpp>

namespace yade {

/* The contact line is an edge of one block (the reference edge); the other block's facing edge is
 * clipped to it, giving a segment p0-p1 of length ℓ on the reference line. Along it, integration
 * points x_k = p0 + s_k (p1 - p0) carry the joint springs (Gauss-Legendre s_k, weights w_k). At each
 * point the seed's eq. (8)-(9) give the relative displacement of block 2 with respect to block 1:
 *   δn_k  normal overlap, total, from the geometry: > 0 penetration, < 0 opening [m]
 *   Δus_k tangential increment of this step, (v2(x_k) - v1(x_k))·t dt [m]; the shear spring is
 *         tracked incrementally (RbsmPhys::shearTraction), so it follows the contact as it rotates
 *         and translates.
 * Convention (YADE's): the normal n points from body 1 to body 2, t = (-n.y, n.x). */
class RbsmGeom : public IGeom {
public:
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmGeom, IGeom,
		"Edge-to-edge contact of two :yref:`Polygon2D` blocks (RBSM): contact segment, frame and, at each integration "
		"point, normal overlap and tangential displacement increment (seed paper eq. 8-9). Created by "
		":yref:`Ig2_Polygon2D_Polygon2D_RbsmGeom`.",
		((Vector2r, normal, Vector2r::Zero(), Attr::readonly, "Unit normal of the contact line, from body 1 to body 2."))
		((Vector2r, tangent, Vector2r::Zero(), Attr::readonly, "Unit tangent (-n.y, n.x)."))
		((Vector2r, p0, Vector2r::Zero(), Attr::readonly, "Start of the contact segment on the reference line [m]."))
		((Vector2r, p1, Vector2r::Zero(), Attr::readonly, "End of the contact segment (p0→p1 along the tangent) [m]."))
		((Real, length, 0, Attr::readonly, "Contact length ℓ = |p1 − p0| [m]."))
		((Real, thickness, 1, Attr::readonly, "Out-of-plane thickness of the joint [m]: the smaller of the two blocks' thickness."))
		((Real, h1, 0, Attr::readonly, "Distance from block 1's centroid to the contact line [m] (Kawai's h1)."))
		((Real, h2, 0, Attr::readonly, "Distance from block 2's centroid to the contact line [m] (Kawai's h2)."))
		((Real, separation, 0, Attr::readonly, "Largest separation between the blocks (separating-axis search) [m]; < 0 when they overlap. In a step with frozen kinematics (Ig2's updateTolerance) minus the larger overlap at the segment's ends."))
		((Real, reducedMass, 0, Attr::readonly, "m1·m2/(m1+m2) of the two blocks [kg] (a fixed block counts as infinite mass); used by contact damping."))
		((int, refBody, 0, Attr::readonly, "Which block holds the reference edge (1 or 2); kept from step to step unless another edge is clearly better."))
		((int, refEdge, -1, Attr::readonly, "Index of the reference edge (vertex i → i+1) on that block."))
		((std::vector<Real>, weights, , Attr::readonly, "Integration weights w_k (sum 1); the tributary area of point k is w_k·ℓ·thickness."))
		((std::vector<Real>, positions, , Attr::readonly, "Parametric positions s_k in [0, 1] of the integration points along p0→p1."))
		((std::vector<Real>, deltaN, , (Attr::readonly | Attr::noSave), "Normal overlap δn_k at each integration point [m] (> 0 penetration)."))
		((std::vector<Real>, shearIncrement, , (Attr::readonly | Attr::noSave), "Tangential relative displacement Δus_k of this step at each point [m]."))
		((std::vector<Real>, normalVelocity, , (Attr::readonly | Attr::noSave), "Relative normal velocity at each point [m/s] (> 0 closing)."))
		((std::vector<Real>, shearVelocity, , (Attr::readonly | Attr::noSave), "Relative tangential velocity at each point [m/s]."))
		((int, frozenSteps, 0, Attr::readonly, "Steps since the contact geometry was last computed exactly (0: exact at this step). Above 0 only with :yref:`Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance` > 0, while the joint is followed as material points."))
		((std::vector<Real>, frozenState, , Attr::hidden, "The frozen contact (rbsm::FrozenContact, see frozenSteps) packed for saving; empty when there is none."))
		((bool, lost, false, (Attr::readonly | Attr::noSave), "The blocks of this joint no longer face each other within reach (the facing edge clipped away, or separated beyond what intact springs can hold): the law breaks every point and removes the joint."))
		((Vector2r, centroid1, Vector2r::Zero(), (Attr::readonly | Attr::noSave), "Centroid of block 1 at this step [m]."))
		((Vector2r, centroid2, Vector2r::Zero(), (Attr::readonly | Attr::noSave), "Centroid of block 2 at this step [m].")),
		/*ctor*/ createIndex();,
		/*py*/ .def("point", &RbsmGeom::point, "World position of integration point k [m].")
	);
	// clang-format on
	Vector2r point(int k) const { return p0 + positions.at(k) * (p1 - p0); }
	/// What the last full separating-axis search of this contact found (rbsm::SearchMemory): lets the
	/// next steps skip the search while it provably would choose the same edge. Not saved: after a
	/// load the first step searches in full, with the same result.
	rbsm::SearchMemory searchMemory;
	/// The contact as material points at its last exact update (Ig2's updateTolerance > 0 only;
	/// rbsm::FrozenContact). Saved through frozenState, so that a loaded scene continues like the
	/// uninterrupted run.
	rbsm::FrozenContact frozen;
	void                preSave(RbsmGeom&) { frozenState = rbsm::packFrozen(frozen); }
	void                postLoad(RbsmGeom&) { frozen = rbsm::unpackFrozen(frozenState); }
	size_t   nPoints() const { return weights.size(); }
	REGISTER_CLASS_INDEX(RbsmGeom, IGeom);
};
REGISTER_SERIALIZABLE(RbsmGeom);

} // namespace yade
