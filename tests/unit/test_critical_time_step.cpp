// Critical time step: closed forms for one block on a spring to a fixed block and for two equal
// blocks; the Gershgorin estimate is a rigorous lower bound of the exact value.
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>

#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace rbsm;

namespace {
DynContact contact(int b1, int b2, const Vec2& n, Real kn, Real ks, std::vector<Vec2> pts, std::vector<Real> areas)
{
	DynContact c;
	c.body1 = b1;
	c.body2 = b2;
	c.normal = n;
	c.tangent = Vec2(-n.y(), n.x());
	c.kn = kn;
	c.ks = ks;
	c.points = std::move(pts);
	c.areas = std::move(areas);
	return c;
}
} // namespace

// Block (m, I) attached to a fixed block by one integration point at its centroid (tilted normal):
// K = diag(ks a, kn a, 0) in the (t, n, theta) frame -> omega^2 = max(kn, ks) a / m, dt = 2/omega.
TEST(CriticalTimeStep, MassOnSpringToGround)
{
	const Real m = 3, I = 0.5, kn = 2e9, ks = 8e8, a = 1e-3;
	std::vector<DynBody> b(2);
	b[0].fixed = true;
	b[1].mass = m, b[1].inertia = I, b[1].centroid = Vec2(1, 2);
	const std::vector<DynContact> c = { contact(0, 1, Vec2(0.6, 0.8), kn, ks, { Vec2(1, 2) }, { a }) };
	const Real expected = 2 / std::sqrt(kn * a / m);
	EXPECT_NEAR(criticalTimeStepExact(b, c), expected, 1e-12 * expected);
	// one free body: the block Gershgorin bound is its 3x3 block's exact eigenvalue, for any normal
	EXPECT_NEAR(criticalTimeStepGershgorin(b, c), expected, 1e-9 * expected);
}

// Offset point, only a normal spring: rank-1 K = k B^T B with B = [n, r x n]:
// omega^2 = k (1/m + (r x n)^2 / I).
TEST(CriticalTimeStep, OffsetSpringToGround)
{
	const Real m = 2, I = 0.3, kn = 1e8, a = 0.01;
	std::vector<DynBody> b(2);
	b[0].fixed = true;
	b[1].mass = m, b[1].inertia = I, b[1].centroid = Vec2(0, 0);
	const Vec2 x(0.4, -0.5), n(0, 1);
	const std::vector<DynContact> c = { contact(0, 1, n, kn, 0, { x }, { a }) };
	const Real rxn = x.x() * n.y() - x.y() * n.x();
	const Real expected = 2 / std::sqrt(kn * a * (1 / m + rxn * rxn / I));
	EXPECT_NEAR(criticalTimeStepExact(b, c), expected, 1e-12 * expected);
	const Real g = criticalTimeStepGershgorin(b, c);
	EXPECT_LE(g, expected * (1 + 1e-12));
	EXPECT_GE(g, 0.5 * expected); // tight enough to be useful
}

// Two equal free blocks (m, I), centroids 2d apart along x, one integration point midway.
// Normal (x) spring couples ux only: omega^2 = 2 kn a / m. Shear spring couples uy and theta
// (lever d each): rank 1, omega^2 = ks a (2/m + 2 d^2 / I). dt = 2/sqrt(max).
TEST(CriticalTimeStep, TwoEqualBlocks)
{
	const Real m = 5, I = 0.4, d = 0.5, a = 0.1;
	for (Real ks : { 1e6, 1e9 }) {
		const Real kn = 1e8;
		std::vector<DynBody> b(2);
		b[0].mass = b[1].mass = m;
		b[0].inertia = b[1].inertia = I;
		b[0].centroid = Vec2(-d, 0);
		b[1].centroid = Vec2(d, 0);
		const std::vector<DynContact> c = { contact(0, 1, Vec2(1, 0), kn, ks, { Vec2(0, 0) }, { a }) };
		const Real w2 = std::max(2 * kn * a / m, ks * a * (2 / m + 2 * d * d / I));
		const Real expected = 2 / std::sqrt(w2);
		EXPECT_NEAR(criticalTimeStepExact(b, c), expected, 1e-12 * expected) << ks;
		const Real g = criticalTimeStepGershgorin(b, c);
		EXPECT_LE(g, expected * (1 + 1e-12));
		EXPECT_GE(g, 0.5 * expected);
	}
}

// Random chains of blocks with two integration points per joint: Gershgorin <= exact, always.
TEST(CriticalTimeStep, GershgorinIsALowerBoundOfExact)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<Real> U(0.5, 2);
	for (int trial = 0; trial < 20; ++trial) {
		const int n = 6;
		std::vector<DynBody> b(n);
		std::vector<DynContact> c;
		for (int i = 0; i < n; ++i) {
			b[i].mass = U(rng);
			b[i].inertia = 0.1 * U(rng);
			b[i].centroid = Vec2(i, 0.1 * U(rng));
			b[i].fixed = (i == 0);
		}
		for (int i = 0; i + 1 < n; ++i) {
			const Real xm = i + 0.5;
			c.push_back(contact(i, i + 1, Vec2(1, 0), 1e8 * U(rng), 4e7 * U(rng), { Vec2(xm, -0.2), Vec2(xm, 0.3) }, { 0.01 * U(rng), 0.01 * U(rng) }));
		}
		const Real e = criticalTimeStepExact(b, c), g = criticalTimeStepGershgorin(b, c);
		EXPECT_LE(g, e * (1 + 1e-12));
		EXPECT_GE(g, 0.5 * e); // block Gershgorin stays within a factor 2 on chains
	}
}

TEST(CriticalTimeStep, NoStiffnessAndBadInput)
{
	std::vector<DynBody> b(1);
	b[0].mass = 1, b[0].inertia = 1;
	EXPECT_TRUE(std::isinf(criticalTimeStepGershgorin(b, {})));
	EXPECT_TRUE(std::isinf(criticalTimeStepExact(b, {})));
	b[0].mass = 0;
	EXPECT_THROW(criticalTimeStepGershgorin(b, {}), std::invalid_argument);
	b[0].mass = 1;
	EXPECT_THROW(criticalTimeStepGershgorin(b, { contact(0, 0, Vec2(1, 0), 1, 1, {}, {}) }), std::invalid_argument);
}
