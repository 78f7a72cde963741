// Kinematic state of a body (YADE's State): 320 bytes in Debian's build. The plugin reads and
// writes it but never constructs one, so only the layout is declared.
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

	Se3r        se3;
	Vector3r    vel;
	Real        mass;
	Vector3r    angVel;
	Vector3r    angMom;
	Vector3r    inertia;
	Vector3r    refPos;
	Quaternionr refOri;
	unsigned    blockedDOFs;
	bool        isDamped;
	Real        densityScaling;

	State() = delete;
	~State() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
