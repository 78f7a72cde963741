// The drawing functors of YADE's OpenGL view (pkg/common/GLDrawFunctors.hpp in YADE): the qt view's
// OpenGLRenderer finds every class deriving from one of them and calls it for each object it draws:
//   GlShapeFunctor (Shape) go(shape, state, wire, viewInfo)      in the body's frame (pos, ori applied)
//   GlIGeomFunctor (IGeom) go(geom, interaction, b1, b2, wire)    in the world frame
//   GlIPhysFunctor (IPhys) go(phys, interaction, b1, b2, wire)    in the world frame
// In Debian's build they are defined inline (weak symbols of libpkg_common.so, 88 bytes each): the
// plugin links to libpkg_common.so for their vtables and Python registration.
#pragma once
#include <core/Body.hpp>
#include <core/Functor.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <core/Interaction.hpp>
#include <core/Shape.hpp>
#include <core/State.hpp>

namespace yade {

// Scene centre and radius that the view passes to shape functors; only used by reference here.
struct GLViewInfo;

// A drawing functor names the class it draws twice: for the dispatcher (FUNCTOR1D) and renders().
#define RENDERS(name)                                                                                                                                  \
public:                                                                                                                                                \
	std::string renders() const override { return #name; };                                                                                        \
	FUNCTOR1D(name);

// The three families share one layout (Functor1D and two virtual functions: renders(), the class
// drawn, and initgl(), called when the view sets its functors up); Debian's build defines them inline.
class GlShapeFunctor : public Functor1D<Shape, void, TYPELIST_4(const shared_ptr<Shape>&, const shared_ptr<State>&, bool, const GLViewInfo&)> {
public:
	~GlShapeFunctor() override;
	virtual std::string renders() const;
	virtual void        initgl();
	YADE_BUILTIN_CLASS(GlShapeFunctor, Functor, , )
};

class GlIGeomFunctor
        : public Functor1D<IGeom, void, TYPELIST_5(const shared_ptr<IGeom>&, const shared_ptr<Interaction>&, const shared_ptr<Body>&, const shared_ptr<Body>&, bool)> {
public:
	~GlIGeomFunctor() override;
	virtual std::string renders() const;
	virtual void        initgl();
	YADE_BUILTIN_CLASS(GlIGeomFunctor, Functor, , )
};

class GlIPhysFunctor
        : public Functor1D<IPhys, void, TYPELIST_5(const shared_ptr<IPhys>&, const shared_ptr<Interaction>&, const shared_ptr<Body>&, const shared_ptr<Body>&, bool)> {
public:
	~GlIPhysFunctor() override;
	virtual std::string renders() const;
	virtual void        initgl();
	YADE_BUILTIN_CLASS(GlIPhysFunctor, Functor, , )
};

} // namespace yade
