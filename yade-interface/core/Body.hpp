// A particle (YADE's Body): 176 bytes in Debian's build. Layout only; Python creates bodies.
#pragma once
#include <core/Bound.hpp>
#include <core/Material.hpp>
#include <core/Shape.hpp>
#include <core/State.hpp>
#include <map>

namespace yade {
class Scene;
class Interaction;

class Body : public Serializable {
public:
	using id_t        = int;
	using MapId2IntrT = std::map<id_t, shared_ptr<Interaction>>;
	enum { FLAG_BOUNDED = 1, FLAG_ASPHERICAL = 2, FLAG_SUBDOMAIN = 4, FLAG_FLUIDDOMAINBBOX = 8 };
	static const id_t ID_NONE = -1;

	virtual void userForcedDisplacementRedrawHook();
	bool         isDynamic() const { return state->blockedDOFs != State::DOF_ALL; }
	bool         isBounded() const { return flags & FLAG_BOUNDED; }
	bool         isClump() const { return clumpId != ID_NONE && id == clumpId; }

	id_t                 id;
	mask_t               groupMask;
	int                  flags;
	int                  subdomain; // YADE_MPI
	shared_ptr<Material> material;
	shared_ptr<State>    state;
	shared_ptr<Shape>    shape;
	shared_ptr<Bound>    bound;
	MapId2IntrT          intrs;
	id_t                 clumpId;
	long                 iterBorn;
	Real                 timeBorn;

	Body() = delete;
	~Body() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
};
} // namespace yade
