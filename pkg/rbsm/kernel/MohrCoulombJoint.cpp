#include <pkg/rbsm/kernel/MohrCoulombJoint.hpp>

#include <cmath>

namespace rbsm {

namespace {
	JointPointResult openPoint(JointPointState& s)
	{
		s.shearTraction = 0;
		s.slipping      = false;
		s.open          = true;
		return JointPointResult {};
	}
} // namespace

JointPointResult updateJointPoint(JointPointState& s, const JointParams& p, Real deltaN, Real dus, Real area)
{
	JointPointResult r;
	// Cohesionless joints (the landslide scenes of the seed, Table 1) skip all strength logic.
	if (s.intact && p.cohesion == 0 && p.tensileStrength == 0) s.intact = false;

	if (!s.intact && deltaN <= 0) return openPoint(s);

	Real sn = p.kn * deltaN;
	if (s.intact && sn < -p.tensileStrength) {
		s.intact = false;
		JointPointResult o = openPoint(s);
		o.brokeInTension   = true;
		return o;
	}

	Real       tau  = s.shearTraction - p.ks * dus;
	const Real c    = s.intact ? p.cohesion : 0;
	Real       tmax = c + sn * p.tanPhi;
	s.open          = false;
	s.slipping      = false;
	if (std::abs(tau) > tmax) {
		if (s.intact) {
			s.intact       = false;
			r.brokeInShear = true;
			if (deltaN <= 0) {
				openPoint(s);
				return r; // tractions and energies zero, the event is reported
			}
			tmax = sn * p.tanPhi;
		}
		if (std::abs(tau) > tmax) {
			const Real trial = tau;
			tau              = std::copysign(tmax, trial);
			const Real slip  = (p.ks > 0) ? (std::abs(trial) - tmax) / p.ks : 0;
			r.dissipated     = tmax * slip * area;
			s.slipping       = true;
		}
	}
	s.shearTraction  = tau;
	r.normalTraction = sn;
	r.shearTraction  = tau;
	r.normalForce    = sn * area;
	r.shearForce     = tau * area;
	r.elasticEnergy  = ((p.kn > 0 ? sn * sn / (2 * p.kn) : 0) + (p.ks > 0 ? tau * tau / (2 * p.ks) : 0)) * area;
	return r;
}

} // namespace rbsm
