// Physical properties of an interaction (YADE's IPhys).
#pragma once
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>

namespace yade {
class IPhys : public Serializable, public Indexable {
public:
	~IPhys() override;
	YADE_BUILTIN_CLASS(IPhys, Serializable, , )
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
