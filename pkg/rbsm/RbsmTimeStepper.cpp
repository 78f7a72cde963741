#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>
#include <pkg/rbsm/RbsmTimeStepper.hpp>
#include <core/Scene.hpp>

#include <sstream>

namespace yade {

YADE_PLUGIN((RbsmTimeStepper));

Real RbsmTimeStepper::estimate()
{
	const auto& bodies = scene->bodies->body;
	dynBodies.clear();
	dynIndex.assign(bodies.size(), -1); // body id -> index in dynBodies
	dashpot.clear(), spring.clear();    // per block: Σ c·A [N·s/m] and Σ min(kn, ks)·A [N/m] of its joints
	size_t nContacts = 0;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		// class indices instead of dynamic_cast (once per contact per check)
		const IGeom* ig = I->geom.get();
		const IPhys* ip = I->phys.get();
		if (!ig || !ip || ig->getClassIndex() != RbsmGeom::getClassIndexStatic() || ip->getClassIndex() != RbsmPhys::getClassIndexStatic()) continue;
		const auto* g = static_cast<const RbsmGeom*>(ig);
		const auto* p = static_cast<const RbsmPhys*>(ip);
		int         ends[2];
		for (int side = 0; side < 2; side++) {
			const Body::id_t id = side == 0 ? I->getId1() : I->getId2();
			if (dynIndex[id] < 0) {
				const State&  s = *bodies[id]->state;
				rbsm::DynBody b;
				b.mass       = s.mass;
				b.inertia    = s.inertia.z();
				b.centroid   = s.pos.head<2>();
				b.fixed      = (s.blockedDOFs & State::DOF_ALL) == State::DOF_ALL;
				dynIndex[id] = int(dynBodies.size());
				dynBodies.push_back(b);
			}
			ends[side] = dynIndex[id];
		}
		// viscous joint damping: dashpot and (softer) spring of the joint, summed per block (see below)
		if (p->dampingCoefficient > 0) {
			const Real area = g->length * g->thickness;
			for (int e : ends) {
				if (int(dashpot.size()) <= e) dashpot.resize(e + 1, 0), spring.resize(e + 1, 0);
				dashpot[e] += p->dampingCoefficient * area;
				spring[e] += std::min(p->kn, p->ks) * area;
			}
		}
		if (dynContacts.size() <= nContacts) dynContacts.emplace_back();
		rbsm::DynContact& c = dynContacts[nContacts++];
		c.body1             = ends[0];
		c.body2             = ends[1];
		c.normal            = g->normal;
		c.tangent           = g->tangent();
		c.kn                = p->kn;
		c.ks                = p->ks;
		c.points.clear(), c.areas.clear(); // (their capacity is kept)
		for (int k = 0; k < g->nPoints(); k++) {
			c.points.push_back(g->p0 + g->rule->s[k] * (g->p1 - g->p0));
			c.areas.push_back(g->rule->w[k] * g->length * g->thickness);
		}
	}
	dynContacts.resize(nContacts);
	std::vector<Real> omega2; // Gershgorin bound of each block's rows
	const Real        undamped = rbsm::criticalTimeStepGershgorin(dynBodies, dynContacts, &omega2);
	// Joint dashpots (Law2's dampingRatio) lower the limit of the central-difference scheme, whose
	// velocity is half a step behind: dt ≤ (2/ω)(√(1+ξ²) − ξ) for a mode of frequency ω and damping
	// ratio ξ. Every eigenvalue lies below the Gershgorin bound ω̂_b² of some block b; for that block
	// the ratio is taken as ξ_b = β_b ω̂_b / 2, β_b = Σ c A / Σ k A over its joints (dashpot over the
	// softer spring), and the step is the smallest (2/ω̂_b)(√(1+ξ_b²) − ξ_b). This is an estimate,
	// not a bound. The bound through the whole damping matrix (C ≤ β K, β = max c/k of a single
	// joint, with the system's ω̂) is dominated by short corner joints, whose dashpots are stiff
	// per area but act on almost no area and belong to soft modes, and shrank the step of a brick
	// wall 30-fold (docs/benchmarks.md). tests/robustness/test_timestep.py checks ξ = 0.1, 0.3, 1.0.
	criticalDt = undamped;
	for (size_t b = 0; b < dashpot.size() && b < omega2.size(); b++) {
		if (!(spring[b] > 0 && dashpot[b] > 0 && omega2[b] > 0)) continue;
		const Real w = std::sqrt(omega2[b]), xi = dashpot[b] / spring[b] * w / 2;
		criticalDt   = std::min(criticalDt, 2 / w * (std::sqrt(1 + xi * xi) - xi));
	}
	return criticalDt;
}

void RbsmTimeStepper::action()
{
	// in every step: the one serial place of an RBSM step that sees a VTKRecorder added to O.engines
	vtkRecorderGuard.check(*scene);
	// (iter < lastCheck: O.iter was set back, e.g. a scene saved by a later run: check now)
	if (lastCheck >= 0 && scene->iter >= lastCheck && scene->iter - lastCheck < interval) return;
	lastCheck        = scene->iter;
	const Real dtMax = safetyFactor * estimate();
	if (!std::isfinite(dtMax)) return; // no joint yet: nothing limits the step
	if (setDt) {
		// The estimate is only as good as the joints of this step: a block meeting another by a
		// corner has a short, soft joint that stiffens as it closes before the next check. So the
		// step set here never grows again once set; it only shrinks when stiffer joints appear.
		scene->dt = dtWasSet ? std::min(scene->dt, dtMax) : dtMax;
		dtWasSet  = true;
		return;
	}
	// The estimate moves with the geometry by round-off from one step to the next: a step set to
	// safetyFactor x estimate() must not be refused for that (the safety factor is the margin).
	if (!(scene->dt <= dtMax * (1 + 1e-6))) {
		std::ostringstream msg;
		msg << "RbsmTimeStepper: O.dt = " << scene->dt << " s exceeds the stable limit of the RBSM system at step " << scene->iter << " ("
		    << safetyFactor << " x critical step " << criticalDt << " s = " << dtMax
		    << " s); the step was refused before integration. Reduce O.dt or set RbsmTimeStepper.setDt=True.";
		throw std::runtime_error(msg.str());
	}
}

} // namespace yade
