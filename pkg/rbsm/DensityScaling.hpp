// DensityScaling: the quasi-static stages' heavier blocks (RbsmTimeStepper.densityScaling). Every block
// whose own stable step is below a common one gets its inertia scaled by s >= 1 so that all run at that
// step; equilibrium is unchanged, the motion towards it is not physical. The stepper keeps the scales
// (its saved attributes massScale, rowDiag, scaledDt) and its rows; this is how they are found and applied.
#pragma once
#include <core/Body.hpp>
#include <core/Scene.hpp>

#include <vector>

namespace yade {

class DensityScaling {
public:
	/// The common step [s]: targetDt if > 0, else the median of the blocks' own steps (which it reorders);
	/// inf without any.
	static Real commonStep(std::vector<Real>& ownSteps, Real targetDt);
	/// The scale that lets a block run at step dt: its rows' Gershgorin bound w2 (own share diag), its
	/// damped step blockDt, the safety factor and NewtonIntegrator's damping.
	static Real scaleFor(Real w2, Real diag, Real blockDt, Real dt, Real safety, Real damping);
	/// A block's scale rises from s0 to s: its free velocities slow by √(s0/s).
	static void slowOnRise(State& s, Real s0, Real s1);
	/// Divides the block's force, weight and torque of this step by its scale (before NewtonIntegrator).
	void applyTo(Scene& scene, const std::vector<Real>& massScale);
	/// NewtonIntegrator.gravity is read again at the next applyTo (once per full estimate, not every step).
	void readGravityAgain() { gravityRead = false; }

private:
	struct ScaledLoad {
		Body::id_t id;
		Vector3r   force, torque;
	};
	std::vector<ScaledLoad> scaledLoads; // this step's corrections (kept: no allocation once grown)
	Vector3r                gravity     = Vector3r::Zero();
	bool                    gravityRead = false;
};

} // namespace yade
