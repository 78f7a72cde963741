#include <pkg/rbsm/DensityScaling.hpp>
#include <pkg/rbsm/NewtonAttribute.hpp>
#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace yade {

Real DensityScaling::commonStep(std::vector<Real>& ownSteps, Real targetDt)
{
	if (ownSteps.empty()) return std::numeric_limits<Real>::infinity();
	std::nth_element(ownSteps.begin(), ownSteps.begin() + ownSteps.size() / 2, ownSteps.end());
	return targetDt > 0 ? targetDt : ownSteps[ownSteps.size() / 2];
}

// rbsm::densityScale makes the block's Gershgorin row allow ω_T whichever neighbours are scaled; its
// joint dashpots keep the factor of its unscaled step (smaller ω: a smaller damping ratio, a larger factor).
Real DensityScaling::scaleFor(Real w2, Real diag, Real blockDt, Real dt, Real safety, Real damping)
{
	if (!(w2 > 0)) return 1;
	const Real damped = blockDt * std::sqrt(w2) / 2; // the dashpots' factor on 2/ω
	const Real wT     = 2 * safety * damped / (dt * std::sqrt(1 + damping));
	return rbsm::densityScale(diag, w2 - diag, wT * wT);
}

// Slowing keeps the kinetic energy ½ s m v² of the scaled motion: a block keeping its velocity while it
// was made s/s0 times heavier (a falling block scaled at its first joint) carried s/s0 times its energy
// into its joints, and a later fall of its scale released that energy into the light block (a 3 cm block
// thrown at 8.8 m/s). A prescribed velocity (a blocked DOF) stays.
void DensityScaling::slowOnRise(State& st, Real s0, Real s1)
{
	if (!(s1 > s0 && s0 > 0)) return;
	const Real k = std::sqrt(s0 / s1);
	for (int i = 0; i < 3; i++) {
		if (!(st.blockedDOFs & (1u << i))) st.vel[i] *= k; // DOF_X, _Y, _Z
		if (!(st.blockedDOFs & (8u << i))) st.angVel[i] *= k; // DOF_RX, _RY, _RZ
	}
}

// NewtonIntegrator divides force + m g by m; adding (1/s − 1) of it (and of the torque) makes that
// (force + m g)/(s m). Equilibrium (zero force) is unchanged.
void DensityScaling::applyTo(Scene& scene, const std::vector<Real>& massScale)
{
	if (!gravityRead) {
		const Vector3r g = newtonAttribute<Vector3r>(scene, "gravity", Vector3r::Zero());
		gravity          = g.allFinite() ? g : Vector3r::Zero();
		gravityRead      = true;
	}
	scene.forces.sync();
	scaledLoads.clear(); // read all first: an addForce unsyncs the container
	for (const auto& b : scene.bodies->body) {
		if (!b || size_t(b->id) >= massScale.size() || !(massScale[b->id] > 1)) continue;
		const Real k = 1 / massScale[b->id] - 1;
		scaledLoads.push_back({ b->id, k * (scene.forces.getForce(b->id) + b->state->mass * gravity), k * scene.forces.getTorque(b->id) });
	}
	for (const ScaledLoad& l : scaledLoads) {
		scene.forces.addForce(l.id, l.force);
		scene.forces.addTorque(l.id, l.torque);
	}
}

} // namespace yade
