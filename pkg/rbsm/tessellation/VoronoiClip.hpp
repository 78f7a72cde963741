// Random Voronoi tessellation of a 2D region (a slope) into convex blocks, with CGAL.
//
// YADE-free: plain std::vector in and out, so that it builds fast and is tested without YADE
// (Python binding: python_module.cpp, module yade_rbsm_tessellation; Python API:
// py/yade_rbsm/voronoi.py).
//
// Pipeline (every step exact, CGAL's Epeck kernel, rational arithmetic):
//  1. Delaunay triangulation of the sites plus four far-away guard sites; the Voronoi cell of a
//     site is the polygon of the circumcentres of its incident triangles (the dual). The guard
//     sites are far enough that every point of the region is nearer a real site than a guard, so
//     the cells of the real sites cover the region exactly as the unbounded Voronoi diagram does.
//  2. Each cell is intersected with the region (Boolean_set_operations_2). A convex cell clipped
//     by a non-convex region can give a non-convex piece, or several pieces.
//  3. Vertices where a piece's boundary goes straight on (a collinear vertex of the region's own
//     outline) are removed: no other piece has a corner there.
//  4. Non-convex pieces are cut into convex ones (Partition_2: optimal convex partition; if it
//     leaves a vertex where the boundary goes straight on, the approximate partitions are tried).
//     The partition uses diagonals between existing vertices only, so no vertex is created.
//  5. Rounding to double once per exact point (the exact rational is rounded, never an interval
//     approximation), so a vertex shared by neighbouring blocks gets identical doubles.
// In exact arithmetic the clipped Voronoi diagram is edge-to-edge (a Voronoi edge is shared by
// exactly the two cells of its sites, and the region's outline cuts both in the same points), so
// blocks on either side of a joint have the same two end vertices, bit for bit.
//
// Output blocks satisfy rbsm::polygonProblem (the check of Polygon2D.vertices): convex,
// counter-clockwise, no repeated or collinear vertices. A piece that rounding makes degenerate
// and whose area is below minArea is dropped ("sliver"); the count and area dropped are reported.
// A degenerate piece larger than minArea is an error (std::runtime_error naming it).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rbsm {
namespace tess {

	using Point   = std::array<double, 2>;
	using Polygon = std::vector<Point>;

	/// "" if `region` is usable as the region to tessellate, otherwise the problem: fewer than
	/// 3 vertices, NaN/inf coordinate, repeated consecutive vertex, not simple (self-intersecting),
	/// zero area. Either orientation is accepted.
	std::string regionProblem(const Polygon& region);

	/// Signed area of a polygon (exact, rounded once to double): > 0 counter-clockwise.
	double signedArea(const Polygon& poly);

	/// `region` counter-clockwise (reversed if it is clockwise). Throws std::invalid_argument if
	/// regionProblem(region) is not empty.
	Polygon counterClockwise(const Polygon& region);

	/// n sites uniformly distributed strictly inside `region`, drawn from std::mt19937_64(seed)
	/// (53-bit uniform doubles from the raw 64-bit outputs, so the same seed gives the same sites
	/// on every platform). With minDistance > 0, candidates closer than minDistance to an
	/// accepted site are rejected (dart throwing); std::runtime_error if n sites do not fit in
	/// maxAttempts candidates.
	std::vector<Point> randomSites(const Polygon& region, std::size_t n, std::uint64_t seed, double minDistance = 0, std::size_t maxAttempts = 0);

	struct Tessellation {
		std::vector<Polygon> blocks;      ///< convex, counter-clockwise, world coordinates
		std::vector<int>     site;        ///< index (in the sites given) of the cell each block comes from
		std::size_t          cells = 0;   ///< Voronoi cells that meet the region (distinct sites)
		std::size_t          split = 0;   ///< non-convex pieces cut into convex blocks
		std::size_t          dropped = 0; ///< slivers dropped (degenerate after rounding, area < minArea)
		double               droppedArea = 0;
	};

	/// Voronoi cells of `sites` clipped to `region` (either orientation, see regionProblem), cut
	/// into convex blocks. Sites outside the region are allowed (their cells may still reach into
	/// it); repeated sites count once. std::invalid_argument for a bad region, no site, a non-finite
	/// site or a negative minArea.
	Tessellation voronoiClip(const Polygon& region, const std::vector<Point>& sites, double minArea = 0);

	/// Area of the union of the polygons (each simple, either orientation), exact then rounded.
	/// Sum of the areas equal to the union's area means the polygons do not overlap.
	double unionArea(const std::vector<Polygon>& polys);

} // namespace tess
} // namespace rbsm
