// A rigid placement in the plane (Box2D's b2Transform): a rotation (cos, sin) followed by a
// translation p. One vocabulary for every pose of the kernel and the plugin: a block in the world
// (Bo1, Ig2), block 2 in block 1's frame (the contact's relative pose, Ig2, SearchMemory,
// FrozenContact), a placed polygon (PosedPolygon).
//
// Round-off. Each method is one fixed sequence of floating-point operations, so that results (and
// the trajectories the tests pin bit for bit) do not depend on which caller computes a pose:
//   rotate(v)   = (c vx − s vy,  s vx + c vy)
//   unrotate(v) = (c vx + s vy, −s vx + c vy)
//   apply(x)    = p + rotate(x)                       Box2D's order: rotate, then translate
//   place(x)    = (px + c xx − s xy, py + s xx + c xy) summed left to right: the order in which the
//                 contact search places the other block's vertices and the frozen kinematics its
//                 material points (PosedPolygon, FrozenContact)
// The two point maps agree up to one rounding; each caller keeps the one it was written with.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

namespace rbsm {

struct Pose2 {
	Vec2 p = Vec2::Zero(); ///< translation (m): the frame's origin in the outer frame
	Real c = 1, s = 0;     ///< cos and sin of the rotation angle

	Pose2() = default;
	Pose2(const Vec2& p_, Real c_, Real s_) : p(p_), c(c_), s(s_) { }

	/// R v (a direction).
	Vec2 rotate(const Vec2& v) const { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); }
	/// Rᵀ v (a direction back to this frame).
	Vec2 unrotate(const Vec2& v) const { return Vec2(c * v.x() + s * v.y(), -s * v.x() + c * v.y()); }
	/// p + R x (a point), rotated first and then translated.
	Vec2 apply(const Vec2& x) const { return p + rotate(x); }
	/// p + R x (a point), each coordinate summed left to right (see the file comment).
	Vec2 place(const Vec2& x) const { return Vec2(p.x() + c * x.x() - s * x.y(), p.y() + s * x.x() + c * x.y()); }
	/// Rᵀ (x − p): a point of the outer frame in this one (the inverse of apply and place).
	Vec2 applyInverse(const Vec2& x) const { return unrotate(x - p); }
	/// The inverse placement: inverse().apply(apply(x)) = x (to round-off).
	Pose2 inverse() const { return Pose2(-unrotate(p), c, -s); }
	/// This placement after b: compose(b).apply(x) = apply(b.apply(x)) (to round-off).
	Pose2 compose(const Pose2& b) const { return Pose2(apply(b.p), c * b.c - s * b.s, s * b.c + c * b.s); }
	/// b as seen from this frame (inverse().compose(b), computed directly): b's origin in this frame
	/// and the rotation θb − θ. The relative pose of two blocks: relative(b).place(x) is b's local
	/// point x in this block's frame.
	Pose2 relative(const Pose2& b) const { return Pose2(unrotate(b.p - p), c * b.c + s * b.s, c * b.s - s * b.c); }
};

} // namespace rbsm
