#include <pkg/rbsm/kernel/ContactMemory.hpp>
#include <pkg/rbsm/kernel/EdgeClip.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbsm {

using namespace detail;

namespace {
	// The skip rule of SearchMemory (ContactMemory.hpp) on the memory's edge, for the step's drift D and
	// relative pose: true if the full search would keep that edge, with c its contact, every field
	// written (clipped, or apart: separation, refBody and refEdge, the rest as default); false, with c
	// untouched or emptied, if the search must decide, or (onlyCertified) if the clip certificates do
	// not hold.
	template <class PA, class PB>
	bool keepHinted(const PA& A, const PB& B, const SearchMemory& m, const FollowStep& step, bool onlyCertified, EdgeContact& c)
	{
		const int              rb = m.refBody, re = m.refEdge;
		const ClipCertificate& k     = m.clip;
		const Real             drift = step.drift, maxSep = step.maxSep, tol = step.tol;
		// the certificates hold for this relative rotation (chord χ, L1: a bound of the Euclidean)?
		const Real chord     = std::abs(step.rel.c - m.rel.c) + std::abs(step.rel.s - m.rel.s);
		const bool certified = k.incEdge >= 0 && k.incLead > 2 * chord && chord < kFacingMargin;
		if (onlyCertified && !(certified && k.supportOnInc)) return false;
		auto sepOf = [&](int body, int edge) { return body == 1 ? edgeSeparation(A, edge, B) : edgeSeparation(B, edge, A); };
		// with the support certified, the two edges are read once, for the separation and the clip
		const bool atIncident = certified && k.supportOnInc;
		EdgePair   edges {};
		if (atIncident) edges = rb == 1 ? edgePair(A, re, B, k.incEdge) : edgePair(B, re, A, k.incEdge);
		const Real prefSep = atIncident ? separationAtIncident(edges) : sepOf(rb, re);
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
		ClipJob job;
		job.refBody = rb, job.refEdge = re, job.maxSep = maxSep, job.cert = certified ? &k : nullptr;
		job.known = atIncident ? &edges : nullptr;
		if (clipOnReference(A, B, job, c)) {
			c.separation = prefSep;
			return true;
		}
		c = EdgeContact {}; // nothing left on that edge: the full search decides
		return false;
	}
} // namespace

bool keepRemembered(const PolygonView& A, const PolygonView& B, const SearchMemory& m, const FollowStep& step, EdgeContact& c)
{
	return keepHinted(arrays(A), arrays(B), m, step, false, c);
}

SearchMemory rememberSearch(const SearchOutcome& found, Real minSize, const Pose2& rel)
{
	SearchMemory m;
	m.refBody        = found.refBody;
	m.refEdge        = found.refEdge;
	m.maxOther       = -std::numeric_limits<Real>::infinity();
	m.rel            = rel;
	Real rivalSep[2] = { -std::numeric_limits<Real>::infinity(), -std::numeric_limits<Real>::infinity() };
	// A rival is an edge within a tenth of the block size of the chosen one (the other block's
	// twin of a shared edge, the two edges of a corner); farther ones are bounded by maxOther.
	const Real rivalFloor = found.sep - 0.1 * minSize;
	auto       offer      = [&](int body, int edge, Real s) {
                if (body == found.refBody && edge == found.refEdge) return;
                if (!(s >= rivalFloor)) {
                        m.maxOther = std::max(m.maxOther, s);
                        return;
                }
                if (s > rivalSep[0]) { // new best rival: the old best becomes second, the old second goes to the rest
                        m.maxOther  = std::max(m.maxOther, rivalSep[1]);
                        rivalSep[1] = rivalSep[0], m.rivalBody[1] = m.rivalBody[0], m.rivalEdge[1] = m.rivalEdge[0];
                        rivalSep[0] = s, m.rivalBody[0] = body, m.rivalEdge[0] = edge;
                } else if (s > rivalSep[1]) {
                        m.maxOther  = std::max(m.maxOther, rivalSep[1]);
                        rivalSep[1] = s, m.rivalBody[1] = body, m.rivalEdge[1] = edge;
                } else
                        m.maxOther = std::max(m.maxOther, s);
	};
	for (int i = 0; i < found.nA; ++i)
		offer(1, i, found.sepsA[i]);
	for (int i = 0; i < found.nB; ++i)
		offer(2, i, found.sepsB[i]);
	for (int k = 0; k < 2; ++k)
		m.rivalLead[k] = rivalSep[k] - found.sep;
	return m;
}

bool followContact(const PolygonView& A, const PosedPolygon& B, const ContactQuery& q, const Coherence& coherence, EdgeContact& c)
{
	// edgeContact's opening, to its skip rule
	const int nA = A.n, nB = B.local.n;
	if (nA < 3 || nB < 3 || !q.hint || !coherence.memory || !hintNamesEdge(*q.hint, nA, nB)) return false;
	const SearchMemory& memory = *coherence.memory;
	FollowStep          step;
	step.maxSep = reachWithSlop(q.maxSeparation, q.minSize);
	step.tol    = q.hysteresis * q.minSize;
	step.drift  = separationDrift(coherence.a, coherence.b, memory, step.rel);
	if (!followable(memory, *q.hint, step.drift)) return false;
	return keepHinted(arrays(A), Posed { B, nB }, memory, step, true, c);
}

} // namespace rbsm
