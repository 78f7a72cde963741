// BlockStateCheck: what is wrong with the state of one RBSM block, for the engine's per-step pass.
#pragma once
#include <core/Body.hpp>
#include <core/State.hpp>

#include <cmath>
#include <string>

namespace yade {

/// The block is fixed for the model: all six DOFs blocked (a fixed end of a joint counts as infinite mass).
inline bool fixedBlock(const State& s) { return (s.blockedDOFs & State::DOF_ALL) == State::DOF_ALL; }

/// The problem with body b's state as a block of the model, "" when there is none (or b is not a
/// Polygon2D block): a free translation with a mass that is not a finite number > 0, a free rotation
/// about z with such an inertia, an orientation out of the x-y plane (or not finite), a position or
/// velocity that is not finite. Read-only and cheap (no allocation when fine): called for every body
/// at every step by RbsmTimeStepper, which refuses the step naming the body (before NewtonIntegrator).
std::string blockStateProblem(const Body& b);

/// True for the usual block (free in x, y and about z, finite positive mass and inertia, finite pose
/// and velocities in the plane): blockStateProblem(b) is then "" without a call. False says nothing
/// (a fixed block, a tilt below the tolerance, a sum that overflows): ask blockStateProblem.
inline bool blockStateSurelyFine(const State& s)
{
	// one sum: a NaN or an infinity anywhere makes it non-finite
	const Real sum = s.mass + s.inertia.z() + s.ori.w() + s.ori.z() + s.pos.x() + s.pos.y() + s.pos.z() + s.vel.x() + s.vel.y() + s.angVel.z();
	return std::isfinite(sum) && s.mass > 0 && s.inertia.z() > 0 && s.ori.x() == 0 && s.ori.y() == 0 && s.vel.z() == 0
	        && s.angVel.x() == 0 && s.angVel.y() == 0;
}

} // namespace yade
