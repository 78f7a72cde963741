// Frozen contact kinematics: an opt-in trade of accuracy for speed between exact updates of the
// edge-to-edge contact (EdgeContact.hpp).
//
// The exact contact (separating-axis search, clipping) is recomputed from the blocks' shapes at
// every step. Between two steps of a resting or slowly moving joint it barely changes, so the
// plugin may instead, while the two blocks have moved relative to each other by less than a
// tolerance since the last exact update, follow the contact segment as material points:
//
//   * p0, p1  the segment's ends on the reference line, fixed in the REFERENCE block
//             (the block that holds the reference edge), with its outward normal nRef;
//   * q0, q1  their partners on the incident block at the update, q = p − d nRef (d the overlap
//             there), fixed in the INCIDENT block.
//
// After rigid motions of the two blocks the overlaps are the distances of q behind the moved
// reference line, d_i = −nRef·(q_i − p_i) (seed eq. (8) for the material point q_i), and the
// segment p0 → p1 moves with the reference block. This is the classical small-displacement RBSM
// kinematics of Kawai (relative displacement of two material points that coincided), with the
// geometry refreshed whenever the motion grows.
//
// Error against the exact contact. A pure approach along the normal is reproduced exactly (to
// round-off). A relative rotation α and tangential slip s since the update change the overlap at
// the material points only at second order: the exact contact measures the overlap where the
// incident edge crosses the normal through the integration point, the frozen one at the material
// point that has slipped by s along an edge tilted by α, |Δd| ≲ (|α| + |d1 − d0|/L) s + α² L
// (the joint's own overlap gradient is a tilt of the same kind); the segment ends
// lag behind the exact ones by at most s (its length is the one of the update). With the motion
// bounded by tol·size (frozenDrift below), the overlap error is O(tol²·size) and the contact
// length error O(tol·size). Unit tests: tests/unit/test_frozen_contact.cpp.
//
// Frames: everything is computed in block A's (body 1's) frame, where B has the relative pose
// `pose` (a Pose2: B's centroid in A's frame, cos and sin of θB − θA; Pose2::relative). Units: metres.
#pragma once

#include <pkg/rbsm/kernel/ContactMemory.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rbsm {

/// The material points of a contact at its last exact update (see above).
struct FrozenContact {
	bool         valid   = false;
	int          refBody = 0; ///< 1: the reference edge is A's, 2: B's
	int          refEdge = -1;
	Vec2         nRef    = Vec2::Zero(); ///< outward normal of the reference edge, reference block's frame
	Vec2         p0 = Vec2::Zero(), p1 = Vec2::Zero(); ///< segment ends, reference block's frame
	Vec2         q0 = Vec2::Zero(), q1 = Vec2::Zero(); ///< their partners, incident block's frame
	Real         length = 0;                           ///< |p1 − p0| (rigid: unchanged)
	Pose2        pose;                                 ///< B relative to A at the update
};

/// Freezes the exact contact c (A's frame, from edgeContact) of blocks at relative pose `pose`.
inline FrozenContact freezeContact(const EdgeContact& c, const Pose2& pose)
{
	FrozenContact f;
	if (!c.touching || (c.refBody != 1 && c.refBody != 2)) return f;
	const Vec2 nRef = c.refBody == 1 ? c.normal : Vec2(-c.normal);
	const Vec2 q0 = c.p0 - c.d0 * nRef, q1 = c.p1 - c.d1 * nRef; // incident points, A's frame
	f.refBody = c.refBody;
	f.refEdge = c.refEdge;
	f.length  = c.length;
	f.pose    = pose;
	if (c.refBody == 1) {
		f.nRef = nRef, f.p0 = c.p0, f.p1 = c.p1;
		f.q0 = pose.applyInverse(q0), f.q1 = pose.applyInverse(q1);
	} else {
		f.nRef = pose.unrotate(nRef), f.p0 = pose.applyInverse(c.p0), f.p1 = pose.applyInverse(c.p1);
		f.q0 = q0, f.q1 = q1;
	}
	f.valid = true;
	return f;
}

/// How far any point of either block can have moved relative to the other since the update (m):
/// relativeMotionBound (ContactMemory.hpp), the bound of edgeContact's coherence. radiusA, radiusB:
/// circumradii (m).
inline Real frozenDrift(const FrozenContact& f, const Pose2& now, Real radiusA, Real radiusB)
{
	return relativeMotionBound(now, f.pose, radiusA, radiusB);
}

/// The contact at relative pose `now` from the material points (A's frame; EdgeContact's fields
/// and conventions; separation = −max(d0, d1), the deepest overlap of the segment's ends).
inline EdgeContact frozenContact(const FrozenContact& f, const Pose2& now)
{
	EdgeContact c;
	Vec2        nRef, p0, p1, q0, q1;
	if (f.refBody == 1) {
		nRef = f.nRef, p0 = f.p0, p1 = f.p1;
		q0 = now.place(f.q0), q1 = now.place(f.q1);
	} else {
		nRef = now.rotate(f.nRef), p0 = now.place(f.p0), p1 = now.place(f.p1);
		q0 = f.q0, q1 = f.q1;
	}
	c.d0         = -nRef.dot(q0 - p0);
	c.d1         = -nRef.dot(q1 - p1);
	c.normal     = f.refBody == 1 ? nRef : Vec2(-nRef);
	c.tangent    = Vec2(-c.normal.y(), c.normal.x());
	c.p0         = p0;
	c.p1         = p1;
	c.length     = f.length;
	c.separation = -std::max(c.d0, c.d1);
	c.refBody    = f.refBody;
	c.refEdge    = f.refEdge;
	c.touching   = true;
	return c;
}

/// The state as 17 numbers, for saving with a scene: refBody, refEdge, nRef, p0, p1, q0, q1, length,
/// pose (r, cos, sin); empty if it is not valid. A scene saved and loaded then continues with the
/// same frozen joints as the uninterrupted run (an exact update instead would differ by the
/// frozen kinematics' own error, not by round-off).
inline std::vector<Real> packFrozen(const FrozenContact& f)
{
	if (!f.valid) return {};
	return { Real(f.refBody), Real(f.refEdge), f.nRef.x(), f.nRef.y(), f.p0.x(), f.p0.y(), f.p1.x(), f.p1.y(), f.q0.x(), f.q0.y(),
		 f.q1.x(),        f.q1.y(),        f.length,   f.pose.p.x(), f.pose.p.y(), f.pose.c, f.pose.s };
}

/// Inverse of packFrozen; anything else (empty, another length, a reference body other than 1 or 2)
/// gives an invalid state, whose joint is then updated exactly at the next step.
inline FrozenContact unpackFrozen(const std::vector<Real>& v)
{
	FrozenContact f;
	if (v.size() != 17 || !(v[0] == 1 || v[0] == 2) || !(v[1] >= 0)) return f;
	f.refBody  = int(v[0]);
	f.refEdge  = int(v[1]);
	f.nRef     = Vec2(v[2], v[3]);
	f.p0       = Vec2(v[4], v[5]);
	f.p1       = Vec2(v[6], v[7]);
	f.q0       = Vec2(v[8], v[9]);
	f.q1       = Vec2(v[10], v[11]);
	f.length   = v[12];
	f.pose.p   = Vec2(v[13], v[14]);
	f.pose.c   = v[15];
	f.pose.s   = v[16];
	f.valid    = true;
	return f;
}

} // namespace rbsm
