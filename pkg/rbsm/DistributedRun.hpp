// DistributedRun: what RbsmTimeStepper does differently under yade.mpy: it bounds and watches only the
// blocks its rank owns, and keeps a refused step for the sync engine instead of throwing it.
#pragma once
#include <core/Body.hpp>
#include <core/Scene.hpp>

#include <stdexcept>
#include <string>

namespace yade {

// A worker (Scene.subdomain > 0) holds its own blocks and copies of its neighbours' blocks near its
// border; NewtonIntegrator moves only its own, and only they have all their joints on this rank (a
// copy's joints with blocks this rank does not hold are computed elsewhere). So the step and the motion
// checks are taken over its own blocks: the union over the ranks is the serial scene. The master
// (subdomain 0) and a serial or merged scene own every block.
[[gnu::always_inline]] inline bool ownedHere(const Scene& scene, const Body& b) { return scene.subdomain == 0 || b.subdomain == scene.subdomain; }

// A refused step: thrown, or with deferErrors kept in `kept` for the sync engine that follows, which
// stops every rank before NewtonIntegrator (a throw here would stop this rank alone and leave the others
// waiting for it in their next exchange).
inline void refuseStep(const std::string& message, bool deferErrors, std::string& kept)
{
	if (!deferErrors) throw std::runtime_error(message);
	kept = message;
}

// A scene split by yade.mpy whose stepper does not defer its errors runs without yade_rbsm's sync engine:
// each rank would take its own O.dt and the ranks drift apart silently (item 2 of issue 34: the master at
// t = 3e-6 s against 0.146 s serially). Refused on every rank at its first step (each rank throws: the job
// ends unless every rank's O.run loses its exception, see scene.advance).
inline void requireSyncEngine(bool split, bool deferErrors)
{
	if (!split || deferErrors) return;
	throw std::runtime_error("RbsmTimeStepper: this scene is split by yade.mpy but runs without yade_rbsm's sync engine: every rank "
	                         "would choose its own O.dt and the ranks would drift apart. "
	                           "Build the engines with yade_rbsm.engines(mpi=True) (the default when yade.mpy is imported before engines()), "
	                           "or run with yade_rbsm.mpi.mpirun, which adds it.");
}

// The sync engine taken out of a list that had it (deferErrors still set) is as silent: it stamps each step it
// runs in (RbsmTimeStepper.syncedAt), so a split scene's step without the stamp of the one before is refused.
inline void requireSyncEachStep(long iter, long& splitSince, long syncedAt)
{
	if (splitSince < 0 || iter <= splitSince) {
		splitSince = splitSince < 0 ? iter : splitSince;
		return;
	}
	if (syncedAt == iter - 1) return;
	throw std::runtime_error("RbsmTimeStepper: this scene is split by yade.mpy, but yade_rbsm's sync engine did not run in step "
	                         + std::to_string(iter - 1) + " (taken out of O.engines?): every rank would choose its own O.dt and the ranks "
	                           "would drift apart. Build the engines with yade_rbsm.engines(mpi=True), or run with yade_rbsm.mpi.mpirun, which adds it.");
}

// A refusal still kept at the next step: no sync engine took it, and the step it refused has run.
inline void throwUnclaimedRefusal(std::string& kept)
{
	if (kept.empty()) return;
	std::string message;
	std::swap(message, kept);
	throw std::runtime_error(message + " [deferErrors is set but no yade_rbsm.mpi sync engine follows RbsmTimeStepper: use yade_rbsm.engines(mpi=True)]");
}

} // namespace yade
