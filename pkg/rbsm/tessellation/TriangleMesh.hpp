// A region (a slope) meshed into triangles with CGAL's Delaunay refinement (Mesh_2): the blocks for
// plastic deformable soil, on which constant-strain blocks do not lock in plastic flow as polygons
// of six edges do (docs/manual/guide/deformable.md). YADE-free, as VoronoiClip.
#pragma once

#include <pkg/rbsm/tessellation/VoronoiClip.hpp>

namespace rbsm {
namespace tess {

	/// Triangles (counter-clockwise) tiling `region` (either orientation, see regionProblem): a constrained
	/// Delaunay triangulation of its outline refined until no edge is longer than maxEdge and no angle smaller
	/// than about 20.7° (Ruppert's bound, CGAL's default shape criterion). Vertices are shared bit for bit by
	/// neighbouring triangles. std::invalid_argument for a bad region or a maxEdge that is not > 0.
	std::vector<Polygon> triangleMesh(const Polygon& region, double maxEdge);

} // namespace tess
} // namespace rbsm
