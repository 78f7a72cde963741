// Per-integration-point RBSM joint law: linear springs (seed eq. (10)) + Mohr-Coulomb slip
// (seed eq. (11)) + tension cut-off, with irreversible loss of cohesion.
//
// Sign conventions (differ from the seed, which takes tension positive):
//  * sigma_n = kn * delta_n, positive in COMPRESSION; delta_n = normal overlap (m, > 0 when the
//    blocks interpenetrate, from EdgeContact d0/d1). The seed's yield function
//    f = tau^2 - (c - sigma tan(phi))^2 with tension-positive sigma = -sigma_n becomes
//        f = tau^2 - (c + sigma_n tan(phi))^2.
//  * tau = shear traction ON BODY 2 ALONG +t (Pa). It is updated incrementally,
//        tau <- tau - ks * dus,
//    where dus = this step's tangential displacement of body 2 relative to body 1 along t (m):
//    the traction resists the relative motion. The traction on body 1 is the opposite.
//  * the normal traction on body 2 is +sigma_n along +n (pushes body 2 away from body 1).
//
// Units: kn, ks in Pa/m; c, sigma_t in Pa; area in m^2 (tributary area of the point =
// weight * length * thickness); energies in J.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

#include <algorithm>
#include <cmath>

namespace rbsm {

struct JointPointState {
	Real shearTraction = 0;     ///< tau (Pa), see above
	bool intact        = true;  ///< cohesion and tensile strength still active
	bool slipping      = false; ///< on the Mohr-Coulomb surface this step
	bool open          = false; ///< broken and not in compression: carries nothing
};

struct JointParams {
	Real kn = 0;              ///< Pa/m
	Real ks = 0;              ///< Pa/m
	Real cohesion = 0;        ///< c (Pa), active while intact
	Real tanPhi = 0;          ///< tan(friction angle)
	Real tensileStrength = 0; ///< sigma_t (Pa), active while intact
	bool ductile = false;     ///< slip keeps the cohesion (perfect plasticity); only tension breaks
};

struct JointPointResult {
	Real normalTraction = 0;   ///< sigma_n (Pa, compression > 0)
	Real shearTraction  = 0;   ///< tau (Pa), = state.shearTraction after the update
	Real normalForce    = 0;   ///< sigma_n * area (N), on body 2 along +n
	Real shearForce     = 0;   ///< tau * area (N), on body 2 along +t
	Real elasticEnergy  = 0;   ///< (sigma_n^2/(2 kn) + tau^2/(2 ks)) * area (J), after the update
	Real dissipated     = 0;   ///< frictional dissipation this step: tau_max * |plastic slip| * area (J)
	bool brokeInTension = false;
	bool brokeInShear   = false;
};

/// One explicit step of the joint law at one integration point.
/// Rules, in order:
///  1. sigma_n = kn * deltaN; trial tau = state.tau - ks * dus.
///  2. Tension cut-off: intact and sigma_n < -sigma_t -> breaks irreversibly (c, sigma_t -> 0),
///     is open, sigma_n = tau = 0.
///  3. Broken (or cohesionless) with deltaN <= 0 -> open, carries nothing, tau reset to 0.
///  4. Shear: |tau| > c + sigma_n tan(phi): if intact it breaks (c -> 0; if it is then not in
///     compression it opens as in 3); tau is returned to the surface +-(sigma_n tan(phi)) and the
///     point is slipping; plastic slip = (|tau_trial| - tau_max) / ks. A ductile joint does not
///     break in shear: it slips on c + sigma_n tan(phi) (>= 0), the perfectly plastic
///     Mohr-Coulomb of continuum strength reduction.
/// Cheap path: c = sigma_t = 0 means a cohesionless joint, treated as already broken (no
/// strength checks beyond friction). A point that has broken never heals.
/// withEnergy = false leaves elasticEnergy at 0 (a scene without O.trackEnergy does not pay for it).
/// Inline: the plugin's law calls it for every point of every joint at every step.
inline JointPointResult updateJointPoint(JointPointState& state, const JointParams& p, Real deltaN, Real dus, Real area, bool withEnergy = true);

namespace detail {
	inline JointPointResult openPoint(JointPointState& s)
	{
		s.shearTraction = 0;
		s.slipping      = false;
		s.open          = true;
		return JointPointResult {};
	}
} // namespace detail

namespace detail {
	/// Rules 1, 3 and 4 for a broken (or cohesionless) point: friction only. The same arithmetic as
	/// the general path, written without data-dependent branches: in a settling assembly points flip
	/// between stick and slip, and joints between open and closed, from step to step, and a
	/// mispredicted branch costs more than computing both outcomes (ternaries on doubles, std::clamp).
	inline JointPointResult frictionalPoint(JointPointState& s, const JointParams& p, Real deltaN, Real dus, Real area, bool withEnergy)
	{
		const bool closed = deltaN > 0; // rule 3: a broken point carries nothing unless in compression
		const Real sn     = closed ? p.kn * deltaN : Real(0);
		const Real trial  = closed ? s.shearTraction - p.ks * dus : Real(0);
		const Real tmax   = sn * p.tanPhi;
		const Real excess = std::abs(trial) - tmax; // > 0: beyond the friction surface, slips (rule 4)
		const Real tau    = std::clamp(trial, -tmax, tmax);
		s.shearTraction   = tau;
		s.open            = !closed;
		s.slipping        = excess > 0;
		JointPointResult r;
		r.normalTraction = sn;
		r.shearTraction  = tau;
		r.normalForce    = sn * area;
		r.shearForce     = tau * area;
		// plastic slip (|trial| − tmax)/ks, dissipated against the friction tmax
		r.dissipated = (excess > 0 && p.ks > 0) ? tmax * (excess / p.ks) * area : Real(0);
		if (withEnergy) r.elasticEnergy = ((p.kn > 0 ? sn * sn / (2 * p.kn) : 0) + (p.ks > 0 ? tau * tau / (2 * p.ks) : 0)) * area;
		return r;
	}
} // namespace detail

inline JointPointResult updateJointPoint(JointPointState& s, const JointParams& p, Real deltaN, Real dus, Real area, bool withEnergy)
{
	JointPointResult r;
	// Cohesionless joints (the landslide scenes of the seed, Table 1) skip all strength logic.
	if (s.intact && p.cohesion == 0 && p.tensileStrength == 0) s.intact = false;

	if (!s.intact) return detail::frictionalPoint(s, p, deltaN, dus, area, withEnergy);

	Real sn = p.kn * deltaN;
	if (s.intact && sn < -p.tensileStrength) {
		s.intact = false;
		JointPointResult o = detail::openPoint(s);
		o.brokeInTension   = true;
		return o;
	}

	Real       tau  = s.shearTraction - p.ks * dus;
	const Real c    = s.intact ? p.cohesion : 0;
	Real       tmax = c + sn * p.tanPhi;
	s.open          = false;
	s.slipping      = false;
	if (p.ductile) tmax = std::max(tmax, Real(0)); // tension above -c/tan(phi) but below sigma_t: no shear strength
	if (std::abs(tau) > tmax) {
		if (s.intact && !p.ductile) {
			s.intact       = false;
			r.brokeInShear = true;
			if (deltaN <= 0) {
				detail::openPoint(s);
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
	if (withEnergy) r.elasticEnergy = ((p.kn > 0 ? sn * sn / (2 * p.kn) : 0) + (p.ks > 0 ? tau * tau / (2 * p.ks) : 0)) * area;
	return r;
}

} // namespace rbsm
