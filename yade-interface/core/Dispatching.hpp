// The four functor families of YADE's simulation loop, with their dispatch and argument types:
//   BoundFunctor  (Shape)          -> Body::bound       called by the collider's BoundDispatcher
//   IGeomFunctor  (Shape, Shape)   -> Interaction::geom called by InteractionLoop
//   IPhysFunctor  (Material, Mat.) -> Interaction::phys called by InteractionLoop
//   LawFunctor    (IGeom, IPhys)   -> forces on bodies  called by InteractionLoop
#pragma once
#include <core/Aabb.hpp>
#include <core/Functor.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <core/Shape.hpp>
#include <core/State.hpp>

namespace yade {

class BoundFunctor : public Functor1D<Shape, void, TYPELIST_4(const shared_ptr<Shape>&, shared_ptr<Bound>&, const Se3r&, const Body*)> {
public:
	~BoundFunctor() override;
	YADE_BUILTIN_CLASS(BoundFunctor, Functor, , )
};

class IGeomFunctor : public Functor2D<
                             Shape,
                             Shape,
                             bool,
                             TYPELIST_7(
                                     const shared_ptr<Shape>&,
                                     const shared_ptr<Shape>&,
                                     const State&,
                                     const State&,
                                     const Vector3r&,
                                     const bool&,
                                     const shared_ptr<Interaction>&)> {
public:
	~IGeomFunctor() override;
	virtual void preStep();
	YADE_BUILTIN_CLASS(IGeomFunctor, Functor, , )
};

class IPhysFunctor
        : public Functor2D<Material, Material, void, TYPELIST_3(const shared_ptr<Material>&, const shared_ptr<Material>&, const shared_ptr<Interaction>&)> {
public:
	~IPhysFunctor() override;
	YADE_BUILTIN_CLASS(IPhysFunctor, Functor, , )
};

class LawFunctor : public Functor2D<IGeom, IPhys, bool, TYPELIST_3(shared_ptr<IGeom>&, shared_ptr<IPhys>&, Interaction*)> {
public:
	~LawFunctor() override;
	YADE_BUILTIN_CLASS(LawFunctor, Functor, , )
};

} // namespace yade
