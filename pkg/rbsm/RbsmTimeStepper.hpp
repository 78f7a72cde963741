// RbsmTimeStepper: the stability limit of the explicit integration of an RBSM block system.
#pragma once
#include <core/GlobalEngine.hpp>
#include <pkg/rbsm/BlockMotionWatch.hpp>
#include <pkg/rbsm/DensityScaling.hpp>
#include <pkg/rbsm/VtkRecorderGuard.hpp>
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>

namespace yade {

class Interaction;
class RbsmPhys;

class RbsmTimeStepper : public GlobalEngine {
public:
	void action() override;
	//! Checks the attributes when they are set (raises ValueError in Python, before any step).
	void postLoad(RbsmTimeStepper&);
	//! A full estimate that the next step would make (a joint's kn, ks or a block's mass, inertia or
	//! shape set since the last step) is saved as lastCheck = -1: the loaded scene cannot see these edits.
	void preSave(RbsmTimeStepper&);
	void postSave(RbsmTimeStepper&);
	//! Switches off a VTKRecorder whose recorders would crash YADE on RBSM joints (see VtkRecorderGuard).
	VtkRecorderGuard vtkRecorderGuard;
	//! Critical time step of the present joints [s] (+inf if no RBSM joint exists yet).
	Real estimate();
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmTimeStepper, GlobalEngine,
		"Keeps the explicit (central-difference) integration of RBSM blocks stable at every step. The stable step is the "
		"smaller of two limits, times safetyFactor and divided by √(1 + NewtonIntegrator.damping) (Cundall's damping "
		"raises a decelerating force by that factor):\n\n"
		"* the joints (:yref:`criticalDt<RbsmTimeStepper.criticalDt>`): dt_crit = 2/ω_max, ω_max² the largest eigenvalue "
		"of M⁻¹K for the blocks (mass, polar inertia) and the joint springs (kn, ks per unit area at every integration point, "
		"times its tributary area), bounded from above by the block Gershgorin theorem (Feingold & Varga 1962) on "
		"M^-½ K M^-½. A joint whose incident block touches by a corner that is closing by rotation counts with the length "
		"it reaches once flat (the shorter of its two edges), not its present one. With joint dashpots (Law2's "
		"dampingRatio) each block's limit is 2/(√(ω̂²+γ̂²) + γ̂) = (2/ω̂)(√(1+ξ²) − ξ), γ̂ half the Gershgorin bound of "
		"M^-½ C M^-½ for the dashpots as they will be once a closing corner lies flat (ξ = γ̂/ω̂). A full "
		"estimate runs every :yref:`interval<RbsmTimeStepper.interval>` steps; a joint made in between raises the bounds of "
		"its two blocks at the step it is made (the Gershgorin terms add up), before anything moves;\n"
		"* the first contacts (:yref:`firstContactDt<RbsmTimeStepper.firstContactDt>`): the stiffest single joint each free "
		"block that has no joint yet can form (one of its edges in full contact, Kawai springs with the thinnest, stiffest partner in the scene), "
		"so that blocks that have not met yet run at a step their first contact survives (a block with joints is bounded by them, and a joint it makes later is added at the step it is made).\n\n"
		"With :yref:`setDt<RbsmTimeStepper.setDt>` O.dt is set to that step at every step (at most "
		":yref:`maxDt<RbsmTimeStepper.maxDt>`); otherwise a larger O.dt (or O.dt ≤ 0) is refused with an error before "
		"anything moves. A block that moves or turns by more than :yref:`maxStepMotion<RbsmTimeStepper.maxStepMotion>` of "
		"its inner radius in one step (tunnelling, or an explosion) is reported by id and the run stops after that step; "
		"with setDt the step is also kept short enough for every block to move by at most half that (never below a tenth of "
		"the stable step, so that an explosion is reported, not run in slow motion).\n\n"
		"It also makes the collider run (Scene.doSort) before a block's rotation since its box was made can carry "
		"a corner out of the box: YADE's Verlet boxes follow translations only, and a rotating block was found already deep "
		"inside its neighbour.\n\n"
		"Place it after :yref:`InteractionLoop` and before :yref:`NewtonIntegrator`, so that the joints of this step are "
		"known before the integration.\n\n"
		"At every step it also switches off (dead) a :yref:`VTKRecorder` whose recorders (intr, stress, bstresses, all, ...) "
		"would read the RBSM joints as sphere contacts and crash YADE, and says so (yade_rbsm.vtkexport.recorder records blocks "
		"and joints instead).\n\n"
		"Under yade.mpy (Scene.subdomain > 0, a worker) it bounds, checks and reports the blocks its rank owns "
		"(Body.subdomain): they have all their joints there, so the minimum over the ranks of :yref:`stepDt<RbsmTimeStepper.stepDt>` "
		"is the serial step. yade_rbsm.mpi's sync engine, placed right after this one, sets that minimum on every rank "
		"and stops every rank when one refuses a step (:yref:`deferErrors<RbsmTimeStepper.deferErrors>`).",
		((Real, safetyFactor, 0.8, Attr::triggerPostLoad, "Fraction of the stable step allowed (0 < safetyFactor ≤ 1)."))
		((Real, impactSafety, 0.25, Attr::triggerPostLoad,
			"Fraction of the stable step allowed while contacts can open and close (0 < impactSafety ≤ 1; at most safetyFactor is used): "
			"frictional joints (no intact point) and the first contacts of blocks without joints, in undamped stages (NewtonIntegrator.damping = 0; contact damping, Law2_RbsmGeom_RbsmPhys_MohrCoulomb.dampingRatio, does not count: its landings are impacts too). "
			"Stability needs only safetyFactor, but an impact resolved in two or three steps stores up to (ω·dt)² of its energy in the overlap of its first step: "
			"at 0.8 a flat block dropped 2 m rebounded to 3.5 m. Bonded joints and damped (quasi-static) stages keep safetyFactor; set it to safetyFactor for the old behaviour. "
			"Accuracy, not stability: only the step the stepper sets (setDt) takes it; with setDt=False a larger O.dt is not refused for it, and yade_rbsm.critical_time_step() is the stability limit."))
		((bool, setDt, false, , "Set O.dt to the stable step (True) or only check it and refuse a larger O.dt (False). An O.dt set from a script (or another engine) between two steps that this engine set switches setDt off, with a note (as YADE's time steppers stop at ``O.dt = x``): the step is then the script's, checked against the stable limit. Assigning setDt (True) lets the stepper choose the step again at its next step, also right after ``O.dt = x``. (YADE's ``O.dt = -1`` looks for a TimeStepper, which this GlobalEngine is not.)"))
		((Real, dtSet, 0, , "The O.dt this engine set at its last step (0: none since setDt was last off or assigned from Python); another O.dt at the next step was set from outside (see :yref:`setDt<RbsmTimeStepper.setDt>`). Saved with the scene, with O.dt: an O.dt set after O.load or O.loadTmp is a script's too. yade_rbsm.mpi's sync engine, which sets O.dt to the ranks' minimum, sets it too."))
		((int, interval, 100, Attr::triggerPostLoad, "Full estimate every this many steps (the first step always has one); joints made in between are added at once. One full estimate costs about one InteractionLoop pass of the exact geometry (docs/benchmarks.md), so 100 keeps it near 1 % of the run."))
		((Real, maxDt, std::numeric_limits<Real>::infinity(), Attr::triggerPostLoad, "Largest step that setDt sets [s] (> 0): a user's cap below the stable step."))
		((Real, maxStepMotion, 0.5, Attr::triggerPostLoad, "Largest motion of a block in one step, (|v| + |ω| R)·dt, as a fraction of its inner radius (the distance from its centroid to its nearest edge line) before it is reported and the run stopped; 0 switches the check off."))
		((long, lastCheck, -1, Attr::readonly, "Step of the last full estimate (saved with the scene, so that a loaded scene is checked on the same steps as an uninterrupted run)."))
		((Real, criticalDt, std::numeric_limits<Real>::infinity(), Attr::readonly, "Critical time step of the joints [s], from the last full estimate and the joints made since (inf: no joint). Where impactSafety applies (frictional joints in undamped stages) those joints count (safetyFactor/impactSafety)² stiffer, so that safetyFactor × criticalDt is their impactSafety step: then it is below the stability limit of yade_rbsm.critical_time_step()."))
		((Real, firstContactDt, std::numeric_limits<Real>::infinity(), Attr::readonly, "Critical time step of the stiffest single joint the free blocks without joints can form [s] (inf: no such block, or nothing it can meet)."))
		((Real, newtonDamping, 0, Attr::readonly, "NewtonIntegrator's damping as read at the last full estimate."))
		((int, criticalBody, -1, Attr::readonly, "Id of the block whose joints limit criticalDt (-1: none)."))
		((bool, densityScaling, false, , "Quasi-static stages only (gravity settling, strength reduction): blocks whose own stable step is below :yref:`targetDt<RbsmTimeStepper.targetDt>` get heavier inertia (massScale, their force and weight divided by it before NewtonIntegrator), so that all of them run at the target step; a joint made between full estimates scales its two blocks at once, and a block it makes s times heavier is slowed by 1/√s (the kinetic energy of its scaled motion kept). Equilibrium, and so a settled state or a factor of safety, is unchanged; the motion towards it is not physical (time, kinetic energy). Off for dynamics. NewtonIntegrator.densityScaling is not used (it is tied to GlobalStiffnessTimeStepper)."))
		((Real, targetDt, 0, Attr::triggerPostLoad, "Step of the density-scaled stages [s] (finite, >= 0); 0: the stable step of the median block (the smaller blocks scaled up to it). A change takes effect at the next step (a full estimate)."))
		((Real, scaledDt, std::numeric_limits<Real>::infinity(), Attr::readonly, "The step density scaling runs at [s] (targetDt, or the median block's step), from the last full estimate."))
		((std::vector<Real>, massScale, , Attr::readonly, "Per body id: the factor s ≥ 1 applied to its inertia by densityScaling (1: none; empty when off)."))
		((bool, massScaled, false, Attr::hidden, "densityScaling as of the last step (a switch makes a full estimate at once)."))
		((bool, deferErrors, false, , "Distributed runs (set by yade_rbsm.engines(mpi=True)): a refused step is not thrown here but kept in :yref:`error<RbsmTimeStepper.error>` (O.dt untouched), and yade_rbsm.mpi's sync engine, which must follow this one, raises it on every rank before NewtonIntegrator. An error still kept when this engine runs again (no sync engine took it) is thrown then. A scene split by yade.mpy without it refuses its first step on every rank: each rank would choose its own O.dt."))
		((std::string, error, "", Attr::noSave, "The refusal kept by :yref:`deferErrors<RbsmTimeStepper.deferErrors>` at this step (empty: none); the sync engine reads and clears it."))
		((long, syncedAt, -1, Attr::noSave, "The step at which yade_rbsm.mpi's sync engine last ran (it sets it): in a scene split by yade.mpy it must have run in every step since the first, or the step is refused (each rank would take its own O.dt)."))
		((long, splitSince, -1, (Attr::hidden | Attr::noSave), "The first step this engine ran in a scene split by yade.mpy (-1: none yet)."))
		((Real, stepDt, std::numeric_limits<Real>::infinity(), (Attr::readonly | Attr::noSave), "The step chosen at the last run [s]: min(stableDt, maxDt, the travel limit of maxStepMotion); what setDt sets (inf: no block of this rank bounds it). Under yade.mpy the sync engine sets O.dt to its minimum over the ranks."))
		((bool, orderInteractions, true, , "Sort the interactions by body ids, in the container and in memory (MemoryOrder.hpp), once, at the first step of this engine that has interactions (so also right after O.load). The collider makes them in sweep order and O.load interleaves them with the bodies, which made a contact-step 1.3-1.7x slower at 10^4-10^5 blocks (docs/benchmarks.md). An interaction held elsewhere (a Python variable) keeps its object. False: YADE's order, as before; results differ by the order of summation only."))
		((long, orderedAt, -1, (Attr::readonly | Attr::noSave), "Step at which :yref:`orderInteractions<RbsmTimeStepper.orderInteractions>` sorted the interactions (-1: not yet by this engine object; under yade.mpy the step at which it was skipped)."))
		((std::vector<Real>, rowBounds, , Attr::hidden, "Per body id: the Gershgorin bounds of its rows, ω² of the springs and λ of the joints' dashpots, and an unused slot, since the last full estimate (saved, so that a loaded scene continues like the uninterrupted run)."))
		((Real, scaledTarget, -1, Attr::hidden, "targetDt as of the last full estimate under densityScaling (another value makes a full estimate at once)."))
		((std::vector<Real>, rowDiag, , Attr::hidden, "densityScaling: per body id, the own-block share of rowBounds' ω² (saved with it: a loaded scene keeps its scales and scales the joints it makes like the uninterrupted run).")),
		/*ctor*/ editsSeen = jointEdits();,
		/*py*/ .def("estimate", &RbsmTimeStepper::estimate, "Critical time step of the present joints [s] (inf if there is no RBSM joint yet); also stored in criticalDt.")
		.def("limit", &RbsmTimeStepper::limit, "Runs a full estimate of the scene as it is now (joints, first contacts, NewtonIntegrator.damping) and returns :yref:`stableDt<RbsmTimeStepper.stableDt>` [s], the step this engine would allow; what yade_rbsm.critical_time_step() returns at safetyFactor=1.")
		.def("checkNextStep", &RbsmTimeStepper::checkNextStep, "Makes the next run of this engine a full estimate (as at the first step), e.g. after a scene was merged from yade.mpy's ranks (yade_rbsm.mpi.to_serial), whose joints this engine has not seen.")
		// setDt assigned from Python (ts.setDt = True after O.dt = x, as scripts/qt_view_landslide.py does)
		// is the script's choice: the O.dt set before it is the stepper's to replace, not a script's step
		.add_property("setDt", &RbsmTimeStepper::getSetDt, &RbsmTimeStepper::assignSetDt, "Set O.dt to the stable step (True) or only check it and refuse a larger O.dt (False). An O.dt set from a script (or another engine) between two steps that this engine set switches setDt off, with a note (as YADE's time steppers stop at ``O.dt = x``): the step is then the script's, checked against the stable limit. Assigning setDt (True) lets the stepper choose the step again at its next step, also right after ``O.dt = x``. (YADE's ``O.dt = -1`` looks for a TimeStepper, which this GlobalEngine is not.)")
		.add_property("stableDt", &RbsmTimeStepper::stableDt, "The step this engine allows now [s]: min(safetyFactor × criticalDt, f × firstContactDt) / √(1 + newtonDamping), f = impactSafety where it applies (setDt, undamped stages), else safetyFactor; with densityScaling, the density-scaled stages' common step (targetDt).")
	);
	// clang-format on
	Real stableDt() const;
	Real limit();
	bool getSetDt() const { return setDt; }
	void assignSetDt(bool on) { setDt = on, dtSet = 0; } // (from Python: the script's choice, see setDt)
	void checkNextStep() { lastCheck = -1; }

private:
	void fullCheck();
	void requireStrainIntegrator();
	void addJointsMadeThisStep();
	inline void watchBody(const Body& b, Real& travelDt, bool& runCollider); // the motion watch of one block
	void        takeScriptDt(); // an O.dt set from outside since this engine set it: setDt off
	void        reportMotion(const Body& b, Real motion, Real r); // (the rare path, out of the loop)
	bool checkBlocks(bool watchLater, Real& travelDt, bool& runCollider, bool& split); // the pass over the bodies; false: a bad block, the step refused
	void updateBounds(long made);
	void chooseStep(Real travelDt);
	void scaleMasses();
	Real massScaleOf(size_t id) const;
	void raiseMassScale(size_t id, Real s);
	bool scalesHold(size_t nBodies);
	template <class Keep> const std::vector<const Interaction*>& jointsByIds(Keep keep);
	Real firstContactEstimate(); // (also fills firstOmega2)
	bool jointAsDynContact(const Interaction& I, int body1, int body2, rbsm::DynContact& c) const;
	bool jointDashpots(const Interaction& I, const rbsm::DynContact& springs, rbsm::DynContact& c) const;
	bool mayImpact(const RbsmPhys& p) const;
	bool impactsMatter() const;
	Real firstContactSafety() const;
	Real blockDt(size_t id) const; // damped step of body id's rows (rowBounds)
	void boundsHold(size_t nBodies);
	// estimate()'s working arrays, kept between calls so that a check allocates nothing once the
	// scene has grown (not saved; the engine runs on one thread)
	std::vector<rbsm::DynBody>    dynBodies;
	std::vector<int>              dynIndex, dynIds;
	std::vector<rbsm::DynContact> dynContacts, dashpots;
	std::vector<Real>             firstOmega2; // firstContactEstimate's ω² of each free block without joints (for scaleMasses)
	long                          jointsSeen = -1;
	long                          savedLastCheck = -1; // lastCheck around a save (preSave, postSave)
	long                          editsSeen  = -1; // RbsmPhys::edits at the last step (a joint's kn, ks set from Python since: a full estimate)
	static long                   jointEdits();
	std::vector<const Interaction*> sortedJoints; // jointsByIds' result
	DensityScaling                  densityScale; // applies the scales, with its own working arrays
	BlockMotionWatch                motionWatch; // the collider trigger and the motion check of every block (and its inner radius)
	std::vector<Body::id_t> reshapedIds; // this step's reshaped blocks, watched after the full estimate
};
REGISTER_SERIALIZABLE(RbsmTimeStepper);

} // namespace yade
