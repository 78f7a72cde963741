// Geometry of a body (YADE's Shape): 96 bytes in Debian's build (YADE_FEM adds a functor cache).
#pragma once
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>

namespace yade {
class BoundFunctor;
class InternalForceFunctor;

class Shape : public Serializable, public Indexable {
public:
	~Shape() override;
	shared_ptr<BoundFunctor>         boundFunctor;         // cache of the bound functor (BV_FUNCTOR_CACHE)
	shared_ptr<InternalForceFunctor> internalforcefunctor; // YADE_FEM
	YADE_BUILTIN_CLASS(Shape, Serializable,
		((Vector3r, color, Vector3r(1, 1, 1), , "Color for rendering (normalized RGB)."))
		((bool, wire, false, , "Render as wireframe."))
		((bool, highlight, false, , "Highlight when rendered.")),
		/*ctor*/)
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
