// An interaction between two bodies (YADE's Interaction): geometry and physics parts, created by
// the functors of InteractionLoop. Layout only.
#pragma once
#include <core/Body.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>

namespace yade {
class IGeomFunctor;
class IPhysFunctor;
class LawFunctor;

class Interaction : public Serializable {
public:
	bool isReal() const { return (bool)geom && (bool)phys; }
	bool isActive;
	struct {
		bool                     geomExists;
		shared_ptr<IGeomFunctor> geom;
		shared_ptr<IPhysFunctor> phys;
		shared_ptr<LawFunctor>   constLaw;
	} functorCache;
	const Body::id_t& getId1() const { return id1; }
	const Body::id_t& getId2() const { return id2; }

	Body::id_t        id1;
	Body::id_t        id2;
	long              iterMadeReal;
	long              iterLastSeen;
	shared_ptr<IGeom> geom;
	shared_ptr<IPhys> phys;
	Vector3i          cellDist;
	int               linIx;
	long              iterBorn;

	Interaction() = delete;
	Interaction(Body::id_t newId1, Body::id_t newId2); // exported by libyade.so
	~Interaction() override;
	boost::python::dict pyDictCustom() const override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
};
} // namespace yade
