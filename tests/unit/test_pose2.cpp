// Pose2 (pkg/rbsm/kernel/Pose2.hpp): the rigid placement every pose of the kernel and the plugin uses.
// Checked: apply ∘ applyInverse and inverse() are the identity, compose is applying one pose after
// the other, relative(b) = inverse().compose(b), and the two point maps (apply, place) are the same
// map up to one rounding.
#include <pkg/rbsm/kernel/Pose2.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace rbsm;

namespace {
Pose2 poseOf(Real x, Real y, Real angle) { return Pose2(Vec2(x, y), std::cos(angle), std::sin(angle)); }
constexpr Real kTol = 1e-12;
void expectNear(const Vec2& a, const Vec2& b) { EXPECT_LT((a - b).norm(), kTol) << a.transpose() << " vs " << b.transpose(); }
void expectNear(const Pose2& a, const Pose2& b)
{
	expectNear(a.p, b.p);
	EXPECT_NEAR(a.c, b.c, kTol);
	EXPECT_NEAR(a.s, b.s, kTol);
}
} // namespace

TEST(Pose2, IdentityAndQuarterTurn)
{
	const Pose2 id;
	EXPECT_EQ(id.apply(Vec2(0.3, -2)), Vec2(0.3, -2));
	const Pose2 q = poseOf(1, 2, M_PI / 2);
	expectNear(q.rotate(Vec2(1, 0)), Vec2(0, 1));
	expectNear(q.apply(Vec2(1, 0)), Vec2(1, 3));
	expectNear(q.unrotate(Vec2(0, 1)), Vec2(1, 0));
}

TEST(Pose2, ApplyInverseAndCompose)
{
	std::mt19937                     rng(7);
	std::uniform_real_distribution<> u(-5, 5);
	for (int k = 0; k < 200; ++k) {
		const Pose2 a = poseOf(u(rng), u(rng), u(rng)), b = poseOf(u(rng), u(rng), u(rng));
		const Vec2  x(u(rng), u(rng));
		// apply ∘ applyInverse = identity, both ways; inverse() is the same map
		expectNear(a.applyInverse(a.apply(x)), x);
		expectNear(a.apply(a.applyInverse(x)), x);
		expectNear(a.inverse().apply(x), a.applyInverse(x));
		expectNear(a.compose(a.inverse()), Pose2());
		expectNear(a.unrotate(a.rotate(x)), x);
		// composition: a after b
		expectNear(a.compose(b).apply(x), a.apply(b.apply(x)));
		// relative pose: b seen from a, and back
		expectNear(a.relative(b), a.inverse().compose(b));
		expectNear(a.compose(a.relative(b)), b);
		expectNear(a.relative(b).apply(x), a.applyInverse(b.apply(x)));
		// the two point maps: the same map up to one rounding
		expectNear(a.place(x), a.apply(x));
	}
}

TEST(Pose2, RelativeIsTheContactFrameFormula)
{
	// Ig2 and SearchMemory: R(−θ1)(x2 − x1), cos and sin of θ2 − θ1, bit for bit
	const Pose2 a = poseOf(0.7, -1.3, 0.4), b = poseOf(2.1, 0.2, -1.1);
	const Vec2  d = b.p - a.p;
	const Pose2 r = a.relative(b);
	EXPECT_EQ(r.p, Vec2(a.c * d.x() + a.s * d.y(), -a.s * d.x() + a.c * d.y()));
	EXPECT_EQ(r.c, a.c * b.c + a.s * b.s);
	EXPECT_EQ(r.s, a.c * b.s - a.s * b.c);
}
