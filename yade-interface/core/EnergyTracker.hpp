// Named energy accumulators of a scene (O.energy), used when O.trackEnergy is True.
#pragma once
#include <lib/base/openmp-accu.hpp>
#include <lib/serialization/Serializable.hpp>
#include <map>

namespace yade {
class EnergyTracker : public Serializable {
public:
	OpenMPArrayAccumulator<Real> energies;
	std::map<std::string, int>   names;
	std::vector<bool>            resetStep;

	// The id of an energy name, created on first use; `reset` makes it a per-step value (power),
	// as opposed to a cumulative one (e.g. dissipated energy). Cache the id in the caller.
	void findId(const std::string& name, int& id, bool reset = false)
	{
		if (id >= 0) return;
		auto it = names.find(name);
		if (it != names.end()) {
			id = it->second;
			return;
		}
#pragma omp critical
		{
			auto again = names.find(name); // another thread may have created it meanwhile
			if (again != names.end()) id = again->second;
			else {
				energies.resize(energies.size() + 1);
				id = int(energies.size()) - 1;
				resetStep.resize(id + 1);
				resetStep[id] = reset;
				names[name]   = id;
			}
		}
	}
	void add(const Real& val, const std::string& name, int& id, bool reset = false)
	{
		if (id < 0) findId(name, id, reset);
		energies.add(id, val);
	}

	EnergyTracker() = delete;
	~EnergyTracker() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
};
} // namespace yade
