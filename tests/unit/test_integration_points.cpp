// Gauss-Legendre points on [0,1]: weights sum to 1, polynomial exactness of degree 2n-1, and
// in particular the force and moment of a linear traction are exact with 2 points.
#include <pkg/rbsm/kernel/IntegrationRule.hpp>

#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>

using namespace rbsm;

TEST(IntegrationPoints, TwoPointValues)
{
	const IntegrationRule& r = integrationRule(2);
	const Real* s = r.s;
	const Real* w = r.w;
	ASSERT_EQ(r.n, 2);
	EXPECT_NEAR(s[0], 0.5 - 0.5 / std::sqrt(3.0), 1e-15);
	EXPECT_NEAR(s[1], 0.5 + 0.5 / std::sqrt(3.0), 1e-15);
	EXPECT_NEAR(w[0], 0.5, 1e-15);
	EXPECT_NEAR(w[1], 0.5, 1e-15);
}

// integral_0^1 x^k dx = 1/(k+1) for k <= 2n-1; and degree 2n is NOT exact (the rule is Gauss).
TEST(IntegrationPoints, ExactnessDegree2nMinus1)
{
	for (int n = 1; n <= 8; ++n) {
		const IntegrationRule& r = integrationRule(n);
		ASSERT_EQ(r.n, n);
		const Real* s = r.s;
		const Real* w = r.w;
		Real sw = 0;
		for (int i = 0; i < n; ++i) {
			sw += w[i];
			EXPECT_GT(s[i], 0);
			EXPECT_LT(s[i], 1);
			if (i) EXPECT_GT(s[i], s[i - 1]);
		}
		EXPECT_NEAR(sw, 1, 1e-14) << n;
		for (int k = 0; k <= 2 * n; ++k) {
			Real q = 0;
			for (int i = 0; i < n; ++i) q += w[i] * std::pow(s[i], k);
			if (k <= 2 * n - 1) EXPECT_NEAR(q, 1.0 / (k + 1), 1e-14) << "n=" << n << " k=" << k;
			else EXPECT_GT(std::abs(q - 1.0 / (k + 1)), 1e-12) << "n=" << n << " k=" << k;
		}
	}
}

// Linear traction p(s) = p0 + (p1-p0) s on a segment of length L:
// force F = L (p0+p1)/2, moment about p0: M = L^2 (p0 + 2 p1)/6.
TEST(IntegrationPoints, LinearTractionForceAndMomentExactWithTwoPoints)
{
	const Real L = 2.5, p0 = 3.0, p1 = -7.0;
	const Real* s = integrationRule(2).s;
	const Real* w = integrationRule(2).w;
	Real F = 0, M = 0;
	for (int i = 0; i < 2; ++i) {
		const Real p = p0 + (p1 - p0) * s[i];
		F += L * w[i] * p;
		M += L * w[i] * p * (s[i] * L);
	}
	EXPECT_NEAR(F, L * (p0 + p1) / 2, 1e-13);
	EXPECT_NEAR(M, L * L * (p0 + 2 * p1) / 6, 1e-13);
	// the 1-point rule gets the force but not the moment: proves the test can fail
	const IntegrationRule& one = integrationRule(1);
	const Real M1 = L * one.w[0] * (p0 + (p1 - p0) * one.s[0]) * one.s[0] * L;
	EXPECT_GT(std::abs(M1 - L * L * (p0 + 2 * p1) / 6), 1.0);
}

TEST(IntegrationPoints, RejectsOutOfRange)
{
	EXPECT_THROW(integrationRule(0), std::invalid_argument);
	EXPECT_THROW(integrationRule(9), std::invalid_argument);
}

// The rules are computed once and shared: a contact keeps a pointer to its rule.
TEST(IntegrationPoints, RuleIsComputedOnceAndShared)
{
	EXPECT_EQ(&integrationRule(3), &integrationRule(3));
	EXPECT_NE(&integrationRule(3), &integrationRule(4));
}
