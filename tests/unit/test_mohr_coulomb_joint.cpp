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
