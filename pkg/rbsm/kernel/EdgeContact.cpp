// The separating-axis search of the edge contact (EdgeContact.hpp) and the choice of the clip that
// makes the contact segment; the clip itself is in EdgeClip.hpp, the memory of a followed contact in
// ContactMemory.cpp.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeClip.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbsm {

using namespace detail;

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
		T*       data() { return p_; }
		T&       operator[](int i) { return p_[i]; }
		const T& operator[](int i) const { return p_[i]; }

	private:
		T              local_[N];
		std::vector<T> heap_;
		T*             p_;
	};

	// The separation of every edge of A against B and of B against A (into sepsA, sepsB, kept for the
	// tie-break and the fall-backs) and the edge of largest separation (found.refBody, refEdge, sep).
	// Ties: where several edges are equally good within round-off (a shared edge meets a corner of the
	// other block at the same separation), the one that faces an edge of the other polygon most
	// squarely, so that two blocks sharing an edge get an edge contact in either order of the bodies,
	// not a corner touch of zero length. Among equals, A's edge comes first.
	void searchAxes(const PolygonView& A, const PolygonView& B, Real slop, Real* sepsA, Real* sepsB, SearchOutcome& found)
	{
		found.sepsA = sepsA, found.sepsB = sepsB, found.nA = A.n, found.nB = B.n;
		int   bestBody = 1, bestEdge = 0;
		Real  best = -std::numeric_limits<Real>::infinity();
		for (int i = 0; i < A.n; ++i) {
			sepsA[i] = edgeSeparation(A, i, B);
			if (sepsA[i] > best) best = sepsA[i], bestBody = 1, bestEdge = i;
		}
		for (int i = 0; i < B.n; ++i) {
			sepsB[i] = edgeSeparation(B, i, A);
			if (sepsB[i] > best) best = sepsB[i], bestBody = 2, bestEdge = i;
		}
		auto facing = [](const Vec2& n, const PolygonView& Q) {
			Real m = std::numeric_limits<Real>::infinity();
			for (int k = 0; k < Q.n; ++k)
				m = std::min(m, Q.nrm[k].dot(n));
			return m; // -1: exactly antiparallel to an edge of the other polygon
		};
		const Real bestSep    = best;
		Real       bestFacing = std::numeric_limits<Real>::infinity();
		for (int body = 1; body <= 2; ++body) {
			const Real* seps = found.seps(body);
			const auto& P    = body == 1 ? A : B;
			const auto& Q    = body == 1 ? B : A;
			for (int i = 0; i < P.n; ++i) {
				if (seps[i] < bestSep - slop) continue;
				const Real f = facing(P.nrm[i], Q);
				if (f < bestFacing - 1e-12) bestFacing = f, bestBody = body, bestEdge = i, best = seps[i];
			}
		}
		found.refBody = bestBody, found.refEdge = bestEdge, found.sep = best;
	}

	// Neither the chosen edge nor the other block's best leaves anything (rare in shallow contacts,
	// about 1 in 500 in the fuzzer's, common in deep ones: a sharp corner poking obliquely into a
	// corner or through a thin tip, two tips crossing): the facing edge of the other block leaves the
	// reference block, or the reference line leaves the other block, wherever they overlap. Search
	// every edge r of either polygon against every edge k of the other that faces it (n_k.n_r < 0):
	// take the r of largest separation for which some k leaves something under the strict clip, and
	// for it the most squarely facing such k. Every overlap of that contact is a chord of the
	// intersection (see clipOn). There is such a pair whenever the interiors overlap and neither
	// polygon contains the other: from a point of the intersection's boundary on an edge r, walk along
	// -n_r across the intersection; the far side is on an edge k of the other polygon (ties in
	// separation: A's edges, lower index first). True, with c, if a pair leaves something.
	bool clipFacingPairs(const PolygonView& A, const PolygonView& B, const SearchOutcome& found, Real maxSep, EdgeContact& c)
	{
		const Arrays a = arrays(A), b = arrays(B);
		EdgeContact  best;
		Real         bestSep = -std::numeric_limits<Real>::infinity();
		for (int body = 1; body <= 2; ++body) {
			const Real* seps = found.seps(body);
			const auto& P    = body == 1 ? A : B;
			const auto& Q    = body == 1 ? B : A;
			for (int r = 0; r < P.n; ++r) {
				if (!(seps[r] > bestSep) || !(seps[r] <= maxSep)) continue;
				int  bestK   = -1;
				Real bestDot = 0; // only edges facing r (n_k . n_r < 0)
				for (int k = 0; k < Q.n; ++k) {
					const Real dk = Q.nrm[k].dot(P.nrm[r]);
					if (!(dk < bestDot)) continue;
					EdgeContact t;
					ClipJob     job;
					job.refBody = body, job.refEdge = r, job.maxSep = maxSep, job.incGiven = k;
					if (clipOnReference(a, b, job, t)) bestK = k, bestDot = dk, best = t;
				}
				if (bestK >= 0) bestSep = seps[r];
			}
		}
		if (!best.touching) return false;
		c            = best;
		c.separation = bestSep;
		return true;
	}

	// The contact segment once the search has chosen (found): the clip on the chosen edge, recording
	// its certificates (record, or null); where the overlap is a corner of the reference block poking
	// into the other one away from its facing edge, (iii) leaves nothing, and the best edge of the
	// other block, which that corner then penetrates, is the reference instead ((iv) likewise leaves
	// nothing where a corner of the other block leans away from the line); then clipFacingPairs; if
	// nothing (one polygon inside the other, or round-off), the projection on the chosen edge (clips
	// (i) and (ii) only). Returns true if the first clip left something (what the memory reproduces).
	bool clipChosen(const PolygonView& A, const PolygonView& B, const SearchOutcome& found, Real maxSep, ClipCertificate* record, Real radius, EdgeContact& c)
	{
		const Arrays a = arrays(A), b = arrays(B);
		ClipJob      job;
		job.refBody = found.refBody, job.refEdge = found.refEdge, job.maxSep = maxSep, job.record = record, job.radius = radius;
		if (clipOnReference(a, b, job, c)) {
			c.separation = found.sep;
			return true;
		}
		const int   other     = 3 - found.refBody;
		const Real* otherSeps = found.seps(other);
		int         alt       = 0;
		for (int i = 1; i < found.n(other); ++i)
			if (otherSeps[i] > otherSeps[alt]) alt = i;
		ClipJob altJob;
		altJob.refBody = other, altJob.refEdge = alt, altJob.maxSep = maxSep;
		if (otherSeps[alt] <= maxSep && clipOnReference(a, b, altJob, c)) {
			c.separation = otherSeps[alt];
			return false;
		}
		if (clipFacingPairs(A, B, found, maxSep, c)) return false;
		ClipJob projection;
		projection.refBody = found.refBody, projection.refEdge = found.refEdge, projection.maxSep = maxSep, projection.strict = false;
		clipOnReference(a, b, projection, c);
		c.separation = found.sep;
		return false;
	}
} // namespace

EdgeContact edgeContact(const std::vector<Vec2>& A, const std::vector<Vec2>& B, Real maxSeparation, const ContactHint* hint, Real hysteresis, Real minSizeGiven)
{
	if (A.size() < 3 || B.size() < 3) return EdgeContact {};
	const std::vector<Vec2> normalsA = edgeNormals(A), normalsB = edgeNormals(B);
	const Real minSize = minSizeGiven >= 0 ? minSizeGiven : std::min(polygonSize(A), polygonSize(B));
	return edgeContact(PolygonView { A.data(), normalsA.data(), int(A.size()) }, PolygonView { B.data(), normalsB.data(), int(B.size()) },
	                   ContactQuery { maxSeparation, hint, hysteresis, minSize });
}

EdgeContact edgeContact(const PolygonView& A, const PolygonView& B, const ContactQuery& q, Coherence* coherence)
{
	EdgeContact c;
	const int   nA = A.n, nB = B.n;
	if (nA < 3 || nB < 3) return c;

	const Real         minSize = q.minSize;
	const Real         maxSep  = reachWithSlop(q.maxSeparation, minSize);
	const ContactHint* hint    = q.hint;
	const bool         hinted  = hint && hintNamesEdge(*hint, nA, nB);

	// --- temporal coherence: keep the hinted edge without a search when provably unchanged ---
	SearchMemory* memory = coherence ? coherence->memory : nullptr;
	FollowStep    step;
	step.maxSep = maxSep, step.tol = q.hysteresis * minSize;
	if (memory) {
		step.drift = separationDrift(coherence->a, coherence->b, *memory, step.rel);
		if (hinted && followable(*memory, *hint, step.drift) && keepRemembered(A, B, *memory, step, c)) return c;
	}

	// --- separating-axis search -----------------------------------------------------------
	SmallBuffer<Real, 16> sepsA(nA), sepsB(nB);
	SearchOutcome         found;
	searchAxes(A, B, roundOffSlop(minSize), sepsA.data(), sepsB.data(), found);

	// Preferred edge: the hint's (the reference of the previous step), kept unless another edge
	// is better by more than the hysteresis.
	if (hinted) {
		const Real prefSep = (hint->refBody == 1) ? sepsA[hint->refEdge] : sepsB[hint->refEdge];
		if (prefSep >= found.sep - step.tol) found.refBody = hint->refBody, found.refEdge = hint->refEdge, found.sep = prefSep;
	}
	// Remember the choice for the skip rule: its two closest rivals, and the largest separation
	// of every other edge now.
	if (memory) *memory = rememberSearch(found, minSize, step.rel);

	c.separation = found.sep;
	c.refBody    = found.refBody;
	c.refEdge    = found.refEdge;
	if (!(found.sep <= maxSep)) { // also rejects NaN
		if (memory) memory->valid = found.sep == found.sep;
		return c;
	}
	// only the first clip's outcome is what the skip rule reproduces
	const bool first = clipChosen(A, B, found, maxSep, memory ? &memory->clip : nullptr, kCertificateRadius * minSize, c);
	if (memory && first) memory->valid = true;
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

bool separatedAlongCentres(const PolygonView& A, const PosedPolygon& B, Real maxSeparation, Real minSize)
{
	const int nA = A.n, nB = B.local.n;
	if (nA < 3 || nB < 3) return false;
	const Real beyond = std::max(maxSeparation, Real(0)) + 2 * roundOffSlop(minSize);
	// the edge of P whose outward normal points most along d (P's own frame)
	auto facing = [](const Vec2* normals, int n, const Vec2& d) {
		int best = 0;
		for (int i = 1; i < n; ++i)
			if (normals[i].dot(d) > normals[best].dot(d)) best = i;
		return best;
	};
	const Posed  b { B, nB };
	const Arrays a = arrays(A);
	if (edgeSeparation(a, facing(A.nrm, nA, B.pose.p), b) > beyond) return true;
	return edgeSeparation(b, facing(B.local.nrm, nB, B.pose.unrotate(-B.pose.p)), a) > beyond;
}

} // namespace rbsm
