// The integration rule along a contact segment (Gauss-Legendre), shared by the geometry (RbsmGeom's
// points), the physics (RbsmPhys's per-point state, kMaxIntegrationPoints) and the law.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

namespace rbsm {

/// Most integration points a contact can have (Ig2_Polygon2D_Polygon2D_RbsmGeom.nIP is 1..8):
/// per-point state is stored inline, without a heap block per contact.
constexpr int kMaxIntegrationPoints = 8;

/// A Gauss-Legendre rule on the contact segment: n points at parametric positions s[k] in [0,1]
/// from p0 to p1 (increasing), weights w[k] summing to 1, so that
///     integral over the segment of f = length * sum_k w_k f(s_k).
/// An n-point rule integrates polynomials of degree 2n-1 exactly; for n = 2 the points are
/// s = 1/2 -+ 1/(2 sqrt 3) with w = 1/2 each, exact up to degree 3, hence exact for the force
/// (degree 1) AND the moment (degree 2) of a linearly varying traction.
struct IntegrationRule {
	int  n = 0;
	Real s[kMaxIntegrationPoints] = {};
	Real w[kMaxIntegrationPoints] = {};
};

/// The rule of nIP points, nIP in 1..8 (throws std::invalid_argument otherwise). The rules are
/// computed once (Newton iteration on the Legendre polynomials) and live as long as the program,
/// so a contact may keep a pointer to its rule.
const IntegrationRule& integrationRule(int nIP);

} // namespace rbsm
