// Edge-to-edge contact between two convex polygons (the seed paper's Fig. 3 and eqs. (8)-(9)),
// computed as a Box2D-style contact manifold: separating-axis search + clipping of the
// incident edge against the reference edge. This header: what a caller asks and gets. The search is
// in EdgeContact.cpp, the clipping in EdgeClip.hpp (kernel-internal), the memory that lets a followed
// contact skip the search in ContactMemory.{hpp,cpp}, the points along the segment in
// IntegrationRule.hpp.
//
// Conventions (YADE's, relied upon by the plugin):
//  * body 1 = polygon A, body 2 = polygon B, both CONVEX and COUNTER-CLOCKWISE, WORLD coordinates;
//  * the unit normal n points from body 1 to body 2, whichever polygon holds the reference edge;
//  * the tangent is t = (-n.y, n.x) (n rotated by +90 deg);
//  * the contact segment runs from p0 to p1 along +t;
//  * overlaps d0, d1 are positive for penetration and negative for a gap (m).
//
// Relation to the seed's eqs. (8)-(9): for a point m of the incident edge and the reference edge
// b1->b2 of length L_b, eq. (8) is the signed distance of m from the reference line and eq. (9)
// its coordinate along that line. Here d = -n_ref.(m - b1) is eq. (8) with the sign chosen so that
// penetration is positive, and the contact points are the feet of those distances on the
// reference line (eq. (9)).
#pragma once

#include <pkg/rbsm/kernel/Pose2.hpp>
#include <pkg/rbsm/kernel/Types.hpp>

#include <vector>

namespace rbsm {

struct EdgeContact {
	bool touching = false; ///< false: largest separation > maxSeparation or nothing overlaps
	Vec2 normal  = Vec2::Zero(); ///< unit, from body 1 (A) to body 2 (B)
	Vec2 tangent = Vec2::Zero(); ///< (-normal.y, normal.x)
	/// End points of the contact segment, ON THE REFERENCE EDGE LINE (the straight line through
	/// the reference edge of the reference polygon): they are the orthogonal projections onto
	/// that line of the clipped incident-edge end points. Ordered so that (p1 - p0).t >= 0.
	Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();
	Real length = 0; ///< |p1 - p0| (m); 0 for a corner-on-corner touch
	/// Normal overlap at p0 and p1 (m): distance of the incident edge behind the reference line,
	/// measured along the reference normal. Positive = penetration, negative = gap. The overlap
	/// is linear in between, because both boundaries are straight.
	Real d0 = 0, d1 = 0;
	Real separation = 0; ///< largest separation found by the axis search (m; negative = overlap)
	int  refBody = 0;    ///< 1 if the reference edge belongs to A, 2 if to B
	int  refEdge = -1;   ///< index i of the reference edge (vertex i -> vertex i+1)
	int  incEdge = -1;   ///< index of the incident edge on the other polygon
};

/// Which edge was the reference at the previous step (refBody 1 or 2; refBody 0 = no hint).
struct ContactHint {
	int refBody = 0;
	int refEdge = -1;
};

/// A convex CCW polygon in world coordinates as the hot path hands it over, without copies:
/// n vertices v[i] and the outward unit normals nrm[i] of its edges i (vertex i -> i+1). A block's
/// normals are fixed in its own frame, so the caller rotates them with the vertices instead of
/// normalising every edge of every contact at every step.
struct PolygonView {
	const Vec2* v   = nullptr;
	const Vec2* nrm = nullptr;
	int         n   = 0;
};

/// What a contact is asked (the inputs of edgeContact and followContact below): the reach
/// maxSeparation (m, >= 0), the hint (the previous step's reference edge, or null), the hysteresis
/// (a fraction of minSize) and minSize (m, > 0 for the PolygonView form).
struct ContactQuery {
	Real               maxSeparation = 0;
	const ContactHint* hint          = nullptr;
	Real               hysteresis    = 1e-3;
	Real               minSize       = -1;
};

struct Coherence; // ContactMemory.hpp: the blocks' poses and the contact's memory

/// Round-off slop of the contact tests (m): 1e-12 of minSize, the smaller block's size. An exactly
/// shared edge moved by a rigid motion has overlaps |d| ~ 1e-16 size, which must still count as
/// touching when maxSeparation = 0: edgeContact reaches maxSeparation plus one slop, separatedBeyond
/// rejects beyond two, and the frozen kinematics (Ig2) keeps a joint within one.
inline Real roundOffSlop(Real minSize) { return 1e-12 * minSize; }

/// Computes the edge-to-edge contact of A (body 1) and B (body 2).
///
/// Separating-axis search: for every edge i of either polygon, with outward unit normal n_i and
/// first vertex v_i, the separation is s_i = min over the other polygon's vertices w of
/// n_i.(w - v_i). The reference edge is the one with the largest s_i. To avoid flip-flopping
/// when two edges are (nearly) equally good -- e.g. an exactly shared edge, where A's and B's
/// edges are antiparallel and both have s = 0 -- a candidate only replaces the preferred edge if
/// it is better by more than  tol = hysteresis * min(size A, size B)  (m). The preferred edge is
/// the hint's edge if a hint is given, otherwise the best edge of A.
///
/// maxSeparation (m, >= 0): if the largest separation exceeds it, there is no contact. A round-off
/// slop of 1e-12 * min(size A, size B) is added so that exactly shared edges count as touching.
/// Otherwise the incident edge (the edge of the other polygon whose outward normal is most
/// anti-parallel to n_ref) is clipped to (i) the two side planes of the reference edge,
/// (ii) the part where the gap is at most maxSeparation (d >= -maxSeparation), (iii) the part
/// inside the reference polygon's other edges and (iv) the part whose foot on the reference line
/// lies inside the incident polygon: with (iii) and (iv) every overlap d is a chord of the two
/// polygons' intersection (checked against CGAL by tests/fuzz). If nothing is left (a corner
/// poking in obliquely), the other polygon's best edge is tried, then every pair of facing edges;
/// only if none leaves anything (one polygon inside the other) the plain projection (i)-(ii) on
/// the chosen edge is returned.
///
/// minSize (m): the size that scales the hysteresis and the round-off slop; by default (< 0) the
/// smaller of the two polygons' bounding-box sizes (polygonSize), which a caller that knows its
/// blocks' sizes can pass to save that work in a hot loop.
/// hint: the reference edge of the previous step, or null.
EdgeContact edgeContact(
        const std::vector<Vec2>& A,
        const std::vector<Vec2>& B,
        Real                     maxSeparation,
        const ContactHint*       hint       = nullptr,
        Real                     hysteresis = 1e-3,
        Real                     minSize    = -1);

/// The same contact for a caller that follows it from step to step (the plugin's Ig2): polygons
/// as views with their edge normals, q.minSize > 0 given, and optionally the poses of the two blocks
/// and the contact's SearchMemory (Coherence, ContactMemory.hpp), which enable the skip of the search:
///
/// Skip rule. In A's frame, B's vertices move by at most |Δr| + χ R_B since the memory's search,
/// where Δr is the change of B's centroid in A's frame and χ = |(cosθ', sinθ') − (cosθ, sinθ)|
/// = 2|sin(Δθ/2)| the chord of the relative rotation; in B's frame A's vertices move by at most
/// |Δr| + χ (R_A + |r|). Every edge separation (a minimum of n·(w − v) over vertices w, with n and
/// v fixed in the edge's own frame) has thus changed by at most D = |Δr| + χ (R_A + R_B + |r|).
/// If the hinted edge's separation s_ref satisfies  s_ref + tol ≥ maxOther + D + pad  and
/// s_ref + tol ≥ the rivals' separations, no edge can now be better than it by more than tol, so the
/// full search would keep it: it is used directly. A rival's separation is computed now unless its
/// lead over the kept edge at the search plus 2D is within tol (both moved by at most D). pad = 1e-9 (|c_A| + |c_B| + R_A + R_B) covers round-off of the world coordinates.
/// If its clipped segment is empty, the full search runs (and decides as it always does).
/// The clip of the kept edge skips what the search's ClipCertificate proves idle; once D reaches the
/// certificates' radius (2 % of minSize) the search runs again, with the same result, and renews them.
EdgeContact edgeContact(const PolygonView& A, const PolygonView& B, const ContactQuery& q, Coherence* coherence = nullptr);

/// A block's polygon in its own frame (vertices about its centroid and edge normals, as a
/// PolygonView) and its pose in the frame a contact is computed in. A vertex or normal is placed
/// when asked, by the one formula place() uses too (Pose2::place, Pose2::rotate).
struct PosedPolygon {
	PolygonView local;
	Pose2       pose;
	Vec2        vertex(int i) const { return pose.place(local.v[i]); }
	Vec2        normal(int i) const { return pose.rotate(local.nrm[i]); }
	/// Every vertex, then every normal, into out (2 n entries): the placed polygon.
	PolygonView place(Vec2* out) const;
};

/// Cheap rejection of a pair that edgeContact would find apart: true if some edge of either polygon
/// separates them by more than maxSeparation + 2 slop (roundOffSlop above: edgeContact's round-off
/// allowance). Stops at the first such edge. Then edgeContact(A, B, maxSeparation, nullptr, ...,
/// minSize) returns touching = false: its chosen edge is at most one slop worse than the best, so
/// its separation exceeds maxSeparation + slop. For the potential interactions of the collider
/// (bounding boxes overlap, blocks apart), which YADE hands to the geometry functor at every step.
bool separatedBeyond(const PolygonView& A, const PolygonView& B, Real maxSeparation, Real minSize);

/// separatedBeyond's "apart" where it is quick: A in its own frame (its centroid at the origin) and B posed in it;
/// the edge of A that faces B's centroid and the edge of B that faces A's are tested first, B's vertices and
/// normal placed one by one (PosedPolygon, the arithmetic of its place()). True if either separates them by more
/// than separatedBeyond's limit (separatedBeyond(A, B.place(...)) is then true as well); false: not decided, and
/// the caller places B and asks separatedBeyond. For the potential interactions of a pile, most of them apart.
bool separatedAlongCentres(const PolygonView& A, const PosedPolygon& B, Real maxSeparation, Real minSize);

} // namespace rbsm
