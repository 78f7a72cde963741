#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rbsm {

namespace {
	// All outward edge normals of P, computed once per call of edgeContact (one square root per
	// edge instead of one per edge and use). Thread-local buffers: the functor runs in parallel.
	void edgeNormals(const std::vector<Vec2>& P, std::vector<Vec2>& out)
	{
		const size_t n = P.size();
		out.resize(n);
		for (size_t i = 0; i < n; ++i) {
			const Vec2 e = P[(i + 1) % n] - P[i];
			out[i]       = Vec2(e.y(), -e.x()).normalized();
		}
	}

	// Separation of polygon Q from edge i of P (normal nP[i]), m: the smallest signed distance of
	// a vertex of Q in front of the edge's line (> 0: Q is entirely outside that edge).
	Real edgeSeparation(const std::vector<Vec2>& P, const std::vector<Vec2>& nP, int i, const std::vector<Vec2>& Q)
	{
		const Vec2& n = nP[i];
		Real        s = std::numeric_limits<Real>::infinity();
		for (const auto& w : Q)
			s = std::min(s, n.dot(w - P[i]));
		return s;
	}

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

	// The contact segment on edge refEdge of polygon refBody (1: A, 2: B): the facing edge of the
	// other polygon (outward normal most anti-parallel to the reference normal) clipped to
	// (i) the side planes of the reference edge, (ii) the part within maxSep of its line and, if
	// strict, (iii) within maxSep of the reference polygon's other edges: where two blocks meet
	// corner to corner, the facing edge passes behind the reference line but leaves the reference
	// block through a neighbouring edge, and that part is no overlap. Fills c (except separation)
	// and returns true if something is left.
	bool clipOnReference(
	        const std::vector<Vec2>& A,
	        const std::vector<Vec2>& B,
	        const std::vector<Vec2>& normalsA,
	        const std::vector<Vec2>& normalsB,
	        int                      refBody,
	        int                      refEdge,
	        Real                     maxSep,
	        bool                     strict,
	        EdgeContact&             c)
	{
		const std::vector<Vec2>& R   = (refBody == 1) ? A : B;
		const std::vector<Vec2>& I   = (refBody == 1) ? B : A;
		const std::vector<Vec2>& nR  = (refBody == 1) ? normalsA : normalsB;
		const std::vector<Vec2>& nIn = (refBody == 1) ? normalsB : normalsA;
		const int                nI  = int(I.size());

		// reference edge frame
		const Vec2 r0 = R[refEdge], r1 = R[(refEdge + 1) % R.size()];
		const Real Lr   = (r1 - r0).norm();
		const Vec2 tRef = (r1 - r0) / Lr; // along the reference edge (CCW direction)
		const Vec2 nRef(tRef.y(), -tRef.x()); // outward normal of the reference polygon

		// incident edge
		int  inc    = 0;
		Real minDot = std::numeric_limits<Real>::infinity();
		for (int i = 0; i < nI; ++i) {
			const Real d = nIn[i].dot(nRef);
			if (d < minDot) minDot = d, inc = i;
		}
		const Vec2 q0 = I[inc], q1 = I[(inc + 1) % nI];

		// Incident point q(lambda) = q0 + lambda (q1 - q0), lambda in [0,1]. In the reference frame:
		//   coordinate along the edge  x(lambda) = tRef.(q - r0)   (seed eq. (9))
		//   overlap                    d(lambda) = -nRef.(q - r0)  (seed eq. (8), penetration > 0)
		const Real x0 = tRef.dot(q0 - r0), x1 = tRef.dot(q1 - r0);
		const Real g0 = -nRef.dot(q0 - r0), g1 = -nRef.dot(q1 - r0);
		Real       lo = 0, hi = 1;
		clipLinear(x0, x1 - x0, lo, hi);          // (i) x >= 0
		clipLinear(Lr - x0, -(x1 - x0), lo, hi);  //     x <= Lr
		clipLinear(g0 + maxSep, g1 - g0, lo, hi); // (ii) d >= -maxSep
		if (strict)
			for (int j = 0; j < int(R.size()); ++j) { // (iii) nR[j].(q - R[j]) <= maxSep
				if (j == refEdge) continue;
				const Real a0 = nR[j].dot(q0 - R[j]), a1 = nR[j].dot(q1 - R[j]);
				clipLinear(maxSep - a0, -(a1 - a0), lo, hi);
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
		return true;
	}
} // namespace

EdgeContact edgeContact(const std::vector<Vec2>& A, const std::vector<Vec2>& B, Real maxSeparation, const ContactHint* hint, Real hysteresis, Real minSizeGiven)
{
	EdgeContact c;
	const int   nA = int(A.size()), nB = int(B.size());
	if (nA < 3 || nB < 3) return c;

	// Scratch arrays, one set per thread (the functor runs in parallel) and fetched once per call:
	// each thread_local access in a shared library costs a call of __tls_get_addr.
	struct Scratch {
		std::vector<Vec2> normalsA, normalsB;
		std::vector<Real> sepsA, sepsB;
	};
	thread_local Scratch scratch;
	auto& normalsA = scratch.normalsA;
	auto& normalsB = scratch.normalsB;
	auto& sepsA    = scratch.sepsA;
	auto& sepsB    = scratch.sepsB;
	edgeNormals(A, normalsA);
	edgeNormals(B, normalsB);

	// --- separating-axis search -----------------------------------------------------------
	// The separation of every edge of A against B and of B against A, kept for the tie-break.
	sepsA.resize(nA);
	sepsB.resize(nB);
	int  bestBody = 1, bestEdge = 0;
	Real best = -std::numeric_limits<Real>::infinity();
	for (int i = 0; i < nA; ++i) {
		sepsA[i] = edgeSeparation(A, normalsA, i, B);
		if (sepsA[i] > best) best = sepsA[i], bestBody = 1, bestEdge = i;
	}
	for (int i = 0; i < nB; ++i) {
		sepsB[i] = edgeSeparation(B, normalsB, i, A);
		if (sepsB[i] > best) best = sepsB[i], bestBody = 2, bestEdge = i;
	}

	const Real minSize = minSizeGiven >= 0 ? minSizeGiven : std::min(polygonSize(A), polygonSize(B));
	// Round-off slop: an exactly shared edge moved by a rigid motion has |d| ~ 1e-16 size, which
	// must still count as touching when maxSeparation = 0.
	const Real slop = 1e-12 * minSize;

	// Ties: where several edges are equally good within round-off (a shared edge meets a corner
	// of the other block at the same separation), take the one that faces an edge of the other
	// polygon most squarely, so that two blocks sharing an edge get an edge contact in either
	// order of the bodies, not a corner touch of zero length. Among equals, A's edge comes first.
	auto facing = [](const Vec2& n, const std::vector<Vec2>& nInc) {
		Real m = std::numeric_limits<Real>::infinity();
		for (const auto& ni : nInc)
			m = std::min(m, ni.dot(n));
		return m; // -1: exactly antiparallel to an edge of the other polygon
	};
	{
		const Real bestSep    = best;
		Real       bestFacing = std::numeric_limits<Real>::infinity();
		for (int body = 1; body <= 2; ++body) {
			const auto& seps = body == 1 ? sepsA : sepsB;
			const auto& nP   = body == 1 ? normalsA : normalsB;
			const auto& nQ   = body == 1 ? normalsB : normalsA;
			for (int i = 0; i < int(seps.size()); ++i) {
				if (seps[i] < bestSep - slop) continue;
				const Real f = facing(nP[i], nQ);
				if (f < bestFacing - 1e-12) bestFacing = f, bestBody = body, bestEdge = i, best = seps[i];
			}
		}
	}

	// Preferred edge: the hint's (the reference of the previous step), kept unless another edge
	// is better by more than the hysteresis.
	const Real tol     = hysteresis * minSize;
	int        refBody = bestBody, refEdge = bestEdge;
	Real       sep     = best;
	if (hint && (hint->refBody == 1 || hint->refBody == 2) && hint->refEdge >= 0 && hint->refEdge < (hint->refBody == 1 ? nA : nB)) {
		const Real prefSep = (hint->refBody == 1) ? sepsA[hint->refEdge] : sepsB[hint->refEdge];
		if (prefSep >= best - tol) refBody = hint->refBody, refEdge = hint->refEdge, sep = prefSep;
	}

	c.separation = sep;
	c.refBody    = refBody;
	c.refEdge    = refEdge;
	const Real maxSep = std::max(maxSeparation, Real(0)) + slop;
	if (!(sep <= maxSep)) return c; // also rejects NaN

	// Clip on the chosen reference edge; where the overlap is a corner of the reference block
	// poking into the other one away from its facing edge, (iii) below leaves nothing, and the
	// best edge of the other block, which that corner then penetrates, is the reference instead.
	if (clipOnReference(A, B, normalsA, normalsB, refBody, refEdge, maxSep, true, c)) {
		c.separation = sep;
		return c;
	}
	const int         other     = 3 - refBody;
	const auto&       otherSeps = other == 1 ? sepsA : sepsB;
	const int         alt       = int(std::max_element(otherSeps.begin(), otherSeps.end()) - otherSeps.begin());
	if (otherSeps[alt] <= maxSep && clipOnReference(A, B, normalsA, normalsB, other, alt, maxSep, true, c)) {
		c.separation = otherSeps[alt];
		return c;
	}
	// neither: the projection on the chosen edge (clips (i) and (ii) only)
	clipOnReference(A, B, normalsA, normalsB, refBody, refEdge, maxSep, false, c);
	c.separation = sep;
	return c;
}

void integrationPoints(int nIP, std::vector<Real>& s, std::vector<Real>& w)
{
	if (nIP < 1 || nIP > 8) throw std::invalid_argument("integrationPoints: nIP must be in 1..8");
	s.assign(nIP, 0);
	w.assign(nIP, 0);
	// Gauss-Legendre nodes x_k on [-1,1] are the roots of P_n; Newton iteration from the
	// classical initial guess cos(pi (k - 1/4)/(n + 1/2)) converges to machine precision.
	// Weights on [-1,1]: 2 / ((1 - x^2) P_n'(x)^2). Mapped to [0,1]: s = (1+x)/2, w/2.
	const int n = nIP;
	for (int k = 0; k < n; ++k) {
		Real x = std::cos(M_PI * (k + 0.75) / (n + 0.5));
		Real dp = 1;
		for (int it = 0; it < 100; ++it) {
			Real p0 = 1, p1 = x; // P_0, P_1
			for (int j = 2; j <= n; ++j) {
				const Real p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
				p0 = p1;
				p1 = p2;
			}
			const Real pn = (n == 1) ? x : p1, pnm1 = (n == 1) ? 1 : p0;
			dp = n * (x * pn - pnm1) / (x * x - 1);
			const Real dx = pn / dp;
			x -= dx;
			if (std::abs(dx) < 1e-16) break;
		}
		// nodes from cos() come in decreasing x; store increasing s
		s[n - 1 - k] = (1 + x) / 2;
		w[n - 1 - k] = 1 / ((1 - x * x) * dp * dp);
	}
}

} // namespace rbsm
