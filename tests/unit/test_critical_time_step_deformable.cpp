// The 6-DOF critical time step of deformable blocks (StrainElement.hpp): the block Gershgorin bound
// stays below the exact omega^2, is exact for one free block, reduces to the block's own strain
// modes without contacts, and leaves the rigid (3-DOF) numbers bit-for-bit unchanged.
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/StrainElement.hpp>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace rbsm;

namespace {
using Mat6 = Eigen::Matrix<Real, 6, 6>;
using Vec6 = Eigen::Matrix<Real, 6, 1>;
const Real rho = 2000, thick = 0.5, young = 3e7;

// A convex polygon about its centroid: k points on an ellipse of semi-axes (size, aspect size).
std::vector<Vec2> randomPolygon(std::mt19937& rng, Real size)
{
	std::uniform_real_distribution<Real> u(0, 1);
	const int         k = 3 + int(u(rng) * 5);
	const Real        aspect = 0.5 + u(rng);
	std::vector<Vec2> v;
	for (int i = 0; i < k; ++i) {
		const Real a = 2 * M_PI * (i + 0.7 * u(rng)) / k;
		v.emplace_back(size * std::cos(a), aspect * size * std::sin(a));
	}
	const Vec2 c = massProperties(v).centroid; // (the kernel's shoelace formulas)
	for (auto& p : v) p -= c;
	return v;
}
std::vector<Vec2> square(Real h) { return { Vec2(-h / 2, -h / 2), Vec2(h / 2, -h / 2), Vec2(h / 2, h / 2), Vec2(-h / 2, h / 2) }; }

// A block of the polygon (block frame, about its centroid) at centroid c, its frame turned by angle.
DynBody block(const std::vector<Vec2>& local, const Vec2& c, Real angle, bool deformable, Real nu = 0.25)
{
	const AreaMoments m = areaMoments(local);
	const StrainMass  M = strainMass(m, rho, thick);
	DynBody           b;
	b.mass = rho * thick * m.area, b.inertia = M.polar, b.centroid = c;
	b.deformable = deformable;
	b.cosAngle = std::cos(angle), b.sinAngle = std::sin(angle);
	b.thetaStrainMass = M.thetaStrain, b.strainMass = M.strain;
	b.strainStiffness = m.area * thick * elasticityMatrix(young, nu, true);
	return b;
}
DynContact contact(int b1, int b2, const Vec2& n, Real kn, Real ks, std::vector<Vec2> pts, std::vector<Real> areas)
{
	DynContact c;
	c.body1 = b1, c.body2 = b2;
	c.normal = n, c.tangent = Vec2(-n.y(), n.x());
	c.kn = kn, c.ks = ks;
	c.points = std::move(pts), c.areas = std::move(areas);
	return c;
}

// Random blocks (sizes 0.1 to 10 m) on a jittered grid, a mix of rigid, deformable and fixed, joined by
// random two-point contacts between neighbours in the grid and a few random pairs.
void randomScene(std::mt19937& rng, std::vector<DynBody>& b, std::vector<DynContact>& c, int n = 8)
{
	std::uniform_real_distribution<Real> u(0, 1);
	b.clear(), c.clear();
	std::vector<Real> size;
	for (int i = 0; i < n; ++i) {
		size.push_back(std::pow(10.0, -1 + 2 * u(rng)));
		b.push_back(block(randomPolygon(rng, size.back()), Vec2(i % 3, i / 3) + 0.2 * Vec2(u(rng), u(rng)), 2 * M_PI * u(rng), u(rng) < 0.6));
		b.back().fixed = u(rng) < 0.15;
	}
	auto join = [&](int i, int j) {
		const Vec2 d = (b[j].centroid - b[i].centroid).normalized(), t(-d.y(), d.x()), mid = 0.5 * (b[i].centroid + b[j].centroid);
		const Real L = std::min(size[i], size[j]), kn = young / (0.5 * (size[i] + size[j])) * (0.5 + u(rng));
		c.push_back(contact(i, j, d, kn, 0.4 * kn * (0.5 + u(rng)), { mid - 0.3 * L * t, mid + 0.3 * L * t }, { 0.5 * L * thick, 0.5 * L * thick }));
	};
	for (int i = 1; i < n; ++i) join(i - 1, i);
	for (int i = 3; i < n; ++i) join(i - 3, i);
	for (int k = 0; k < 3; ++k) {
		const int i = int(u(rng) * n), j = (i + 1 + int(u(rng) * (n - 1))) % n;
		join(i, j);
	}
}

// The 6x6 mass of a deformable block, blockdiag(m, m, [[I, M_te^T], [M_te, M_ee]]).
Mat6 mass6(const DynBody& b)
{
	Mat6 M = Mat6::Zero();
	M(0, 0) = M(1, 1) = b.mass;
	M(2, 2)                     = b.inertia;
	M.block<3, 1>(3, 2)         = b.thetaStrainMass;
	M.block<1, 3>(2, 3)         = b.thetaStrainMass.transpose();
	M.bottomRightCorner<3, 3>() = b.strainMass;
	return M;
}
} // namespace

// Random 6-DOF systems (random convex blocks of sizes over two orders of magnitude, rigid, deformable
// and fixed mixed, several seeds): dt_Gershgorin <= dt_exact, always.
TEST(CriticalTimeStepDeformable, GershgorinIsALowerBoundOfExact)
{
	Real worst = 1;
	for (unsigned seed : { 1u, 2u, 3u, 4u, 5u }) {
		std::mt19937 rng(seed);
		for (int trial = 0; trial < 40; ++trial) {
			std::vector<DynBody>    b;
			std::vector<DynContact> c;
			randomScene(rng, b, c, 4 + trial % 6);
			const Real e = criticalTimeStepExact(b, c), g = criticalTimeStepGershgorin(b, c);
			ASSERT_TRUE(std::isfinite(e));
			EXPECT_LE(g, e * (1 + 1e-10)) << "seed " << seed << " trial " << trial;
			EXPECT_GT(g, 0);
			worst = std::min(worst, g / e);
		}
	}
	EXPECT_GT(worst, 0.5); // observed 0.85 over these seeds
	RecordProperty("worst dt_bound / dt_exact", std::to_string(worst));
}

// Rank 1: one normal spring k at x on a deformable block (its frame turned), the other side fixed:
// omega^2 = k b^T M^-1 b, b_i = n . u(e_i)(x) from the displacement field itself,
// u(q) = (q0, q1) + q2 z x r + R B(R^T r) (q3, q4, q5). One free block: the bound is exact.
TEST(CriticalTimeStepDeformable, OneSpringOnADeformableBlockMatchesTheDisplacementField)
{
	const Real                angle = 0.6, k = 3e8, a = 0.02;
	const std::vector<Vec2>   tri   = { Vec2(-0.4, -0.3), Vec2(0.7, -0.2), Vec2(-0.3, 0.5) };
	std::vector<DynBody>      b     = { DynBody(), block(tri, Vec2(1, 2), angle, true) };
	const Vec2                x(1.3, 1.6), n = Vec2(0.28, 0.96);
	Eigen::Matrix<Real, 2, 2> R;
	b[0].fixed = true;
	R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
	Vec6 row;
	for (int i = 0; i < 6; ++i) {
		const Vec6 q = Vec6::Unit(i);
		const Vec2 r = x - b[1].centroid;
		const Vec2 u = q.head<2>() + q[2] * Vec2(-r.y(), r.x()) + R * strainDisplacement(R.transpose() * r, q.tail<3>());
		row[i] = n.dot(u);
	}
	const Real w2       = k * a * row.dot(mass6(b[1]).ldlt().solve(row));
	const Real expected = 2 / std::sqrt(w2);
	const std::vector<DynContact> c = { contact(0, 1, n, k, 0, { x }, { a }) };
	b[1].strainStiffness.setZero(); // the spring alone
	EXPECT_NEAR(criticalTimeStepExact(b, c), expected, 1e-9 * expected);
	EXPECT_NEAR(criticalTimeStepGershgorin(b, c), expected, 1e-9 * expected);
	// the strain terms matter: the rigid block alone is slower
	b[1].deformable = false;
	EXPECT_GT(criticalTimeStepExact(b, c), 1.05 * expected);
}

// One deformable square on fixed supports (bottom and left edges, two Gauss points each, Kawai-type
// springs): a single free block's bound is lambda_max(S_bb) itself, exact. The rigid block is the
// same system with eps = 0, a constraint, so its step is longer; the strain modes shorten it.
TEST(CriticalTimeStepDeformable, SquareOnFixedSupports)
{
	const Real h = 0.5, g = h / (2 * std::sqrt(3.0)), nu = 0.2;
	const Real En = young / ((1 + nu) * (1 - 2 * nu)) * (1 - nu), kn = En / (h / 2), ks = 0.4 * kn;
	for (Real angle : { 0.0, 0.4 }) {
		std::vector<DynBody> b = { DynBody(), DynBody(), block(square(h), Vec2::Zero(), angle, true, nu) };
		b[0].fixed = b[1].fixed = true;
		const std::vector<DynContact> c = {
			contact(0, 2, Vec2(0, 1), kn, ks, { Vec2(-g, -h / 2), Vec2(g, -h / 2) }, { h * thick / 2, h * thick / 2 }),
			contact(1, 2, Vec2(1, 0), kn, ks, { Vec2(-h / 2, -g), Vec2(-h / 2, g) }, { h * thick / 2, h * thick / 2 }),
		};
		const Real e = criticalTimeStepExact(b, c);
		EXPECT_NEAR(criticalTimeStepGershgorin(b, c), e, 1e-9 * e) << angle;
		std::vector<DynBody> rigid = b;
		rigid[2].deformable        = false;
		const Real er              = criticalTimeStepExact(rigid, c);
		EXPECT_LT(e, er);
		EXPECT_GT(e, 0.3 * er); // the notes' estimate: roughly 0.5-0.7 of the rigid step
		RecordProperty("dt_deformable / dt_rigid", std::to_string(e / er));
	}
}

// No contacts: the block's own K_ee on the free (theta, eps) system, omega^2 = ownStrainOmega2
// (translations carry no stiffness); a triangle, where theta and eps couple.
TEST(CriticalTimeStepDeformable, OwnStrainModesAlone)
{
	const Vec2              c(0.4, 0.3);
	const std::vector<Vec2> tri = { Vec2(0, 0) - c, Vec2(1.2, 0) - c, Vec2(0, 0.9) - c };
	const DynBody           b   = block(tri, Vec2(5, -1), 1.1, true);
	const Real              w2 = ownStrainOmega2(strainMass(areaMoments(tri), rho, thick), b.strainStiffness);
	const Real              expected = 2 / std::sqrt(w2);
	EXPECT_NEAR(criticalTimeStepExact({ b }, {}), expected, 1e-9 * expected);
	EXPECT_NEAR(criticalTimeStepGershgorin({ b }, {}), expected, 1e-9 * expected);
	std::vector<Real> rows, diag;
	criticalTimeStepGershgorin({ b }, {}, &rows, &diag);
	EXPECT_NEAR(rows[0], w2, 1e-9 * w2);
	EXPECT_EQ(rows[0], diag[0]);
}

// Turning the whole scene (centroids, points, normals and the blocks' frames) changes nothing: the
// strain is expressed in the block's frame.
TEST(CriticalTimeStepDeformable, InvariantUnderARotationOfTheScene)
{
	std::mt19937 rng(11);
	const Real   phi = 0.9, cs = std::cos(phi), sn = std::sin(phi);
	auto         turn = [&](const Vec2& p) { return Vec2(cs * p.x() - sn * p.y(), sn * p.x() + cs * p.y()); };
	for (int trial = 0; trial < 10; ++trial) {
		std::vector<DynBody>    b;
		std::vector<DynContact> c;
		randomScene(rng, b, c, 6);
		std::vector<DynBody>    b2 = b;
		std::vector<DynContact> c2 = c;
		for (auto& x : b2) {
			x.centroid = turn(x.centroid);
			const Real ca = x.cosAngle * cs - x.sinAngle * sn, sa = x.sinAngle * cs + x.cosAngle * sn;
			x.cosAngle = ca, x.sinAngle = sa;
		}
		for (auto& k : c2) {
			k.normal = turn(k.normal), k.tangent = turn(k.tangent);
			for (auto& p : k.points) p = turn(p);
		}
		const Real e = criticalTimeStepExact(b, c), g = criticalTimeStepGershgorin(b, c);
		EXPECT_NEAR(criticalTimeStepExact(b2, c2), e, 1e-8 * e) << trial;
		EXPECT_NEAR(criticalTimeStepGershgorin(b2, c2), g, 1e-8 * g) << trial;
	}
}

// A contact made after an estimate, with deformable blocks: its row terms added to the estimate's
// bounds bound the estimate of the whole system (subadditive terms), as in the rigid case.
TEST(CriticalTimeStepDeformable, RowBoundsOfANewContactAddUp)
{
	std::mt19937                     rng(5);
	std::uniform_real_distribution<> u(0.1, 2.0), a(-1, 1);
	for (int trial = 0; trial < 100; ++trial) {
		std::vector<DynBody> b;
		for (int i = 0; i < 3; ++i) b.push_back(block(randomPolygon(rng, u(rng)), Vec2(a(rng), a(rng)), 3 * a(rng), (trial >> i) % 2 == 0));
		b[0].fixed = trial % 3 == 0;
		auto randomContact = [&](int i, int j) {
			const Vec2 n = Vec2(a(rng), a(rng)).normalized();
			return contact(i, j, n, 1e7 * u(rng), 1e7 * u(rng), { Vec2(a(rng), a(rng)), Vec2(a(rng), a(rng)) }, { u(rng), u(rng) });
		};
		const std::vector<DynContact> before = { randomContact(0, 1) };
		const DynContact              added  = randomContact(1, 2);
		std::vector<Real>             rows, diag;
		criticalTimeStepGershgorin(b, before, &rows, &diag);
		Real add1, add2, diag1, diag2;
		contactRowBounds(b, added, add1, add2, &diag1, &diag2);
		rows[1] += add1, rows[2] += add2;
		diag[1] += diag1, diag[2] += diag2;
		const Real              bound = 2 / std::sqrt(*std::max_element(rows.begin(), rows.end()));
		std::vector<DynContact> all   = before;
		all.push_back(added);
		EXPECT_LE(bound, criticalTimeStepGershgorin(b, all) * (1 + 1e-10)) << trial;
		EXPECT_LE(bound, criticalTimeStepExact(b, all) * (1 + 1e-10)) << trial;
		std::vector<Real> rowsAll, diagAll;
		criticalTimeStepGershgorin(b, all, &rowsAll, &diagAll);
		for (int k = 1; k < 3; ++k) {
			EXPECT_GE(diag[k], diagAll[k] * (1 - 1e-10)) << trial;
			EXPECT_GE(rows[k] - diag[k], (rowsAll[k] - diagAll[k]) * (1 - 1e-10) - 1e-9 * rowsAll[k]) << trial;
		}
	}
}

// Density scaling of deformable blocks (their whole mass: m, I, M_te, M_ee, by s) for the median
// block's row bound: the scaled system's exact step meets the target.
TEST(CriticalTimeStepDeformable, DensityScaledSystemMeetsTheTarget)
{
	std::mt19937 rng(9);
	for (int trial = 0; trial < 40; ++trial) {
		std::vector<DynBody>    b;
		std::vector<DynContact> c;
		randomScene(rng, b, c, 7);
		std::vector<Real> total, diag, rows;
		criticalTimeStepGershgorin(b, c, &total, &diag);
		for (size_t i = 0; i < b.size(); ++i)
			if (!b[i].fixed) rows.push_back(total[i]);
		std::nth_element(rows.begin(), rows.begin() + rows.size() / 2, rows.end());
		const Real omegaT2 = rows[rows.size() / 2];
		for (size_t i = 0; i < b.size(); ++i) {
			const Real s = densityScale(diag[i], total[i] - diag[i], omegaT2);
			b[i].mass *= s, b[i].inertia *= s, b[i].thetaStrainMass *= s, b[i].strainMass *= s;
		}
		const Real target = 2 / std::sqrt(omegaT2);
		EXPECT_GE(criticalTimeStepExact(b, c), target * (1 - 1e-9)) << trial;
		EXPECT_GE(criticalTimeStepGershgorin(b, c), target * (1 - 1e-9)) << trial;
	}
}

TEST(CriticalTimeStepDeformable, BadStrainMassThrows)
{
	std::vector<DynBody> b = { block(square(1), Vec2::Zero(), 0, true) };
	b[0].strainMass.setZero();
	EXPECT_THROW(criticalTimeStepGershgorin(b, {}), std::invalid_argument);
	EXPECT_THROW(criticalTimeStepExact(b, {}), std::invalid_argument);
	b[0].fixed = true; // a fixed block's mass is never used
	EXPECT_NO_THROW(criticalTimeStepGershgorin(b, {}));
}

namespace {
// A rigid-only scene from exact integer arithmetic (portable: no std distributions).
Real unitDraw(std::mt19937& g) { return Real(g() >> 8) / Real(1 << 24); }
void rigidScene(unsigned seed, std::vector<DynBody>& b, std::vector<DynContact>& c)
{
	std::mt19937 g(seed);
	const int    n = 7;
	b.assign(n, DynBody());
	for (int i = 0; i < n; ++i) {
		b[i].mass = 0.5 + unitDraw(g), b[i].inertia = 0.05 + 0.2 * unitDraw(g);
		b[i].centroid = Vec2(i % 4, i / 4 + 0.1 * unitDraw(g));
		b[i].fixed    = i == 0;
	}
	c.clear();
	for (int i = 1; i < n; ++i)
		for (int j : { i - 1, i - 4 }) {
			if (j < 0) continue;
			const Vec2 d = (b[i].centroid - b[j].centroid).normalized(), mid = 0.5 * (b[i].centroid + b[j].centroid), t(-d.y(), d.x());
			const Real kn = 1e8 * (0.5 + unitDraw(g)), ks = 4e7 * (0.5 + unitDraw(g));
			const Real a1 = 0.01 * (0.5 + unitDraw(g)), a2 = 0.01 * (0.5 + unitDraw(g));
			c.push_back(contact(j, i, d, kn, ks, { mid - 0.3 * t, mid + 0.2 * t }, { a1, a2 }));
		}
}
struct RigidValues {
	Real              dtBound, dtExact;
	std::vector<Real> rows, diag;
	Real              add1, add2, diag1, diag2;
};
} // namespace

// With no deformable block the 3-DOF code runs alone: the numbers below are those of the kernel
// before the 6-DOF extension (printed with %a, gcc on x86-64; a platform fusing multiply-adds may
// differ in the last bits, hence the tolerance elsewhere).
TEST(CriticalTimeStepDeformable, RigidOnlySceneUnchanged)
{
	const RigidValues expected[2] = {
		{ 0x1.1aedf7d8d0eb3p-12, 0x1.30f090d36078dp-12,
		  { 0, 0x1.8f84439b3886p+24, 0x1.8d680eef8259bp+23, 0x1.a32c457b865f6p+25, 0x1.55bdcc6fa730cp+25, 0x1.596b67817719ap+24, 0x1.1a6c27e9fdfccp+23 },
		  { 0, 0x1.2cac4c2a13fe9p+24, 0x1.3e17cd9f3c94ap+22, 0x1.0122cb50f18d8p+25, 0x1.6ba16025af4dap+24, 0x1.79434af7e4452p+23, 0x1.0c29caa22ad7p+22 },
		  0x1.52afed5982215p+25, 0x1.effa29658a56p+24, 0x1.96e362d78efe2p+24, 0x1.c2fb63142a23p+23 },
		{ 0x1.3a029027d8327p-12, 0x1.548b58bca4fa7p-12,
		  { 0, 0x1.dc56babd75b26p+22, 0x1.9452fcc2ee19cp+23, 0x1.544cfda4b33fep+25, 0x1.09afb01ab0b45p+25, 0x1.86731b81d03dep+23, 0x1.0dd71b8b61346p+23 },
		  { 0, 0x1.4188747726e86p+22, 0x1.a090ebe85701bp+22, 0x1.8d95f77720ab5p+24, 0x1.05a494d7d0d6fp+24, 0x1.b394f55cd0bdcp+22, 0x1.07e75784cf53cp+22 },
		  0x1.1ce57ea37342p+25, 0x1.c1adc633f1ec3p+24, 0x1.4bc5badc7db3p+24, 0x1.a751079312368p+23 },
	};
#if defined(__x86_64__) && !defined(__FMA__)
	const Real tol = 0; // bit for bit
#else
	const Real tol = 1e-13;
#endif
	for (unsigned seed : { 1u, 2u }) {
		const RigidValues&      x = expected[seed - 1];
		std::vector<DynBody>    b;
		std::vector<DynContact> c;
		rigidScene(seed, b, c);
		ASSERT_EQ(c.size(), 9u);
		std::vector<Real> rows, diag;
		EXPECT_NEAR(criticalTimeStepGershgorin(b, c, &rows, &diag), x.dtBound, tol * x.dtBound);
		EXPECT_NEAR(criticalTimeStepExact(b, c), x.dtExact, tol * x.dtExact);
		for (size_t i = 0; i < rows.size(); ++i) {
			EXPECT_NEAR(rows[i], x.rows[i], tol * x.rows[i]) << i;
			EXPECT_NEAR(diag[i], x.diag[i], tol * x.diag[i]) << i;
		}
		Real add1, add2, diag1, diag2;
		contactRowBounds(b, c[3], add1, add2, &diag1, &diag2);
		EXPECT_NEAR(add1, x.add1, tol * x.add1);
		EXPECT_NEAR(add2, x.add2, tol * x.add2);
		EXPECT_NEAR(diag1, x.diag1, tol * x.diag1);
		EXPECT_NEAR(diag2, x.diag2, tol * x.diag2);

		// the 6-DOF path on the same rigid blocks (a loose deformable block with no stiffness forces it)
		// agrees with the 3-DOF numbers to rounding
		std::vector<DynBody> withLoose = b;
		withLoose.push_back(block(square(1), Vec2(50, 50), 0.3, true));
		withLoose.back().strainStiffness.setZero();
		std::vector<Real> rows6, diag6;
		EXPECT_NEAR(criticalTimeStepGershgorin(withLoose, c, &rows6, &diag6), x.dtBound, 1e-12 * x.dtBound);
		EXPECT_NEAR(criticalTimeStepExact(withLoose, c), x.dtExact, 1e-10 * x.dtExact);
		for (size_t i = 0; i < rows.size(); ++i) {
			EXPECT_NEAR(rows6[i], x.rows[i], 1e-12 * x.rows[i]) << i;
			EXPECT_NEAR(diag6[i], x.diag[i], 1e-12 * x.diag[i]) << i;
		}
		EXPECT_EQ(rows6.back(), 0);
	}
}
