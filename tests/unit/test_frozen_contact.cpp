// Frozen contact kinematics (FrozenContact.hpp) against the exact edge contact (EdgeContact.hpp).
// Block A sits at the origin unrotated, so the world frame is A's frame; block B is placed by a
// relative pose. Compared: (1) at the pose of the update, the frozen contact IS the exact one (to
// round-off); (2) an approach along the normal is followed exactly; (3) after a small relative
// rotation α and slip s, the overlaps differ at second order, |Δd| ≤ C (|α| s + α² L + ...), checked
// by halving the motion (the error must drop about fourfold) and against a closed-form bound;
// (4) frozenDrift bounds the displacement of every vertex of either block relative to the other.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/FrozenContact.hpp>

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace rbsm;

namespace {
std::vector<Vec2> rect(Real w, Real h) { return { { -w / 2, -h / 2 }, { w / 2, -h / 2 }, { w / 2, h / 2 }, { -w / 2, h / 2 } }; }

std::vector<Vec2> placed(const std::vector<Vec2>& local, const Pose2& pose)
{
	std::vector<Vec2> v;
	for (const Vec2& x : local) v.push_back(pose.place(x));
	return v;
}

Pose2 poseOf(Real x, Real y, Real angle) { return Pose2(Vec2(x, y), std::cos(angle), std::sin(angle)); }

// A scene: A (1 x 0.5) at the origin, B on top of it overlapping by `overlap`, shifted by `shift`.
struct Pair {
	std::vector<Vec2> a, bLocal;
	Pose2      pose;
	ContactHint       hint;
	Pair(Real bWidth, Real shift, Real overlap, int refBody)
	    : a(rect(1.0, 0.5))
	    , bLocal(rect(bWidth, 0.5))
	    , pose(poseOf(shift, 0.5 - overlap, 0))
	{
		// the shared edge: A's top (edge 2) or B's bottom (edge 0); the hint keeps the chosen one
		hint = refBody == 1 ? ContactHint { 1, 2 } : ContactHint { 2, 0 };
	}
	EdgeContact exact(const Pose2& p) const { return edgeContact(a, placed(bLocal, p), 0.0, &hint, 1e-3, 0.5); }
};

void expectNear(const Vec2& a, const Vec2& b, Real tol) { EXPECT_LE((a - b).norm(), tol) << a.transpose() << " vs " << b.transpose(); }
} // namespace

TEST(FrozenContact, AtTheUpdateItIsTheExactContact)
{
	for (int refBody = 1; refBody <= 2; ++refBody)
		for (Real bWidth : { 1.0, 0.6, 1.4 })
			for (Real shift : { 0.0, 0.3, -0.45 }) {
				const Pair        pr(bWidth, shift, 1e-3, refBody);
				const EdgeContact ex = pr.exact(pr.pose);
				ASSERT_TRUE(ex.touching);
				ASSERT_EQ(ex.refBody, refBody);
				const EdgeContact fr = frozenContact(freezeContact(ex, pr.pose), pr.pose);
				EXPECT_NEAR(fr.d0, ex.d0, 1e-15);
				EXPECT_NEAR(fr.d1, ex.d1, 1e-15);
				expectNear(fr.p0, ex.p0, 1e-15);
				expectNear(fr.p1, ex.p1, 1e-15);
				expectNear(fr.normal, ex.normal, 1e-15);
				expectNear(fr.tangent, ex.tangent, 1e-15);
				EXPECT_EQ(fr.length, ex.length);
				EXPECT_EQ(fr.refEdge, ex.refEdge);
			}
}

TEST(FrozenContact, ApproachAlongTheNormalIsExact)
{
	for (int refBody = 1; refBody <= 2; ++refBody) {
		const Pair          pr(0.6, 0.2, 1e-3, refBody);
		const FrozenContact f = freezeContact(pr.exact(pr.pose), pr.pose);
		for (Real dy : { -4e-3, -1e-4, 5e-4 }) { // closer (deeper) and farther (still overlapping)
			const Pose2 now = poseOf(pr.pose.p.x(), pr.pose.p.y() + dy, 0);
			const EdgeContact  ex = pr.exact(now), fr = frozenContact(f, now);
			EXPECT_NEAR(fr.d0, ex.d0, 1e-15) << "dy " << dy;
			EXPECT_NEAR(fr.d1, ex.d1, 1e-15) << "dy " << dy;
			EXPECT_NEAR(fr.d0, 1e-3 - dy, 1e-15); // closed form: overlap − dy
		}
	}
}

// Largest overlap error over random small motions of size eps (rotation eps rad, slip and approach
// eps·L) from the update, for one pair.
Real worstOverlapError(const Pair& pr, Real eps, std::mt19937& rng, Real* worstLengthError = nullptr, Real* worstRatioToBound = nullptr)
{
	std::uniform_real_distribution<Real> u(-1, 1);
	const FrozenContact                  f     = freezeContact(pr.exact(pr.pose), pr.pose);
	Real                                 worst = 0;
	for (int trial = 0; trial < 200; ++trial) {
		const Real         alpha = eps * u(rng), sx = eps * u(rng), sy = 0.2 * eps * u(rng);
		const Pose2 now   = poseOf(pr.pose.p.x() + sx, pr.pose.p.y() + sy, alpha);
		const EdgeContact  ex = pr.exact(now), fr = frozenContact(f, now);
		if (!ex.touching || ex.refBody != f.refBody) continue;
		// the exact overlap at the frozen segment's ends: linear along the exact segment
		const Vec2 t    = ex.tangent;
		auto       dAt  = [&](const Vec2& x) {
                        const Real l = (ex.p1 - ex.p0).dot(t), s = l > 0 ? (x - ex.p0).dot(t) / l : 0;
                        return ex.d0 + s * (ex.d1 - ex.d0);
		};
		const Real err = std::max(std::abs(fr.d0 - dAt(fr.p0)), std::abs(fr.d1 - dAt(fr.p1)));
		worst          = std::max(worst, err);
		// closed-form bound (FrozenContact.hpp): |α| s + α² L plus the joint's own overlap gradient
		// times the slip, s = the tangential motion (here |sx| + |α| times the lever arm ≤ 1)
		const Real slip = std::abs(sx) + std::abs(alpha) * 1.0, gradient = std::abs(ex.d1 - ex.d0) / std::max(ex.length, 1e-12);
		const Real bound = std::abs(alpha) * slip + alpha * alpha * 1.0 + gradient * slip + 1e-15;
		if (worstRatioToBound) *worstRatioToBound = std::max(*worstRatioToBound, err / bound);
		if (worstLengthError) *worstLengthError = std::max(*worstLengthError, std::abs(fr.length - ex.length) / (2 * slip + 1e-15));
	}
	return worst;
}

TEST(FrozenContact, OverlapErrorIsSecondOrderInTheMotion)
{
	std::mt19937 rng(7);
	for (int refBody = 1; refBody <= 2; ++refBody)
		for (Real bWidth : { 1.0, 0.6 })
			for (Real shift : { 0.0, 0.3 }) {
				const Pair pr(bWidth, shift, 1e-3, refBody);
				Real       lengthRatio = 0, boundRatio = 0;
				const Real e1 = worstOverlapError(pr, 1e-4, rng, &lengthRatio, &boundRatio);
				const Real e2 = worstOverlapError(pr, 0.5e-4, rng, &lengthRatio, &boundRatio);
				const Real e3 = worstOverlapError(pr, 0.25e-4, rng, &lengthRatio, &boundRatio);
				// second order: halving the motion divides the error by about 4 (3 allows for the
				// random sampling); first order would give 2
				EXPECT_GT(e1 / e2, 3.0) << "refBody " << refBody << " width " << bWidth << " shift " << shift << " errors " << e1 << " " << e2;
				EXPECT_GT(e2 / e3, 3.0) << "refBody " << refBody << " width " << bWidth << " shift " << shift << " errors " << e2 << " " << e3;
				EXPECT_LE(boundRatio, 2.0) << "error against the closed-form bound";
				EXPECT_LE(lengthRatio, 1.0) << "length error exceeds twice the slip";
				EXPECT_LT(e1, 1e-7); // a motion of 1e-4 of the block: overlap error ~1e-8 m
			}
}

TEST(FrozenContact, DriftBoundsEveryVertexMotion)
{
	std::mt19937                         rng(3);
	std::uniform_real_distribution<Real> u(-1, 1);
	const std::vector<Vec2>              a = rect(1.0, 0.5), b = rect(0.7, 0.4);
	Real                                 rA = 0, rB = 0;
	for (const Vec2& v : a) rA = std::max(rA, v.norm());
	for (const Vec2& v : b) rB = std::max(rB, v.norm());
	for (int trial = 0; trial < 1000; ++trial) {
		const Pose2 p0 = poseOf(u(rng), 0.5 + u(rng), 3 * u(rng));
		const Real         eps = std::pow(10.0, -4 * std::abs(u(rng)));
		const Pose2 p1  = poseOf(p0.p.x() + eps * u(rng), p0.p.y() + eps * u(rng), std::atan2(p0.s, p0.c) + eps * u(rng));
		FrozenContact      f;
		f.pose          = p0;
		const Real drift = frozenDrift(f, p1, rA, rB);
		Real       moved = 0;
		for (const Vec2& v : b) moved = std::max(moved, (p1.place(v) - p0.place(v)).norm()); // B's vertices in A's frame
		for (const Vec2& v : a) moved = std::max(moved, (p1.applyInverse(v) - p0.applyInverse(v)).norm()); // A's vertices in B's frame
		EXPECT_GE(drift * (1 + 1e-12), moved) << "trial " << trial;
	}
	FrozenContact f;
	f.pose = poseOf(0.2, 0.5, 0.1);
	EXPECT_EQ(frozenDrift(f, f.pose, rA, rB), 0.0);
}

TEST(FrozenContact, FreezingNothingIsInvalid)
{
	EdgeContact apart; // touching = false
	EXPECT_FALSE(freezeContact(apart, Pose2 {}).valid);
}

TEST(FrozenContact, PackAndUnpackRoundTrip)
{
	const Pair          pr(0.6, 0.2, 1e-3, 2);
	const FrozenContact f = freezeContact(pr.exact(pr.pose), pr.pose);
	ASSERT_TRUE(f.valid);
	const std::vector<Real> v = packFrozen(f);
	EXPECT_EQ(v.size(), 17u);
	const FrozenContact g = unpackFrozen(v);
	ASSERT_TRUE(g.valid);
	const Pose2 now = poseOf(0.21, 0.5 - 1.2e-3, 1e-5);
	const EdgeContact  a = frozenContact(f, now), b = frozenContact(g, now);
	EXPECT_EQ(a.d0, b.d0); // bitwise: a loaded scene continues exactly
	EXPECT_EQ(a.d1, b.d1);
	EXPECT_EQ(a.p0, b.p0);
	EXPECT_EQ(a.p1, b.p1);
	EXPECT_EQ(a.normal, b.normal);
	EXPECT_EQ(a.refEdge, b.refEdge);
	EXPECT_TRUE(packFrozen(FrozenContact {}).empty());
	EXPECT_FALSE(unpackFrozen({}).valid);
	EXPECT_FALSE(unpackFrozen(std::vector<Real>(16, 1.0)).valid);
	std::vector<Real> bad = v;
	bad[0]                = 3; // no such reference body
	EXPECT_FALSE(unpackFrozen(bad).valid);
}
