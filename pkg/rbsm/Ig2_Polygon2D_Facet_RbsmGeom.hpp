// Ig2_Polygon2D_Facet_RbsmGeom: a Polygon2D block on a YADE Facet, as the edge-to-edge RBSM joint.
#pragma once
#include <core/Dispatching.hpp>
#include <pkg/rbsm/Polygon2D.hpp>

namespace yade {

class Ig2_Polygon2D_Facet_RbsmGeom : public IGeomFunctor {
public:
	bool go(const shared_ptr<Shape>& block,
	        const shared_ptr<Shape>& boundary,
	        const State&             stateBlock,
	        const State&             stateBoundary,
	        const Vector3r&          shift2,
	        const bool&              force,
	        const shared_ptr<Interaction>& I) override;
	bool goReverse(const shared_ptr<Shape>&, const shared_ptr<Shape>&, const State&, const State&, const Vector3r&, const bool&, const shared_ptr<Interaction>&) override
	{
		throw std::logic_error("Ig2_Polygon2D_Facet_RbsmGeom::goReverse called: InteractionLoop puts the block first (DEFINE_FUNCTOR_ORDER_2D)");
	}
	//! Checks the attributes when they are set (raises ValueError in Python, before any step).
	void postLoad(Ig2_Polygon2D_Facet_RbsmGeom&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ig2_Polygon2D_Facet_RbsmGeom, IGeomFunctor,
		"A :yref:`Polygon2D` block on a YADE :yref:`Facet` crossing the block's plane (z of the block's position): its trace, the segment where the triangle (in the world frame) cuts the plane, is the top edge of a rectangle on its far side from the block's centroid, as deep as the block's diameter (pkg/rbsm/kernel/BoundaryEdge.hpp): a block beyond an end of the trace meets it as a thin plate. A facet that does not cross the plane makes no contact. "
		"The joint is the same edge-to-edge contact as between two blocks (:yref:`RbsmGeom`, for :yref:`Law2_RbsmGeom_RbsmPhys_MohrCoulomb`), body 1 the block, body 2 the boundary, which is rigid: the joint's h2 = 0, so its springs are the block's half only (kn = E′/h1). Materials: an :yref:`RbsmMat` boundary joins by :yref:`Ip2_RbsmMat_RbsmMat_RbsmPhys`, a :yref:`FrictMat` one by :yref:`Ip2_RbsmMat_FrictMat_FrictPhys` (frictional, the smaller friction angle). A block on it behaves like a block on a fixed Polygon2D (the same incline closed forms). ",
		((int, nIP, 2, Attr::triggerPostLoad, "Integration points per contact (1-8), as :yref:`Ig2_Polygon2D_Polygon2D_RbsmGeom.nIP`."))
		((Real, interactionDistance, 0, Attr::triggerPostLoad, "Largest gap [m] at which a new contact is made (0: touching or overlapping).")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(Polygon2D, Facet);
	DEFINE_FUNCTOR_ORDER_2D(Polygon2D, Facet);
};
REGISTER_SERIALIZABLE(Ig2_Polygon2D_Facet_RbsmGeom);

} // namespace yade
