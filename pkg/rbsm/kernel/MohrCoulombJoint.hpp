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

#include <pkg/rbsm/kernel/IntegrationRule.hpp>
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
	/// Spring energy lost this step without friction work (J): a point that opens or breaks drops its
	/// springs' energy; a return to the friction surface loses (|trial| − tau_max)²/(2 ks) beyond friction's
	/// tau_max × slip, less the (ks dus)²/(2 ks) that the explicit step's work, old traction × dus, leaves out
	/// (0 in steady sliding; > 0 where the friction limit falls, the cohesion of a point that breaks in shear).
	Real released       = 0;
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
/// withEnergy = false leaves elasticEnergy and released at 0 (a scene without O.trackEnergy does not pay for it).
/// Inline: the plugin's law calls it for every point of every joint at every step.
inline JointPointResult updateJointPoint(JointPointState& state, const JointParams& p, Real deltaN, Real dus, Real area, bool withEnergy = true);

namespace detail {
	/// The energy a return to the friction surface by `excess` (|trial| − tau_max, Pa; none if <= 0) loses
	/// beyond friction's work [J] (JointPointResult::released).
	inline Real returnLoss(const JointParams& p, Real excess, Real dus, Real area)
	{
		return (excess > 0 && p.ks > 0) ? (excess * excess - p.ks * p.ks * dus * dus) / (2 * p.ks) * area : Real(0);
	}
	/// The springs' energy at tractions (sn, tau) on area [J].
	inline Real springEnergy(const JointParams& p, Real sn, Real tau, Real area)
	{
		return ((p.kn > 0 ? sn * sn / (2 * p.kn) : 0) + (p.ks > 0 ? tau * tau / (2 * p.ks) : 0)) * area;
	}
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
		const Real before = s.shearTraction;
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
		if (withEnergy) {
			r.elasticEnergy = springEnergy(p, sn, tau, area);
			// opened: its shear spring goes; slipped: the part of the return friction does not do
			r.released = closed ? returnLoss(p, excess, dus, area) : springEnergy(p, 0, before, area);
		}
		return r;
	}
} // namespace detail

inline JointPointResult updateJointPoint(JointPointState& s, const JointParams& p, Real deltaN, Real dus, Real area, bool withEnergy)
{
	JointPointResult r;
	// Cohesionless joints (the landslide scenes of the seed, Table 1) skip all strength logic.
	if (s.intact && p.cohesion == 0 && p.tensileStrength == 0) s.intact = false;

	if (!s.intact) return detail::frictionalPoint(s, p, deltaN, dus, area, withEnergy);

	Real       sn  = p.kn * deltaN;
	Real       tau = s.shearTraction - p.ks * dus;
	if (s.intact && sn < -p.tensileStrength) {
		s.intact = false;
		JointPointResult o = detail::openPoint(s);
		o.brokeInTension   = true;
		if (withEnergy) o.released = detail::springEnergy(p, sn, tau, area);
		return o;
	}

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
				if (withEnergy) r.released = detail::springEnergy(p, sn, tau, area);
				return r; // tractions and energies zero, the event is reported
			}
			tmax = sn * p.tanPhi;
		}
		if (std::abs(tau) > tmax) {
			const Real trial = tau;
			tau              = std::copysign(tmax, trial);
			const Real slip  = (p.ks > 0) ? (std::abs(trial) - tmax) / p.ks : 0;
			r.dissipated     = tmax * slip * area;
			if (withEnergy) r.released = detail::returnLoss(p, std::abs(trial) - tmax, dus, area);
			s.slipping       = true;
		}
	}
	s.shearTraction  = tau;
	r.normalTraction = sn;
	r.shearTraction  = tau;
	r.normalForce    = sn * area;
	r.shearForce     = tau * area;
	if (withEnergy) r.elasticEnergy = detail::springEnergy(p, sn, tau, area);
	return r;
}

/// One explicit step of the frictional points of one joint (broken or cohesionless: no cohesion, no
/// tension), updated together. Two rigid blocks move relative to each other with the same tangential
/// displacement all along their straight joint (SegmentKinematics: a relative rotation moves its points
/// along the normal only), so the joint slips as a whole, by Coulomb's law for its resultant:
///     |Σ a_k τ_k| <= tan(phi) Σ a_k sigma_n,k        (over the closed points, deltaN > 0).
/// Beyond it every closed point's trial τ shifts by the same λ (a uniform plastic slip λ/ks: the
/// return closest to the trial in the springs' energy). An open point carries nothing (rule 3).
/// Capped point by point instead, a lightly loaded point slipped alone while the others stuck, and
/// that partial slip of a rocking block fed a flutter: a block held by friction chattered and slid
/// (issue 35). state(k) gives point k's JointPointState; r[k] its result (the dissipation of the
/// joint, C·|λ|/ks, is shared out as τ_k a_k λ/ks, which can be negative at a point but sums right).
template <class States>
inline void updateFrictionalPoints(States&& state, int n, const JointParams& p, const Real* deltaN, const Real* dus, const Real* area, JointPointResult* r, bool withEnergy)
{
	Real resultant = 0, capacity = 0, closedArea = 0, before[kMaxIntegrationPoints];
	for (int k = 0; k < n; k++) {
		JointPointState& s      = state(k);
		const bool       closed = deltaN[k] > 0;
		before[k]               = s.shearTraction;
		r[k]                    = JointPointResult {};
		r[k].normalTraction     = closed ? p.kn * deltaN[k] : Real(0);
		r[k].shearTraction      = closed ? s.shearTraction - p.ks * dus[k] : Real(0); // the trial
		s.intact                = false;
		s.open                  = !closed;
		resultant += r[k].shearTraction * area[k];
		capacity += r[k].normalTraction * p.tanPhi * area[k];
		closedArea += closed ? area[k] : Real(0);
	}
	const Real excess = std::abs(resultant) - capacity;
	const bool slips  = excess > 0 && closedArea > 0;
	// frictionless (capacity 0): no shear at all, rather than a shear that sums to zero
	const bool none   = slips && capacity == 0;
	const Real shift  = slips ? std::copysign(excess / closedArea, resultant) : Real(0); // λ [Pa]
	const Real slip   = (slips && p.ks > 0) ? shift / p.ks : Real(0);                    // λ/ks [m]
	for (int k = 0; k < n; k++) {
		JointPointState& s     = state(k);
		const Real       a     = area[k];
		const Real       trial = r[k].shearTraction;
		const Real       tau   = (s.open || none) ? Real(0) : trial - shift;
		s.shearTraction        = tau;
		s.slipping             = slips && !s.open;
		r[k].shearTraction     = tau;
		r[k].normalForce       = r[k].normalTraction * a;
		r[k].shearForce        = tau * a;
		r[k].dissipated        = none ? Real(0) : tau * a * slip;
		if (withEnergy) {
			r[k].elasticEnergy = detail::springEnergy(p, r[k].normalTraction, tau, a);
			// opened: its old shear spring goes; slipped: the return's loss beyond the friction's work
			r[k].released = s.open ? detail::springEnergy(p, 0, before[k], a)
			                       : slips ? detail::returnLoss(p, std::abs(none ? trial : shift), dus[k], a) : Real(0);
		}
	}
}

} // namespace rbsm
