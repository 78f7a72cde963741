// Interaction physics with normal and shear stiffness (YADE's NormPhys, NormShearPhys). Layout only.
#pragma once
#include <core/IPhys.hpp>

namespace yade {
class NormPhys : public IPhys {
public:
	Real     kn;          // [N/m]
	Vector3r normalForce; // on body 2 from body 1 [N]
	NormPhys() = delete;
	~NormPhys() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};

class NormShearPhys : public NormPhys {
public:
	Real     ks;         // [N/m]
	Vector3r shearForce; // on body 2 from body 1 [N]
	NormShearPhys() = delete;
	~NormShearPhys() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
