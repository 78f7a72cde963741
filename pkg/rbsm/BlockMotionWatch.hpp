// BlockMotionWatch: what RbsmTimeStepper checks of every block's motion at every step, in its one pass over
// the bodies: that the collider's box still holds the block's next pose, and that no block moves by a good
// part of its size in one step. (Inline: a call per block cost 11 instructions per contact-step on a wall.)
#pragma once
#include <core/Body.hpp>
#include <core/Bound.hpp>
#include <core/Scene.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace yade {

class BlockMotionWatch {
public:
	/// Room for nBodies blocks' box poses.
	void grow(size_t nBodies)
	{
		if (boundPose.size() < nBodies) boundPose.resize(nBodies);
	}
	/// Sets runCollider when the block's next pose can leave its box (keepBoundAhead below).
	inline void keepBoundAhead(const Scene& scene, const Body& b, const Polygon2D& poly, bool& runCollider);
	/// Lowers travelDt to the step at which the block would move by half maxStepMotion of its inner radius;
	/// true if it moved by more than that in this step (motion and r then say how much, and of what).
	inline bool movesTooFar(const Scene& scene, const Body& b, const Polygon2D& poly, Real maxStepMotion, Real& travelDt, Real& motion, Real& r);

private:
	struct BoundPose {
		long iter = -1; // Bound::lastUpdateIter when c, s were taken
		Real c = 1, s = 0;
	};
	std::vector<BoundPose> boundPose; // per body id: its rotation when the collider last made its box
};

// A block that moves by a good part of its own size in one step passes through thin neighbours
// (tunnelling) or is exploding: never silent. travelDt: for setDt, a block with short, soft edges (a
// near-circle) has a long stable step.
[[gnu::always_inline]] inline bool
BlockMotionWatch::movesTooFar(const Scene& scene, const Body& b, const Polygon2D& poly, Real maxStepMotion, Real& travelDt, Real& motion, Real& r)
{
	const State& s = *b.state;
	r = poly.inradius;
	const Real speed = s.vel.head<2>().norm() + std::abs(s.angVel.z()) * poly.circumradius;
	motion           = speed * scene.dt;
	if (speed > 0) travelDt = std::min(travelDt, 0.5 * maxStepMotion * r / speed);
	return motion > maxStepMotion * r; // (a NaN O.dt is the step check's to refuse, not a move)
}

// YADE's collider enlarges each box by its Verlet sweep and runs again once a body's centroid has
// moved beyond it (NewtonIntegrator), but a rotation moves a block's corners too: by R·χ, χ the chord
// of the rotation since the box was made. A block tipping onto its neighbour was found deep inside
// it, a step of spring energy from nothing at every landing (a rocking block bounced metres high).
// So the collider runs at the next step when the next pose can leave the box: |Δx|∞ + R χ, with
// this step's velocities added twice as margin, beyond the sweep (and half the box's round-off margin).
[[gnu::always_inline]] inline void BlockMotionWatch::keepBoundAhead(const Scene& scene, const Body& b, const Polygon2D& poly, bool& runCollider)
{
	const State& st = *b.state;
	Real         c, s;
	planarCosSin(st.ori, c, s);
	BoundPose& ref = boundPose[size_t(b.id)];
	if (b.bound->lastUpdateIter == scene.iter) ref = BoundPose { scene.iter, c, s }; // the collider ran this step
	else if (b.bound->lastUpdateIter == scene.iter - 1 && ref.iter != scene.iter - 1)
		// made after the stepper ran in the last step, so after its integration: yade.mpy runs its
		// collider at the end of a step. Nothing has moved since; the pose is the one the box saw.
		ref = BoundPose { scene.iter - 1, c, s };
	if (runCollider) return;
	if (ref.iter != b.bound->lastUpdateIter) { // a box made while the stepper was not watching
		runCollider = true;
		return;
	}
	const Real     R     = poly.circumradius;
	const Real     chord = std::hypot(c - ref.c, s - ref.s);
	const Vector3r d     = st.pos - b.bound->refPos;
	const Real     move  = std::max(std::abs(d.x()), std::abs(d.y())) + 2 * scene.dt * st.vel.head<2>().cwiseAbs().maxCoeff()
	        + R * (chord + 2 * scene.dt * std::abs(st.angVel.z()));
	if (move > b.bound->sweepLength + 0.5e-6 * R) runCollider = true;
}

} // namespace yade
