#include <pkg/rbsm/RbsmMat.hpp>

#include <cmath>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RbsmMat));

namespace {
	void require(bool ok, const RbsmMat& m, const char* attribute, const std::string& what)
	{
		if (!ok) {
			const std::string name = m.label.empty() ? "RbsmMat" : "RbsmMat '" + m.label + "'";
			throw std::invalid_argument(name + "." + attribute + ": " + what);
		}
	}
}

void RbsmMat::postLoad(RbsmMat& m)
{
	require(std::isfinite(m.density) && m.density > 0, m, "density", "must be a finite number > 0 (got " + std::to_string(m.density) + ")");
	require(std::isfinite(m.young) && m.young > 0, m, "young", "must be a finite number > 0 (got " + std::to_string(m.young) + ")");
	require(std::isfinite(m.poisson) && m.poisson > -1 && m.poisson < 0.5, m, "poisson", "must be in (-1, 0.5) (got " + std::to_string(m.poisson) + ")");
	require(std::isfinite(m.frictionAngle) && m.frictionAngle >= 0 && m.frictionAngle < Mathr_PI / 2,
	        m,
	        "frictionAngle",
	        "must be in [0, pi/2) radians (got " + std::to_string(m.frictionAngle) + ")");
	require(std::isfinite(m.cohesion) && m.cohesion >= 0, m, "cohesion", "must be a finite number >= 0 (got " + std::to_string(m.cohesion) + ")");
	require(std::isfinite(m.tensileStrength) && m.tensileStrength >= 0,
	        m,
	        "tensileStrength",
	        "must be a finite number >= 0 (got " + std::to_string(m.tensileStrength) + ")");
}

} // namespace yade
