// Bo1_Polygon2D_Aabb: axis-aligned bounding box of a Polygon2D block for YADE's collider.
#pragma once
#include <core/Dispatching.hpp>
#include <pkg/rbsm/Polygon2D.hpp>

namespace yade {

class Bo1_Polygon2D_Aabb : public BoundFunctor {
public:
	void go(const shared_ptr<Shape>& shape, shared_ptr<Bound>& bound, const Se3r& se3, const Body* body) override;
	//! Checks the attributes when they are set (raises ValueError in Python, before any step).
	void postLoad(Bo1_Polygon2D_Aabb&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Bo1_Polygon2D_Aabb, BoundFunctor,
		"Axis-aligned box around the world vertices of a :yref:`Polygon2D` (z extent ± half the thickness), enlarged by "
		":yref:`enlarge<Bo1_Polygon2D_Aabb.enlarge>`; YADE's collider (InsertionSortCollider, with its verletDist) finds "
		"the candidate pairs.",
		((Real, enlarge, 0, Attr::triggerPostLoad, "Distance [m] by which the box is enlarged on every side, so that contacts are detected before the blocks touch (≥ 0).")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR1D(Polygon2D);
};
REGISTER_SERIALIZABLE(Bo1_Polygon2D_Aabb);

} // namespace yade
