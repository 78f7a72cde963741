#include <pkg/rbsm/tessellation/VoronoiClip.hpp>

#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/tessellation/ExactPieces.hpp>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace rbsm {
namespace tess {

namespace {
	using exact::convexPieces;
	using exact::dropStraight;
	using exact::where;
	using K      = exact::K; // exact constructions (rationals)
	using Ki     = CGAL::Exact_predicates_inexact_constructions_kernel; // exact predicates on doubles
	using P2     = K::Point_2;
	using Poly   = CGAL::Polygon_2<K>;
	using PolyH  = CGAL::Polygon_with_holes_2<K>;
	using PolyI  = CGAL::Polygon_2<Ki>;

	struct SiteInfo {
		int id = -1;
	};
	using Vb = CGAL::Triangulation_vertex_base_with_info_2<SiteInfo, K>;
	using Tds = CGAL::Triangulation_data_structure_2<Vb>;
	using DT  = CGAL::Delaunay_triangulation_2<K, Tds>;

	bool finite(const Point& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

	PolyI toInexact(const Polygon& v)
	{
		PolyI p;
		for (const auto& q : v) p.push_back(Ki::Point_2(q[0], q[1]));
		return p;
	}

	Poly toExact(const Polygon& v)
	{
		Poly p;
		for (const auto& q : v) p.push_back(P2(q[0], q[1]));
		return p;
	}

} // namespace

std::string regionProblem(const Polygon& region)
{
	const std::size_t n = region.size();
	if (n < 3) {
		std::ostringstream o;
		o << "the region has " << n << " vertices, at least 3 are needed";
		return o.str();
	}
	for (std::size_t i = 0; i < n; ++i)
		if (!finite(region[i])) {
			std::ostringstream o;
			o << "the region has a non-finite (NaN or inf) coordinate at vertex " << i;
			return o.str();
		}
	for (std::size_t i = 0; i < n; ++i)
		if (region[i] == region[(i + 1) % n]) {
			std::ostringstream o;
			o << "the region repeats vertex " << i << " (" << region[i][0] << ", " << region[i][1] << ")";
			return o.str();
		}
	const PolyI p = toInexact(region);
	if (!p.is_simple()) return "the region is not a simple polygon (its edges cross or touch)";
	if (p.orientation() == CGAL::COLLINEAR) return "the region has zero area";
	return "";
}

double signedArea(const Polygon& poly)
{
	if (poly.size() < 3) return 0;
	return CGAL::to_double(toExact(poly).area().exact());
}

Polygon counterClockwise(const Polygon& region)
{
	const std::string problem = regionProblem(region);
	if (!problem.empty()) throw std::invalid_argument(problem);
	Polygon r = region;
	if (toInexact(r).orientation() == CGAL::CLOCKWISE) std::reverse(r.begin(), r.end());
	return r;
}

std::vector<Point> randomSites(const Polygon& region_, std::size_t n, std::uint64_t seed, double minDistance, std::size_t maxAttempts)
{
	const Polygon region = counterClockwise(region_);
	if (!(std::isfinite(minDistance) && minDistance >= 0)) throw std::invalid_argument("min_distance must be a finite number >= 0");
	if (maxAttempts == 0) maxAttempts = 1000 * n + 1000;
	const PolyI poly = toInexact(region);
	const auto bb = poly.bbox();
	const double x0 = bb.xmin(), y0 = bb.ymin(), wx = bb.xmax() - bb.xmin(), wy = bb.ymax() - bb.ymin();
	std::mt19937_64 gen(seed);
	auto uniform = [&gen]() { return double(gen() >> 11) * 0x1.0p-53; }; // [0,1), 53 random bits

	// Accepted sites in a grid of cells of side minDistance (neighbour search of dart throwing).
	const double cell = minDistance > 0 ? minDistance : 1.0;
	std::unordered_map<long long, std::vector<std::size_t>> grid;
	auto key = [&](long long i, long long j) { return i * 2000003LL + j; };
	auto idx = [&](double x, double y) { return std::make_pair((long long)std::floor((x - x0) / cell), (long long)std::floor((y - y0) / cell)); };

	std::vector<Point> sites;
	sites.reserve(n);
	for (std::size_t attempt = 0; sites.size() < n; ++attempt) {
		if (attempt >= maxAttempts) {
			std::ostringstream o;
			o << "could place only " << sites.size() << " of " << n << " sites at least " << minDistance << " apart in " << maxAttempts
			  << " attempts: lower min_distance or the number of sites";
			throw std::runtime_error(o.str());
		}
		const Point p{x0 + wx * uniform(), y0 + wy * uniform()};
		if (poly.bounded_side(Ki::Point_2(p[0], p[1])) != CGAL::ON_BOUNDED_SIDE) continue;
		if (minDistance > 0) {
			const auto ij = idx(p[0], p[1]);
			bool near = false;
			for (long long di = -1; di <= 1 && !near; ++di)
				for (long long dj = -1; dj <= 1 && !near; ++dj) {
					auto it = grid.find(key(ij.first + di, ij.second + dj));
					if (it == grid.end()) continue;
					for (std::size_t s : it->second)
						if (std::hypot(sites[s][0] - p[0], sites[s][1] - p[1]) < minDistance) {
							near = true;
							break;
						}
				}
			if (near) continue;
			grid[key(ij.first, ij.second)].push_back(sites.size());
		}
		sites.push_back(p);
	}
	return sites;
}

namespace {
	// 1. Delaunay triangulation of the sites and four guard sites far outside (see the header).
	void triangulateWithGuards(DT& dt, const CGAL::Bbox_2& rbb, const std::vector<Point>& sites)
	{
		double xmin = rbb.xmin(), xmax = rbb.xmax(), ymin = rbb.ymin(), ymax = rbb.ymax();
		for (const auto& s : sites) {
			xmin = std::min(xmin, s[0]), xmax = std::max(xmax, s[0]);
			ymin = std::min(ymin, s[1]), ymax = std::max(ymax, s[1]);
		}
		const double D = std::hypot(xmax - xmin, ymax - ymin), cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
		for (int gx = -1; gx <= 1; gx += 2)
			for (int gy = -1; gy <= 1; gy += 2) dt.insert(P2(cx + gx * 4 * D, cy + gy * 4 * D));
		for (std::size_t i = 0; i < sites.size(); ++i) {
			auto v = dt.insert(P2(sites[i][0], sites[i][1]));
			if (v->info().id < 0) v->info().id = int(i); // a repeated site keeps its first index
		}
	}

	// 2.-4. Each real site's Voronoi cell clipped to the region, without straight vertices, in convex
	// pieces (site, exact piece); counts cells and split cells into out.
	std::vector<std::pair<int, std::vector<P2>>> clippedPieces(const DT& dt, const Poly& regionPoly, Tessellation& out)
	{
		const auto                                   rbb = regionPoly.bbox();
		std::vector<std::pair<int, std::vector<P2>>> pieces; // (site, exact convex piece)
		for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
			if (v->info().id < 0) continue; // guard
			std::vector<P2> cellPts;
			auto fc = dt.incident_faces(v), done = fc;
			do {
				if (dt.is_infinite(fc)) throw std::logic_error("voronoiClip: unbounded cell of a real site (guard sites too near)");
				const P2 c = dt.circumcenter(fc);
				if (cellPts.empty() || cellPts.back() != c) cellPts.push_back(c); // cocircular sites: same centre
			} while (++fc != done);
			while (cellPts.size() > 1 && cellPts.front() == cellPts.back()) cellPts.pop_back();
			if (cellPts.size() < 3) throw std::logic_error("voronoiClip: degenerate Voronoi cell");
			const Poly cell(cellPts.begin(), cellPts.end());
			if (!CGAL::do_overlap(cell.bbox(), rbb)) continue;

			// 2. clip to the region
			std::vector<PolyH> clipped;
			CGAL::intersection(cell, regionPoly, std::back_inserter(clipped));
			if (!clipped.empty()) ++out.cells;
			for (const auto& ph : clipped) {
				if (ph.number_of_holes() != 0) throw std::logic_error("voronoiClip: a clipped cell has a hole");
				// 3. straight vertices (collinear vertices of the region's outline) out
				std::vector<P2> v3 = dropStraight({ph.outer_boundary().vertices_begin(), ph.outer_boundary().vertices_end()});
				if (v3.size() < 3) continue;
				Poly p3(v3.begin(), v3.end());
				if (!p3.is_simple()) {
					std::ostringstream o;
					o << "a clipped Voronoi cell is not simple (it touches itself); site " << v->info().id << ": try another seed";
					throw std::runtime_error(o.str());
				}
				if (p3.orientation() != CGAL::COUNTERCLOCKWISE) std::reverse(v3.begin(), v3.end());
				// 4. convex pieces
				bool split = false;
				for (auto& c : convexPieces(v3, split)) pieces.emplace_back(v->info().id, std::move(c));
				if (split) ++out.split;
			}
		}
		return pieces;
	}

	// 5. one rounding per exact point; then the check Polygon2D makes: blocks (or dropped) into out.
	void roundPieces(const std::vector<std::pair<int, std::vector<P2>>>& pieces, double minArea, Tessellation& out)
	{
		exact::Rounder rounded;
		for (const auto& pc : pieces) {
			Polygon poly = rounded.polygon(pc.second);
			std::vector<Vec2> ev;
			for (const auto& p : poly) ev.emplace_back(p[0], p[1]);
			const double area = CGAL::to_double(Poly(pc.second.begin(), pc.second.end()).area().exact());
			const std::string problem = polygonProblem(ev);
			if (area < minArea) {
				++out.dropped;
				out.droppedArea += area;
				continue;
			}
			if (!problem.empty()) {
				std::ostringstream o;
				o << "a block of the tessellation is degenerate after rounding to double (" << problem << "), area " << area << " > min_area "
				  << minArea << ": " << where(poly) << "; raise min_area or try another seed";
				throw std::runtime_error(o.str());
			}
			out.blocks.push_back(std::move(poly));
			out.site.push_back(pc.first);
		}
	}
} // namespace

Tessellation voronoiClip(const Polygon& region_, const std::vector<Point>& sites, double minArea)
{
	const Polygon region = counterClockwise(region_);
	if (sites.empty()) throw std::invalid_argument("no site given");
	for (std::size_t i = 0; i < sites.size(); ++i)
		if (!finite(sites[i])) {
			std::ostringstream o;
			o << "site " << i << " has a non-finite (NaN or inf) coordinate";
			throw std::invalid_argument(o.str());
		}
	if (!(std::isfinite(minArea) && minArea >= 0)) throw std::invalid_argument("min_area must be a finite number >= 0");

	const Poly regionPoly = toExact(region);
	DT         dt;
	triangulateWithGuards(dt, regionPoly.bbox(), sites);
	Tessellation out;
	roundPieces(clippedPieces(dt, regionPoly, out), minArea, out);
	return out;
}

double unionArea(const std::vector<Polygon>& polys)
{
	CGAL::Polygon_set_2<K> set;
	for (const auto& v : polys) {
		if (!regionProblem(v).empty()) throw std::invalid_argument("unionArea: " + regionProblem(v));
		Poly p = toExact(v);
		if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
		set.join(p);
	}
	std::vector<PolyH> res;
	set.polygons_with_holes(std::back_inserter(res));
	K::FT a = 0;
	for (const auto& ph : res) {
		a += ph.outer_boundary().area();
		for (auto h = ph.holes_begin(); h != ph.holes_end(); ++h) a += h->area(); // holes are clockwise
	}
	return CGAL::to_double(a.exact());
}

} // namespace tess
} // namespace rbsm
