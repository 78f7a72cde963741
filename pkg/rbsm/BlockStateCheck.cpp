#include <pkg/rbsm/BlockStateCheck.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <core/State.hpp>

#include <cmath>
#include <sstream>

namespace yade {

namespace {
	bool finite(const Vector3r& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

	std::string problem(const char* what, Real value, const char* needed)
	{
		std::ostringstream msg;
		msg << what << " = " << value << " " << needed;
		return msg.str();
	}
}

std::string blockStateProblem(const Body& b)
{
	if (!b.shape || !b.state || b.shape->getClassIndex() != Polygon2D::getClassIndexStatic()) return {};
	const State& s = *b.state;
	// Only free degrees of freedom divide by the mass or inertia (a fixed base may have none).
	const bool moves = (s.blockedDOFs & (State::DOF_X | State::DOF_Y)) != (State::DOF_X | State::DOF_Y);
	const bool turns = !(s.blockedDOFs & State::DOF_RZ);
	if (moves && !(std::isfinite(s.mass) && s.mass > 0)) return problem("has state.mass", s.mass, "(a free block needs a finite mass > 0)");
	if (turns && !(std::isfinite(s.inertia.z()) && s.inertia.z() > 0))
		return problem("has state.inertia[2]", s.inertia.z(), "(a block free to rotate needs a finite polar inertia > 0)");
	const Quaternionr& q = s.ori;
	if (!(std::isfinite(q.w()) && std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z()))) return "has a state.ori that is not finite";
	// A rotation about z only is (cos θ/2, 0, 0, sin θ/2); the contact geometry reads θ alone.
	const Real tilt = std::abs(q.x()) + std::abs(q.y());
	if (tilt * tilt > 1e-18 * q.squaredNorm()) { // |x| + |y| > 1e-9 |q|, without a square root
		std::ostringstream msg;
		msg << "is rotated out of the x-y plane (state.ori has x, y components " << q.x() << ", " << q.y()
		    << "; a Polygon2D block rotates about z only: keep 'XY' in state.blockedDOFs)";
		return msg.str();
	}
	if (!finite(s.pos)) return "has a state.pos that is not finite";
	if (!finite(s.vel) || !finite(s.angVel)) return "has a state.vel or state.angVel that is not finite";
	// YADE keeps the velocity of a blocked DOF as it is: a z velocity carries the block out of the
	// plane of its neighbours (their boxes stop overlapping) and it passes through them silently.
	if (s.vel.z() != 0 || s.angVel.x() != 0 || s.angVel.y() != 0) {
		std::ostringstream msg;
		msg << "moves out of the x-y plane (state.vel z = " << s.vel.z() << ", state.angVel x, y = " << s.angVel.x() << ", " << s.angVel.y()
		    << "; a Polygon2D block moves in the plane only: set them to 0)";
		return msg.str();
	}
	return {};
}

} // namespace yade
