#include <pkg/rbsm/kernel/DiskContact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbsm {

DiskContact diskPolygonContact(const PolygonView& P, const Vec2& c, Real r)
{
	DiskContact out;
	// The edge line the centre is farthest outside of (or least inside of): s* = max_i n_i·(c − v_i).
	int  best      = 0;
	Real bestLine  = -std::numeric_limits<Real>::infinity();
	Real extentSq  = 0; // squared size of the polygon about v_0, for the round-off scale
	for (int i = 0; i < P.n; i++) {
		const Real s = P.nrm[i].dot(c - P.v[i]);
		if (s > bestLine) bestLine = s, best = i;
		extentSq = std::max(extentSq, (P.v[i] - P.v[0]).squaredNorm());
	}
	const Real slop = 1e-12 * std::sqrt(extentSq);
	if (bestLine <= slop) {
		// Inside (or on the boundary): the nearest edge line, whose foot is on that edge.
		out.distance = bestLine;
		out.normal   = P.nrm[best];
		out.closest  = c - bestLine * out.normal;
		out.edge     = best;
	} else {
		// Outside: the nearest point of the edge segments.
		Real bestSq = std::numeric_limits<Real>::infinity();
		for (int i = 0; i < P.n; i++) {
			const Vec2& a = P.v[i];
			const Vec2  e = P.v[(i + 1) % P.n] - a;
			const Real  t = std::clamp((c - a).dot(e) / e.squaredNorm(), Real(0), Real(1));
			const Vec2  q = a + t * e;
			const Real  d = (c - q).squaredNorm();
			if (d < bestSq) bestSq = d, out.closest = q, out.edge = i;
		}
		out.distance = std::sqrt(bestSq);
		out.normal   = (c - out.closest) / out.distance;
	}
	out.overlap = r - out.distance;
	out.point   = out.closest - 0.5 * out.overlap * out.normal;
	return out;
}

} // namespace rbsm
