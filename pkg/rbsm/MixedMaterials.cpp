#include <pkg/rbsm/MixedMaterials.hpp>
#include <pkg/common/ElastMat.hpp>
#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/StepReport.hpp>

namespace yade {
namespace rbsm_mixed {

	std::string materialProblem(const Scene& scene, int id, Role role)
	{
		const auto&     bodies = scene.bodies->body;
		const Material* m      = (id >= 0 && size_t(id) < bodies.size() && bodies[id]) ? bodies[id]->material.get() : nullptr;
		const bool      rbsm   = dynamic_cast<const RbsmMat*>(m) != nullptr;
		const bool      frict  = dynamic_cast<const FrictMat*>(m) != nullptr;
		const std::string has  = m ? "has a " + m->getClassName() : "has no material";
		switch (role) {
			case Role::Block: return rbsm ? "" : "(a Polygon2D block) " + has + "; blocks need an RbsmMat";
			case Role::Grain: return (rbsm || frict) ? "" : "(a sphere) " + has + "; spheres next to blocks need a FrictMat or an RbsmMat";
			case Role::Boundary: return (rbsm || frict) ? "" : "(a wall or facet) " + has + "; walls and facets under blocks need an RbsmMat or a FrictMat";
		}
		return "";
	}

	bool materialsAccepted(std::atomic<int>& reports, Scene& scene, const char* who, const Interaction& I, Role role1, Role role2)
	{
		std::string problem = materialProblem(scene, I.getId1(), role1);
		int         body    = I.getId1();
		if (problem.empty()) problem = materialProblem(scene, body = I.getId2(), role2);
		if (problem.empty()) return true;
		const std::string what = "meet, but body #" + std::to_string(body) + " " + problem + " (no contact is made)";
		rbsm_report::stopForPair(reports, scene, who, I.getId1(), I.getId2(), what.c_str());
		return false;
	}

} // namespace rbsm_mixed
} // namespace yade
