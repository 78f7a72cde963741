#include <pkg/rbsm/tessellation/ExactPieces.hpp>

#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/partition_2.h>

#include <list>
#include <sstream>

namespace rbsm {
namespace tess {
namespace exact {

std::vector<P2> dropStraight(const std::vector<P2>& in)
{
	std::vector<P2> v(in);
	bool changed = true;
	while (changed && v.size() >= 3) {
		changed = false;
		for (std::size_t i = 0; i < v.size() && v.size() >= 3; ++i) {
			const P2& a = v[(i + v.size() - 1) % v.size()];
			const P2& b = v[(i + 1) % v.size()];
			if (v[i] == a || CGAL::collinear(a, v[i], b)) {
				v.erase(v.begin() + i);
				changed = true;
				break;
			}
		}
	}
	return v;
}

namespace {
	template <class Pts>
	bool hasStraight(const Pts& in)
	{
		std::vector<P2> v(in.begin(), in.end());
		for (std::size_t i = 0; i < v.size(); ++i)
			if (CGAL::collinear(v[(i + v.size() - 1) % v.size()], v[i], v[(i + 1) % v.size()])) return true;
		return false;
	}
} // namespace

std::vector<std::vector<P2>> convexPieces(const std::vector<P2>& v, bool& split)
{
	using PartPoly = CGAL::Partition_traits_2<K>::Polygon_2;
	CGAL::Polygon_2<K> poly(v.begin(), v.end());
	split = false;
	if (poly.is_convex()) return {v};
	split = true;
	for (int method = 0; method < 3; ++method) {
		std::list<PartPoly> parts;
		if (method == 0) CGAL::optimal_convex_partition_2(v.begin(), v.end(), std::back_inserter(parts));
		else if (method == 1) CGAL::approx_convex_partition_2(v.begin(), v.end(), std::back_inserter(parts));
		else CGAL::greene_approx_convex_partition_2(v.begin(), v.end(), std::back_inserter(parts));
		bool ok = true;
		for (const auto& p : parts) ok = ok && !hasStraight(p.container());
		if (ok || method == 2) {
			std::vector<std::vector<P2>> out;
			// Last resort: drop the straight vertex (the neighbour across keeps it: a T-junction).
			for (const auto& p : parts) {
				std::vector<P2> pts(p.vertices_begin(), p.vertices_end());
				out.push_back(ok ? pts : dropStraight(pts));
			}
			return out;
		}
	}
	return {};
}

Point round(const P2& p) { return {CGAL::to_double(p.x().exact()), CGAL::to_double(p.y().exact())}; }

const Point& Rounder::operator()(const P2& p)
{
	auto it = done_.find(p);
	if (it == done_.end()) it = done_.emplace(p, round(p)).first;
	return it->second;
}

Polygon Rounder::polygon(const std::vector<P2>& piece)
{
	Polygon poly;
	for (const auto& p : piece) {
		const Point& q = (*this)(p);
		if (poly.empty() || poly.back() != q) poly.push_back(q);
	}
	while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
	return poly;
}

std::string where(const Polygon& v)
{
	std::ostringstream o;
	o.precision(17);
	o << "[";
	for (std::size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "") << "(" << v[i][0] << ", " << v[i][1] << ")";
	o << "]";
	return o.str();
}

} // namespace exact
} // namespace tess
} // namespace rbsm
