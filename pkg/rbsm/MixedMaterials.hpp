// Which materials the contacts of blocks with YADE's own bodies accept, checked when a contact is
// made: a functor that met another material would leave the interaction to an IPhys dispatch that
// has no functor for it, and InteractionLoop then throws inside its OpenMP loop (the process ends).
// A refused pair is reported (StepReport.hpp) and the run stops after the step.
#pragma once
#include <core/Body.hpp>
#include <core/Interaction.hpp>
#include <core/Scene.hpp>

#include <atomic>
#include <string>

namespace yade {
namespace rbsm_mixed {
	/// "" if body id's material is one that `role` accepts, otherwise the problem in words:
	///  role Block: an RbsmMat; role Grain: a FrictMat (or a subclass) or an RbsmMat;
	///  role Boundary (a wall or facet under blocks): an RbsmMat or a FrictMat.
	enum class Role { Block, Grain, Boundary };
	std::string materialProblem(const Scene& scene, int id, Role role);

	/// Checks both bodies of a new contact; reports the first problem (naming functor `who`, the
	/// bodies and what is wrong) and returns false if there is one.
	bool materialsAccepted(std::atomic<int>& reports, Scene& scene, const char* who, const Interaction& I, Role role1, Role role2);
} // namespace rbsm_mixed
} // namespace yade
