// Kernel-internal (included by EdgeContact.cpp and ContactMemory.cpp only): the building blocks of
// the edge contact, templates over how a polygon is read: the separation of an edge (the
// separating-axis test) and the clip of the incident edge on a reference edge (clipOn), which also
// records the certificates of the clip (ClipCertificate, ContactMemory.hpp).
#pragma once

#include <pkg/rbsm/kernel/ContactMemory.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rbsm {
namespace detail {

	// How the templates below read a polygon: Arrays from the placed arrays of a PolygonView, Posed by
	// placing a vertex or normal of a PosedPolygon when asked (the same arithmetic as its place()).
	struct Arrays {
		const Vec2* vs;
		const Vec2* ns;
		int         n;
		const Vec2& v(int i) const { return vs[i]; }
		const Vec2& nrm(int i) const { return ns[i]; }
	};
	inline Arrays arrays(const PolygonView& p) { return Arrays { p.v, p.nrm, p.n }; }
	struct Posed {
		const PosedPolygon& p;
		int                 n;
		Vec2                v(int i) const { return p.vertex(i); }
		Vec2                nrm(int i) const { return p.normal(i); }
	};

	// The vertex after i on a polygon of n (edge i runs from vertex i to it); a compare, not a division.
	inline int nextVertex(int i, int n) { return i + 1 < n ? i + 1 : 0; }

	// Separation of polygon Q from edge i of P, m: the smallest signed distance of a vertex of Q
	// in front of the edge's line (> 0: Q is entirely outside that edge).
	template <class PP, class PQ> Real edgeSeparation(const PP& P, int i, const PQ& Q)
	{
		const Vec2 n = P.nrm(i);
		const Vec2 v = P.v(i);
		Real       s = std::numeric_limits<Real>::infinity();
		for (int k = 0; k < Q.n; ++k)
			s = std::min(s, n.dot(Q.v(k) - v));
		return s;
	}
	inline Real edgeSeparation(const PolygonView& P, int i, const PolygonView& Q) { return edgeSeparation(arrays(P), i, arrays(Q)); }

	// A followed contact's two edges as read once (a posed polygon's vertices and normal placed once) for both its
	// separation and its clip: the reference edge's first vertex and normal, the incident edge inc's ends.
	struct EdgePair {
		Vec2 r0, nRef, q0, q1;
		bool wraps; ///< the incident edge is the polygon's last (its second end is vertex 0)
	};
	template <class PR, class PI> EdgePair edgePair(const PR& R, int refEdge, const PI& I, int inc)
	{
		const int i1 = nextVertex(inc, I.n);
		return EdgePair { R.v(refEdge), R.nrm(refEdge), I.v(inc), I.v(i1), i1 < inc };
	}

	// edgeSeparation where it is certified to be at the incident edge's ends (ClipCertificate::supportOnInc):
	// the same terms in the same order (vertices by index), the others being larger.
	inline Real separationAtIncident(const EdgePair& e)
	{
		Real s = std::numeric_limits<Real>::infinity();
		s      = std::min(s, e.nRef.dot((e.wraps ? e.q1 : e.q0) - e.r0));
		return std::min(s, e.nRef.dot((e.wraps ? e.q0 : e.q1) - e.r0));
	}

	// Radius of the clip certificates (ClipCertificate), a fraction of the smaller block's size: larger
	// certifies fewer clips as quiet, smaller searches again more often.
	constexpr Real kCertificateRadius = 0.02;
	// Facing dots within this of the threshold kParallel are recomputed at every step (an edge square
	// to the reference one, the sides of two stacked bricks, is at the threshold); the others keep
	// their side of it while the relative rotation's chord stays below it.
	constexpr Real kFacingMargin = 0.05;

	// |cos| below which an edge counts as parallel to a normal (round-off of unit normals).
	constexpr Real kParallel = 1e-12;

	// What edgeContact and followContact both start from: the reach is maxSeparation (at least 0)
	// plus the round-off slop (roundOffSlop, EdgeContact.hpp).
	inline Real reachWithSlop(Real maxSeparation, Real minSize) { return std::max(maxSeparation, Real(0)) + roundOffSlop(minSize); }
	// the hint names an edge of A (refBody 1) or B (2)
	inline bool hintNamesEdge(const ContactHint& h, int nA, int nB)
	{
		return (h.refBody == 1 || h.refBody == 2) && h.refEdge >= 0 && h.refEdge < (h.refBody == 1 ? nA : nB);
	}

	// Restricts [lo,hi] (parameter lambda in [0,1]) to where a + b*lambda >= 0.
	inline void clipLinear(Real a, Real b, Real& lo, Real& hi)
	{
		if (b == 0) {
			if (a < 0) hi = lo - 1; // empty
			return;
		}
		const Real root = -a / b;
		if (b > 0) lo = std::max(lo, root);
		else hi = std::min(hi, root);
	}

	// The certificates of a clip that kept something (ClipCertificate, ContactMemory.hpp): from the
	// facing dots, the incident edge's lead over the next edge and the edges facing along +nRef by
	// more than kFacingMargin (or within it: unsure); the quiet clips found by clipOn; whether the
	// reference edge's separation is at the incident edge's ends with every other vertex 2 radius
	// farther. Only at a search, not in the steps between.
	template <class PR, class PI>
	void recordCertificate(const PR& R, const PI& I, int refEdge, int inc, const Vec2& nRef, uint64_t quietR, uint64_t quietI, Real radius, ClipCertificate& k)
	{
		k = ClipCertificate {};
		if (R.n > 64 || I.n > 64) return; // no certificate: bit masks
		Real best = std::numeric_limits<Real>::infinity(), second = best;
		for (int i = 0; i < I.n; ++i) {
			const Real d = I.nrm(i).dot(nRef);
			if (d < best) second = best, best = d;
			else if (d < second) second = d;
			if (std::abs(d - kParallel) <= kFacingMargin) k.unsure |= uint64_t(1) << i;
			else k.facing |= uint64_t(d > kParallel) << i;
		}
		const Vec2 r0      = R.v(refEdge);
		const int  inc1    = nextVertex(inc, I.n);
		const Real atInc   = std::min(nRef.dot(I.v(inc) - r0), nRef.dot(I.v(inc1) - r0));
		bool       support = true;
		for (int i = 0; i < I.n && support; ++i)
			if (i != inc && i != inc1) support = nRef.dot(I.v(i) - r0) >= atInc + 2 * radius;
		k.incEdge      = inc;
		k.incLead      = second - best;
		k.quietR       = quietR;
		k.quietI       = quietI;
		k.supportOnInc = support;
		k.radius       = radius;
	}

	// What clipOn is asked: the reference edge refEdge of polygon refBody (1: A, 2: B) and the reach
	// maxSep (m); strict: also clips (iii) and (iv) (below); incGiven >= 0: that edge of the other
	// polygon is the incident edge instead of the most facing one; cert: the certificates of the
	// memory's search (ClipCertificate), checked by the caller for this step: the incident edge and
	// the facing edges are taken from it, and the quiet clips are skipped, which changes nothing (each
	// would have left [lo, hi] as it is); record: filled with the certificates of this clip (strict,
	// no incGiven) if something is left; radius: theirs (m); known: the two edges as already read (with cert,
	// whose incident edge it holds).
	struct ClipJob {
		int                    refBody = 1, refEdge = 0;
		Real                   maxSep   = 0;
		bool                   strict   = true;
		int                    incGiven = -1;
		const ClipCertificate* cert     = nullptr;
		ClipCertificate*       record   = nullptr;
		Real                   radius   = 0;
		const EdgePair*        known    = nullptr;
	};

	// The incident edge q0 -> q1 in the reference edge's frame, and the part [lo, hi] of it (parameter
	// lambda, q = q0 + lambda (q1 - q0)) the clips leave. In the reference frame:
	//   coordinate along the edge  x(lambda) = tRef.(q - r0)   (seed eq. (9))
	//   overlap                    d(lambda) = -nRef.(q - r0)  (seed eq. (8), penetration > 0)
	struct ClipSpan {
		Vec2     r0, nRef, tRef;
		Real     Lr;
		Vec2     q0, q1;
		Real     x0, x1, g0, g1;
		Real     lo = 0, hi = 1;
		uint64_t quietR = 0, quietI = 0; // the quiet clips, for the record
	};

	// The incident edge (the edge of I whose outward normal is most anti-parallel to nRef, or the
	// certificate's) and, in up, the edges of I facing along +nRef (bit i; for clip (iv)).
	template <class PI> [[gnu::always_inline]] inline int incidentEdge(const PI& I, const Vec2& nRef, const ClipCertificate* cert, uint64_t& up)
	{
		int  inc    = 0;
		Real minDot = std::numeric_limits<Real>::infinity();
		up          = 0;
		if (cert) {
			inc = cert->incEdge, up = cert->facing;
			for (uint64_t m = cert->unsure; m; m &= m - 1) { // near the threshold: as now
				const int i = __builtin_ctzll(m);
				up |= uint64_t(I.nrm(i).dot(nRef) > kParallel) << i;
			}
		} else
			for (int i = 0; i < I.n; ++i) {
				const Real d = I.nrm(i).dot(nRef);
				if (d < minDot) minDot = d, inc = i;
				up |= uint64_t(d > kParallel) << (i & 63);
			}
		return inc;
	}

	// (iii): within maxSep of the reference polygon's other edges, nR[j].(q - R[j]) <= maxSep: where two
	// blocks meet corner to corner, the facing edge passes behind the reference line but leaves the
	// reference block through a neighbouring edge, and that part is no overlap.
	template <class PR> [[gnu::always_inline]] inline void clipBySides(const PR& R, const ClipJob& job, ClipSpan& s)
	{
		const Real     maxSep = job.maxSep;
		const uint64_t skipR  = job.cert ? job.cert->quietR : 0;
		auto           sideIn = [&](int j) {
                        const Vec2 nj = R.nrm(j), vj = R.v(j);
                        const Real a0 = nj.dot(s.q0 - vj), a1 = nj.dot(s.q1 - vj);
                        if (a0 > maxSep || a1 > maxSep) clipLinear(maxSep - a0, -(a1 - a0), s.lo, s.hi);
                        else if (job.record && j < 64 && std::max(a0, a1) <= -job.radius) s.quietR |= uint64_t(1) << j;
		};
		if (R.n <= 64) // the other edges in increasing order, less the quiet ones
			for (uint64_t m = (~uint64_t(0) >> (64 - R.n)) & ~(uint64_t(1) << job.refEdge) & ~skipR; m; m &= m - 1)
				sideIn(__builtin_ctzll(m));
		else
			for (int j = 0; j < R.n; ++j)
				if (j != job.refEdge) sideIn(j);
	}

	// (iv) the foot f = r0 + x tRef of q on the reference line lies in the incident polygon:
	// nI[j].(f - I[j]) <= maxSep. With (i) and (iii) the chord q-f is then in both polygons,
	// so every overlap d reported is a chord of their intersection: where a sharp or oblique
	// corner of I pokes in, the reference line may pass outside I above q, and the distance
	// of q from it is no overlap. Since q is in I and f = q + d nRef, only edges with
	// nI[j].nRef > 0 (bit j of up) can cut the chord (one nearly parallel to nRef, within kParallel,
	// by at most kParallel d: round-off); for blocks meeting squarely that is one edge,
	// the far side of I, which passes the test below without a clip.
	template <class PI> [[gnu::always_inline]] inline void clipByFeet(const PI& I, const ClipJob& job, uint64_t up, ClipSpan& s)
	{
		const Real     maxSep = job.maxSep;
		const uint64_t skipI  = job.cert ? job.cert->quietI : 0;
		const Vec2     f0 = s.r0 + s.x0 * s.tRef, f1 = s.r0 + s.x1 * s.tRef;
		auto           footIn = [&](int j) {
                        const Vec2 nj = I.nrm(j), vj = I.v(j);
                        const Real a0 = nj.dot(f0 - vj), a1 = nj.dot(f1 - vj);
                        if (a0 > maxSep || a1 > maxSep) clipLinear(maxSep - a0, -(a1 - a0), s.lo, s.hi); // else nothing to clip
                        else if (job.record && std::max(a0, a1) <= -2 * job.radius) s.quietI |= uint64_t(1) << (j & 63);
		};
		if (I.n <= 64)
			for (uint64_t m = up & ~skipI; m; m &= m - 1)
				footIn(__builtin_ctzll(m));
		else
			for (int j = 0; j < I.n; ++j)
				if (I.nrm(j).dot(s.nRef) > kParallel) footIn(j);
	}

	// The contact of the part [lo, hi] that is left: its ends' feet on the reference line and overlaps,
	// in the body-1 -> body-2 convention. Every field of c but separation.
	[[gnu::always_inline]] inline void writeContact(const ClipSpan& s, const ClipJob& job, int inc, EdgeContact& c)
	{
		auto xAt = [&](Real l) { return std::clamp(s.x0 + l * (s.x1 - s.x0), Real(0), s.Lr); };
		auto dAt = [&](Real l) { return s.g0 + l * (s.g1 - s.g0); };
		Vec2 pa = s.r0 + xAt(s.lo) * s.tRef, pb = s.r0 + xAt(s.hi) * s.tRef;
		Real da = dAt(s.lo), db = dAt(s.hi);

		c.normal  = (job.refBody == 1) ? s.nRef : Vec2(-s.nRef);
		c.tangent = Vec2(-c.normal.y(), c.normal.x());
		if ((pb - pa).dot(c.tangent) < 0) std::swap(pa, pb), std::swap(da, db);
		c.p0       = pa;
		c.p1       = pb;
		c.d0       = da;
		c.d1       = db;
		c.length   = (pb - pa).norm();
		c.refBody  = job.refBody;
		c.refEdge  = job.refEdge;
		c.incEdge  = inc;
		c.touching = true;
	}

	// The contact segment on the reference edge of R (job.refEdge of polygon job.refBody): the
	// incident edge of I clipped to (i) the side planes of the reference edge, (ii) the part within
	// maxSep of its line and, if strict, (iii) clipBySides and (iv) clipByFeet. Fills c (except
	// separation) and returns true if something is left. R: the reference polygon, I: the other one,
	// read through Arrays or Posed. (The helpers above are inlined into it: the clip keeps its span
	// in registers, as in one function.)
	template <class PR, class PI> [[gnu::always_inline]] inline bool clipOn(const PR& R, const PI& I, const ClipJob& job, EdgeContact& c)
	{
		const int nI = I.n;
		ClipSpan  s;
		// reference edge frame: the outward normal is the polygon's own (exactly the one the
		// separating-axis search used), the tangent follows the CCW direction
		const EdgePair* known = job.cert ? job.known : nullptr;
		s.r0             = known ? known->r0 : R.v(job.refEdge);
		const Vec2 r1    = R.v(nextVertex(job.refEdge, R.n));
		s.nRef           = known ? known->nRef : R.nrm(job.refEdge);
		s.tRef           = Vec2(-s.nRef.y(), s.nRef.x());
		s.Lr             = (r1 - s.r0).norm();
		uint64_t  up     = 0;
		const int found  = incidentEdge(I, s.nRef, job.cert, up);
		const int inc    = job.incGiven >= 0 ? job.incGiven : found;
		if (known && job.incGiven < 0) s.q0 = known->q0, s.q1 = known->q1;
		else s.q0 = I.v(inc), s.q1 = I.v(nextVertex(inc, nI));
		s.x0 = s.tRef.dot(s.q0 - s.r0), s.x1 = s.tRef.dot(s.q1 - s.r0);
		s.g0 = -s.nRef.dot(s.q0 - s.r0), s.g1 = -s.nRef.dot(s.q1 - s.r0);
		// Each clip is a linear condition on lambda; where it holds at both ends it holds on all of
		// [0,1] and is skipped (the usual case: a shared edge is clipped by nothing).
		const Real maxSep = job.maxSep;
		if (s.x0 < 0 || s.x1 < 0) clipLinear(s.x0, s.x1 - s.x0, s.lo, s.hi);                          // (i) x >= 0
		if (s.x0 > s.Lr || s.x1 > s.Lr) clipLinear(s.Lr - s.x0, -(s.x1 - s.x0), s.lo, s.hi);          //     x <= Lr
		if (s.g0 < -maxSep || s.g1 < -maxSep) clipLinear(s.g0 + maxSep, s.g1 - s.g0, s.lo, s.hi);     // (ii) d >= -maxSep
		if (job.strict) {
			clipBySides(R, job, s);
			clipByFeet(I, job, up, s);
		}
		if (!(s.lo <= s.hi)) return false;
		writeContact(s, job, inc, c);
		if (job.record) recordCertificate(R, I, job.refEdge, inc, s.nRef, s.quietR, s.quietI, job.radius, *job.record);
		return true;
	}

	// clipOn with the reference polygon chosen by job.refBody among A (1) and B (2).
	template <class PA, class PB> [[gnu::always_inline]] inline bool clipOnReference(const PA& A, const PB& B, const ClipJob& job, EdgeContact& c)
	{
		return job.refBody == 1 ? clipOn(A, B, job, c) : clipOn(B, A, job, c);
	}

} // namespace detail
} // namespace rbsm
