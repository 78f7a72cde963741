// Per-thread force and torque accumulators of a scene (YADE's ForceContainer, OpenMP flavour):
// 304 bytes in Debian's build. All member functions are exported by libyade.so.
#pragma once
#include <lib/base/Math.hpp>
#include <mutex>

namespace yade {
class ForceContainer {
	using vvector = std::vector<Vector3r>;
	std::vector<vvector> _forceData;
	std::vector<vvector> _torqueData;
	std::vector<int>     _maxId;
	std::vector<size_t>  sizeOfThreads;
	vvector              _force, _torque, _permForce, _permTorque;
	size_t               size;
	bool                 syncedSizes;
	int                  nThreads;
	bool                 permForceUsed;
	bool                 permForceSynced;
	std::mutex           globalMutex;
	const Vector3r       _zero;

public:
	bool          synced;
	unsigned long syncCount;
	long          lastReset;

	ForceContainer() = delete;
	// Thread-safe: each OpenMP thread adds into its own array, summed by sync().
	void            addForce(int id, const Vector3r& f);
	void            addTorque(int id, const Vector3r& t);
	const Vector3r& getForce(int id);
	const Vector3r& getTorque(int id);
	void            sync();
};
} // namespace yade
