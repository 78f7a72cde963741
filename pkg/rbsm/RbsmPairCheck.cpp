#include <pkg/rbsm/RbsmPairCheck.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <core/Scene.hpp>

#include <algorithm>
#include <iostream>

namespace yade {

YADE_PLUGIN((RbsmPairCheck));

namespace {
	// yade_rbsm.dispatch.phys_functor_missing(id1, id2), with Python's lock (this engine runs outside the OpenMP
	// loops, like YADE's PyRunner); a Python error is printed and counts as no problem found.
	std::string physFunctorMissing(int id1, int id2)
	{
		namespace py              = boost::python;
		const PyGILState_STATE gil = PyGILState_Ensure();
		std::string            missing;
		try {
			missing = py::extract<std::string>(py::import("yade_rbsm.dispatch").attr("phys_functor_missing")(id1, id2));
		} catch (const py::error_already_set&) {
			PyErr_Print();
		}
		PyGILState_Release(gil);
		return missing;
	}
}

// Two NewtonIntegrators each move the bodies by the step (a block fell 3.6 times as far as in free fall), silently.
void RbsmPairCheck::checkEngineList()
{
	if (scene->engines.size() == enginesSeen) return; // (a changed list is a new size in practice: cheap every step)
	enginesSeen = scene->engines.size();
	const auto newtons = std::count_if(scene->engines.begin(), scene->engines.end(),
	                                   [](const shared_ptr<Engine>& e) { return e && e->getClassName() == "NewtonIntegrator"; });
	if (newtons < 2) return;
	std::cerr << "yade-rbsm: ERROR: RbsmPairCheck: O.engines has " << newtons
	          << " NewtonIntegrators: each moves the bodies by the step, so they move too far; keep one (last); the run stops after step "
	          << scene->iter << "\n";
	rbsm_report::stopAfterThisStep(*scene);
}

void RbsmPairCheck::action()
{
	checkEngineList();
	const auto& bodies = scene->bodies->body;
	// Only the pairs the collider made since the last call: InteractionLoop has dispatched them in the step
	// they were made (a check of every pair at every step cost 2 % of a brick wall's step).
	const long since = lastIter + 1;
	lastIter         = scene->iter;
	for (const auto& I : *scene->interactions) {
		if (I->iterBorn < since || I->isReal()) continue;
		// a geometry functor exists (InteractionLoop cached it): is there an IPhys functor for the materials?
		if (I->functorCache.geomExists) {
			if (I->functorCache.geom) checkPhys(*I);
			continue;
		}
		// InteractionLoop marks a pair for which its geometry dispatcher found no functor
		const int id1 = I->getId1(), id2 = I->getId2();
		if (id1 < 0 || id2 < 0 || size_t(std::max(id1, id2)) >= bodies.size()) continue;
		const Body *b1 = bodies[id1].get(), *b2 = bodies[id2].get();
		if (!b1 || !b2 || !b1->shape || !b2->shape || b1->isClump() || b2->isClump()) continue;
		const bool block1 = b1->shape->getClassIndex() == Polygon2D::getClassIndexStatic(), block2 = b2->shape->getClassIndex() == Polygon2D::getClassIndexStatic();
		if (!block1 && !block2) continue; // YADE's own pairs are YADE's business
		const std::string s1 = b1->shape->getClassName(), s2 = b2->shape->getClassName();
		if (s1 == "Subdomain" || s2 == "Subdomain") continue; // yade.mpy's own bodies: bounds of a rank's blocks, not shapes
		const std::string pair = block1 ? s1 + " " + s2 : s2 + " " + s1;
		if (std::find(reported.begin(), reported.end(), pair) != reported.end()) continue;
		reported.push_back(pair);
		const std::string other = block1 ? s2 : s1;
		std::cerr << "yade-rbsm: ERROR: RbsmPairCheck: bodies #" + std::to_string(id1) + " (" + s1 + ") and #" + std::to_string(id2) + " (" + s2
		                     + ") meet, but no IGeomFunctor of the InteractionLoop handles Polygon2D and " + other + " (Ig2_Polygon2D_" + other
		                     + "_... is missing): they pass through each other"
		                     + (other == "Sphere" || other == "Wall" || other == "Facet" ? std::string(" (yade_rbsm.mixed_engines() has the functors for them)") : std::string())
		                     + (stopRun ? "; the run stops after step " + std::to_string(scene->iter) : std::string("; the run goes on (stopRun=False)"))
		                     + "\n";
		if (stopRun) rbsm_report::stopAfterThisStep(*scene);
	}
}

} // namespace yade

namespace yade {

void RbsmPairCheck::checkPhys(const Interaction& I)
{
	// at every step for every potential contact: class indices, names only for a pair not seen before
	const auto& bodies = scene->bodies->body;
	const int   id1 = I.getId1(), id2 = I.getId2();
	if (id1 < 0 || id2 < 0 || size_t(std::max(id1, id2)) >= bodies.size()) return;
	const Body *b1 = bodies[id1].get(), *b2 = bodies[id2].get();
	if (!b1 || !b2 || !b1->shape || !b2->shape || !b1->material || !b2->material) return;
	const int block = Polygon2D::getClassIndexStatic();
	if (b1->shape->getClassIndex() != block && b2->shape->getClassIndex() != block) return;
	const std::pair<int, int> mats(b1->material->getClassIndex(), b2->material->getClassIndex());
	auto                      it = physChecked.find(mats);
	if (it == physChecked.end()) it = physChecked.emplace(mats, physFunctorMissing(id1, id2).empty()).first;
	if (it->second) return;
	const std::string key = b1->material->getClassName() + " " + b2->material->getClassName();
	if (it->second || std::find(reported.begin(), reported.end(), key) != reported.end()) return;
	reported.push_back(key);
	std::cerr << "yade-rbsm: ERROR: RbsmPairCheck: bodies #" + std::to_string(id1) + " (" + b1->shape->getClassName() + ", "
	                     + b1->material->getClassName() + ") and #" + std::to_string(id2) + " (" + b2->shape->getClassName() + ", "
	                     + b2->material->getClassName() + ") are about to touch, but no IPhysFunctor of the InteractionLoop handles "
	                     + b1->material->getClassName() + " and " + b2->material->getClassName() + " (Ip2_" + b1->material->getClassName() + "_"
	                     + b2->material->getClassName() + "_... is missing): YADE would end the process at their contact; the run stops after step "
	                     + std::to_string(scene->iter) + "\n";
	rbsm_report::stopAfterThisStep(*scene);
}

} // namespace yade
