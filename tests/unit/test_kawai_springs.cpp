// Kawai springs in a one-joint patch: two rigid blocks whose centroids (and rotations) follow a
// uniform continuum strain field must reproduce the continuum tractions on the joint.
// Continuum moduli are computed independently from the Lame constants.
#include <pkg/rbsm/kernel/KawaiSprings.hpp>

#include <gtest/gtest.h>
#include <stdexcept>

using namespace rbsm;

namespace {
struct Lame {
	Real lambda, mu;
};
Lame lame(Real E, Real nu) { return { E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu)) }; }

// Joint on the line y = 0 (n = (0,1), t = (-1,0)); block 1 centroid (0,-h1), block 2 (0,h2).
// Displacement gradient H (u = H x); the blocks move rigidly with their centroid's displacement
// and the continuum rotation omega = (H10 - H01)/2. Returns the relative displacement of
// body 2 w.r.t. body 1 at the joint point (0,0).
Vec2 jointJump(const Eigen::Matrix2d& H, Real h1, Real h2)
{
	const Real omega = (H(1, 0) - H(0, 1)) / 2;
	auto pointDisp   = [&](const Vec2& c) {
                const Vec2 r = Vec2(0, 0) - c;
                return Vec2(H * c + omega * Vec2(-r.y(), r.x()));
	};
	return pointDisp(Vec2(0, h2)) - pointDisp(Vec2(0, -h1));
}
} // namespace

// Laterally constrained strain eps_yy = eps: sigma_yy = (lambda* + 2 mu) eps, with
// lambda* = lambda (plane strain) or 2 lambda mu / (lambda + 2 mu) (plane stress).
TEST(KawaiSprings, NormalSpringGivesConstrainedModulus)
{
	const Real E = 200e6, nu = 0.2, h1 = 0.3, h2 = 0.7, eps = 1e-4;
	Eigen::Matrix2d H;
	H << 0, 0, 0, eps;
	const Vec2 jump = jointJump(H, h1, h2);
	const Lame L    = lame(E, nu);
	for (auto ps : { PlaneState::PlaneStress, PlaneState::PlaneStrain }) {
		const auto k       = kawaiSprings(E, nu, h1 + h2, ps);
		const Real lstar   = ps == PlaneState::PlaneStrain ? L.lambda : 2 * L.lambda * L.mu / (L.lambda + 2 * L.mu);
		const Real sigmaYY = (lstar + 2 * L.mu) * eps; // tension positive
		// joint opening = jump.n (positive: blocks move apart) -> tensile traction kn * opening
		EXPECT_NEAR(k.kn * jump.y(), sigmaYY, 1e-9 * sigmaYY);
		EXPECT_NEAR(jump.x(), 0, 1e-20);
	}
	// and the two plane states really differ (the test can tell them apart)
	EXPECT_GT(kawaiSprings(E, 0.3, 1, PlaneState::PlaneStrain).kn, 1.1 * kawaiSprings(E, 0.3, 1, PlaneState::PlaneStress).kn);
}

// Pure shear (H symmetric, off-diagonal gamma/2) and simple shear (H01 = gamma, with the block
// rotation -gamma/2) both give a jump gamma h/2 along the joint, so tau = mu gamma.
TEST(KawaiSprings, ShearSpringGivesShearModulus)
{
	const Real E = 30e9, nu = 0.25, h1 = 0.5, h2 = 0.5, g = 2e-4;
	Eigen::Matrix2d pure, simple;
	pure << 0, g / 2, g / 2, 0;
	simple << 0, g, 0, 0;
	const Real mu = lame(E, nu).mu;
	for (auto ps : { PlaneState::PlaneStress, PlaneState::PlaneStrain }) {
		const auto k = kawaiSprings(E, nu, h1 + h2, ps);
		for (const auto& H : { pure, simple }) {
			const Vec2 jump = jointJump(H, h1, h2);
			EXPECT_NEAR(std::abs(jump.x()), g * (h1 + h2) / 2, 1e-18);
			EXPECT_NEAR(k.ks * std::abs(jump.x()), mu * g, 1e-9 * mu * g);
		}
	}
}

// Two materials: a constrained stress sigma crossing both halves strains them by sigma/E_i',
// so the centroids separate by sigma (h1/E1' + h2/E2'); the series spring must return sigma.
TEST(KawaiSprings, TwoMaterialsInSeries)
{
	const Real E1 = 10e9, nu1 = 0.2, h1 = 0.4, E2 = 50e6, nu2 = 0.35, h2 = 1.1, sigma = 1e5;
	for (auto ps : { PlaneState::PlaneStress, PlaneState::PlaneStrain }) {
		const auto k    = kawaiSpringsTwoMaterials(E1, nu1, h1, E2, nu2, h2, ps);
		const Real open = sigma * h1 / constrainedModulus(E1, nu1, ps) + sigma * h2 / constrainedModulus(E2, nu2, ps);
		EXPECT_NEAR(k.kn * open, sigma, 1e-9 * sigma);
		const Real slip = sigma * h1 / (2 * shearModulus(E1, nu1)) + sigma * h2 / (2 * shearModulus(E2, nu2));
		EXPECT_NEAR(k.ks * slip, sigma, 1e-9 * sigma);
		// same material on both sides reduces to the single-material formula
		const auto a = kawaiSpringsTwoMaterials(E1, nu1, h1, E1, nu1, h2, ps), b = kawaiSprings(E1, nu1, h1 + h2, ps);
		EXPECT_NEAR(a.kn, b.kn, 1e-9 * b.kn);
		EXPECT_NEAR(a.ks, b.ks, 1e-9 * b.ks);
	}
}

TEST(KawaiSprings, DistanceAndInvalidInput)
{
	EXPECT_NEAR(distanceToLine(Vec2(1, 3), Vec2(5, 1), Vec2(0, 1)), 2, 1e-15);
	EXPECT_NEAR(distanceToLine(Vec2(1, -3), Vec2(5, 1), Vec2(0, 1)), 4, 1e-15);
	EXPECT_THROW(kawaiSprings(1e9, 0.2, 0, PlaneState::PlaneStress), std::invalid_argument);
	EXPECT_THROW(kawaiSprings(-1, 0.2, 1, PlaneState::PlaneStress), std::invalid_argument);
	EXPECT_THROW(kawaiSprings(1e9, 0.5, 1, PlaneState::PlaneStrain), std::invalid_argument);
	EXPECT_NO_THROW(kawaiSprings(1e9, 0.5, 1, PlaneState::PlaneStress));
}
