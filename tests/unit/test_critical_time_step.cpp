// Critical time step: closed forms for one block on a spring to a fixed block and for two equal
// blocks; the Gershgorin estimate is a rigorous lower bound of the exact value.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
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

// A contact made after an estimate: adding its row terms to the estimate's bounds bounds the
// estimate of the whole system (the Gershgorin terms are subadditive), random two-block contacts.
TEST(CriticalTimeStep, RowBoundsOfANewContactAddUp)
{
	std::mt19937                     rng(3);
	std::uniform_real_distribution<> u(0.1, 2.0), a(-1, 1);
	for (int trial = 0; trial < 200; ++trial) {
		std::vector<DynBody> b(3);
		for (auto& x : b) x.mass = u(rng), x.inertia = u(rng), x.centroid = Vec2(a(rng), a(rng));
		b[0].fixed = trial % 3 == 0;
		auto randomContact = [&](int i, int j) {
			const Vec2 n = Vec2(a(rng), a(rng)).normalized();
			return contact(i, j, n, 1e6 * u(rng), 1e6 * u(rng), { Vec2(a(rng), a(rng)), Vec2(a(rng), a(rng)) }, { u(rng), u(rng) });
		};
		const std::vector<DynContact> before = { randomContact(0, 1) };
		const DynContact              added  = randomContact(1, 2);
		std::vector<Real>             rows, diag;
		criticalTimeStepGershgorin(b, before, &rows, &diag);
		Real add1, add2, diag1, diag2;
		contactRowBounds(b, added, add1, add2, &diag1, &diag2);
		rows[1] += add1, rows[2] += add2;
		diag[1] += diag1, diag[2] += diag2; // (density scaling's increments)
		const Real bound = 2 / std::sqrt(*std::max_element(rows.begin(), rows.end()));
		std::vector<DynContact> all = before;
		all.push_back(added);
		EXPECT_LE(bound, criticalTimeStepGershgorin(b, all) * (1 + 1e-12));
		EXPECT_LE(bound, criticalTimeStepExact(b, all) * (1 + 1e-12));
		std::vector<Real> rowsAll, diagAll;
		criticalTimeStepGershgorin(b, all, &rowsAll, &diagAll);
		for (int k = 1; k < 3; ++k) {
			EXPECT_GE(diag[k], diagAll[k] * (1 - 1e-12)) << trial;             // the own-block share, bounded
			EXPECT_GE(rows[k] - diag[k], (rowsAll[k] - diagAll[k]) * (1 - 1e-12) - 1e-9 * rowsAll[k]) << trial; // and the coupling
		}
		// alone on its two blocks, the diagonal parts are the estimate's own
		std::vector<Real> rowsNew, diagNew;
		criticalTimeStepGershgorin(b, { added }, &rowsNew, &diagNew);
		EXPECT_NEAR(diag1, diagNew[1], 1e-12 * diagNew[1]);
		EXPECT_NEAR(diag2, diagNew[2], 1e-12 * diagNew[2]);
	}
}

// The stiffest single joint of a block bounds every joint it can form along one of its edges, and
// for a unit square on a fixed base it is that joint exactly.
TEST(CriticalTimeStep, StiffestJointOfABlock)
{
	const std::vector<Vec2> square = { Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.5, 0.5), Vec2(-0.5, 0.5) };
	DynBody                 body { 2000, 2000.0 / 6, Vec2::Zero(), false };
	const Real              En = 1e8, Es = 8e7, t = 1;
	const Real              w2 = stiffestJointOmega2(body, square, En, Es, 0, 0, t);
	// the bottom edge on a rigid base: kn = En/h, ks = Es/h, h = 0.5, two Gauss points
	std::vector<DynBody> two = { DynBody { 0, 0, Vec2::Zero(), true }, body };
	const Real           g   = 0.5 / std::sqrt(3.0);
	const DynContact     c   = contact(0, 1, Vec2(0, 1), En / 0.5, Es / 0.5, { Vec2(-g, -0.5), Vec2(g, -0.5) }, { 0.5, 0.5 });
	EXPECT_NEAR(2 / std::sqrt(w2), criticalTimeStepExact(two, { c }), 1e-9);
	// a partner's compliance only softens it
	EXPECT_LT(stiffestJointOmega2(body, square, En, Es, 0.1 / En, 0.1 / Es, t), w2);
	EXPECT_NEAR(centroidInradius(square), 0.5, 1e-15);
}

// A corner closing by rotation counts with the shorter edge's length; a flat joint keeps its own.
TEST(CriticalTimeStep, ClosingContact)
{
	const Vec2 r0u(5, 0), r1u(-5, 0); // the top edge of a block below (CCW: outward normal +y)
	// a unit edge tilted by 45 degrees, its corner 1 cm in: grows to length 1
	const Vec2 corner(0, -0.01), far = corner + Vec2(std::sqrt(0.5), std::sqrt(0.5));
	const auto tilted = closingContact(r0u, r1u, corner, far, Vec2(0.01, 0), Vec2(0, 0));
	EXPECT_NEAR((tilted.second - tilted.first).norm(), 1.0, 1e-12);
	// running bond: a flat 2 m edge overlapping the reference by 1 m keeps its 1 m
	const auto flat = closingContact(r0u, r1u, Vec2(6, -1e-3), Vec2(4, -1e-3), Vec2(5, 0), Vec2(4, 0));
	EXPECT_NEAR((flat.second - flat.first).norm(), 1.0, 1e-12);
	// diagonal neighbours: a corner on the reference edge's end, the edge (slightly turned) beyond it
	const auto diagonal = closingContact(r0u, r1u, Vec2(-5, -1e-6), Vec2(-6, 1e-5), Vec2(-5, 0), Vec2(-5, 0));
	EXPECT_NEAR((diagonal.second - diagonal.first).norm(), 0.0, 1e-12);
}

// Density scaling: a block on fixed ground (no coupling) needs s = diag / omega_T^2 exactly; a block
// already below the target keeps s = 1.
TEST(CriticalTimeStep, DensityScaleClosedForm)
{
	EXPECT_DOUBLE_EQ(densityScale(400, 0, 100), 4);
	EXPECT_DOUBLE_EQ(densityScale(50, 30, 100), 1);
	EXPECT_DOUBLE_EQ(densityScale(0, 0, 100), 1);
	EXPECT_DOUBLE_EQ(densityScale(0, 200, 100), 4); // coupling only: off / sqrt(s) = omega_T^2
	const Real s = densityScale(300, 100, 100); // 300/s + 100/sqrt(s) = 100
	EXPECT_NEAR(300 / s + 100 / std::sqrt(s), 100, 1e-12);
}

// Random chains of free blocks (masses over three orders of magnitude) joined by random contacts:
// every block scaled by densityScale for the target of the median block, the exact critical step of
// the scaled system is at least the target step (the bound holds whichever neighbours are scaled).
TEST(CriticalTimeStep, DensityScaledSystemMeetsTheTarget)
{
	std::mt19937                     rng(7);
	std::uniform_real_distribution<> u(0, 1);
	for (int trial = 0; trial < 200; ++trial) {
		const int            n = 2 + int(u(rng) * 6);
		std::vector<DynBody> b(n + 1);
		b[0].fixed = true;
		for (int i = 1; i <= n; ++i) {
			const Real size = std::pow(10.0, -1 + 2 * u(rng)), mass = 2000 * size * size;
			b[i].mass = mass, b[i].inertia = mass * size * size / 6, b[i].centroid = Vec2(i, u(rng));
		}
		std::vector<DynContact> c;
		for (int i = 1; i <= n; ++i) {
			const int  j = int(u(rng) * i); // to an earlier block or the ground
			const Real a = std::atan2(u(rng) - 0.5, 1.0), L = 0.05 + u(rng);
			const Vec2 nrm(std::cos(a + 1.5), std::sin(a + 1.5)), mid = b[i].centroid + Vec2(0.3 * u(rng), -0.5);
			const Vec2 t(-nrm.y(), nrm.x());
			c.push_back(contact(j, i, nrm, 1e8 * (0.1 + u(rng)), 4e7 * (0.1 + u(rng)), { mid - 0.3 * L * t, mid + 0.3 * L * t }, { 0.5 * L, 0.5 * L }));
		}
		std::vector<Real> total, diag;
		criticalTimeStepGershgorin(b, c, &total, &diag);
		std::vector<Real> rows(total.begin() + 1, total.end());
		std::nth_element(rows.begin(), rows.begin() + rows.size() / 2, rows.end());
		const Real omegaT2 = rows[rows.size() / 2];
		std::vector<DynBody> scaled = b;
		for (int i = 1; i <= n; ++i) {
			const Real s = densityScale(diag[i], total[i] - diag[i], omegaT2);
			EXPECT_GE(s, 1);
			scaled[i].mass *= s, scaled[i].inertia *= s;
		}
		const Real target = 2 / std::sqrt(omegaT2);
		EXPECT_GE(criticalTimeStepExact(scaled, c), target * (1 - 1e-9)) << "trial " << trial;
		EXPECT_GE(criticalTimeStepGershgorin(scaled, c), target * (1 - 1e-9)) << "trial " << trial;
	}
}
