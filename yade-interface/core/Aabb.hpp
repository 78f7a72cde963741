#pragma once
#include <core/Bound.hpp>

namespace yade {
class Aabb : public Bound {
public:
	~Aabb() override;
	YADE_BUILTIN_CLASS(Aabb, Bound, , createIndex();)
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
