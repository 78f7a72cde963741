// A region (a simple polygon, convex or not) cut into convex blocks by joint traces, with CGAL.
//
// YADE-free, like VoronoiClip (Python binding: python_module.cpp; Python API:
// py/yade_rbsm/joint_sets.py). Every step is exact (Epeck, rational arithmetic):
//  1. The outline's edges and the traces (segments, which may reach outside the region) go into an
//     arrangement (Arrangement_2): every crossing is an exact vertex, so no sliver comes from
//     round-off, and a trace through a vertex of the outline or of another trace meets it there.
//  2. A trace that does not cut a block apart (a dangling end, a trace that ends inside rock) is
//     removed edge by edge, as UDEC does: only a joint that separates two blocks is a joint; the
//     length removed is not reported here (the Python side measures what is kept); so does an edge
//     with the same face on both sides (a bridge). A network of traces that reaches neither the
//     outline nor the traces that do (an island) is joined to the rest by two horizontal welds from
//     its leftmost and rightmost vertices (its joints are the rock mass's); outside the region it goes.
//  3. The faces inside the region are found from the outline's edges (the region is on their left,
//     counter-clockwise) and across the traces' edges only.
//  3b. Slivers (faces below min_area, or thinner than min_width: mean width 2 A / P) are merged into a
//     neighbour: across the sliver's longest inner
//     edge whose removal leaves a convex face (a sliver between two joints at a small angle goes
//     with the block on the other side of its longest joint); the joint piece removed is reported
//     by the Python side. A sliver that no neighbour takes convexly stays, reported.
//  4. A non-convex face (the outline's reflex corners) is cut into convex blocks by diagonals between
//     its vertices (ExactPieces::convexPieces); the diagonals are returned as welds: they are
//     no joints of the rock mass, the Python side bonds them with the rock's strength.
//  5. One rounding to double per exact point: neighbouring blocks share their vertices bit for bit.
#pragma once

#include <pkg/rbsm/tessellation/VoronoiClip.hpp>

#include <array>
#include <vector>

namespace rbsm {
namespace tess {

	using Segment = std::array<Point, 2>;

	struct TraceCut {
		std::vector<Polygon> blocks; ///< convex, counter-clockwise, no straight or repeated vertex
		std::vector<Segment> welds;  ///< the diagonals of step 4 and the islands' welds, rounded (block edges)
		std::size_t          faces = 0; ///< faces inside the region (before step 4)
		std::size_t          split = 0; ///< non-convex faces cut into convex blocks
		std::size_t          merged = 0; ///< slivers (area < minArea or mean width < minWidth) merged into a neighbour
		double               mergedArea = 0;
		std::vector<Point>   mergedAt;   ///< their vertex averages
		std::vector<Point>   kept;       ///< slivers that no neighbour takes (no convex union): still blocks
		double               keptArea = 0;
	};

	/// The region (either orientation, see regionProblem) cut along the traces (segments; parts
	/// outside the region are ignored); faces below minArea or thinner than minWidth (mean width 2 A / P) merged as step 3b says. std::invalid_argument for a bad region or a degenerate or
	/// non-finite trace; std::runtime_error if a block is degenerate after rounding or a face holds an
	/// island of traces, naming it.
	TraceCut cutByTraces(const Polygon& region, const std::vector<Segment>& traces, double minArea = 0, double minWidth = 0);

} // namespace tess
} // namespace rbsm
