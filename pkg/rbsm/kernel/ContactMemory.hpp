// The memory of a followed contact (temporal coherence): what a full separating-axis search leaves
// for the next steps (SearchMemory), the certificates of its clip (ClipCertificate), and the step that
// they decide without a search (followContact). Exact: every step it decides, the full search of
// edgeContact (EdgeContact.hpp) would give the same result bit for bit.
#pragma once

#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <cmath>
#include <cstdint>

namespace rbsm {

/// A rigid block's pose in the frame a contact is computed in, and its circumradius about the
/// centroid (m). Needed only for the temporal coherence below.
struct BlockPose {
	Pose2 pose;
	Real  radius = 0;
};

/// Certificates for the clipping of a kept reference edge (clipOn in EdgeClip.hpp), taken at the
/// search of a SearchMemory (below): which work of the clip cannot change the result while every
/// point of either block has moved by less than `radius` relative to the other since then (the drift
/// D of SearchMemory's skip rule) and the relative rotation's chord χ is within the margins below.
/// Each skipped test would have left the segment unchanged, so the result is the full clip's, bit for
/// bit.
///  * the incident edge: the facing dots nI·nRef change by at most χ, so an edge that faced more
///    squarely than any other by incLead > 2χ still does, and the edges facing along +nRef
///    (clip (iv)) are the same while χ is below the margin (0.05) by which their dots were above
///    the threshold then (`facing`), those within it (`unsure`) being tested again;
///  * clip (iii) by an edge j of the reference polygon acts only where an incident end lies beyond
///    it, nR[j]·(q − R[j]) > maxSep; the ends move by at most D, so an edge they were at least
///    `radius` inside (bit j of quietR) still does not act (maxSep > 0);
///  * clip (iv) by an edge j of the incident polygon tests the feet f = q + g nRef of the ends on
///    the reference line, which move by at most 2D relative to it (|Δg| ≤ D, and |g| χ ≤ D since
///    |g| ≤ R_A + R_B + |r| and χ < 1): bit j of quietI, at least 2 radius inside;
///  * the separation of the reference edge, the smallest nRef·(w − r0) over incident vertices w,
///    is at an end of the incident edge while every other vertex was 2 radius farther
///    (supportOnInc; each term moves by at most D).
/// Only for polygons of at most 64 edges (bit masks); incEdge = -1: no certificate.
struct ClipCertificate {
	int      incEdge      = -1;
	Real     incLead      = 0;
	uint64_t facing = 0, unsure = 0;
	uint64_t quietR = 0, quietI = 0;
	bool     supportOnInc = false;
	Real     radius       = 0; ///< m; a step whose drift reaches it searches again (same result) and renews them
};

/// What a full separating-axis search leaves for the next steps of the same contact (temporal
/// coherence, in the spirit of Box2D's and Bullet's cached separating axes, but exact): the edge it
/// chose, its two closest rivals (for two blocks sharing an edge, the other block's twin edge has
/// the same separation: it must be watched exactly, not bounded), the largest separation of all the
/// remaining edges at that moment, and the pose of B relative to A then. While the chosen edge's
/// separation now is within the hysteresis of its rivals' (recomputed) and of that old maximum plus
/// the largest change a rigid motion since then can have made of any separation (the skip rule of
/// edgeContact, EdgeContact.hpp), a new full search would choose the same edge again, so it is
/// skipped: the result is identical to the full search, only cheaper. Owned by the caller (one per contact); a default-constructed
/// (invalid) memory forces a full search.
struct SearchMemory {
	bool valid   = false;
	int  refBody = 0, refEdge = -1;
	int  rivalBody[2] = { 0, 0 }, rivalEdge[2] = { -1, -1 }; ///< the two next-best edges (body 0: none)
	Real rivalLead[2] = { 0, 0 };  ///< their separation minus the chosen edge's at the search (m)
	Real maxOther = 0;            ///< largest separation of all other edges at the search (m)
	Pose2 rel;                    ///< pose of B in A's frame at the search (Pose2::relative)
	ClipCertificate clip;         ///< what the clip of the kept edge may skip (see above)
};

/// Upper bound (m) of how far any point of either block can have moved relative to the other since
/// an earlier pose: B at `now` in A's frame, at `then` earlier (r = now.p, r0 = then.p). In A's
/// frame B's points move by at most |Δr| + χ R_B, in B's frame A's by at most |Δr| + χ (R_A + |r|),
/// χ the chord of the relative rotation; every Euclidean norm is bounded by the L1 norm
/// (|x| + |y| ≥ √(x² + y²)), a looser but still rigorous bound without square roots:
///     |Δr|₁ + χ₁ (R_A + R_B + |r0|₁).
/// Used by edgeContact's skip of the search (SearchMemory) and by the frozen kinematics
/// (FrozenContact.hpp). radiusA, radiusB: circumradii (m).
inline Real relativeMotionBound(const Pose2& now, const Pose2& then, Real radiusA, Real radiusB)
{
	auto       l1    = [](const Vec2& v) { return std::abs(v.x()) + std::abs(v.y()); };
	const Real chord = std::abs(now.c - then.c) + std::abs(now.s - then.s);
	return l1(now.p - then.p) + chord * (radiusA + radiusB + l1(then.p));
}

/// A followed contact's coherence, as edgeContact and followContact take it: the two blocks in the
/// frame the contact is computed in and the contact's memory (read; renewed by edgeContact's search).
struct Coherence {
	BlockPose     a, b;
	SearchMemory* memory = nullptr;
};

/// The step of a followed contact when its memory certifies it: edgeContact(A, B.place(...), q,
/// &coherence) bit for bit, from the few
/// vertices and edges of B that the skip rule and the clip certificates (ClipCertificate) leave to
/// test, placed one by one instead of all of B. Returns false where they do not decide the step (no
/// memory of this edge, the certificates outgrown or not holding, the search needed, nothing left on
/// the edge, no hint in q); then c is unspecified, and the caller places B and calls edgeContact. The
/// memory is only read: every step it decides, edgeContact would decide without searching.
bool followContact(const PolygonView& A, const PosedPolygon& B, const ContactQuery& q, const Coherence& coherence, EdgeContact& c);

// ---- the memory's part of edgeContact (EdgeContact.cpp), defined in ContactMemory.cpp ----

/// Largest change of any edge separation since the memory's search (the skip rule's drift D):
/// relativeMotionBound plus the round-off pad; rel: the relative pose now (Pose2::relative).
[[gnu::always_inline]] inline Real separationDrift(const BlockPose& a, const BlockPose& b, const SearchMemory& m, Pose2& rel)
{
	rel            = a.pose.relative(b.pose);
	auto       l1  = [](const Vec2& v) { return std::abs(v.x()) + std::abs(v.y()); };
	const Real pad = 1e-9 * (l1(a.pose.p) + l1(b.pose.p) + a.radius + b.radius);
	return relativeMotionBound(rel, m.rel, a.radius, b.radius) + pad;
}

/// The memory's search chose the hinted edge, and its clip certificates (if any) have not been
/// outgrown: a step whose drift reaches their radius searches again instead (the same result),
/// which renews them.
inline bool followable(const SearchMemory& m, const ContactHint& hint, Real drift)
{
	return m.valid && m.refBody == hint.refBody && m.refEdge == hint.refEdge && !(m.clip.incEdge >= 0 && !(drift < m.clip.radius));
}

/// The skip rule on the placed polygons: true if the full search would keep the memory's edge, with
/// c its contact (every field written); false, with c untouched or emptied, if the search must
/// decide. maxSep: the reach with the round-off slop, tol: hysteresis × minSize (m).
/// The step's side of the skip rule: drift D (separationDrift), the relative pose now, the reach with
/// the round-off slop and the hysteresis tol = hysteresis × minSize (m).
struct FollowStep {
	Real  drift = 0;
	Pose2 rel;
	Real  maxSep = 0, tol = 0;
};
bool keepRemembered(const PolygonView& A, const PolygonView& B, const SearchMemory& m, const FollowStep& step, EdgeContact& c);

/// What a full separating-axis search found: the separation of every edge (A's, B's) and its choice.
struct SearchOutcome {
	const Real* sepsA = nullptr;
	const Real* sepsB = nullptr;
	int         nA = 0, nB = 0;
	int         refBody = 0, refEdge = -1;
	Real        sep = 0;
	const Real* seps(int body) const { return body == 1 ? sepsA : sepsB; }
	int         n(int body) const { return body == 1 ? nA : nB; }
};

/// The memory of a full search: its choice, the two closest rivals and the largest separation of the
/// other edges, at the relative pose rel. valid and clip are left for the caller (the clip of the
/// chosen edge).
SearchMemory rememberSearch(const SearchOutcome& found, Real minSize, const Pose2& rel);

} // namespace rbsm
