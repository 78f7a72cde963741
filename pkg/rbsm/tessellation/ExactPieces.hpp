// Exact convex pieces and their one rounding to double, shared by the Voronoi tessellation
// (VoronoiClip) and the joint-trace cutter (TraceCut). Internal to the tessellation module.
//
// A piece is built in CGAL's Epeck kernel (rational arithmetic); it reaches double once per exact
// point (the rational rounded, never an interval approximation), so that a vertex shared by
// neighbouring blocks gets identical doubles.
#pragma once

#include <pkg/rbsm/tessellation/VoronoiClip.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <map>
#include <vector>

namespace rbsm {
namespace tess {
	namespace exact {
		using K  = CGAL::Exact_predicates_exact_constructions_kernel;
		using P2 = K::Point_2;

		/// The polygon's vertices without those where the boundary goes straight on (exact test).
		std::vector<P2> dropStraight(const std::vector<P2>& v);

		/// Convex pieces of a simple counter-clockwise polygon without straight vertices: itself if
		/// convex (split false), else a convex partition by diagonals between existing vertices whose
		/// pieces have no straight vertex (CGAL's optimal partition first, then its approximate ones).
		std::vector<std::vector<P2>> convexPieces(const std::vector<P2>& v, bool& split);

		/// The exact rational rounded to double.
		Point round(const P2& p);

		/// One rounding per exact point: equal exact points give equal doubles.
		class Rounder {
		public:
			const Point& operator()(const P2& p);
			/// The piece in doubles, repeated consecutive points merged.
			Polygon polygon(const std::vector<P2>& piece);

		private:
			std::map<P2, Point> done_; // P2 ordered lexicographically (exact comparison)
		};

		/// "[(x, y), ...]" with all digits, for error messages.
		std::string where(const Polygon& v);
	} // namespace exact
} // namespace tess
} // namespace rbsm
