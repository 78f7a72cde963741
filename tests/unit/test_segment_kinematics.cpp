// SegmentKinematics: the linear field the law samples equals, at every point of the segment, the
// closed-form relative motion of two rigid blocks (velocity v_i + ω_i ẑ × (x - c_i)), and the
// overlap interpolates the two end overlaps.
#include <pkg/rbsm/kernel/SegmentKinematics.hpp>

#include <gtest/gtest.h>

using namespace rbsm;

TEST(SegmentKinematics, VelocityIsTheRigidRelativeVelocityEverywhere)
{
	const Vec2 p0(0.3, -0.2), p1(1.7, 0.5), c1(-0.4, -1.1), c2(0.9, 1.3), v1(0.2, -0.7), v2(-1.1, 0.4);
	const Real w1 = 0.8, w2 = -2.3;
	const SegmentKinematics k = segmentKinematics(0.01, -0.02, p0, p1, c1, v1, w1, c2, v2, w2);
	auto rigid = [](const Vec2& v, Real w, const Vec2& c, const Vec2& x) { return Vec2(v.x() - w * (x.y() - c.y()), v.y() + w * (x.x() - c.x())); };
	for (Real s : { 0.0, 0.2113, 0.5, 0.7887, 1.0 }) {
		const Vec2 x     = p0 + s * (p1 - p0);
		const Vec2 exact = rigid(v2, w2, c2, x) - rigid(v1, w1, c1, x);
		EXPECT_NEAR((k.velocity(s) - exact).norm(), 0, 1e-14) << "s=" << s;
	}
	EXPECT_DOUBLE_EQ(k.overlap(0), 0.01);
	EXPECT_DOUBLE_EQ(k.overlap(1), -0.02);
	EXPECT_NEAR(k.overlap(0.25), 0.75 * 0.01 + 0.25 * -0.02, 1e-17);
}

// A common rigid motion of both blocks (same v, same ω, one rigid body) is no relative motion.
TEST(SegmentKinematics, CommonRigidMotionIsNoRelativeMotion)
{
	const Vec2 p0(1, 2), p1(3, 2.5), c1(0, 0), c2(4, 1), v(0.3, -0.9);
	const Real w = 1.7;
	// block 2's centroid velocity in the common motion: v + ω ẑ × (c2 - c1)
	const Vec2 v2 = v + w * Vec2(-(c2 - c1).y(), (c2 - c1).x());
	const SegmentKinematics k = segmentKinematics(0, 0, p0, p1, c1, v, w, c2, v2, w);
	EXPECT_NEAR(k.v0.norm(), 0, 1e-14);
	EXPECT_NEAR(k.dvds.norm(), 0, 1e-14);
}
