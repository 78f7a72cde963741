// Cundall–Strack interaction physics (YADE's FrictPhys): the one Law2_ScGeom_FrictPhys_CundallStrack
// reads. Layout only; the plugin makes one through the class factory (Debian's constructor).
#pragma once
#include <pkg/common/NormShearPhys.hpp>

namespace yade {
class FrictPhys : public NormShearPhys {
public:
	Real tangensOfFrictionAngle;
	FrictPhys() = delete;
	~FrictPhys() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
