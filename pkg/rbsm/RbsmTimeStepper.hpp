// RbsmTimeStepper: the stability limit of the explicit integration of an RBSM block system.
#pragma once
#include <core/GlobalEngine.hpp>
#include <pkg/rbsm/VtkRecorderGuard.hpp>
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>

namespace yade {

class RbsmTimeStepper : public GlobalEngine {
public:
	void action() override;
	//! Checks the attributes when they are set (raises ValueError in Python, before any step).
	void postLoad(RbsmTimeStepper&)
	{
		if (!(safetyFactor > 0 && safetyFactor <= 1))
			throw std::invalid_argument("RbsmTimeStepper.safetyFactor: must be in (0, 1] (got " + std::to_string(safetyFactor) + ")");
		if (interval < 1) throw std::invalid_argument("RbsmTimeStepper.interval: must be >= 1 (got " + std::to_string(interval) + ")");
	}
	//! Switches off a VTKRecorder whose recorders would crash YADE on RBSM joints (see VtkRecorderGuard).
	VtkRecorderGuard vtkRecorderGuard;
	//! Critical time step of the current system [s] (+inf if no RBSM joint exists yet).
	Real estimate();
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmTimeStepper, GlobalEngine,
		"Guards the explicit (central-difference) integration of RBSM blocks against instability. The critical step is "
		"dt_crit = 2/ω_max, ω_max² the largest eigenvalue of M⁻¹K for the blocks (mass, polar inertia) and the joint springs "
		"(kn, ks per unit area at every integration point, times its tributary area). ω_max² is bounded from above by the "
		"block Gershgorin theorem (Feingold & Varga 1962) on M^-½ K M^-½, so the undamped estimate is never above the true "
		"limit. With joint dashpots (Law2's dampingRatio) it is multiplied by √(1+ξ²) − ξ, ξ the largest damping ratio of a "
		"joint's own normal or shear mode (an estimate, not a bound).\n\n"
		"Place it after :yref:`InteractionLoop` and before :yref:`NewtonIntegrator`, so that the joints of this step are "
		"known before the integration. Every :yref:`interval<RbsmTimeStepper.interval>` steps: if "
		":yref:`setDt<RbsmTimeStepper.setDt>`, O.dt becomes safetyFactor·dt_crit; otherwise a step with "
		"O.dt > safetyFactor·dt_crit is refused with an error before anything moves.\n\n"
		"At every step it also switches off (dead) a :yref:`VTKRecorder` whose recorders (intr, stress, bstresses, all, ...) "
		"would read the RBSM joints as sphere contacts and crash YADE, and says so (yade_rbsm.vtkexport.recorder records blocks "
		"and joints instead).",
		((Real, safetyFactor, 0.8, Attr::triggerPostLoad, "Fraction of the critical step allowed (0 < safetyFactor ≤ 1)."))
		((bool, setDt, false, , "Set O.dt to safetyFactor·dt_crit (True) or only check it and refuse an unstable O.dt (False)."))
		((int, interval, 100, Attr::triggerPostLoad, "Check every this many steps (the first step is always checked). One estimate costs about one InteractionLoop pass of the exact geometry (docs/benchmarks.md), so 100 keeps it near 1 % of the run."))
		((bool, dtWasSet, false, , "Whether this engine has set O.dt already; from then on it only lowers O.dt (a corner contact found at a check may stiffen before the next one)."))
		((long, lastCheck, -1, Attr::readonly, "Step of the last check (saved with the scene, so that a loaded scene is checked on the same steps as an uninterrupted run)."))
		((Real, criticalDt, std::numeric_limits<Real>::infinity(), Attr::readonly, "Critical time step found at the last check [s].")),
		/*ctor*/,
		/*py*/ .def("estimate", &RbsmTimeStepper::estimate, "Critical time step of the current system [s] (inf if there is no RBSM joint yet); also stored in criticalDt.")
	);
	// clang-format on
private:
	// estimate()'s working arrays, kept between calls so that a check allocates nothing once the
	// scene has grown (not saved; the engine runs on one thread)
	std::vector<rbsm::DynBody>    dynBodies;
	std::vector<int>              dynIndex;
	std::vector<rbsm::DynContact> dynContacts;
	std::vector<Real>             dashpot, spring;
};
REGISTER_SERIALIZABLE(RbsmTimeStepper);

} // namespace yade
