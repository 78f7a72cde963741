// Ig2_Polygon2D_Sphere_ScGeom: a YADE sphere against a Polygon2D block, as YADE's point contact ScGeom.
#pragma once
#include <core/Dispatching.hpp>
#include <pkg/rbsm/Polygon2D.hpp>

namespace yade {

class Ig2_Polygon2D_Sphere_ScGeom : public IGeomFunctor {
public:
	bool go(const shared_ptr<Shape>& polygon,
	        const shared_ptr<Shape>& sphere,
	        const State&             statePolygon,
	        const State&             stateSphere,
	        const Vector3r&          shift2,
	        const bool&              force,
	        const shared_ptr<Interaction>& I) override;
	bool goReverse(const shared_ptr<Shape>&, const shared_ptr<Shape>&, const State&, const State&, const Vector3r&, const bool&, const shared_ptr<Interaction>&) override
	{
		throw std::logic_error("Ig2_Polygon2D_Sphere_ScGeom::goReverse called: InteractionLoop puts the block first (DEFINE_FUNCTOR_ORDER_2D)");
	}
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ig2_Polygon2D_Sphere_ScGeom, IGeomFunctor,
		"Contact of a :yref:`Sphere` (a disk moving in the x-y plane; block its z, rx, ry motion with blockedDOFs) with a "
		":yref:`Polygon2D` block, as YADE's :yref:`ScGeom`, so that YADE's sphere laws apply. Body 1 is the block, body 2 the "
		"sphere. The sphere's centre is taken to the block's frame and the closest feature of the block's boundary found "
		"(pkg/rbsm/kernel/DiskContact.hpp): normal from the block to the sphere (an edge's normal, or the direction from a "
		"corner), penetrationDepth = radius − distance of the centre from the boundary, contactPoint in the middle of the "
		"overlap, refR1 = refR2 = the sphere's radius (as YADE's box-sphere contact); the shear increment and the rotation of "
		"the contact plane come from YADE's ScGeom::precompute with the true branch vectors (contact point minus each body's "
		"centre). Use :yref:`Law2_ScGeom_FrictPhys_CundallStrack` with sphericalBodies=False: its default computes the "
		"block's torque as if it were a sphere. A new contact is made when they touch (or overlap); an existing one is "
		"followed until the law removes it.",
		/*attrs*/,
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(Polygon2D, Sphere);
	DEFINE_FUNCTOR_ORDER_2D(Polygon2D, Sphere);
};
REGISTER_SERIALIZABLE(Ig2_Polygon2D_Sphere_ScGeom);

} // namespace yade
