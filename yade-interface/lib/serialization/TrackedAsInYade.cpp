// Part of the plugin library: makes its serializers of YADE's base classes track objects as
// libyade.so's do (see TrackedAsInYade.hpp). One object per YADE class the plugin derives from.
#include <lib/serialization/TrackedAsInYade.hpp>
#include <core/Dispatching.hpp>
#include <core/GlobalEngine.hpp>

namespace yade {
namespace {
	const detail::TrackedAsInYade<Serializable> trackSerializable;
	const detail::TrackedAsInYade<Shape>        trackShape;
	const detail::TrackedAsInYade<IGeom>        trackIGeom;
	const detail::TrackedAsInYade<IPhys>        trackIPhys;
	const detail::TrackedAsInYade<Material>     trackMaterial;
	const detail::TrackedAsInYade<Functor>      trackFunctor;
	const detail::TrackedAsInYade<BoundFunctor> trackBoundFunctor;
	const detail::TrackedAsInYade<IGeomFunctor> trackIGeomFunctor;
	const detail::TrackedAsInYade<IPhysFunctor> trackIPhysFunctor;
	const detail::TrackedAsInYade<LawFunctor>   trackLawFunctor;
	const detail::TrackedAsInYade<Engine>       trackEngine;
	const detail::TrackedAsInYade<GlobalEngine> trackGlobalEngine;
}
} // namespace yade
