// Problems found while a step runs. The functors run inside YADE's OpenMP loops, which an exception
// cannot leave (std::terminate ends YADE), so they report on stderr instead, and stop the run after
// the step where going on would compute without part of the model.
#pragma once
#include <core/Interaction.hpp>
#include <core/Scene.hpp>

#include <atomic>
#include <cmath>
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>

namespace yade {
namespace rbsm_report {
	/// Prints the line that message(last) makes, for the first five calls with this counter (one
	/// counter per kind of problem); last is true for the fifth, whose line should say that further
	/// ones are not shown. The message is made only when it is printed.
	template <class MakeMessage> void limited(std::atomic<int>& count, MakeMessage message)
	{
		const int k = count.fetch_add(1);
		if (k >= 5) return;
		std::cerr << std::string(message(k == 4)) + "\n";
	}

	/// Stops the run at the end of the current step (Scene.stopAtIter); safe from several threads.
	inline void stopAfterThisStep(Scene& scene)
	{
		static std::mutex           stop;
		const std::lock_guard<std::mutex> lock(stop);
		scene.stopAtIter = scene.iter + 1;
	}

	/// A pair of bodies the model cannot handle, found by functor `who` during a step: the run stops
	/// after this step, and the line "yade-rbsm: ERROR: who: bodies #id1 and #id2 problem; the run
	/// stops after step N" is printed as limited() prints.
	inline void stopForPair(std::atomic<int>& count, Scene& scene, const char* who, int id1, int id2, const char* problem)
	{
		stopAfterThisStep(scene);
		limited(count, [&](bool last) {
			std::ostringstream msg;
			msg << "yade-rbsm: ERROR: " << who << ": bodies #" << id1 << " and #" << id2 << " " << problem << "; the run stops after step "
			    << scene.iter << (last ? "; further such errors are not shown" : "");
			return msg.str();
		});
	}
	/// A body the model cannot handle, found by engine `who` during a step: the run stops after this
	/// step, and "yade-rbsm: ERROR: who: body #id problem; the run stops after step N" is printed as
	/// limited() prints.
	inline void stopForBody(std::atomic<int>& count, Scene& scene, const char* who, int id, const std::string& problem)
	{
		stopAfterThisStep(scene);
		limited(count, [&](bool last) {
			std::ostringstream msg;
			msg << "yade-rbsm: ERROR: " << who << ": body #" << id << " " << problem << "; the run stops after step " << scene.iter
			    << (last ? "; further such errors are not shown" : "");
			return msg.str();
		});
	}

	/// The report of acrossPeriodicCell (below), out of line: inlined, the setup of its message would be
	/// scheduled into every call of the functor.
	[[gnu::cold, gnu::noinline]] inline void refusePeriodic(std::atomic<int>& count, Scene& scene, const char* who, const Interaction& I)
	{
		stopForPair(count, scene, who, I.getId1(), I.getId2(), "meet across the boundary of a periodic cell (O.periodic): periodic cells are not supported");
	}
	/// Periodic cells are not supported by the block functors: a pair met across the cell's boundary
	/// (shift2 ≠ 0) is reported and the run stopped after this step, so that no step runs with the
	/// contacts across it missing. True if refused.
	inline bool acrossPeriodicCell(std::atomic<int>& count, Scene& scene, const char* who, const Interaction& I, const Vector3r& shift2)
	{
		if (shift2 == Vector3r::Zero()) return false;
		refusePeriodic(count, scene, who, I);
		return true;
	}

	/// The attributes every contact functor of blocks has, checked when set (postLoad; ValueError in
	/// Python, before any step): nIP in 1..8, interactionDistance finite and >= 0.
	inline void checkContactAttributes(const char* who, int nIP, Real interactionDistance)
	{
		if (nIP < 1 || nIP > 8) throw std::invalid_argument(std::string(who) + ".nIP: must be 1..8 (got " + std::to_string(nIP) + ")");
		if (!(std::isfinite(interactionDistance) && interactionDistance >= 0))
			throw std::invalid_argument(std::string(who) + ".interactionDistance: must be a finite distance >= 0 (got " + std::to_string(interactionDistance)
			                            + ")");
	}
} // namespace rbsm_report
} // namespace yade
