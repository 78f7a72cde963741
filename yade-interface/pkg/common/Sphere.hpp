// A sphere (YADE's Sphere): 104 bytes in Debian's build. Layout only: the plugin reads the radius of
// the spheres it meets and never makes one.
#pragma once
#include <core/Shape.hpp>

namespace yade {
class Sphere : public Shape {
public:
	Real radius; // [m]
	Sphere() = delete;
	~Sphere() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
