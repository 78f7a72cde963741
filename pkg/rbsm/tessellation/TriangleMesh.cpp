#include <pkg/rbsm/tessellation/TriangleMesh.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rbsm {
namespace tess {

namespace {
	// Exact predicates decide the triangulation; the points Ruppert's refinement inserts are computed in
	// double, which is all a block's vertex is.
	using K        = CGAL::Exact_predicates_inexact_constructions_kernel;
	using Vb       = CGAL::Delaunay_mesh_vertex_base_2<K>;
	using Fb       = CGAL::Delaunay_mesh_face_base_2<K>;
	using Tds      = CGAL::Triangulation_data_structure_2<Vb, Fb>;
	using Cdt      = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
	using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
}

std::vector<Polygon> triangleMesh(const Polygon& region, double maxEdge)
{
	if (!(std::isfinite(maxEdge) && maxEdge > 0)) throw std::invalid_argument("triangleMesh: the largest edge must be a length > 0 (got " + std::to_string(maxEdge) + ")");
	const Polygon ccw = counterClockwise(region); // (throws naming the region's problem)
	Cdt           cdt;
	for (std::size_t i = 0; i < ccw.size(); ++i) {
		const Point& a = ccw[i];
		const Point& b = ccw[(i + 1) % ccw.size()];
		cdt.insert_constraint(K::Point_2(a[0], a[1]), K::Point_2(b[0], b[1]));
	}
	// 0.125: the least sin² of a triangle's smallest angle (20.7°), the bound up to which Ruppert's refinement terminates
	CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, maxEdge));
	std::vector<Polygon> out;
	for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
		if (!f->is_in_domain()) continue; // outside the outline (the mesher marks the faces it refined)
		Polygon t;
		for (int k = 0; k < 3; ++k) t.push_back({ f->vertex(k)->point().x(), f->vertex(k)->point().y() });
		out.push_back(t); // (CGAL's faces are counter-clockwise)
	}
	return out;
}

} // namespace tess
} // namespace rbsm
