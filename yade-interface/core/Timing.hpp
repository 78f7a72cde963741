// Execution-time accounting of engines and functors (O.timingEnabled).
#pragma once
#include <string>
#include <vector>

namespace yade {
struct TimingInfo {
	using delta = unsigned long long;
	long  nExec = 0;
	delta nsec  = 0;
	static bool enabled; // defined in libyade.so
};

class TimingDeltas {
	TimingInfo::delta last;
	size_t            i;

public:
	std::vector<TimingInfo>  data;
	std::vector<std::string> labels;
};
} // namespace yade
