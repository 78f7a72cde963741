// The relative motion of two rigid blocks along their contact segment, as the joint law samples it
// at its integration points (seed paper eq. (8)-(9) at the points x(s) = p0 + s (p1 - p0)).
//
// Both blocks are rigid and both boundaries straight, so every quantity is linear in s:
//   overlap      δn(s) = (1 - s) d0 + s d1                         [m], > 0 penetration
//   velocity     v(s)  = v0 + s (ω2 - ω1) ẑ × (p1 - p0)            [m/s], of block 2's material
//                        point at x(s) relative to block 1's, v0 at p0
// The geometry functor therefore hands the law the two end overlaps and the relative rigid motion
// (6 numbers), not per-point arrays; the law samples them where its rule puts the points.
// Signs (YADE's): n from body 1 to body 2, t = (-n.y, n.x); a closing velocity is positive, like
// the overlap; the tangential displacement of a step is the tangential velocity times dt.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

namespace rbsm {

struct SegmentKinematics {
	Real d0 = 0, d1 = 0;    ///< overlap at p0 and at p1 (m)
	Vec2 v0   = Vec2::Zero(); ///< velocity of block 2 relative to block 1 at p0 (m/s)
	Vec2 dvds = Vec2::Zero(); ///< (ω2 - ω1) ẑ × (p1 - p0): change of that velocity from p0 to p1 (m/s)

	Real overlap(Real s) const { return (1 - s) * d0 + s * d1; }
	Vec2 velocity(Real s) const { return v0 + s * dvds; }
};

/// From the segment p0 → p1, its end overlaps and the two blocks' rigid motions (centroid c,
/// velocity v, angular velocity ω about z); a material point x of block i moves with
/// v_i + ω_i ẑ × (x - c_i).
inline SegmentKinematics segmentKinematics(
        Real d0, Real d1, const Vec2& p0, const Vec2& p1, const Vec2& c1, const Vec2& v1, Real omega1, const Vec2& c2, const Vec2& v2, Real omega2)
{
	auto       perp = [](const Vec2& r) { return Vec2(-r.y(), r.x()); }; // ẑ × r
	const Vec2 seg  = p1 - p0;
	return SegmentKinematics { d0, d1, (v2 + omega2 * perp(p0 - c2)) - (v1 + omega1 * perp(p0 - c1)), (omega2 - omega1) * perp(seg) };
}

} // namespace rbsm
