// Geometry of an interaction (YADE's IGeom).
#pragma once
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>

namespace yade {
class IGeom : public Serializable, public Indexable {
public:
	~IGeom() override;
	YADE_BUILTIN_CLASS(IGeom, Serializable, , )
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
