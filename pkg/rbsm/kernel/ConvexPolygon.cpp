#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/Pose2.hpp>

#include <cmath>
#include <limits>
#include <sstream>

namespace rbsm {

namespace {
	// Relative tolerances of polygonProblem (see the header).
	constexpr Real kRepeatTol    = 1e-9; // distance / size
	constexpr Real kCollinearTol = 1e-9; // sine of the turn angle

	std::string msg(const std::string& what, size_t i)
	{
		std::ostringstream o;
		o << what << " at vertex " << i;
		return o.str();
	}

	// True if segments [a,b] and [c,d] intersect (including touching), tolerance tol on the
	// orientation tests (cross products, units m^2).
	bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Real tol)
	{
		const Real d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
		const Real d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
		if (((d1 > tol && d2 < -tol) || (d1 < -tol && d2 > tol)) && ((d3 > tol && d4 < -tol) || (d3 < -tol && d4 > tol))) return true;
		// collinear / touching cases: a point lies on the other segment
		auto onSeg = [tol](const Vec2& p, const Vec2& q, const Vec2& r, Real o) {
			// r on segment pq given orientation o = cross(q-p, r-p)
			if (std::abs(o) > tol) return false;
			const Vec2 e = q - p;
			const Real s = e.dot(r - p);
			return s >= 0 && s <= e.squaredNorm();
		};
		return onSeg(a, b, c, d1) || onSeg(a, b, d, d2) || onSeg(c, d, a, d3) || onSeg(c, d, b, d4);
	}
} // namespace

std::vector<Vec2> edgeNormals(const std::vector<Vec2>& v)
{
	const size_t      n = v.size();
	std::vector<Vec2> out(n);
	for (size_t i = 0; i < n; ++i) {
		const Vec2 e = v[(i + 1) % n] - v[i];
		out[i]       = Vec2(e.y(), -e.x()).normalized();
	}
	return out;
}

Real centroidInradius(const std::vector<Vec2>& v)
{
	Real r = std::numeric_limits<Real>::infinity();
	for (size_t i = 0; i < v.size(); ++i) {
		const Vec2 e = v[(i + 1) % v.size()] - v[i];
		if (e.norm() > 0) r = std::min(r, std::abs(cross2(e, v[i])) / e.norm());
	}
	return v.size() < 3 ? 0 : r;
}

Real halfWidthAlong(const std::vector<Vec2>& v, const Vec2& n)
{
	if (v.empty()) return 0;
	Real lo = std::numeric_limits<Real>::infinity(), hi = -lo;
	for (const Vec2& x : v) {
		const Real d = x.dot(n);
		lo           = std::min(lo, d);
		hi           = std::max(hi, d);
	}
	return 0.5 * (hi - lo);
}

Real polygonSize(const std::vector<Vec2>& v)
{
	if (v.empty()) return 0;
	Vec2 lo = v[0], hi = v[0];
	for (const auto& p : v) {
		lo = lo.cwiseMin(p);
		hi = hi.cwiseMax(p);
	}
	return (hi - lo).maxCoeff();
}

std::string polygonProblem(const std::vector<Vec2>& v)
{
	const size_t n = v.size();
	if (n < 3) {
		std::ostringstream o;
		o << "polygon has " << n << " vertices, at least 3 are needed";
		return o.str();
	}
	for (size_t i = 0; i < n; ++i)
		if (!std::isfinite(v[i].x()) || !std::isfinite(v[i].y())) return msg("non-finite (NaN or inf) coordinate", i);

	const Real L = polygonSize(v);
	if (!(L > 0)) return "all vertices coincide (polygon of zero size)";
	for (size_t i = 0; i < n; ++i)
		for (size_t j = i + 1; j < n; ++j)
			if ((v[i] - v[j]).norm() <= kRepeatTol * L) {
				std::ostringstream o;
				// Two corners of a sliver (a 1e9:1 rectangle) are this close too; name the shape, not a typo.
				Real twiceArea = 0;
				for (size_t k = 0; k < n; ++k)
					twiceArea += cross2(v[k] - v[0], v[(k + 1) % n] - v[0]);
				if (std::abs(twiceArea) / 2 <= kRepeatTol * L * L)
					o << "sliver: area " << std::abs(twiceArea) / 2 << " m² is below 1e-9 of its size squared (size " << L
					  << " m), too thin to model (vertices " << i << " and " << j << " are " << (v[i] - v[j]).norm() << " m apart)";
				else
					o << "repeated vertex: vertex " << j << " equals vertex " << i;
				return o.str();
			}

	// Turn at each vertex i: sine of the angle between the incoming and outgoing edges.
	std::vector<Real> turn(n);
	for (size_t i = 0; i < n; ++i) {
		const Vec2 a = v[i] - v[(i + n - 1) % n], b = v[(i + 1) % n] - v[i];
		turn[i]      = cross2(a, b) / (a.norm() * b.norm());
		if (std::abs(turn[i]) <= kCollinearTol && a.dot(b) > 0) return msg("collinear consecutive vertices (vertex lies on the line of its neighbours)", i);
		if (std::abs(turn[i]) <= kCollinearTol) return msg("polygon folds back on itself (edges overlap)", i);
	}

	// Self-intersection: any two non-adjacent edges touching or crossing.
	const Real crossTol = kRepeatTol * L * L;
	for (size_t i = 0; i < n; ++i)
		for (size_t j = i + 2; j < n; ++j) {
			if (i == 0 && j == n - 1) continue; // adjacent through the closing edge
			if (segmentsIntersect(v[i], v[i + 1], v[j], v[(j + 1) % n], crossTol)) {
				std::ostringstream o;
				o << "self-intersecting: edge " << i << "-" << (i + 1) << " crosses edge " << j << "-" << (j + 1) % n;
				return o.str();
			}
		}

	size_t nNeg = 0;
	for (Real t : turn)
		if (t < 0) ++nNeg;
	if (nNeg == n) return "clockwise orientation (vertices must be counter-clockwise)";
	if (nNeg > 0) {
		// A simple polygon: the sign of the area tells the intended orientation; report the
		// first vertex that turns the other way.
		Real area2 = 0;
		for (size_t i = 0; i < n; ++i) area2 += cross2(v[i], v[(i + 1) % n]);
		for (size_t i = 0; i < n; ++i)
			if ((area2 > 0 && turn[i] < 0) || (area2 < 0 && turn[i] > 0)) return msg("non-convex (reflex angle)", i);
	}
	return "";
}

MassProperties massProperties(const std::vector<Vec2>& v)
{
	const size_t n = v.size();
	Vec2 o = Vec2::Zero();
	for (const auto& p : v) o += p;
	if (n > 0) o /= Real(n);
	Real A2 = 0, J12 = 0; // 2A and 12 J_o
	Vec2 C6 = Vec2::Zero(); // 6 A (C - o)
	for (size_t i = 0; i < n; ++i) {
		const Vec2 p = v[i] - o, q = v[(i + 1) % n] - o;
		const Real c = cross2(p, q);
		A2 += c;
		C6 += c * (p + q);
		J12 += c * (p.dot(p) + p.dot(q) + q.dot(q));
	}
	MassProperties m;
	m.area           = A2 / 2;
	const Vec2 dc    = (m.area != 0) ? Vec2(C6 / (3 * A2)) : Vec2(Vec2::Zero());
	m.centroid       = o + dc;
	m.polarMoment    = J12 / 12 - m.area * dc.squaredNorm();
	return m;
}

Vec2 rotate(const Vec2& x, Real angle)
{
	return Pose2(Vec2::Zero(), std::cos(angle), std::sin(angle)).rotate(x);
}

Vec2 localToWorld(const Vec2& local, const Vec2& pos, Real angle) { return pos + rotate(local, angle); }

Vec2 worldToLocal(const Vec2& world, const Vec2& pos, Real angle) { return rotate(world - pos, -angle); }

std::vector<Vec2> toWorld(const std::vector<Vec2>& local, const Vec2& pos, Real angle)
{
	std::vector<Vec2> w;
	w.reserve(local.size());
	for (const auto& p : local) w.push_back(localToWorld(p, pos, angle));
	return w;
}

} // namespace rbsm
