// Elastic and frictional materials of YADE's spheres (ElastMat, FrictMat). Layout only.
#pragma once
#include <core/Material.hpp>

namespace yade {
class ElastMat : public Material {
public:
	Real young;   // [Pa]
	Real poisson; // [-]; for FrictPhys the ratio ks/kn of one particle
	ElastMat() = delete;
	~ElastMat() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};

class FrictMat : public ElastMat {
public:
	Real frictionAngle; // [rad]
	FrictMat() = delete;
	~FrictMat() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
