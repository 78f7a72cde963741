#include <pkg/rbsm/tessellation/TraceCut.hpp>

#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/tessellation/ExactPieces.hpp>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/intersections.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rbsm {
namespace tess {

namespace {
	using exact::K;
	using exact::P2;
	using Traits = CGAL::Arr_segment_traits_2<K>;
	using Arr    = CGAL::Arrangement_2<Traits>;
	using S2     = K::Segment_2;

	bool finite(const Point& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

	// Step 2: edges with an end of degree 1 removed until none is left (a dangling trace end).
	void pruneDangling(Arr& arr)
	{
		bool removed = true;
		while (removed) {
			removed = false;
			for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e)
				if (e->source()->degree() == 1 || e->target()->degree() == 1) {
					arr.remove_edge(e);
					removed = true;
					break;
				}
		}
	}

	// The halfedge runs along an edge of the counter-clockwise outline, in its direction: the
	// region is on its left. Sets onOutline when it lies on the outline in either direction.
	bool alongOutline(const Arr::Halfedge_const_handle& h, const std::vector<P2>& outline, bool& onOutline)
	{
		const P2 &a = h->source()->point(), &b = h->target()->point();
		const std::size_t n = outline.size();
		for (std::size_t i = 0; i < n; ++i) {
			const S2 s(outline[i], outline[(i + 1) % n]);
			if (s.has_on(a) && s.has_on(b)) {
				onOutline = true;
				return CGAL::compare_distance_to_point(s.source(), a, b) == CGAL::SMALLER;
			}
		}
		onOutline = false;
		return false;
	}

	// Step 2b: a network of traces that touches neither the outline nor the traces that reach it (an
	// island in a face) goes, as a dangling trace does: a block inside a block is no block of the model.
	// (Joining it to the rest by welds is the better answer, not done yet; the lengths kept report it.)
	// The edges of the connected component of vertex v; touches is set if one lies on the outline.
	std::set<Arr::Halfedge_handle> component(Arr::Vertex_handle v0, const std::vector<P2>& outline, bool& touches)
	{
		std::set<Arr::Vertex_handle>    seen{v0};
		std::vector<Arr::Vertex_handle> todo{v0};
		std::set<Arr::Halfedge_handle>  edges;
		touches = false;
		while (!todo.empty()) {
			const auto v = todo.back();
			todo.pop_back();
			auto c = v->incident_halfedges(), h = c;
			do {
				bool on = false;
				alongOutline(h, outline, on);
				touches = touches || on;
				if (!edges.count(h->twin())) edges.insert(h);
				if (seen.insert(h->source()).second) todo.push_back(h->source());
			} while (++h != c);
		}
		return edges;
	}

	// An edge with the same face on both sides (a bridge between two networks of traces) separates
	// no blocks: it goes, as a dangling trace does. Returns whether one went.
	bool removeBridges(Arr& arr)
	{
		std::vector<Arr::Halfedge_handle> bridges;
		for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e)
			if (e->face() == e->twin()->face()) bridges.push_back(e);
		for (auto h : bridges) arr.remove_edge(h);
		return !bridges.empty();
	}

	// Step 3: the faces on the left of the outline, then those reached across trace edges only, in
	// discovery order (not the handles' addresses: the same blocks in the same order on every run).
	std::vector<Arr::Face_handle> insideFaces(Arr& arr, const std::vector<P2>& outline)
	{
		std::set<Arr::Face_handle>    seen;
		std::vector<Arr::Face_handle> inside;
		auto visit = [&](Arr::Face_handle f) {
			if (seen.insert(f).second) inside.push_back(f);
		};
		for (auto h = arr.halfedges_begin(); h != arr.halfedges_end(); ++h) {
			bool on = false;
			if (alongOutline(h, outline, on)) visit(h->face());
		}
		for (std::size_t next = 0; next < inside.size(); ++next) {
			const auto f = inside[next];
			if (f->is_unbounded()) throw std::logic_error("cutByTraces: the region's inside reaches the unbounded face");
			auto c = f->outer_ccb(), h = c;
			do {
				bool on = false;
				alongOutline(h, outline, on);
				if (!on) visit(h->twin()->face());
			} while (++h != c);
		}
		return inside;
	}

	// The nearest point where the horizontal ray from v towards dir (-1 or +1) meets an edge of arr
	// that is not in skip (exact): the end of a weld from v.
	P2 rayHit(Arr& arr, const P2& v, int dir, const std::set<Arr::Halfedge_handle>& skip)
	{
		const K::Ray_2 ray(v, K::Direction_2(dir, 0));
		bool  found = false;
		P2    best;
		K::FT bestDist = 0;
		for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
			if (skip.count(e) || skip.count(e->twin())) continue;
			const S2 seg(e->source()->point(), e->target()->point());
			const auto hit = CGAL::intersection(ray, seg);
			if (!hit) continue;
			P2 p;
			if (const P2* q = boost::get<P2>(&*hit)) p = *q;
			else if (const S2* c = boost::get<S2>(&*hit)) // along the ray: its nearer end
				p = CGAL::compare_distance_to_point(v, c->source(), c->target()) == CGAL::SMALLER ? c->source() : c->target();
			else continue;
			if (p == v) continue;
			const K::FT d = CGAL::abs(p.x() - v.x());
			if (!found || d < bestDist) found = true, best = p, bestDist = d;
		}
		if (!found) throw std::logic_error("cutByTraces: a ray from an island of traces met nothing");
		return best;
	}

	// Step 2b: a network of traces that touches neither the outline nor the traces that reach it (an
	// island) is joined to the rest by two welds, horizontal from its leftmost and rightmost vertices,
	// which cut the face around it in two (an island outside the region goes). Its joints are joints of
	// the rock mass; the welds are no joints (bonded with the rock's strength, as the outline's cuts).
	void joinIslands(Arr& arr, const std::vector<P2>& outline, std::vector<S2>& welds)
	{
		for (bool changed = true; changed;) {
			changed = false;
			const auto inside = insideFaces(arr, outline);
			const std::set<Arr::Face_handle> in(inside.begin(), inside.end());
			for (auto f = arr.faces_begin(); f != arr.faces_end() && !changed; ++f)
				for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end() && !changed; ++hole) {
					bool touches = false;
					auto edges   = component((*hole)->source(), outline, touches);
					if (touches) continue;
					if (!in.count(f)) { // outside the region: it cuts nothing of it
						for (auto h : edges) arr.remove_edge(h);
						changed = true;
						continue;
					}
					P2 lo = (*edges.begin())->source()->point(), hi = lo;
					for (auto h : edges)
						for (const P2& p : {h->source()->point(), h->target()->point()}) {
							if (p < lo) lo = p;
							if (hi < p) hi = p;
						}
					const P2 a = rayHit(arr, lo, -1, edges), b = rayHit(arr, hi, +1, edges);
					welds.emplace_back(lo, a);
					welds.emplace_back(hi, b);
					CGAL::insert(arr, welds[welds.size() - 2]);
					CGAL::insert(arr, welds.back());
					changed = true; // (the handles went stale: look again)
				}
		}
	}

	std::vector<P2> boundary(Arr::Ccb_halfedge_const_circulator c)
	{
		std::vector<P2> v;
		auto h = c;
		do v.push_back(h->source()->point());
		while (++h != c);
		return v;
	}
	K::FT faceArea(Arr::Face_const_handle f)
	{
		const auto v = boundary(f->outer_ccb());
		return CGAL::Polygon_2<K>(v.begin(), v.end()).area();
	}

	bool convexFace(Arr::Face_const_handle f)
	{
		if (f->number_of_inner_ccbs() != 0) return false;
		const auto v = exact::dropStraight(boundary(f->outer_ccb()));
		const CGAL::Polygon_2<K> p(v.begin(), v.end());
		return v.size() >= 3 && p.is_simple() && p.is_convex();
	}

	Point centroid(const std::vector<P2>& v)
	{
		double x = 0, y = 0;
		for (const auto& p : v) x += CGAL::to_double(p.x()), y += CGAL::to_double(p.y());
		return {x / double(v.size()), y / double(v.size())};
	}

	// A face's mean width 2 A / P (a thin strip w x L: about w), the measure of a sliver that is long.
	double meanWidth(Arr::Face_const_handle f, double area)
	{
		const auto v = boundary(f->outer_ccb());
		double     perimeter = 0;
		for (std::size_t i = 0; i < v.size(); ++i) perimeter += std::sqrt(CGAL::to_double(CGAL::squared_distance(v[i], v[(i + 1) % v.size()])));
		return perimeter > 0 ? 2 * area / perimeter : 0;
	}

	// Step 3b: a face below minArea, or thinner than minWidth (mean width), is merged with the neighbour
	// across its longest inner edge whose union is convex (the edge removed; tried edges put back), the
	// worst first (the least of area / minArea and width / minWidth); one that no neighbour takes stays,
	// reported.
	void mergeSlivers(Arr& arr, const std::vector<P2>& outline, double minArea, double minWidth, TraceCut& out)
	{
		std::set<P2> kept; // the least vertex of each sliver that stays
		for (;;) {
			Arr::Face_handle sliver;
			double           worst = 1, least = 0;
			for (const auto& f : insideFaces(arr, outline)) {
				const auto v = boundary(f->outer_ccb());
				if (kept.count(*std::min_element(v.begin(), v.end()))) continue;
				const double a     = CGAL::to_double(faceArea(f));
				const double score = std::min(minArea > 0 ? a / minArea : 1.0, minWidth > 0 ? meanWidth(f, a) / minWidth : 1.0);
				if (score < worst) worst = score, sliver = f, least = a;
			}
			if (sliver == Arr::Face_handle()) return;
			const auto v = boundary(sliver->outer_ccb());
			std::vector<std::pair<K::FT, S2>> inner; // (squared length, edge) of the inner edges
			auto c = sliver->outer_ccb(), h = c;
			do {
				bool on = false;
				alongOutline(h, outline, on);
				if (!on) inner.emplace_back(CGAL::squared_distance(h->source()->point(), h->target()->point()), S2(h->source()->point(), h->target()->point()));
			} while (++h != c);
			std::stable_sort(inner.begin(), inner.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
			bool merged = false;
			for (const auto& e : inner) {
				Arr::Halfedge_handle he;
				for (auto g = arr.halfedges_begin(); g != arr.halfedges_end(); ++g)
					if (g->source()->point() == e.second.source() && g->target()->point() == e.second.target()) he = g;
				if (he == Arr::Halfedge_handle()) continue; // (not an edge as it stands now: a merge split it)
				const Arr::Face_handle f = arr.remove_edge(he, false, false);
				if (convexFace(f)) {
					pruneDangling(arr); // what is left of the removed joint's trace, if it cuts nothing now
					merged = true;
					break;
				}
				CGAL::insert(arr, e.second);
			}
			const Point where = centroid(v);
			if (merged) {
				++out.merged;
				out.mergedArea += least;
				out.mergedAt.push_back(where);
			} else {
				kept.insert(*std::min_element(v.begin(), v.end()));
				out.kept.push_back(where);
				out.keptArea += least;
			}
		}
	}
} // namespace

TraceCut cutByTraces(const Polygon& region_, const std::vector<Segment>& traces, double minArea, double minWidth)
{
	if (!(std::isfinite(minArea) && minArea >= 0)) throw std::invalid_argument("min_area must be a finite number >= 0");
	if (!(std::isfinite(minWidth) && minWidth >= 0)) throw std::invalid_argument("min_width must be a finite number >= 0");
	const Polygon   region = counterClockwise(region_);
	std::vector<P2> outline;
	for (const auto& p : region) outline.emplace_back(p[0], p[1]);
	std::vector<S2> curves;
	for (std::size_t i = 0; i < outline.size(); ++i) curves.emplace_back(outline[i], outline[(i + 1) % outline.size()]);
	for (std::size_t k = 0; k < traces.size(); ++k) {
		const auto& t = traces[k];
		if (!finite(t[0]) || !finite(t[1]) || t[0] == t[1]) {
			std::ostringstream o;
			o << "trace " << k << " is " << (finite(t[0]) && finite(t[1]) ? "a single point" : "not finite (NaN or inf)");
			throw std::invalid_argument(o.str());
		}
		curves.emplace_back(P2(t[0][0], t[0][1]), P2(t[1][0], t[1][1]));
	}
	Arr arr;
	CGAL::insert(arr, curves.begin(), curves.end()); // step 1
	do // step 2: until none is left (a bridge gone may leave a dangling end)
		pruneDangling(arr);
	while (removeBridges(arr));
	std::vector<S2> islandWelds;
	joinIslands(arr, outline, islandWelds); // step 2b

	TraceCut out;
	if (minArea > 0 || minWidth > 0) mergeSlivers(arr, outline, minArea, minWidth, out);
	exact::Rounder rounded;
	for (const auto& w : islandWelds) out.welds.push_back({rounded(w.source()), rounded(w.target())});
	for (const auto& f : insideFaces(arr, outline)) {
		std::vector<P2> face = boundary(f->outer_ccb());
		if (f->number_of_inner_ccbs() != 0) {
			std::ostringstream o;
			o << "traces enclose an island not connected to the outline or to other traces, inside the block "
			  << exact::where(rounded.polygon(face)) << ": join them to the rest or remove them";
			throw std::runtime_error(o.str());
		}
		++out.faces;
		const std::vector<P2> v = exact::dropStraight(face);
		if (v.size() < 3) continue;
		if (!CGAL::Polygon_2<K>(v.begin(), v.end()).is_simple()) { // (the partition would crash on it)
			std::ostringstream o;
			o << "a block is not a simple polygon (it touches itself): " << exact::where(rounded.polygon(v));
			throw std::runtime_error(o.str());
		}
		bool split = false;
		const auto pieces = exact::convexPieces(v, split);
		out.split += split;
		std::set<std::pair<P2, P2>> faceEdges;
		for (std::size_t i = 0; i < v.size(); ++i) faceEdges.emplace(v[i], v[(i + 1) % v.size()]);
		for (const auto& piece : pieces) {
			Polygon poly = rounded.polygon(piece);
			std::string problem;
			for (;;) { // a corner that rounding puts on its neighbours' line, or onto a neighbour, goes (T-junction)
				std::vector<Vec2> ev;
				for (const auto& p : poly) ev.emplace_back(p[0], p[1]);
				problem = polygonProblem(ev);
				// "... collinear ... at vertex N" or "repeated vertex: vertex N equals ..." (rbsm::polygonProblem)
				const bool        collinear = problem.find("collinear") != std::string::npos;
				const std::string key       = collinear ? "at vertex " : "repeated vertex: vertex ";
				const std::size_t k         = problem.find(key);
				if (poly.size() <= 3 || k == std::string::npos || !(collinear || problem.find("repeated") != std::string::npos)) break;
				poly.erase(poly.begin() + std::stoul(problem.substr(k + key.size())));
			}
			if (!problem.empty()) {
				std::ostringstream o;
				o << "a block is degenerate after rounding to double (" << problem << "): " << exact::where(poly);
				throw std::runtime_error(o.str());
			}
			for (std::size_t i = 0; i < piece.size(); ++i) { // a diagonal of step 4: each once (a < b)
				const P2 &a = piece[i], &b = piece[(i + 1) % piece.size()];
				if (!faceEdges.count({a, b}) && a < b) out.welds.push_back({rounded(a), rounded(b)});
			}
			out.blocks.push_back(std::move(poly));
		}
	}
	return out;
}

} // namespace tess
} // namespace rbsm
