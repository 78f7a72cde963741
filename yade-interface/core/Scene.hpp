// The whole simulation (YADE's Scene, O in Python): 752 bytes in Debian's build (YADE_MPI and
// YADE_OPENGL add members). Layout only; the plugin reads time step, iteration, bodies,
// interactions, energies and adds forces.
#pragma once
#include <core/Body.hpp>
#include <core/BodyContainer.hpp>
#include <core/EnergyTracker.hpp>
#include <core/Engine.hpp>
#include <core/ForceContainer.hpp>
#include <core/InteractionContainer.hpp>
#include <core/Material.hpp>
#include <boost/date_time/posix_time/ptime.hpp>

namespace yade {
class Cell;
class DisplayParameters;
class OpenGLRenderer;

class Scene : public Serializable {
	const unsigned int hostNameMax = 255;

public:
	ForceContainer                     forces;
	Eigen::Matrix<Real, 10, 1>         SpeedElements;
	shared_ptr<OpenGLRenderer>         renderer; // YADE_OPENGL
	boost::posix_time::ptime           prevTime;
	Real                               dt;
	long                               iter;
	bool                               subStepping;
	int                                subStep;
	Real                               time;
	Real                               speed;
	long                               stopAtIter;
	Real                               stopAtTime;
	bool                               isPeriodic;
	bool                               trackEnergy;
	bool                               doSort;
	bool                               runInternalConsistencyChecks;
	Body::id_t                         selectedBody;
	int                                subdomain; // YADE_MPI
	shared_ptr<Shape>                  subD;      // YADE_MPI
	std::vector<std::string>           tags;
	std::vector<shared_ptr<Engine>>    engines;
	std::vector<shared_ptr<Engine>>    _nextEngines;
	shared_ptr<BodyContainer>          bodies;
	shared_ptr<InteractionContainer>   interactions;
	shared_ptr<EnergyTracker>          energy;
	std::vector<shared_ptr<Material>>  materials;
	shared_ptr<Bound>                  bound;
	shared_ptr<Cell>                   cell;
	std::vector<shared_ptr<Serializable>>      miscParams;
	std::vector<shared_ptr<DisplayParameters>> dispParams;

	Scene() = delete;
	~Scene() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
};
} // namespace yade
