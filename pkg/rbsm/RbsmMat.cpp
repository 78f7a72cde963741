#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RbsmMat));

namespace {
	// what is the problem with value of attribute, if not ok: "RbsmMat 'label'.attribute: what (got value)"
	void require(bool ok, const RbsmMat& m, const char* attribute, Real value, const char* what)
	{
		if (ok) return;
		std::ostringstream msg; // (%g-like: 1e-8 must not print as 0.000000)
		msg << (m.label.empty() ? "RbsmMat" : "RbsmMat '" + m.label + "'") << "." << attribute << ": " << what << " (got " << value << ")";
		throw std::invalid_argument(msg.str());
	}
}

void RbsmMat::postLoad(RbsmMat& m)
{
	require(std::isfinite(m.density) && m.density > 0, m, "density", m.density, "must be a finite number > 0");
	require(std::isfinite(m.young) && m.young > 0, m, "young", m.young, "must be a finite number > 0");
	require(std::isfinite(m.poisson) && m.poisson > -1 && m.poisson < 0.5, m, "poisson", m.poisson, "must be in (-1, 0.5)");
	require(!m.planeStrain || 1 - 2 * m.poisson >= rbsm::kMinOneMinusTwoNu,
	        m,
	        "poisson",
	        m.poisson,
	        "is too close to 0.5 for plane strain: 1 - 2 poisson < 1e-8 makes the joints' modulus E(1-nu)/((1+nu)(1-2nu)) over 1e8 x young, "
	        "a nearly incompressible solid with no stable explicit step (use poisson <= 0.5 - 5e-9)");
	require(std::isfinite(m.frictionAngle) && m.frictionAngle >= 0 && m.frictionAngle < Mathr_PI / 2,
	        m,
	        "frictionAngle",
	        m.frictionAngle,
	        "must be in [0, pi/2) radians");
	require(std::isfinite(m.cohesion) && m.cohesion >= 0, m, "cohesion", m.cohesion, "must be a finite number >= 0");
	require(std::isfinite(m.tensileStrength) && m.tensileStrength >= 0, m, "tensileStrength", m.tensileStrength, "must be a finite number >= 0");
	require(std::isfinite(m.jointKn) && m.jointKn >= 0, m, "jointKn", m.jointKn, "must be a finite number >= 0 (0: Kawai's stiffness)");
	require(std::isfinite(m.jointKs) && m.jointKs >= 0, m, "jointKs", m.jointKs, "must be a finite number >= 0 (0: Kawai's stiffness)");
	require(std::isfinite(m.dilatancy) && m.dilatancy >= 0 && m.dilatancy < Mathr_PI / 2, m, "dilatancy", m.dilatancy, "must be in [0, pi/2) radians");
	require(std::isfinite(m.weldBreakStrain) && m.weldBreakStrain >= 0, m, "weldBreakStrain", m.weldBreakStrain, "must be a finite plastic strain >= 0 (0: welded joints stay welded)");
	require(std::isfinite(m.penalty) && m.penalty >= 1, m, "penalty", m.penalty, "must be a finite number >= 1 (a multiple of Kawai's joint stiffness)");
}

shared_ptr<State> RbsmMat::newAssocState() const { return deformable ? shared_ptr<State>(new DeformableState) : Material::newAssocState(); }

bool RbsmMat::stateTypeOk(State* s) const { return !deformable || dynamic_cast<DeformableState*>(s) != nullptr; }

} // namespace yade
