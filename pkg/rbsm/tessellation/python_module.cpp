// Python binding of VoronoiClip (boost::python): the top-level module yade_rbsm_tessellation,
// used by py/yade_rbsm/voronoi.py (the documented Python API). Polygons are lists of (x, y).
// std::invalid_argument becomes ValueError, other std::exception RuntimeError (boost::python).
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/tessellation/TraceCut.hpp>
#include <pkg/rbsm/tessellation/TriangleMesh.hpp>
#include <pkg/rbsm/tessellation/VoronoiClip.hpp>

#include <boost/python.hpp>

namespace py = boost::python;
using namespace rbsm::tess;

namespace {

Point toPoint(const py::object& o)
{
	if (py::len(o) != 2) throw std::invalid_argument("a point must be a pair (x, y)");
	return {py::extract<double>(o[0])(), py::extract<double>(o[1])()};
}

Polygon toPolygon(const py::object& seq)
{
	Polygon p;
	const long n = py::len(seq);
	for (long i = 0; i < n; ++i) p.push_back(toPoint(seq[i]));
	return p;
}

py::list fromPolygon(const Polygon& p)
{
	py::list l;
	for (const auto& q : p) l.append(py::make_tuple(q[0], q[1]));
	return l;
}

py::str regionProblemPy(const py::object& region) { return py::str(regionProblem(toPolygon(region))); }

double signedAreaPy(const py::object& poly) { return signedArea(toPolygon(poly)); }

py::list randomSitesPy(const py::object& region, long n, unsigned long long seed, double minDistance, long maxAttempts)
{
	if (n <= 0) throw std::invalid_argument("the number of sites must be > 0");
	if (maxAttempts < 0) throw std::invalid_argument("max_attempts must be >= 0");
	return fromPolygon(randomSites(toPolygon(region), std::size_t(n), seed, minDistance, std::size_t(maxAttempts)));
}

py::dict voronoiClipPy(const py::object& region, const py::object& sites, double minArea)
{
	const Tessellation t = voronoiClip(toPolygon(region), toPolygon(sites), minArea);
	py::list blocks, site;
	for (std::size_t i = 0; i < t.blocks.size(); ++i) {
		blocks.append(fromPolygon(t.blocks[i]));
		site.append(t.site[i]);
	}
	py::dict d;
	d["blocks"]       = blocks;
	d["site"]         = site;
	d["cells"]        = t.cells;
	d["split"]        = t.split;
	d["dropped"]      = t.dropped;
	d["dropped_area"] = t.droppedArea;
	return d;
}

py::list triangleMeshPy(const py::object& region, double maxEdge)
{
	py::list l;
	for (const auto& t : triangleMesh(toPolygon(region), maxEdge)) l.append(fromPolygon(t));
	return l;
}

double unionAreaPy(const py::object& polys)
{
	std::vector<Polygon> v;
	const long n = py::len(polys);
	for (long i = 0; i < n; ++i) v.push_back(toPolygon(polys[i]));
	return unionArea(v);
}

py::str polygonProblemPy(const py::object& poly)
{
	std::vector<rbsm::Vec2> v;
	for (const auto& p : toPolygon(poly)) v.emplace_back(p[0], p[1]);
	return py::str(rbsm::polygonProblem(v));
}

py::dict cutByTracesPy(const py::object& region, const py::object& traces, double minArea, double minWidth)
{
	std::vector<Segment> segs;
	const long n = py::len(traces);
	for (long i = 0; i < n; ++i) {
		const Polygon s = toPolygon(traces[i]);
		if (s.size() != 2) throw std::invalid_argument("a trace must be a pair of points ((x0, y0), (x1, y1))");
		segs.push_back({s[0], s[1]});
	}
	const TraceCut t = cutByTraces(toPolygon(region), segs, minArea, minWidth);
	py::list blocks, welds;
	for (const auto& b : t.blocks) blocks.append(fromPolygon(b));
	for (const auto& w : t.welds) welds.append(fromPolygon({w[0], w[1]}));
	py::dict d;
	d["blocks"] = blocks;
	d["welds"]  = welds;
	d["faces"]  = t.faces;
	d["split"]  = t.split;
	d["merged"] = fromPolygon(t.mergedAt);
	d["merged_area"] = t.mergedArea;
	d["kept_slivers"] = fromPolygon(t.kept);
	d["kept_area"] = t.keptArea;
	return d;
}

} // namespace

BOOST_PYTHON_MODULE(yade_rbsm_tessellation)
{
	py::scope().attr("__doc__") = "CGAL Voronoi tessellation of a region into convex blocks (yade-rbsm); use yade_rbsm.voronoi.";
	py::def("region_problem", regionProblemPy, py::arg("region"),
	        "'' if the polygon can be tessellated, else the problem (too few vertices, NaN, repeated vertex, not simple, zero area).");
	py::def("signed_area", signedAreaPy, py::arg("polygon"), "Signed area (exact, then rounded): > 0 counter-clockwise.");
	py::def("random_sites", randomSitesPy, (py::arg("region"), py::arg("n"), py::arg("seed"), py::arg("min_distance") = 0.0, py::arg("max_attempts") = 0),
	        "n sites uniform inside region from std::mt19937_64(seed); dart throwing with min_distance > 0.");
	py::def("voronoi_clip", voronoiClipPy, (py::arg("region"), py::arg("sites"), py::arg("min_area") = 0.0),
	        "Voronoi cells of sites clipped to region, cut into convex CCW blocks: dict(blocks, site, cells, split, dropped, dropped_area).");
	py::def("cut_by_traces", cutByTracesPy, (py::arg("region"), py::arg("traces"), py::arg("min_area") = 0.0, py::arg("min_width") = 0.0),
	        "region cut along the traces (segments) into convex CCW blocks, exactly; traces that do not separate blocks are "
	        "removed (UDEC's rule); faces below min_area or thinner than min_width (2 A / P) merged into a neighbour (convex union): dict(blocks, welds (diagonals cutting non-convex faces), faces, split, merged (sliver places), merged_area, kept_slivers, kept_area).");
	py::def("triangle_mesh", triangleMeshPy, (py::arg("region"), py::arg("max_edge")),
	        "Triangles (CCW) tiling region: CGAL's constrained Delaunay refinement, no edge longer than max_edge, no angle below about 20.7 deg.");
	py::def("union_area", unionAreaPy, py::arg("polygons"), "Area of the union of simple polygons (exact, then rounded).");
	py::def("polygon_problem", polygonProblemPy, py::arg("polygon"),
	        "'' if Polygon2D accepts the vertices (convex, CCW, no repeated or collinear vertex), else the problem.");
}
