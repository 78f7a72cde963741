// Material of a body (YADE's Material).
#pragma once
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>
#include <core/State.hpp>

namespace yade {
class Material : public Serializable, public Indexable {
public:
	~Material() override;
	virtual shared_ptr<State> newAssocState() const;
	virtual bool              stateTypeOk(State*) const;
	YADE_BUILTIN_CLASS(Material, Serializable,
		((int, id, -1, Attr::readonly, "Index in O.materials, -1 if not shared."))
		((std::string, label, , , "Textual identifier."))
		((Real, density, 1000, , "Density [kg/m³].")),
		/*ctor*/)
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
