// BlockStateCheck: what is wrong with the state of one RBSM block, for the engine's per-step pass.
#pragma once
#include <core/Body.hpp>

#include <string>

namespace yade {

/// The problem with body b's state as a block of the model, "" when there is none (or b is not a
/// Polygon2D block): a free translation with a mass that is not a finite number > 0, a free rotation
/// about z with such an inertia, an orientation out of the x-y plane (or not finite), a position or
/// velocity that is not finite. Read-only and cheap (no allocation when fine): called for every body
/// at every step by RbsmTimeStepper, which reports it by body id and stops the run after the step.
std::string blockStateProblem(const Body& b);

} // namespace yade
