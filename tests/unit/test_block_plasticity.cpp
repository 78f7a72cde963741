// The block's Mohr–Coulomb return map (issue 39): admissible results, the consistency of f = 0, the flow
// rule (ψ = 0 keeps the area; ψ = φ is normal to f), the tension cut-off and its corner, isotropy.
#include <pkg/rbsm/kernel/BlockPlasticity.hpp>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <cmath>
#include <random>

using namespace rbsm;

namespace {
const Real deg = M_PI / 180;

MohrCoulombStrength soil(Real c, Real phiDeg, Real tension, Real psiDeg = 0)
{
	return { c, phiDeg * deg, tension, psiDeg * deg };
}
// σ1 ≥ σ3 of a plane stress
std::pair<Real, Real> principals(const Vec3& s)
{
	const Real m = (s[0] + s[1]) / 2, r = std::hypot((s[0] - s[1]) / 2, s[2]);
	return { m + r, m - r };
}
Vec3 rotated(const Vec3& s, Real angle)
{
	Eigen::Matrix2d R, S;
	R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
	S << s[0], s[2], s[2], s[1];
	S = R * S * R.transpose();
	return Vec3(S(0, 0), S(1, 1), S(0, 1));
}
} // namespace

TEST(BlockPlasticity, AdmissibleStressIsKept)
{
	const Mat3 D = elasticityMatrix(1e8, 0.3, true);
	const Vec3 s(-2e5, -1e5, 1e4);
	const PlasticReturn r = mohrCoulombReturn(s, D, soil(1e4, 30, 0));
	EXPECT_EQ(r.mode, YieldMode::elastic);
	EXPECT_EQ(r.stress, s);
	EXPECT_EQ(r.plasticStrain, Vec3::Zero());
}

// ψ = 0: the return keeps the mean in-plane stress and lands on f = 0; the plastic strain is D⁻¹(σ_trial − σ).
TEST(BlockPlasticity, ShearReturnWithoutDilatancy)
{
	const Mat3 D = elasticityMatrix(1e8, 0.3, true);
	const MohrCoulombStrength m = soil(1e4, 20, 1e9);
	const Vec3 trial(-3e5, -5e4, 8e4);
	const PlasticReturn r = mohrCoulombReturn(trial, D, m);
	EXPECT_EQ(r.mode, YieldMode::shear);
	EXPECT_NEAR(mohrCoulombShear(r.stress, m), 0, 1e-9 * m.cohesion);
	EXPECT_NEAR(r.stress[0] + r.stress[1], trial[0] + trial[1], 1e-9 * std::abs(trial[0]));
	EXPECT_NEAR(r.plasticStrain[0] + r.plasticStrain[1], 0, 1e-15); // no plastic change of area
	EXPECT_LT((D * r.plasticStrain - (trial - r.stress)).norm(), 1e-6);
	EXPECT_GT(r.plasticShear, 0);
	// the principal axes are the trial's
	EXPECT_NEAR(std::atan2(2 * r.stress[2], r.stress[0] - r.stress[1]), std::atan2(2 * trial[2], trial[0] - trial[1]), 1e-12);
}

// ψ = φ (associated): the plastic strain is normal to f, Δε1/Δε3 = −(1 + sin φ)/(1 − sin φ).
TEST(BlockPlasticity, AssociatedFlowIsNormal)
{
	const Mat3 D = elasticityMatrix(5e7, 0.25, false);
	const MohrCoulombStrength m = soil(2e4, 35, 1e9, 35);
	const PlasticReturn r = mohrCoulombReturn(Vec3(-4e5, -1e4, 0), D, m);
	ASSERT_EQ(r.mode, YieldMode::shear);
	const Real s = std::sin(35 * deg);
	EXPECT_NEAR(r.plasticStrain[1] / r.plasticStrain[0], -(1 + s) / (1 - s), 1e-9); // σ1 along y here
	EXPECT_NEAR(mohrCoulombShear(r.stress, m), 0, 1e-9 * m.cohesion);
}

// Tresca (φ = 0): whatever the trial, the returned radius of Mohr's circle is c.
TEST(BlockPlasticity, TrescaRadiusIsCohesion)
{
	const Mat3 D = elasticityMatrix(1e8, 0.49, true);
	std::mt19937 rng(3);
	std::uniform_real_distribution<Real> u(-1e6, 1e6);
	for (int k = 0; k < 200; k++) {
		const Vec3 trial(u(rng) - 1e6, u(rng) - 1e6, u(rng));
		const PlasticReturn r = mohrCoulombReturn(trial, D, soil(5e4, 0, 1e12));
		const auto [s1, s3] = principals(r.stress);
		if (r.mode == YieldMode::elastic) EXPECT_LE(s1 - s3, 1e5 * (1 + 1e-12));
		else EXPECT_NEAR(s1 - s3, 1e5, 1e-6);
	}
}

// The tension cut-off: uniaxial tension returns σ1 to σt (plastic strain along 1 only); biaxial tension
// to σt both ways; a cut-off above the apex acts at the apex c cot φ.
TEST(BlockPlasticity, TensionCutOffAndCorner)
{
	const Mat3 D = elasticityMatrix(1e8, 0.2, false);
	const MohrCoulombStrength m = soil(1e5, 30, 2e4);
	PlasticReturn r = mohrCoulombReturn(Vec3(5e4, 0, 0), D, m);
	EXPECT_EQ(r.mode, YieldMode::tension);
	EXPECT_NEAR(r.stress[0], 2e4, 1e-6);
	EXPECT_NEAR(r.plasticStrain[1], 0, 1e-18);
	EXPECT_NEAR(r.plasticStrain[2], 0, 1e-18);
	r = mohrCoulombReturn(Vec3(5e4, 6e4, 0), D, m);
	EXPECT_NEAR(r.stress[0], 2e4, 1e-6);
	EXPECT_NEAR(r.stress[1], 2e4, 1e-6);
	// a trial in tension with much compression across: returned to the corner of the two surfaces
	r = mohrCoulombReturn(Vec3(3e5, -5e5, 0), D, m);
	EXPECT_EQ(r.mode, YieldMode::corner);
	EXPECT_NEAR(r.stress[0], 2e4, 1e-6);
	EXPECT_NEAR(mohrCoulombShear(r.stress, m), 0, 1e-6);
	// σt above the apex: the apex
	const MohrCoulombStrength weak = soil(1e4, 30, 1e9);
	r = mohrCoulombReturn(Vec3(1e6, 1e6, 0), D, weak);
	EXPECT_NEAR(r.stress[0], 1e4 / std::tan(30 * deg), 1e-6);
	EXPECT_NEAR(r.stress[1], 1e4 / std::tan(30 * deg), 1e-6);
}

// Random trials: the result is admissible, the plastic work is not negative,
// and a rotated trial gives the rotated result.
TEST(BlockPlasticity, RandomTrialsAreAdmissibleAndIsotropic)
{
	std::mt19937 rng(11);
	std::uniform_real_distribution<Real> u(-1, 1), unit(0, 1);
	for (int k = 0; k < 2000; k++) {
		const Real scale = std::pow(10.0, 3 + 4 * unit(rng));
		const Mat3 D = elasticityMatrix(std::pow(10.0, 6 + 4 * unit(rng)), 0.45 * unit(rng), k % 2 == 0);
		const Real phi = 44 * unit(rng);
		const MohrCoulombStrength m = soil(scale * unit(rng), phi, scale * unit(rng), phi * unit(rng));
		const Vec3 trial = scale * Vec3(10 * u(rng) - 3, 10 * u(rng) - 3, 5 * u(rng));
		const PlasticReturn r = mohrCoulombReturn(trial, D, m);
		const Real tol = 1e-9 * scale * 20;
		const Real cut = std::min(m.tensileStrength, phi > 0 ? m.cohesion / std::tan(m.frictionAngle) : 1e300);
		EXPECT_LE(mohrCoulombShear(r.stress, m), tol) << k;
		EXPECT_LE(principals(r.stress).first, cut + tol) << k;
		EXPECT_GE(r.stress.dot(r.plasticStrain), -1e-9 * scale * r.plasticStrain.norm()) << k;
		const Real angle = 6.28 * unit(rng);
		const PlasticReturn q = mohrCoulombReturn(rotated(trial, angle), D, m);
		EXPECT_LT((q.stress - rotated(r.stress, angle)).norm(), 1e-9 * trial.norm()) << k;
		EXPECT_NEAR(q.plasticShear, r.plasticShear, 1e-9 * (r.plasticShear + 1e-30)) << k;
	}
}
