#include <pkg/rbsm/kernel/IntegrationRule.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rbsm {

namespace {
	// Gauss-Legendre nodes x_k on [-1,1] are the roots of P_n; Newton iteration from the
	// classical initial guess cos(pi (k - 1/4)/(n + 1/2)) converges to machine precision.
	// Weights on [-1,1]: 2 / ((1 - x^2) P_n'(x)^2). Mapped to [0,1]: s = (1+x)/2, w/2.
	IntegrationRule gaussLegendre(int n)
	{
		IntegrationRule r;
		r.n = n;
		for (int k = 0; k < n; ++k) {
			Real x  = std::cos(M_PI * (k + 0.75) / (n + 0.5));
			Real dp = 1;
			for (int it = 0; it < 100; ++it) {
				Real p0 = 1, p1 = x; // P_0, P_1
				for (int j = 2; j <= n; ++j) {
					const Real p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
					p0            = p1;
					p1            = p2;
				}
				const Real pn = (n == 1) ? x : p1, pnm1 = (n == 1) ? 1 : p0;
				dp            = n * (x * pn - pnm1) / (x * x - 1);
				const Real dx = pn / dp;
				x -= dx;
				if (std::abs(dx) < 1e-16) break;
			}
			// nodes from cos() come in decreasing x; store increasing s
			r.s[n - 1 - k] = (1 + x) / 2;
			r.w[n - 1 - k] = 1 / ((1 - x * x) * dp * dp);
		}
		return r;
	}
} // namespace

const IntegrationRule& integrationRule(int nIP)
{
	if (nIP < 1 || nIP > kMaxIntegrationPoints) throw std::invalid_argument("integrationRule: nIP must be in 1..8 (got " + std::to_string(nIP) + ")");
	static const auto rules = [] { // thread-safe initialisation on first use
		std::array<IntegrationRule, kMaxIntegrationPoints> all;
		for (int n = 1; n <= kMaxIntegrationPoints; ++n)
			all[n - 1] = gaussLegendre(n);
		return all;
	}();
	return rules[nIP - 1];
}

} // namespace rbsm
