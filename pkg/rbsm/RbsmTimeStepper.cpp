#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>
#include <pkg/rbsm/RbsmTimeStepper.hpp>
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>
#include <core/Scene.hpp>

#include <sstream>

namespace yade {

YADE_PLUGIN((RbsmTimeStepper));

Real RbsmTimeStepper::estimate()
{
	const auto& bodies = scene->bodies->body;
	std::vector<rbsm::DynBody> dyn;
	std::vector<int>           index(bodies.size(), -1); // body id -> index in dyn
	std::vector<rbsm::DynContact> contacts;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* g = dynamic_cast<const RbsmGeom*>(I->geom.get());
		const auto* p = dynamic_cast<const RbsmPhys*>(I->phys.get());
		if (!g || !p) continue;
		int ends[2];
		for (int side = 0; side < 2; side++) {
			const Body::id_t id = side == 0 ? I->getId1() : I->getId2();
			if (index[id] < 0) {
				const State& s = *bodies[id]->state;
				rbsm::DynBody b;
				b.mass     = s.mass;
				b.inertia  = s.inertia.z();
				b.centroid = s.pos.head<2>();
				b.fixed    = (s.blockedDOFs & State::DOF_ALL) == State::DOF_ALL;
				index[id]  = int(dyn.size());
				dyn.push_back(b);
			}
			ends[side] = index[id];
		}
		rbsm::DynContact c;
		c.body1   = ends[0];
		c.body2   = ends[1];
		c.normal  = g->normal;
		c.tangent = g->tangent;
		c.kn      = p->kn;
		c.ks      = p->ks;
		for (size_t k = 0; k < g->nPoints(); k++) {
			c.points.push_back(g->point(int(k)));
			c.areas.push_back(g->weights[k] * g->length * g->thickness);
		}
		contacts.push_back(std::move(c));
	}
	criticalDt = rbsm::criticalTimeStepGershgorin(dyn, contacts);
	return criticalDt;
}

void RbsmTimeStepper::action()
{
	if (!(safetyFactor > 0 && safetyFactor <= 1)) throw std::invalid_argument("RbsmTimeStepper.safetyFactor: must be in (0, 1]");
	if (interval < 1) throw std::invalid_argument("RbsmTimeStepper.interval: must be >= 1");
	if (lastCheck >= 0 && scene->iter - lastCheck < interval) return;
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
