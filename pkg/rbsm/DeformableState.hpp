// DeformableState: the state of a deformable RBSM block, its rigid motion (State) plus a constant
// strain (the seed's eq. 4), with the loads its joints put on that strain in the step.
#pragma once
#include <core/State.hpp>
#include <pkg/rbsm/kernel/StrainElement.hpp>

#include <atomic>
#include <vector>

namespace yade {

class Polygon2D;

class DeformableState : public State {
public:
	~DeformableState() override;
	//! Adds a joint's load Bᵀf on the strain (block frame) for this step; called by the joint law from
	//! InteractionLoop's threads (one slot per thread, like YADE's ForceContainer; a lock beyond them).
	void addStrainLoad(const Vector3r& load);
	//! The sum of this step's joint loads, the slots cleared (the strain integrator, one thread).
	Vector3r takeStrainLoad();
	//! The (θ, ε) mass of this block for its shape, mass and polar inertia (cached until one changes).
	const rbsm::StrainMass& strainMass(const Polygon2D& shape);
	//! How many DeformableState objects exist: 0 lets the strain integrator and the time stepper skip
	//! everything, so a rigid scene pays nothing for deformable blocks.
	static inline std::atomic<long> alive { 0 };
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(DeformableState, State,
		"State of a deformable RBSM block (:yref:`RbsmMat.deformable`): its rigid motion (:yref:`State`) and a constant strain, the "
		"seed paper's full element (eq. 4; Takeuchi's hybrid-type penalty method). A material point at r from the centroid (in the block's "
		"own frame) moves by d + θ ẑ×r + B(r)ε, B(r) = [[rx, 0, ry/2], [0, ry, rx/2]]; the joints see that displacement, and their "
		"tractions load the strain as the block's own stiffness D (from young, poisson, planeStrain) resists it. Made by "
		"RbsmMat.newAssocState() for a deformable material (yade_rbsm.polygon2d does it); integrated by :yref:`BlockStrainIntegrator`.",
		((Vector3r, strain, Vector3r::Zero(), , "Strain of the block (εxx, εyy, γxy) in its own frame (rotating with it; γxy the engineering shear strain) [-]."))
		((Vector3r, strainRate, Vector3r::Zero(), , "Rate of :yref:`strain<DeformableState.strain>` [1/s]."))
		((Vector3r, plasticStrain, Vector3r::Zero(), , "Plastic strain εᵖ of a yielding block (:yref:`RbsmMat.plastic`), (εxx, εyy, γxy) in the block's frame [-]; its stress is D(ε − εᵖ)."))
		((Real, plasticShear, 0, , "Accumulated plastic shear strain of the block, Σ|Δε1ᵖ − Δε3ᵖ| [-] (the band of a mechanism; 0: never yielded)."))
		((int, yieldMode, 0, Attr::readonly, "Where the block's stress was at the last step: 0 elastic, 1 on the Mohr-Coulomb shear surface, 2 on the tension cut-off, 3 at their corner."))
		((Vector3r, stress, Vector3r::Zero(), Attr::readonly, "Stress of the block, D(ε − εᵖ), in the world frame (σxx, σyy, σxy) [Pa], tension positive as in continuum mechanics; set by :yref:`BlockStrainIntegrator` at every step."))
		((Real, szz, 0, Attr::readonly, "Out-of-plane stress σzz [Pa] (plane strain: ν(σxx + σyy); plane stress: 0)."))
		((Vector3r, strainLoad, Vector3r::Zero(), (Attr::readonly | Attr::noSave), "The joints' load on the strain at the last step, Σ Bᵀ(r)f (block frame) [N m].")),
		/*ctor*/ createIndex(); initLoads();,
		/*py*/
	);
	// clang-format on
	REGISTER_CLASS_INDEX(DeformableState, State);

private:
	void                  initLoads();
	std::vector<Vector3r> threadLoads; // per OpenMP thread
	struct MassKey {
		long revision = -1;
		Real mass = -1, inertia = -1, area = -1, thickness = -1;
	} massKey;
	rbsm::StrainMass massCache;
};
REGISTER_SERIALIZABLE(DeformableState);

//! The deformable state of a block, or null for a rigid one (by class index, as polygonOf: a dynamic_cast
//! per joint side and step was 7 % of a deformable plate's instructions).
inline DeformableState* deformableState(State* s)
{
	return s && s->getClassIndex() == DeformableState::getClassIndexStatic() ? static_cast<DeformableState*>(s) : nullptr;
}
inline const DeformableState* deformableState(const State* s)
{
	return s && s->getClassIndex() == DeformableState::getClassIndexStatic() ? static_cast<const DeformableState*>(s) : nullptr;
}

} // namespace yade
