// Problems found while a step runs. The functors run inside YADE's OpenMP loops, which an exception
// cannot leave (std::terminate ends YADE), so they report on stderr instead, and stop the run after
// the step where going on would compute without part of the model.
#pragma once
#include <core/Scene.hpp>

#include <atomic>
#include <iostream>
#include <mutex>
#include <sstream>
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
} // namespace rbsm_report
} // namespace yade
