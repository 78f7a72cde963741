// The deformable block's constant-strain element: polygon moments against closed forms, its mass
// against quadrature, the patch identity of its strain load, and its own strain frequencies.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/StrainElement.hpp>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace rbsm;

namespace {
using Mat2 = Eigen::Matrix<Real, 2, 2>;

std::vector<Vec2> rectangle(Real a, Real b)
{
	return { Vec2(-a / 2, -b / 2), Vec2(a / 2, -b / 2), Vec2(a / 2, b / 2), Vec2(-a / 2, b / 2) };
}
// An irregular convex pentagon, moved to its centroid.
std::vector<Vec2> pentagon()
{
	std::vector<Vec2> v = { Vec2(0.1, -0.3), Vec2(1.2, 0.0), Vec2(1.4, 0.9), Vec2(0.5, 1.3), Vec2(-0.2, 0.6) };
	const Vec2 c = massProperties(v).centroid; // (the kernel's shoelace formulas)
	for (auto& p : v) p -= c;
	return v;
}
Mat4 fullMass(const StrainMass& M)
{
	Mat4 M4;
	M4 << M.polar, M.thetaStrain.transpose(), M.thetaStrain, M.strain;
	return M4;
}
Mat2 tensor(const AreaMoments& m) { return (Mat2() << m.Ixx, m.Ixy, m.Ixy, m.Iyy).finished(); }
} // namespace

// Rectangle a (along x) by b: Ixx = b a³/12, Iyy = a b³/12, Ixy = 0, A = a b.
TEST(StrainElement, RectangleMoments)
{
	const Real        a = 3, b = 0.7;
	const AreaMoments m = areaMoments(rectangle(a, b));
	EXPECT_NEAR(m.area, a * b, 1e-14);
	EXPECT_NEAR(m.Ixx, b * a * a * a / 12, 1e-14);
	EXPECT_NEAR(m.Iyy, a * b * b * b / 12, 1e-14);
	EXPECT_NEAR(m.Ixy, 0, 1e-14);
}

// Rotating a polygon by R turns its moment tensor J = [[Ixx, Ixy], [Ixy, Iyy]] into R J Rᵀ.
TEST(StrainElement, RotatedMomentsTransformAsATensor)
{
	const Real phi = 0.37;
	Mat2       R;
	R << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
	for (const auto& v : { rectangle(2, 0.5), pentagon() }) {
		std::vector<Vec2> w = v;
		for (auto& p : w) p = R * p;
		const Mat2 expected = R * tensor(areaMoments(v)) * R.transpose();
		EXPECT_LT((tensor(areaMoments(w)) - expected).norm(), 1e-14 * expected.norm());
		EXPECT_NEAR(areaMoments(w).area, areaMoments(v).area, 1e-14);
	}
}

// Right triangle with legs a (x) and b (y), about its centroid: Ixx = b a³/36, Iyy = a b³/36,
// Ixy = −a² b²/72.
TEST(StrainElement, RightTriangleMoments)
{
	const Real              a = 2, b = 0.9;
	const Vec2              c(a / 3, b / 3);
	const std::vector<Vec2> v = { Vec2(0, 0) - c, Vec2(a, 0) - c, Vec2(0, b) - c };
	const AreaMoments       m = areaMoments(v);
	EXPECT_NEAR(m.area, a * b / 2, 1e-14);
	EXPECT_NEAR(m.Ixx, b * a * a * a / 36, 1e-14);
	EXPECT_NEAR(m.Iyy, a * b * b * b / 36, 1e-14);
	EXPECT_NEAR(m.Ixy, -a * a * b * b / 72, 1e-14);
}

// M_θε = (−Ixy, Ixy, (Ixx − Iyy)/2): zero when the moment tensor is isotropic (square, regular
// hexagon); a rectangle couples θ with γ only, by (Ixx − Iyy)/2; a triangle couples all three.
TEST(StrainElement, RotationStrainCoupling)
{
	const Real        rho = 2000, t = 0.5;
	std::vector<Vec2> hexagon;
	for (int k = 0; k < 6; ++k) hexagon.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3));
	EXPECT_LT(strainMass(areaMoments(rectangle(1, 1)), rho, t).thetaStrain.norm(), 1e-12);
	EXPECT_LT(strainMass(areaMoments(hexagon), rho, t).thetaStrain.norm(), 1e-12);
	const Real a = 2, b = 1;
	const Vec3 rect = strainMass(areaMoments(rectangle(a, b)), rho, t).thetaStrain;
	EXPECT_NEAR(rect[0], 0, 1e-12);
	EXPECT_NEAR(rect[1], 0, 1e-12);
	EXPECT_NEAR(rect[2], rho * t * (b * a * a * a - a * b * b * b) / 24, 1e-9);
	const Vec2 c(1.0 / 3, 1.0 / 3);
	const Vec3 tri = strainMass(areaMoments({ Vec2(0, 0) - c, Vec2(1, 0) - c, Vec2(0, 1) - c }), rho, t).thetaStrain;
	EXPECT_GT(std::abs(tri[0]), 1);
	EXPECT_GT(std::abs(tri[1]), 1);
}

// M = ρ t ∫ NᵀN dA, N(r) = [(−ry, rx)ᵀ, B(r)] (2×4), by a fan of triangles from the centroid, each with
// the edge-midpoint rule (exact for the quadratic integrand).
TEST(StrainElement, MassEqualsQuadrature)
{
	const Real rho = 2500, t = 0.3;
	for (const auto& v : { pentagon(), rectangle(1.5, 0.4) }) {
		Mat4 Q = Mat4::Zero();
		for (size_t i = 0; i < v.size(); ++i) {
			const Vec2 p0 = Vec2::Zero(), p1 = v[i], p2 = v[(i + 1) % v.size()];
			const Real area = cross2(p1, p2) / 2;
			for (const Vec2& r : { Vec2((p0 + p1) / 2), Vec2((p1 + p2) / 2), Vec2((p2 + p0) / 2) }) {
				Eigen::Matrix<Real, 2, 4> N;
				N << -r.y(), r.x(), 0, r.y() / 2, r.x(), 0, r.y(), r.x() / 2;
				Q += (area / 3) * N.transpose() * N;
			}
		}
		Q *= rho * t;
		const StrainMass M = strainMass(areaMoments(v), rho, t);
		EXPECT_LT((fullMass(M) - Q).norm(), 1e-12 * Q.norm());
		// the columns of N are consistent with strainDisplacement
		const Vec2 r(0.3, -0.2);
		const Vec3 eps(0.1, -0.4, 0.7);
		EXPECT_LT((strainDisplacement(r, eps) - Vec2(r.x() * 0.1 + r.y() * 0.35, r.y() * -0.4 + r.x() * 0.35)).norm(), 1e-15);
	}
}

// Patch identity: the tractions σ·n of a uniform stress on the boundary load ε with
// Σ_edges ∫ Bᵀ(r) σ·n ds = A (σxx, σyy, σxy) (divergence theorem); r is linear along an edge, so its
// first moment is exact with the edge midpoint.
TEST(StrainElement, PatchIdentityOfTheStrainLoad)
{
	Mat2 sigma;
	sigma << 3.0, -1.2, -1.2, 0.5;
	for (const auto& v : { pentagon(), rectangle(1.5, 0.4) }) {
		Mat2 Q = Mat2::Zero();
		for (size_t i = 0; i < v.size(); ++i) {
			const Vec2 a = v[i], b = v[(i + 1) % v.size()];
			const Vec2 nL(b.y() - a.y(), a.x() - b.x()); // outward normal times the edge length (CCW)
			Q += ((a + b) / 2) * (sigma * nL).transpose();
		}
		const Real A        = areaMoments(v).area;
		const Vec3 expected = A * Vec3(sigma(0, 0), sigma(1, 1), sigma(0, 1));
		EXPECT_LT((strainLoad(Q) - expected).norm(), 1e-13 * expected.norm());
	}
}

// strainAccelerations solves [[M_θθ, M_θεᵀ], [M_θε, M_εε]] (θ̈, ε̈) = (T, P).
TEST(StrainElement, StrainAccelerationsSolveTheCoupledSystem)
{
	const StrainMass M = strainMass(areaMoments(pentagon()), 2000, 0.7);
	const Vec3       P(1e3, -2e3, 5e2);
	const Real       T   = 300;
	const Vec4       acc = strainAccelerations(M, T, P);
	EXPECT_LT((fullMass(M) * acc - Vec4(T, P[0], P[1], P[2])).norm(), 1e-10 * P.norm());
	EXPECT_LT((M.inverse * fullMass(M) - Mat4::Identity()).norm(), 1e-12);
}

// Square of side h, plane stress: M_θε = 0, M_εε = ρ t h⁴/12 diag(1, 1, 1/2), K = h² t D, so
// ω² = 12 max(D11 + D12, 2 D33) / (ρ h²); with c_p = √(D11/ρ), ω h / c_p = √(12 (1 + ν)) ≈ 3.5 at ν = 0
// (the 1D intuition: a few c_p/h). A triangle (θ coupled to ε) against the Schur complement
// M_εε − M_θε M_θεᵀ / M_θθ, solved densely.
TEST(StrainElement, OwnStrainOmega2)
{
	const Real rho = 2400, t = 1, E = 3e10, h = 0.2;
	for (Real nu : { 0.0, 0.2, 0.45 }) {
		const Mat3       D = elasticityMatrix(E, nu, false);
		const StrainMass M = strainMass(areaMoments(rectangle(h, h)), rho, t);
		const Real       w2 = ownStrainOmega2(M, h * h * t * D);
		EXPECT_NEAR(w2, 12 * std::max(D(0, 0) + D(0, 1), 2 * D(2, 2)) / (rho * h * h), 1e-10 * w2);
		const Real ratio = std::sqrt(w2) * h / std::sqrt(D(0, 0) / rho);
		EXPECT_NEAR(ratio, std::sqrt(12 * (1 + nu)), 1e-9);
		EXPECT_GT(ratio, 2);
		EXPECT_LT(ratio, 6);
	}
	const Vec2              c(h / 3, h / 3);
	const std::vector<Vec2> tri = { Vec2(0, 0) - c, Vec2(h, 0) - c, Vec2(0, h) - c };
	const AreaMoments       m   = areaMoments(tri);
	const StrainMass        M   = strainMass(m, rho, t);
	const Mat3              K   = m.area * t * elasticityMatrix(E, 0.3, true);
	const Mat3              Meff = M.strain - M.thetaStrain * M.thetaStrain.transpose() / M.polar;
	const Eigen::EigenSolver<Mat3> es(Meff.inverse() * K);
	const Real                     expected = es.eigenvalues().real().maxCoeff();
	EXPECT_NEAR(ownStrainOmega2(M, K), expected, 1e-10 * expected);
	// θ locked is a constrained system: its highest ω² cannot exceed the free one's
	const Eigen::EigenSolver<Mat3> locked(M.strain.inverse() * K);
	EXPECT_GE(ownStrainOmega2(M, K), locked.eigenvalues().real().maxCoeff() * (1 - 1e-12));
}

// Uniaxial stress σ = (1, 0, 0): plane stress gives back 1/εxx = E, −εyy/εxx = ν; plane strain the
// apparent E/(1 − ν²) and ν/(1 − ν). Both have σxy = G γxy, G = E / (2 (1 + ν)).
TEST(StrainElement, ElasticityMatrixGivesBackEAndNu)
{
	const Real E = 2e7, nu = 0.3;
	for (bool planeStrain : { false, true }) {
		const Mat3 D   = elasticityMatrix(E, nu, planeStrain);
		const Vec3 eps = D.inverse() * Vec3(1, 0, 0);
		const Real Eapp = planeStrain ? E / (1 - nu * nu) : E, nuApp = planeStrain ? nu / (1 - nu) : nu;
		EXPECT_NEAR(1 / eps[0], Eapp, 1e-9 * E);
		EXPECT_NEAR(-eps[1] / eps[0], nuApp, 1e-12);
		EXPECT_NEAR(eps[2], 0, 1e-20);
		EXPECT_NEAR(D(2, 2), E / (2 * (1 + nu)), 1e-9 * E);
		EXPECT_LT((D - D.transpose()).norm(), 1e-9);
	}
}

TEST(StrainElement, BadInputThrows)
{
	const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
	for (Real E : { 0.0, -1.0, nan, inf }) EXPECT_THROW(elasticityMatrix(E, 0.2, true), std::invalid_argument) << E;
	for (Real nu : { 0.5, -1.0, 0.7, nan }) EXPECT_THROW(elasticityMatrix(1e9, nu, false), std::invalid_argument) << nu;
	EXPECT_NO_THROW(elasticityMatrix(1e9, -0.9, false));
	// a degenerate (collinear) polygon, or no density, has no positive definite mass
	EXPECT_THROW(strainMass(areaMoments({ Vec2(-1, 0), Vec2(0, 0), Vec2(1, 0) }), 2000, 1), std::invalid_argument);
	EXPECT_THROW(strainMass(areaMoments(rectangle(1, 1)), 0, 1), std::invalid_argument);
}
