// Prints "Class sizeof" for every class declared in yade-interface/ that has a data layout, as
// compiled with the project's declarations and compile definitions; test_sizes.py compares each
// with the size read from Debian's binary at test time.
#include <core/Aabb.hpp>
#include <core/Body.hpp>
#include <core/BodyContainer.hpp>
#include <core/Bound.hpp>
#include <core/Dispatching.hpp>
#include <core/EnergyTracker.hpp>
#include <core/Engine.hpp>
#include <core/ForceContainer.hpp>
#include <core/Functor.hpp>
#include <core/GlobalEngine.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <core/Interaction.hpp>
#include <core/InteractionContainer.hpp>
#include <core/Material.hpp>
#include <core/Scene.hpp>
#include <core/Shape.hpp>
#include <core/State.hpp>
#include <lib/factory/Factorable.hpp>
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>
#include <pkg/common/GLDrawFunctors.hpp>
#include <pkg/common/ElastMat.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/NormShearPhys.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/DemXDofGeom.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

#include <cstdio>

#define SIZE(c) std::printf("%s %zu\n", #c, sizeof(yade::c));

int main()
{
	SIZE(Factorable)
	SIZE(Serializable)
	SIZE(Indexable)
	SIZE(Shape)
	SIZE(Bound)
	SIZE(Aabb)
	SIZE(IGeom)
	SIZE(IPhys)
	SIZE(Material)
	SIZE(State)
	SIZE(Body)
	SIZE(Interaction)
	SIZE(Scene)
	SIZE(BodyContainer)
	SIZE(InteractionContainer)
	SIZE(EnergyTracker)
	SIZE(ForceContainer)
	SIZE(Engine)
	SIZE(GlobalEngine)
	SIZE(Functor)
	SIZE(BoundFunctor)
	SIZE(IGeomFunctor)
	SIZE(IPhysFunctor)
	SIZE(LawFunctor)
	SIZE(TimingDeltas)
	SIZE(GlShapeFunctor)
	SIZE(GlIGeomFunctor)
	SIZE(GlIPhysFunctor)
	// YADE's DEM classes that mixed scenes (Polygon2D with spheres, walls, facets) meet
	SIZE(Sphere)
	SIZE(Wall)
	SIZE(Facet)
	SIZE(ElastMat)
	SIZE(FrictMat)
	SIZE(NormPhys)
	SIZE(NormShearPhys)
	SIZE(FrictPhys)
	SIZE(GenericSpheresContact)
	SIZE(ScGeom)
	return 0;
}
