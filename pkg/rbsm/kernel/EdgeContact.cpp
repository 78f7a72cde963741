#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace rbsm {

namespace {
	// Small per-call buffer: on the stack for the usual blocks (no heap, no thread_local lookup,
	// which in a shared library costs a call of __tls_get_addr), on the heap beyond.
	template <class T, int N> class SmallBuffer {
	public:
		explicit SmallBuffer(int n)
		{
			if (n > N) heap_.resize(n);
			p_ = n > N ? heap_.data() : local_;
		}
		T&       operator[](int i) { return p_[i]; }
		const T& operator[](int i) const { return p_[i]; }

	private:
		T              local_[N];
		std::vector<T> heap_;
		T*             p_;
	};

	// How the templates below read a polygon: Arrays from the placed arrays of a PolygonView, Posed by
	// placing a vertex or normal of a PosedPolygon when asked (the same arithmetic as its place()).
	struct Arrays {
		const Vec2* vs;
		const Vec2* ns;
		int         n;
		const Vec2& v(int i) const { return vs[i]; }
		const Vec2& nrm(int i) const { return ns[i]; }
	};
	Arrays arrays(const PolygonView& p) { return Arrays { p.v, p.nrm, p.n }; }
	struct Posed {
		const PosedPolygon& p;
		int                 n;
		Vec2                v(int i) const { return p.vertex(i); }
		Vec2                nrm(int i) const { return p.normal(i); }
	};

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
	Real edgeSeparation(const PolygonView& P, int i, const PolygonView& Q) { return edgeSeparation(arrays(P), i, arrays(Q)); }

	// The same minimum where it is certified to be at the incident edge's ends (ClipCertificate::
	// supportOnInc): the same terms in the same order, the others being larger.
	template <class PR, class PI> Real separationAtIncident(const PR& R, int refEdge, const PI& I, int inc)
	{
		const int  i1 = inc + 1 < I.n ? inc + 1 : 0;
		const Vec2 n  = R.nrm(refEdge);
		const Vec2 v  = R.v(refEdge);
		Real       s  = std::numeric_limits<Real>::infinity();
		s             = std::min(s, n.dot(I.v(std::min(inc, i1)) - v));
		return std::min(s, n.dot(I.v(std::max(inc, i1)) - v));
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

	// Restricts [lo,hi] (parameter lambda in [0,1]) to where a + b*lambda >= 0.
	void clipLinear(Real a, Real b, Real& lo, Real& hi)
	{
		if (b == 0) {
			if (a < 0) hi = lo - 1; // empty
			return;
		}
		const Real root = -a / b;
		if (b > 0) lo = std::max(lo, root);
		else hi = std::min(hi, root);
	}

	// The certificates of a clip that kept something (ClipCertificate, EdgeContact.hpp): from the
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
		const int  inc1    = inc + 1 < I.n ? inc + 1 : 0;
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

	// The contact segment on edge refEdge of polygon refBody (1: A, 2: B): the facing edge of the
	// other polygon (outward normal most anti-parallel to the reference normal) clipped to
	// (i) the side planes of the reference edge, (ii) the part within maxSep of its line and, if
	// strict, (iii) within maxSep of the reference polygon's other edges: where two blocks meet
	// corner to corner, the facing edge passes behind the reference line but leaves the reference
	// block through a neighbouring edge, and that part is no overlap; and (iv) where the foot on
	// the reference line is within maxSep of the incident polygon (see below). incGiven >= 0: that
	// edge of the other polygon is the incident edge instead. Fills c (except separation) and
	// returns true if something is left.
	// R: the reference polygon (body refBody), I: the other one, read through Arrays or Posed.
	// cert: the certificates of the memory's search (ClipCertificate, EdgeContact.hpp), checked by the
	// caller for this step: the incident edge and the facing edges are taken from it, and the quiet
	// clips are skipped, which changes nothing (each would have left [lo, hi] as it is). record:
	// filled with the certificates of this clip (strict, no incGiven) if something is left; radius:
	// theirs (m).
	template <class PR, class PI>
	bool clipOn(const PR&              R,
	            const PI&              I,
	            int                    refBody,
	            int                    refEdge,
	            Real                   maxSep,
	            bool                   strict,
	            EdgeContact&           c,
	            int                    incGiven,
	            const ClipCertificate* cert,
	            ClipCertificate*       record,
	            Real                   radius)
	{
		const int nI = I.n;

		// reference edge frame: the outward normal is the polygon's own (exactly the one the
		// separating-axis search used), the tangent follows the CCW direction
		const Vec2 r0 = R.v(refEdge), r1 = R.v((refEdge + 1) % R.n);
		const Vec2 nRef = R.nrm(refEdge);
		const Vec2 tRef(-nRef.y(), nRef.x());
		const Real Lr = (r1 - r0).norm();

		// incident edge (unless given); on the way, the edges of I facing along +nRef (bit i of
		// up, for (iv) below; all edges are scanned there if I has more than 64)
		int      inc    = 0;
		Real     minDot = std::numeric_limits<Real>::infinity();
		uint64_t up     = 0;
		if (cert) {
			inc = cert->incEdge, up = cert->facing;
			for (uint64_t m = cert->unsure; m; m &= m - 1) { // near the threshold: as now
				const int i = __builtin_ctzll(m);
				up |= uint64_t(I.nrm(i).dot(nRef) > kParallel) << i;
			}
		} else
			for (int i = 0; i < nI; ++i) {
				const Real d = I.nrm(i).dot(nRef);
				if (d < minDot) minDot = d, inc = i;
				up |= uint64_t(d > kParallel) << (i & 63);
			}
		if (incGiven >= 0) inc = incGiven;
		const Vec2 q0 = I.v(inc), q1 = I.v((inc + 1) % nI);

		// Incident point q(lambda) = q0 + lambda (q1 - q0), lambda in [0,1]. In the reference frame:
		//   coordinate along the edge  x(lambda) = tRef.(q - r0)   (seed eq. (9))
		//   overlap                    d(lambda) = -nRef.(q - r0)  (seed eq. (8), penetration > 0)
		const Real x0 = tRef.dot(q0 - r0), x1 = tRef.dot(q1 - r0);
		const Real g0 = -nRef.dot(q0 - r0), g1 = -nRef.dot(q1 - r0);
		// Each clip is a linear condition on lambda; where it holds at both ends it holds on all of
		// [0,1] and is skipped (the usual case: a shared edge is clipped by nothing).
		Real lo = 0, hi = 1;
		if (x0 < 0 || x1 < 0) clipLinear(x0, x1 - x0, lo, hi);                  // (i) x >= 0
		if (x0 > Lr || x1 > Lr) clipLinear(Lr - x0, -(x1 - x0), lo, hi);        //     x <= Lr
		if (g0 < -maxSep || g1 < -maxSep) clipLinear(g0 + maxSep, g1 - g0, lo, hi); // (ii) d >= -maxSep
		const uint64_t skipR = cert ? cert->quietR : 0, skipI = cert ? cert->quietI : 0;
		uint64_t       quietR = 0, quietI = 0; // for record
		if (strict) {
			auto sideIn = [&](int j) { // (iii) nR[j].(q - R[j]) <= maxSep
				const Vec2 nj = R.nrm(j), vj = R.v(j);
				const Real a0 = nj.dot(q0 - vj), a1 = nj.dot(q1 - vj);
				if (a0 > maxSep || a1 > maxSep) clipLinear(maxSep - a0, -(a1 - a0), lo, hi);
				else if (record && j < 64 && std::max(a0, a1) <= -radius) quietR |= uint64_t(1) << j;
			};
			if (R.n <= 64) // the other edges in increasing order, less the quiet ones
				for (uint64_t m = (~uint64_t(0) >> (64 - R.n)) & ~(uint64_t(1) << refEdge) & ~skipR; m; m &= m - 1)
					sideIn(__builtin_ctzll(m));
			else
				for (int j = 0; j < R.n; ++j)
					if (j != refEdge) sideIn(j);
			// (iv) the foot f = r0 + x tRef of q on the reference line lies in the incident polygon:
			// nI[j].(f - I[j]) <= maxSep. With (i) and (iii) the chord q-f is then in both polygons,
			// so every overlap d reported is a chord of their intersection: where a sharp or oblique
			// corner of I pokes in, the reference line may pass outside I above q, and the distance
			// of q from it is no overlap. Since q is in I and f = q + d nRef, only edges with
			// nI[j].nRef > 0 can cut the chord (one nearly parallel to nRef, within kParallel,
			// by at most kParallel d: round-off); for blocks meeting squarely that is one edge,
			// the far side of I, which passes the test below without a clip.
			const Vec2 f0 = r0 + x0 * tRef, f1 = r0 + x1 * tRef;
			auto       footIn = [&](int j) {
                                const Vec2 nj = I.nrm(j), vj = I.v(j);
                                const Real a0 = nj.dot(f0 - vj), a1 = nj.dot(f1 - vj);
                                if (a0 > maxSep || a1 > maxSep) clipLinear(maxSep - a0, -(a1 - a0), lo, hi); // else nothing to clip
                                else if (record && std::max(a0, a1) <= -2 * radius) quietI |= uint64_t(1) << (j & 63);
			};
			if (nI <= 64)
				for (uint64_t m = up & ~skipI; m; m &= m - 1)
					footIn(__builtin_ctzll(m));
			else
				for (int j = 0; j < nI; ++j)
					if (I.nrm(j).dot(nRef) > kParallel) footIn(j);
		}
		if (!(lo <= hi)) return false;

		auto xAt = [&](Real l) { return std::clamp(x0 + l * (x1 - x0), Real(0), Lr); };
		auto dAt = [&](Real l) { return g0 + l * (g1 - g0); };
		Vec2 pa = r0 + xAt(lo) * tRef, pb = r0 + xAt(hi) * tRef;
		Real da = dAt(lo), db = dAt(hi);

		// body-1 -> body-2 convention
		c.normal  = (refBody == 1) ? nRef : Vec2(-nRef);
		c.tangent = Vec2(-c.normal.y(), c.normal.x());
		if ((pb - pa).dot(c.tangent) < 0) std::swap(pa, pb), std::swap(da, db);
		c.p0       = pa;
		c.p1       = pb;
		c.d0       = da;
		c.d1       = db;
		c.length   = (pb - pa).norm();
		c.refBody  = refBody;
		c.refEdge  = refEdge;
		c.incEdge  = inc;
		c.touching = true;
		if (record) recordCertificate(R, I, refEdge, inc, nRef, quietR, quietI, radius, *record);
		return true;
	}
	template <class PA, class PB>
	bool clipOnReference(
	        const PA&              A,
	        const PB&              B,
	        int                    refBody,
	        int                    refEdge,
	        Real                   maxSep,
	        bool                   strict,
	        EdgeContact&           c,
	        int                    incGiven = -1,
	        const ClipCertificate* cert     = nullptr,
	        ClipCertificate*       record   = nullptr,
	        Real                   radius   = 0)
	{
		return refBody == 1 ? clipOn(A, B, 1, refEdge, maxSep, strict, c, incGiven, cert, record, radius)
		                    : clipOn(B, A, 2, refEdge, maxSep, strict, c, incGiven, cert, record, radius);
	}

	// Largest change of any edge separation since the memory's search (SearchMemory, skip rule in
	// EdgeContact.hpp): relativeMotionBound, plus the round-off pad. Also returns the current
	// relative pose.
	[[gnu::always_inline]] inline Real separationDrift(const BlockPose& a, const BlockPose& b, const SearchMemory& m, Pose2& rel)
	{
		rel            = a.pose.relative(b.pose);
		auto       l1  = [](const Vec2& v) { return std::abs(v.x()) + std::abs(v.y()); };
		const Real pad = 1e-9 * (l1(a.pose.p) + l1(b.pose.p) + a.radius + b.radius);
		return relativeMotionBound(rel, m.rel, a.radius, b.radius) + pad;
	}

	// What edgeContact and followContact both start from: the reach is maxSeparation (at least 0)
	// plus the round-off slop (roundOffSlop, EdgeContact.hpp).
	Real reachWithSlop(Real maxSeparation, Real minSize) { return std::max(maxSeparation, Real(0)) + roundOffSlop(minSize); }
	// the hint names an edge of A (refBody 1) or B (2)
	bool hintNamesEdge(const ContactHint& h, int nA, int nB) { return (h.refBody == 1 || h.refBody == 2) && h.refEdge >= 0 && h.refEdge < (h.refBody == 1 ? nA : nB); }

	// The memory's search chose the hinted edge, and its clip certificates (if any) have not been
	// outgrown: a step whose drift reaches their radius searches again instead (the same result),
	// which renews them.
	bool followable(const SearchMemory& m, const ContactHint& hint, Real drift)
	{
		return m.valid && m.refBody == hint.refBody && m.refEdge == hint.refEdge && !(m.clip.incEdge >= 0 && !(drift < m.clip.radius));
	}

	// The skip rule of SearchMemory (EdgeContact.hpp) on the memory's edge, drift D and the relative
	// pose rel given: true if the full search would keep that edge, with c its
	// contact, every field written (clipped, or apart: separation, refBody and refEdge, the rest as
	// default); false, with c untouched or emptied, if the search must decide, or (onlyCertified) if
	// the clip certificates do not hold.
	template <class PA, class PB>
	bool keepHinted(const PA& A, const PB& B, const SearchMemory& m, Real drift, const Pose2& rel, Real maxSep, Real tol, bool onlyCertified, EdgeContact& c)
	{
		const int              rb = m.refBody, re = m.refEdge;
		const ClipCertificate& k  = m.clip;
		// the certificates hold for this relative rotation (chord χ, L1: a bound of the Euclidean)?
		const Real chord     = std::abs(rel.c - m.rel.c) + std::abs(rel.s - m.rel.s);
		const bool certified = k.incEdge >= 0 && k.incLead > 2 * chord && chord < kFacingMargin;
		if (onlyCertified && !(certified && k.supportOnInc)) return false;
		auto sepOf = [&](int body, int edge) { return body == 1 ? edgeSeparation(A, edge, B) : edgeSeparation(B, edge, A); };
		auto prefSepOf = [&]() {
			if (!(certified && k.supportOnInc)) return sepOf(rb, re);
			return rb == 1 ? separationAtIncident(A, re, B, k.incEdge) : separationAtIncident(B, re, A, k.incEdge);
		};
		const Real prefSep = prefSepOf();
		bool       keep    = prefSep + tol >= m.maxOther + drift;
		for (int r = 0; r < 2 && keep; ++r) {
			if (m.rivalBody[r] == 0) continue;
			// a rival ahead of the kept edge by l then is ahead by at most l + 2D now
			if (m.rivalLead[r] + 2 * drift <= tol) continue;
			keep = prefSep + tol >= sepOf(m.rivalBody[r], m.rivalEdge[r]);
		}
		if (!keep) return false;
		if (!(prefSep <= maxSep)) { // the full search would find the same: apart
			c            = EdgeContact {};
			c.separation = prefSep;
			c.refBody    = rb;
			c.refEdge    = re;
			return true;
		}
		// (the clip writes every other field)
		if (clipOnReference(A, B, rb, re, maxSep, true, c, -1, certified ? &k : nullptr)) {
			c.separation = prefSep;
			return true;
		}
		c = EdgeContact {}; // nothing left on that edge: the full search decides
		return false;
	}
} // namespace

EdgeContact edgeContact(const std::vector<Vec2>& A, const std::vector<Vec2>& B, Real maxSeparation, const ContactHint* hint, Real hysteresis, Real minSizeGiven)
{
	if (A.size() < 3 || B.size() < 3) return EdgeContact {};
	const std::vector<Vec2> normalsA = edgeNormals(A), normalsB = edgeNormals(B);
	const Real minSize = minSizeGiven >= 0 ? minSizeGiven : std::min(polygonSize(A), polygonSize(B));
	return edgeContact(
	        PolygonView { A.data(), normalsA.data(), int(A.size()) },
	        PolygonView { B.data(), normalsB.data(), int(B.size()) },
	        maxSeparation,
	        hint,
	        hysteresis,
	        minSize);
}

EdgeContact edgeContact(
        const PolygonView& A,
        const PolygonView& B,
        Real               maxSeparation,
        const ContactHint* hint,
        Real               hysteresis,
        Real               minSize,
        const BlockPose*   poseA,
        const BlockPose*   poseB,
        SearchMemory*      memory)
{
	EdgeContact c;
	const int   nA = A.n, nB = B.n;
	if (nA < 3 || nB < 3) return c;

	const Real slop   = roundOffSlop(minSize);
	const Real maxSep = reachWithSlop(maxSeparation, minSize);
	const Real tol    = hysteresis * minSize;
	const bool hinted = hint && hintNamesEdge(*hint, nA, nB);

	// --- temporal coherence: keep the hinted edge without a search when provably unchanged ---
	const bool coherent = poseA && poseB && memory;
	Pose2      rel;
	if (coherent) {
		const Real drift = separationDrift(*poseA, *poseB, *memory, rel);
		if (hinted && followable(*memory, *hint, drift)) {
			if (keepHinted(arrays(A), arrays(B), *memory, drift, rel, maxSep, tol, false, c)) return c;
		}
	}

	// --- separating-axis search -----------------------------------------------------------
	// The separation of every edge of A against B and of B against A, kept for the tie-break.
	SmallBuffer<Real, 16> sepsA(nA), sepsB(nB);
	int                   bestBody = 1, bestEdge = 0;
	Real                  best = -std::numeric_limits<Real>::infinity();
	for (int i = 0; i < nA; ++i) {
		sepsA[i] = edgeSeparation(A, i, B);
		if (sepsA[i] > best) best = sepsA[i], bestBody = 1, bestEdge = i;
	}
	for (int i = 0; i < nB; ++i) {
		sepsB[i] = edgeSeparation(B, i, A);
		if (sepsB[i] > best) best = sepsB[i], bestBody = 2, bestEdge = i;
	}

	// Ties: where several edges are equally good within round-off (a shared edge meets a corner
	// of the other block at the same separation), take the one that faces an edge of the other
	// polygon most squarely, so that two blocks sharing an edge get an edge contact in either
	// order of the bodies, not a corner touch of zero length. Among equals, A's edge comes first.
	auto facing = [](const Vec2& n, const PolygonView& Q) {
		Real m = std::numeric_limits<Real>::infinity();
		for (int k = 0; k < Q.n; ++k)
			m = std::min(m, Q.nrm[k].dot(n));
		return m; // -1: exactly antiparallel to an edge of the other polygon
	};
	{
		const Real bestSep    = best;
		Real       bestFacing = std::numeric_limits<Real>::infinity();
		for (int body = 1; body <= 2; ++body) {
			const auto& seps = body == 1 ? sepsA : sepsB;
			const auto& P    = body == 1 ? A : B;
			const auto& Q    = body == 1 ? B : A;
			for (int i = 0; i < P.n; ++i) {
				if (seps[i] < bestSep - slop) continue;
				const Real f = facing(P.nrm[i], Q);
				if (f < bestFacing - 1e-12) bestFacing = f, bestBody = body, bestEdge = i, best = seps[i];
			}
		}
	}

	// Preferred edge: the hint's (the reference of the previous step), kept unless another edge
	// is better by more than the hysteresis.
	int  refBody = bestBody, refEdge = bestEdge;
	Real sep     = best;
	if (hinted) {
		const Real prefSep = (hint->refBody == 1) ? sepsA[hint->refEdge] : sepsB[hint->refEdge];
		if (prefSep >= best - tol) refBody = hint->refBody, refEdge = hint->refEdge, sep = prefSep;
	}

	// Remember the choice for the skip rule: its two closest rivals, and the largest separation
	// of every other edge now.
	if (coherent) {
		SearchMemory m;
		m.refBody  = refBody;
		m.refEdge  = refEdge;
		m.maxOther = -std::numeric_limits<Real>::infinity();
		m.rel      = rel;
		Real         rivalSep[2] = { -std::numeric_limits<Real>::infinity(), -std::numeric_limits<Real>::infinity() };
		// A rival is an edge within a tenth of the block size of the chosen one (the other block's
		// twin of a shared edge, the two edges of a corner); farther ones are bounded by maxOther.
		const Real rivalFloor = sep - 0.1 * minSize;
		auto       offer      = [&](int body, int edge, Real s) {
                        if (body == refBody && edge == refEdge) return;
                        if (!(s >= rivalFloor)) {
                                m.maxOther = std::max(m.maxOther, s);
                                return;
                        }
                        if (s > rivalSep[0]) { // new best rival: the old best becomes second, the old second goes to the rest
                                m.maxOther = std::max(m.maxOther, rivalSep[1]);
                                rivalSep[1] = rivalSep[0], m.rivalBody[1] = m.rivalBody[0], m.rivalEdge[1] = m.rivalEdge[0];
                                rivalSep[0] = s, m.rivalBody[0] = body, m.rivalEdge[0] = edge;
                        } else if (s > rivalSep[1]) {
                                m.maxOther  = std::max(m.maxOther, rivalSep[1]);
                                rivalSep[1] = s, m.rivalBody[1] = body, m.rivalEdge[1] = edge;
                        } else
                                m.maxOther = std::max(m.maxOther, s);
		};
		for (int i = 0; i < nA; ++i)
			offer(1, i, sepsA[i]);
		for (int i = 0; i < nB; ++i)
			offer(2, i, sepsB[i]);
		for (int k = 0; k < 2; ++k)
			m.rivalLead[k] = rivalSep[k] - sep;
		*memory = m;
	}

	c.separation = sep;
	c.refBody    = refBody;
	c.refEdge    = refEdge;
	if (!(sep <= maxSep)) { // also rejects NaN
		if (coherent) memory->valid = sep == sep;
		return c;
	}

	// Clip on the chosen reference edge; where the overlap is a corner of the reference block
	// poking into the other one away from its facing edge, (iii) below leaves nothing, and the
	// best edge of the other block, which that corner then penetrates, is the reference instead
	// ((iv) likewise leaves nothing where a corner of the other block leans away from the line).
	const Arrays a = arrays(A), b = arrays(B);
	if (clipOnReference(a, b, refBody, refEdge, maxSep, true, c, -1, nullptr, coherent ? &memory->clip : nullptr, kCertificateRadius * minSize)) {
		c.separation = sep;
		if (coherent) memory->valid = true; // only this outcome is what the skip rule reproduces
		return c;
	}
	const int   other     = 3 - refBody;
	const auto& otherSeps = other == 1 ? sepsA : sepsB;
	int         alt       = 0;
	for (int i = 1; i < (other == 1 ? nA : nB); ++i)
		if (otherSeps[i] > otherSeps[alt]) alt = i;
	if (otherSeps[alt] <= maxSep && clipOnReference(a, b, other, alt, maxSep, true, c)) {
		c.separation = otherSeps[alt];
		return c;
	}
	// Neither (rare in shallow contacts, about 1 in 500 in the fuzzer's, common in deep ones: a
	// sharp corner poking obliquely into a corner or through a thin tip, two tips crossing): the
	// facing edge of the other block leaves the reference block, or the reference line leaves the
	// other block, wherever they overlap. Search every edge r of either polygon against every edge
	// k of the other that faces it (n_k.n_r < 0): take the r of largest separation for which some
	// k leaves something under the strict clip, and for it the most squarely facing such k. Every
	// overlap of that contact is a chord of the intersection (see clipOnReference). There is such
	// a pair whenever the interiors overlap and neither polygon contains the other: from a point of
	// the intersection's boundary on an edge r, walk along -n_r across the intersection; the far
	// side is on an edge k of the other polygon (ties in separation: A's edges, lower index first).
	{
		EdgeContact found;
		Real        foundSep = -std::numeric_limits<Real>::infinity();
		for (int body = 1; body <= 2; ++body) {
			const auto& seps = body == 1 ? sepsA : sepsB;
			const auto& P    = body == 1 ? A : B;
			const auto& Q    = body == 1 ? B : A;
			for (int r = 0; r < P.n; ++r) {
				if (!(seps[r] > foundSep) || !(seps[r] <= maxSep)) continue;
				int  bestK   = -1;
				Real bestDot = 0; // only edges facing r (n_k . n_r < 0)
				for (int k = 0; k < Q.n; ++k) {
					const Real dk = Q.nrm[k].dot(P.nrm[r]);
					if (!(dk < bestDot)) continue;
					EdgeContact t;
					if (clipOnReference(a, b, body, r, maxSep, true, t, k)) bestK = k, bestDot = dk, found = t;
				}
				if (bestK >= 0) foundSep = seps[r];
			}
		}
		if (found.touching) {
			c            = found;
			c.separation = foundSep;
			return c;
		}
	}
	// nothing (one polygon inside the other, or round-off): the projection on the chosen edge
	// (clips (i) and (ii) only)
	clipOnReference(a, b, refBody, refEdge, maxSep, false, c);
	c.separation = sep;
	return c;
}

PolygonView PosedPolygon::place(Vec2* out) const
{
	const int n = local.n;
	for (int i = 0; i < n; ++i)
		out[i] = vertex(i);
	for (int i = 0; i < n; ++i)
		out[n + i] = normal(i);
	return PolygonView { out, out + n, n };
}

bool followContact(
        const PolygonView&  A,
        const PosedPolygon& B,
        Real                maxSeparation,
        const ContactHint&  hint,
        Real                hysteresis,
        Real                minSize,
        const BlockPose&    poseA,
        const BlockPose&    poseB,
        const SearchMemory& memory,
        EdgeContact&        c)
{
	// edgeContact's opening, to its skip rule
	const int nA = A.n, nB = B.local.n;
	if (nA < 3 || nB < 3 || !hintNamesEdge(hint, nA, nB)) return false;
	const Real maxSep = reachWithSlop(maxSeparation, minSize);
	const Real tol    = hysteresis * minSize;
	Pose2      rel;
	const Real drift = separationDrift(poseA, poseB, memory, rel);
	if (!followable(memory, hint, drift)) return false;
	return keepHinted(arrays(A), Posed { B, nB }, memory, drift, rel, maxSep, tol, true, c);
}

bool separatedBeyond(const PolygonView& A, const PolygonView& B, Real maxSeparation, Real minSize)
{
	if (A.n < 3 || B.n < 3) return false; // edgeContact decides (no contact)
	const Real beyond = std::max(maxSeparation, Real(0)) + 2 * roundOffSlop(minSize);
	for (int i = 0; i < A.n; ++i)
		if (edgeSeparation(A, i, B) > beyond) return true;
	for (int i = 0; i < B.n; ++i)
		if (edgeSeparation(B, i, A) > beyond) return true;
	return false;
}

namespace {
	// Gauss-Legendre nodes x_k on [-1,1] are the roots of P_n; Newton iteration from the
	// classical initial guess cos(pi (k - 1/4)/(n + 1/2)) converges to machine precision.
	// Weights on [-1,1]: 2 / ((1 - x^2) P_n'(x)^2). Mapped to [0,1]: s = (1+x)/2, w/2.
	IntegrationRule gaussLegendre(int n)
	{
		IntegrationRule r;
		r.n = n;
		for (int k = 0; k < n; ++k) {
			Real x  = std::cos(M_PI * (k + 0.75) / (n + 0.5));
			Real dp = 1;
			for (int it = 0; it < 100; ++it) {
				Real p0 = 1, p1 = x; // P_0, P_1
				for (int j = 2; j <= n; ++j) {
					const Real p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
					p0            = p1;
					p1            = p2;
				}
				const Real pn = (n == 1) ? x : p1, pnm1 = (n == 1) ? 1 : p0;
				dp            = n * (x * pn - pnm1) / (x * x - 1);
				const Real dx = pn / dp;
				x -= dx;
				if (std::abs(dx) < 1e-16) break;
			}
			// nodes from cos() come in decreasing x; store increasing s
			r.s[n - 1 - k] = (1 + x) / 2;
			r.w[n - 1 - k] = 1 / ((1 - x * x) * dp * dp);
		}
		return r;
	}
} // namespace

const IntegrationRule& integrationRule(int nIP)
{
	if (nIP < 1 || nIP > kMaxIntegrationPoints) throw std::invalid_argument("integrationRule: nIP must be in 1..8 (got " + std::to_string(nIP) + ")");
	static const auto rules = [] { // thread-safe initialisation on first use
		std::array<IntegrationRule, kMaxIntegrationPoints> all;
		for (int n = 1; n <= kMaxIntegrationPoints; ++n)
			all[n - 1] = gaussLegendre(n);
		return all;
	}();
	return rules[nIP - 1];
}

} // namespace rbsm
