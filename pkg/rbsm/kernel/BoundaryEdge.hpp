// Rigid boundaries of the plane (a YADE Wall, a Facet crossing the x-y plane) as polygons, so that a
// block meets them with the same edge-to-edge contact as another block (EdgeContact.hpp).
//
// A boundary's trace in the plane is a line (Wall) or a segment (Facet). It becomes the top edge
// a→b of a rectangle lying behind it, on the side away from the block:
//        block side (normal m)
//    a ─────────────── b        top edge, on the trace
//    │                 │        depth D behind it
//    a − D m ───── b − D m
// For a Wall the edge is centred on the foot of the block's centroid and reaches farther than the
// block on both sides, so that only the edge, never the rectangle's corners, can touch it: the
// contact is that of a half-plane. For a Facet a, b are the ends of its trace: a block beyond an end
// meets the facet's end as it would meet a thin plate.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace rbsm {

/// The rectangle a, b, b − D m, a − D m, counter-clockwise whatever the order of a and b (m: the unit
/// normal of the edge towards the block).
inline std::vector<Vec2> boundaryRectangle(const Vec2& a, const Vec2& b, const Vec2& m, Real depth)
{
	const bool ccw = cross2(b - a, -m) < 0; // going down from p (−m), q must lie to the left
	const Vec2 p = ccw ? a : b, q = ccw ? b : a;
	return { p, p - depth * m, q - depth * m, q };
}

/// A wall through point w with unit normal m towards the block, as seen by a block of centroid c and
/// circumradius R: the rectangle whose top edge runs from f − 2R t to f + 2R t (f the foot of c on the
/// line, t ⟂ m), depth 2R. Every point of the block within 2R of the line faces the edge's interior.
inline std::vector<Vec2> wallRectangle(const Vec2& w, const Vec2& m, const Vec2& c, Real R)
{
	const Vec2 t(-m.y(), m.x());
	const Vec2 f = c - m.dot(c - w) * m;
	return boundaryRectangle(f - 2 * R * t, f + 2 * R * t, m, 2 * R);
}

/// Where the triangle v0 v1 v2 crosses the plane z = z0: true and the ends a, b of the segment if it
/// does in more than a point (edges lying in the plane count; a triangle lying in the plane does not).
inline bool planeTrace(const Eigen::Vector3d v[3], Real z0, Vec2& a, Vec2& b)
{
	if (v[0].z() == z0 && v[1].z() == z0 && v[2].z() == z0) return false; // lying in the plane
	std::vector<Vec2> pts;
	for (int i = 0; i < 3; i++) {
		const Eigen::Vector3d &p = v[i], &q = v[(i + 1) % 3];
		const Real             dp = p.z() - z0, dq = q.z() - z0;
		if (dp == 0) pts.push_back(p.head<2>());
		if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
			const Real s = dp / (dp - dq);
			pts.push_back(p.head<2>() + s * (q.head<2>() - p.head<2>()));
		}
	}
	if (pts.size() < 2) return false; // apart, or touching at a vertex
	// the two points farthest apart (a vertex in the plane may repeat a crossing point)
	Real best = -1;
	for (size_t i = 0; i < pts.size(); i++)
		for (size_t j = i + 1; j < pts.size(); j++)
			if ((pts[i] - pts[j]).squaredNorm() > best) best = (pts[i] - pts[j]).squaredNorm(), a = pts[i], b = pts[j];
	return best > 0;
}

} // namespace rbsm
