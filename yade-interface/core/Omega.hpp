// The simulation controller of libyade.so; the plugin only asks it for the current scene.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/base/Singleton.hpp>

namespace yade {
class Scene;
class Omega : public Singleton<Omega> {
public:
	const shared_ptr<Scene>& getScene() const; // exported by libyade.so
};
} // namespace yade

template <> yade::Omega* Singleton<yade::Omega>::self;
