// Kinematic state of a body (YADE's State): 320 bytes in Debian's build. Declared with YADE's
// defaults and archive format, so that the plugin's DeformableState can derive from it.
#pragma once
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>
#include <mutex>

namespace yade {
class State : public Serializable, public Indexable {
public:
	Vector3r&    pos; // refers to se3.position
	Quaternionr& ori; // refers to se3.orientation
	std::mutex   updateMutex;
	enum { DOF_NONE = 0, DOF_X = 1, DOF_Y = 2, DOF_Z = 4, DOF_RX = 8, DOF_RY = 16, DOF_RZ = 32 };
	static const unsigned DOF_ALL = DOF_X | DOF_Y | DOF_Z | DOF_RX | DOF_RY | DOF_RZ;

	~State() override;
	YADE_BUILTIN_CLASS_INIT(State, Serializable,
		((Se3r, se3, Se3r(Vector3r::Zero(), Quaternionr::Identity()), , "Position and orientation as one object."))
		((Vector3r, vel, Vector3r::Zero(), , "Current linear velocity."))
		((Real, mass, 0, , "Mass of this body."))
		((Vector3r, angVel, Vector3r::Zero(), , "Current angular velocity."))
		((Vector3r, angMom, Vector3r::Zero(), , "Current angular momentum."))
		((Vector3r, inertia, Vector3r::Zero(), , "Inertia of the body, in its local frame."))
		((Vector3r, refPos, Vector3r::Zero(), , "Reference position."))
		((Quaternionr, refOri, Quaternionr::Identity(), , "Reference orientation."))
		((unsigned, blockedDOFs, 0, , "Blocked degrees of freedom."))
		((bool, isDamped, true, , "NewtonIntegrator's damping acts on this body."))
		((Real, densityScaling, -1, , "GlobalStiffnessTimeStepper's density scaling.")),
		/*inits*/ ((pos, se3.position))((ori, se3.orientation)),
		/*ctor*/)
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
