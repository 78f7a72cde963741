#include <pkg/rbsm/kernel/BlockPlasticity.hpp>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace rbsm {

namespace {
	// A plane stress in principal form: σ1 ≥ σ3 and the angle 2θ of σ1's direction from x.
	struct Principal {
		Real s1, s3, cos2, sin2;
	};

	Principal principal(const Vec3& s)
	{
		const Real mean = (s[0] + s[1]) / 2, half = (s[0] - s[1]) / 2, radius = std::hypot(half, s[2]);
		if (radius == 0) return { mean, mean, 1, 0 };
		return { mean + radius, mean - radius, half / radius, s[2] / radius };
	}

	// Isotropic elasticity keeps the principal axes: the returned σ1, σ3 go back on the trial's.
	Vec3 toPlane(Real s1, Real s3, const Principal& axes)
	{
		const Real mean = (s1 + s3) / 2, radius = std::max<Real>(0, (s1 - s3) / 2);
		return Vec3(mean + radius * axes.cos2, mean - radius * axes.cos2, radius * axes.sin2);
	}

	Real shear(Real s1, Real s3, const MohrCoulombStrength& s)
	{
		return (s1 - s3) / 2 + (s1 + s3) / 2 * std::sin(s.frictionAngle) - s.cohesion * std::cos(s.frictionAngle);
	}
}

Real mohrCoulombShear(const Vec3& stress, const MohrCoulombStrength& s)
{
	const Principal p = principal(stress);
	return shear(p.s1, p.s3, s);
}

PlasticReturn mohrCoulombReturn(const Vec3& trial, const Mat3& D, const MohrCoulombStrength& s)
{
	const Principal p   = principal(trial);
	const Real      sf  = std::sin(s.frictionAngle), cf = std::cos(s.frictionAngle), sp = std::sin(s.dilatancy);
	const Real      cut = sf > 0 ? std::min(s.tensileStrength, s.cohesion * cf / sf) : s.tensileStrength;
	const Real      a = D(0, 0), b = D(0, 1); // principal elasticity [[a, b], [b, a]]
	const Real      f = shear(p.s1, p.s3, s);
	PlasticReturn   r { trial, Vec3::Zero(), 0, YieldMode::elastic };
	if (f <= 0 && p.s1 <= cut) return r;

	Real s1 = p.s1, s3 = p.s3;
	bool done = false;
	if (f > 0) { // along D·∂g/∂σ to f = 0 (exact: f is linear in σ1, σ3)
		const Real nf1 = (1 + sf) / 2, nf3 = -(1 - sf) / 2, ng1 = (1 + sp) / 2, ng3 = -(1 - sp) / 2;
		const Real d1 = a * ng1 + b * ng3, d3 = b * ng1 + a * ng3;
		const Real lambda = f / (nf1 * d1 + nf3 * d3);
		s1 = p.s1 - lambda * d1, s3 = p.s3 - lambda * d3;
		done = s1 <= cut;
		r.mode = YieldMode::shear;
	}
	if (!done) { // tension: σ1 to the cut-off with plastic strain along 1 only (a > b: the shear return lowered σ1)
		s1 = cut, s3 = p.s3 - b / a * (p.s1 - cut);
		r.mode = YieldMode::tension;
		if (s3 > cut) s3 = cut; // both principal stresses at the cut-off (inside the shear surface: cut ≤ c cot φ)
		else if (shear(s1, s3, s) > 0) { // the corner of the cut-off and the shear surface
			s3     = (cut * (1 + sf) - 2 * s.cohesion * cf) / (1 - sf);
			r.mode = YieldMode::corner;
		}
	}
	r.stress        = toPlane(s1, s3, p);
	r.plasticStrain = D.inverse() * (trial - r.stress);
	// principal plastic strains in the trial's axes (engineering shear halves)
	const Real half = (r.plasticStrain[0] - r.plasticStrain[1]) / 2, g2 = r.plasticStrain[2] / 2;
	r.plasticShear  = 2 * std::hypot(half, g2);
	return r;
}

} // namespace rbsm
