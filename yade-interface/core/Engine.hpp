// An engine of the simulation loop (YADE's Engine, GlobalEngine): 104 bytes in Debian's build.
#pragma once
#include <lib/serialization/Serializable.hpp>
#include <core/Omega.hpp>
#include <core/Timing.hpp>

namespace yade {
class Scene;

class Engine : public Serializable {
public:
	Scene*                   scene;
	TimingInfo               timingInfo;
	shared_ptr<TimingDeltas> timingDeltas;
	~Engine() override;
	virtual bool isActivated();
	virtual void action();
	YADE_BUILTIN_CLASS(Engine, Serializable,
		((bool, dead, false, , "If true, this engine will not run at all."))
		((int, ompThreads, -1, , "Number of threads of the engine's parallel regions."))
		((std::string, label, , , "Textual label for this object.")),
		/*ctor*/ scene = Omega::instance().getScene().get();)
};

class GlobalEngine : public Engine {
public:
	~GlobalEngine() override;
	YADE_BUILTIN_CLASS(GlobalEngine, Engine, , )
};
} // namespace yade
