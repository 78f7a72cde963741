// Mohr-Coulomb joint point: stick, slip, dissipation = tau_max * plastic slip, tension and shear
// breakage, irreversibility, open joints, cohesionless fast path.
#include <pkg/rbsm/kernel/MohrCoulombJoint.hpp>

#include <gtest/gtest.h>

using namespace rbsm;

namespace {
JointParams frictional() { return JointParams { 1e9, 5e8, 0, 0.5, 0 }; }
JointParams cohesive() { return JointParams { 1e9, 5e8, 1e5, 0.5, 2e4 }; }
constexpr Real a = 0.02; // tributary area, m^2
} // namespace

// Elastic stick: sigma_n = kn dn; tau = -ks dus (traction on body 2 opposes its slip).
TEST(MohrCoulombJoint, StickElastic)
{
	JointPointState s;
	const auto      p = frictional();
	auto r = updateJointPoint(s, p, 1e-4, 1e-5, a);
	EXPECT_DOUBLE_EQ(r.normalTraction, 1e5);
	EXPECT_DOUBLE_EQ(r.shearTraction, -5e3);
	EXPECT_DOUBLE_EQ(s.shearTraction, -5e3);
	EXPECT_DOUBLE_EQ(r.normalForce, 1e5 * a);
	EXPECT_DOUBLE_EQ(r.shearForce, -5e3 * a);
	EXPECT_FALSE(s.slipping);
	EXPECT_FALSE(s.open);
	EXPECT_DOUBLE_EQ(r.dissipated, 0);
	EXPECT_NEAR(r.elasticEnergy, (1e10 / (2 * 1e9) + 25e6 / (2 * 5e8)) * a, 1e-12);
	// incremental: a second equal increment doubles tau
	r = updateJointPoint(s, p, 1e-4, 1e-5, a);
	EXPECT_DOUBLE_EQ(s.shearTraction, -1e4);
}

// Monotonic slip U in N equal steps at constant sigma_n: tau saturates at tau_max = sigma_n tan(phi),
// and the total dissipation is tau_max * (U - tau_max/ks) * a (closed form).
TEST(MohrCoulombJoint, SlipAndDissipation)
{
	JointPointState s;
	const auto      p = frictional();
	const Real      dn = 1e-4, tmax = 1e9 * dn * 0.5; // 5e4 Pa
	const Real      du = -1e-5;
	const int       N  = 30;                          // U = 3e-4, yield at 1e-4
	Real            D  = 0;
	for (int i = 0; i < N; ++i) D += updateJointPoint(s, p, dn, du, a).dissipated;
	EXPECT_TRUE(s.slipping);
	EXPECT_DOUBLE_EQ(s.shearTraction, tmax);
	EXPECT_NEAR(D, tmax * (N * std::abs(du) - tmax / p.ks) * a, 1e-9 * tmax * a);
	// reversing the motion unloads elastically (no more slip, no dissipation)
	const auto r = updateJointPoint(s, p, dn, -du, a);
	EXPECT_FALSE(s.slipping);
	EXPECT_DOUBLE_EQ(r.dissipated, 0);
	EXPECT_NEAR(s.shearTraction, tmax - 5e3, 1e-9);
	// the friction limit follows sigma_n: halving dn halves tau_max
	updateJointPoint(s, p, dn / 2, 0, a);
	EXPECT_NEAR(s.shearTraction, tmax / 2, 1e-9);
	EXPECT_TRUE(s.slipping);
}

// Tension cut-off: sigma_n < -sigma_t breaks the point irreversibly; it then carries no tension
// even at a tensile overlap an intact point would carry, but it does carry compression + friction.
TEST(MohrCoulombJoint, TensionBreakIsIrreversible)
{
	const auto      p = cohesive();
	JointPointState intact;
	auto r = updateJointPoint(intact, p, -1e-5, 0, a); // sigma_n = -1e4 > -2e4: holds
	EXPECT_TRUE(intact.intact);
	EXPECT_DOUBLE_EQ(r.normalTraction, -1e4);

	JointPointState s;
	r = updateJointPoint(s, p, -3e-5, 0, a); // -3e4 < -2e4: breaks
	EXPECT_TRUE(r.brokeInTension);
	EXPECT_FALSE(r.brokeInShear);
	EXPECT_FALSE(s.intact);
	EXPECT_TRUE(s.open);
	EXPECT_DOUBLE_EQ(r.normalForce, 0);
	EXPECT_DOUBLE_EQ(r.shearForce, 0);
	r = updateJointPoint(s, p, -1e-5, 0, a); // would hold if intact; broken carries nothing
	EXPECT_TRUE(s.open);
	EXPECT_DOUBLE_EQ(r.normalTraction, 0);
	EXPECT_FALSE(r.brokeInTension); // the event is reported once
	r = updateJointPoint(s, p, 1e-4, -1e-4, a); // closed again: friction only, no cohesion
	EXPECT_FALSE(s.open);
	EXPECT_DOUBLE_EQ(r.normalTraction, 1e5);
	EXPECT_DOUBLE_EQ(r.shearTraction, 0.5 * 1e5); // trial 5e4 = limit without cohesion
	r = updateJointPoint(s, p, 1e-4, -1e-4, a);
	EXPECT_TRUE(s.slipping);
	EXPECT_DOUBLE_EQ(r.shearTraction, 0.5 * 1e5);
}

// Shear break: intact limit c + sigma_n tan(phi) = 1.5e5 Pa; a trial of 2e5 breaks the cohesion
// and returns tau to sigma_n tan(phi) = 5e4, dissipating 5e4 * (2e5 - 5e4)/ks * a.
TEST(MohrCoulombJoint, ShearBreak)
{
	const auto      p = cohesive();
	JointPointState s;
	auto r = updateJointPoint(s, p, 1e-4, -2.8e-4, a); // trial 1.4e5 < 1.5e5: holds
	EXPECT_TRUE(s.intact);
	EXPECT_FALSE(s.slipping);
	EXPECT_DOUBLE_EQ(r.shearTraction, 1.4e5);
	JointPointState t;
	r = updateJointPoint(t, p, 1e-4, -4e-4, a); // trial 2e5
	EXPECT_TRUE(r.brokeInShear);
	EXPECT_FALSE(t.intact);
	EXPECT_TRUE(t.slipping);
	EXPECT_DOUBLE_EQ(r.shearTraction, 5e4);
	EXPECT_NEAR(r.dissipated, 5e4 * (2e5 - 5e4) / p.ks * a, 1e-9);
	// the cohesion never comes back
	r = updateJointPoint(t, p, 1e-4, -2e-4, a);
	EXPECT_FALSE(r.brokeInShear);
	EXPECT_DOUBLE_EQ(r.shearTraction, 5e4);
}

// Shear break of a point in (allowed) tension: with c gone it cannot hold tension -> open.
TEST(MohrCoulombJoint, ShearBreakInTensionOpens)
{
	const auto      p = cohesive();
	JointPointState s;
	const auto r = updateJointPoint(s, p, -1e-5, -3e-4, a); // limit 1e5 - 5e3; trial 1.5e5
	EXPECT_TRUE(r.brokeInShear);
	EXPECT_TRUE(s.open);
	EXPECT_DOUBLE_EQ(r.shearForce, 0);
	EXPECT_DOUBLE_EQ(s.shearTraction, 0);
}

// A broken point that opens forgets its shear traction; on re-contact tau restarts from 0.
TEST(MohrCoulombJoint, OpenJointResetsShear)
{
	const auto      p = frictional();
	JointPointState s;
	updateJointPoint(s, p, 1e-4, 1e-5, a);
	EXPECT_NE(s.shearTraction, 0);
	const auto r = updateJointPoint(s, p, -1e-6, 1e-5, a);
	EXPECT_TRUE(s.open);
	EXPECT_DOUBLE_EQ(s.shearTraction, 0);
	EXPECT_DOUBLE_EQ(r.elasticEnergy, 0);
	updateJointPoint(s, p, 1e-4, 1e-5, a);
	EXPECT_DOUBLE_EQ(s.shearTraction, -5e3);
}

// Cohesionless fast path: no tension at all, not even a tiny one, and no break events.
TEST(MohrCoulombJoint, CohesionlessCarriesNoTension)
{
	const auto      p = frictional();
	JointPointState s;
	const auto r = updateJointPoint(s, p, -1e-12, 0, a);
	EXPECT_FALSE(s.intact);
	EXPECT_TRUE(s.open);
	EXPECT_FALSE(r.brokeInTension);
	EXPECT_DOUBLE_EQ(r.normalForce, 0);
}

// Ductile joint: the same trial as ShearBreak slips on c + sigma_n tan(phi) and keeps its cohesion at
// every later step (perfect plasticity); tension still breaks it.
TEST(MohrCoulombJoint, DuctileSlipKeepsCohesion)
{
	auto p    = cohesive();
	p.ductile = true;
	JointPointState s;
	auto r = updateJointPoint(s, p, 1e-4, -4e-4, a); // trial 2e5 > 1.5e5
	EXPECT_FALSE(r.brokeInShear);
	EXPECT_TRUE(s.intact);
	EXPECT_TRUE(s.slipping);
	EXPECT_DOUBLE_EQ(r.shearTraction, 1.5e5);
	EXPECT_NEAR(r.dissipated, 1.5e5 * (2e5 - 1.5e5) / p.ks * a, 1e-9);
	r = updateJointPoint(s, p, 1e-4, -4e-4, a); // keeps slipping on the same surface
	EXPECT_DOUBLE_EQ(r.shearTraction, 1.5e5);
	EXPECT_TRUE(s.intact);
	// in tension beyond -c/tan(phi) but above -sigma_t the strength is zero, not negative
	auto q            = p;
	q.tensileStrength = 10 * p.cohesion / p.tanPhi;
	JointPointState u;
	r = updateJointPoint(u, q, -2 * p.cohesion / p.tanPhi / p.kn, 1e-6, a);
	EXPECT_TRUE(u.intact);
	EXPECT_DOUBLE_EQ(r.shearTraction, 0);
	// tension beyond sigma_t breaks it as before
	r = updateJointPoint(s, p, -2 * p.tensileStrength / p.kn, 0, a);
	EXPECT_TRUE(r.brokeInTension);
	EXPECT_FALSE(s.intact);
}

// The frictional points of a joint slip together, by Coulomb's law for the resultant (issue 35).
namespace {
struct TwoPoints {
	JointPointState s[2];
	JointPointResult r[2];
	void step(const JointParams& p, Real dn0, Real dn1, Real du, const Real area[2])
	{
		const Real dn[2] = { dn0, dn1 }, dus[2] = { du, du };
		updateFrictionalPoints([this](int k) -> JointPointState& { return s[k]; }, 2, p, dn, dus, area, r, true);
	}
	Real shearForce() const { return r[0].shearForce + r[1].shearForce; }
	Real normalForce() const { return r[0].normalForce + r[1].normalForce; }
};
} // namespace

// A lightly loaded point does not slip alone: below the joint's resultant limit every point sticks,
// though the back point alone is far beyond sigma_n tan(phi) (it slipped, point by point).
TEST(MohrCoulombJoint, FrictionalJointSticksBelowResultantLimit)
{
	const auto p = frictional(); // tan(phi) 0.5
	const Real area[2] = { a, a };
	TwoPoints  j;
	// back point 1e-6 (sigma 1e3), front 1e-4 (1e5); capacity 0.5 * 1.01e5 * a
	for (int i = 0; i < 10; i++) j.step(p, 1e-4, 1e-6, 2e-6, area); // tau = -ks * 2e-5 = -1e4 each
	EXPECT_DOUBLE_EQ(j.s[0].shearTraction, -1e4);
	EXPECT_DOUBLE_EQ(j.s[1].shearTraction, -1e4); // per point it would be capped at 500
	EXPECT_FALSE(j.s[0].slipping || j.s[1].slipping);
	EXPECT_DOUBLE_EQ(j.r[0].dissipated + j.r[1].dissipated, 0);
	EXPECT_LT(std::abs(j.shearForce()), 0.5 * j.normalForce());
	// ... and per point, the same history slips at the back point
	JointPointState back;
	for (int i = 0; i < 10; i++) updateJointPoint(back, p, 1e-6, 2e-6, a);
	EXPECT_TRUE(back.slipping);
}

// Beyond the limit the joint slips as a whole: the resultant is on the Coulomb limit, every closed
// point's traction shifted by the same amount (uniform plastic slip), the dissipation is the
// resultant friction times that slip, and an open point carries nothing.
TEST(MohrCoulombJoint, FrictionalJointSlipsAsAWhole)
{
	const auto p = frictional();
	const Real area[2] = { a, 2 * a };
	TwoPoints  j;
	j.s[0].shearTraction = 3e4; // a history: the points differ
	j.s[1].shearTraction = 1e4;
	const Real du = 1e-3; // trial: 3e4 - 5e5 = -4.7e5 and 1e4 - 5e5 = -4.9e5
	j.step(p, 2e-4, 1e-4, du, area);
	const Real C = 0.5 * (2e5 * a + 1e5 * 2 * a);
	EXPECT_NEAR(j.shearForce(), -C, 1e-9 * C);
	EXPECT_NEAR(j.s[0].shearTraction - j.s[1].shearTraction, 2e4, 1e-6); // the same shift
	EXPECT_TRUE(j.s[0].slipping && j.s[1].slipping);
	const Real trialForce = -4.7e5 * a - 4.9e5 * 2 * a, slip = (std::abs(trialForce) - C) / (3 * a) / p.ks;
	EXPECT_NEAR(j.r[0].dissipated + j.r[1].dissipated, C * slip, 1e-9 * C * slip);
	// point 1 opens: it carries nothing, the joint's limit is point 0's
	j.step(p, 2e-4, -1e-5, du, area);
	EXPECT_TRUE(j.s[1].open);
	EXPECT_DOUBLE_EQ(j.s[1].shearTraction, 0);
	EXPECT_DOUBLE_EQ(j.r[1].normalForce, 0);
	EXPECT_NEAR(std::abs(j.shearForce()), 0.5 * 2e5 * a, 1e-9);
	EXPECT_TRUE(j.s[0].slipping && !j.s[1].slipping);
}

// The spring energy lost without friction work (JointPointResult::released, 'jointRelease') closes the
// springs' balance of a step exactly: E_old + the step's work (the old traction times dus, as the explicit
// step moves the blocks) = E_new + dissipated + released.
TEST(MohrCoulombJoint, ReleasedEnergyBalancesTheSprings)
{
	const auto p = frictional(); // ks 5e8, tan(phi) 0.5
	// steady sliding at constant sigma_n: nothing released, friction does all the work
	JointPointState s;
	JointPointResult r;
	for (int i = 0; i < 50; i++) r = updateJointPoint(s, p, 1e-4, 1e-5, a);
	ASSERT_TRUE(s.slipping);
	EXPECT_NEAR(r.released, 0, 1e-12);
	EXPECT_NEAR(r.dissipated, 0.5 * 1e5 * 1e-5 * a, 1e-12); // tau_max x slip
	// the normal traction halves while it slips: the springs lose (tau_old^2 - tau_new^2)/(2 ks) more than
	// friction's work on the slip (tau_new x slip), less the step's ks dus^2/2
	const Real told = s.shearTraction, du = 1e-5;
	r               = updateJointPoint(s, p, 0.5e-4, du, a);
	const Real tnew = s.shearTraction, work = -told * du * a;
	const Real Eold = told * told / (2 * p.ks) * a, Enew = tnew * tnew / (2 * p.ks) * a;
	EXPECT_GT(r.released, 0);
	EXPECT_NEAR(Eold + work, Enew + r.dissipated + r.released, 1e-9 * Eold);
	// it opens: its shear spring's energy goes
	const Real stored = tnew * tnew / (2 * p.ks) * a;
	r                 = updateJointPoint(s, p, -1e-6, du, a);
	EXPECT_TRUE(s.open);
	EXPECT_NEAR(r.released, stored, 1e-12 * stored);
	EXPECT_DOUBLE_EQ(r.dissipated, 0);
}

TEST(MohrCoulombJoint, FrictionalJointReleasedEnergy)
{
	const auto p = frictional();
	const Real area[2] = { a, a };
	TwoPoints  j;
	for (int i = 0; i < 50; i++) j.step(p, 1e-4, 1e-4, 1e-5, area); // slides steadily
	ASSERT_TRUE(j.s[0].slipping && j.s[1].slipping);
	EXPECT_NEAR(j.r[0].released + j.r[1].released, 0, 1e-12);
	// point 1 opens: its stored shear energy goes
	const Real stored = j.s[1].shearTraction * j.s[1].shearTraction / (2 * p.ks) * a;
	j.step(p, 1e-4, -1e-6, 1e-5, area);
	EXPECT_TRUE(j.s[1].open);
	EXPECT_NEAR(j.r[1].released, stored, 1e-12 * stored);
}
