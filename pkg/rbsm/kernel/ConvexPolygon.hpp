// Convex polygon checks, mass properties and the local->world transform of RBSM blocks.
//
// Conventions: a block is a convex polygon whose vertices are listed counter-clockwise
// (positive signed area). Lengths in m, angles in rad (counter-clockwise positive).
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

#include <string>
#include <vector>

namespace rbsm {

/// Returns "" if v is a valid convex counter-clockwise polygon, otherwise a message naming the
/// first problem found (checked in this order): fewer than 3 vertices, non-finite coordinate,
/// repeated vertex, collinear consecutive vertices, self-intersection, clockwise orientation,
/// non-convexity. Vertex indices in the messages are 0-based.
///
/// Tolerances are relative to the polygon size L (largest bounding-box side), so that the
/// answer does not depend on the unit of length: two vertices are "repeated" if closer than
/// 1e-9 L; three consecutive vertices are "collinear" if the sine of the turn angle is below 1e-9.
std::string polygonProblem(const std::vector<Vec2>& v);

/// Outward unit normals of the edges of a counter-clockwise polygon: entry i is the normal of the
/// edge from v[i] to v[i+1], the edge vector rotated by -90 deg and normalised.
std::vector<Vec2> edgeNormals(const std::vector<Vec2>& v);

/// Size of a polygon: the largest side of its axis-aligned bounding box (m). 0 for empty input.
Real polygonSize(const std::vector<Vec2>& v);

/// Distance from the centroid (the origin) to the nearest edge line of a convex CCW polygon given
/// about its centroid [m]: the least distance from the centroid to any supporting line, hence the
/// least Kawai h a joint of this block can have, and half the thickness of a thin block.
Real centroidInradius(const std::vector<Vec2>& vertices);

/// Half the width of a polygon along the unit direction n: (max v·n − min v·n) / 2 [m]. Two blocks overlapping
/// by more than the thinner one's half-width along their contact normal have passed its middle.
Real halfWidthAlong(const std::vector<Vec2>& vertices, const Vec2& n);

/// Geometric mass properties of a uniform polygon of unit density and unit thickness.
struct MassProperties {
	Real area;        ///< m^2 (positive for a counter-clockwise polygon)
	Vec2 centroid;    ///< m, in the coordinates of the input vertices
	Real polarMoment; ///< J = integral of (x^2 + y^2) dA about the centroid, m^4.
	                  ///< Multiply by density*thickness to get the polar inertia in kg m^2.
};

/// Area, centroid and polar second moment by the triangle-fan (shoelace) formulas. With
/// c_i = cross(p_i, p_{i+1}) and indices taken cyclically (p relative to a reference point o):
///   A   = 1/2  sum c_i
///   C   = o + 1/(6A) sum c_i (p_i + p_{i+1})
///   J_o = 1/12 sum c_i (p_i.p_i + p_i.p_{i+1} + p_{i+1}.p_{i+1})   (Ixx + Iyy about o)
///   J   = J_o - A |C - o|^2                                         (parallel-axis theorem)
/// The reference o is the vertex mean, which keeps round-off small far from the origin.
/// Requires a valid polygon (see polygonProblem); for a clockwise polygon A and J are negative.
MassProperties massProperties(const std::vector<Vec2>& v);

/// Rotates a vector by angle (rad, counter-clockwise): R(angle) * x.
Vec2 rotate(const Vec2& x, Real angle);

/// World position of a point given in block-local coordinates: pos + R(angle) * local.
Vec2 localToWorld(const Vec2& local, const Vec2& pos, Real angle);

/// Block-local coordinates of a world point: R(-angle) * (world - pos).
Vec2 worldToLocal(const Vec2& world, const Vec2& pos, Real angle);

/// All vertices of a block to world coordinates (a rigid motion keeps them convex and CCW).
std::vector<Vec2> toWorld(const std::vector<Vec2>& local, const Vec2& pos, Real angle);

} // namespace rbsm
