// An axis-aligned infinite plane (YADE's Wall) through its body's position. Layout only.
#pragma once
#include <core/Shape.hpp>

namespace yade {
class Wall : public Shape {
public:
	int sense; // which side interacts: -1 negative only, 0 both, +1 positive only
	int axis;  // 0, 1, 2: the normal is +x, +y, +z (the body's orientation is disregarded)
	Wall() = delete;
	~Wall() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
