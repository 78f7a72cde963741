#include <pkg/rbsm/RbsmPairCheck.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <core/Scene.hpp>

#include <algorithm>
#include <iostream>

namespace yade {

YADE_PLUGIN((RbsmPairCheck));

void RbsmPairCheck::action()
{
	const auto& bodies = scene->bodies->body;
	for (const auto& I : *scene->interactions) {
		// InteractionLoop marks a pair for which its geometry dispatcher found no functor
		if (I->functorCache.geomExists || I->isReal()) continue;
		const int id1 = I->getId1(), id2 = I->getId2();
		if (id1 < 0 || id2 < 0 || size_t(std::max(id1, id2)) >= bodies.size()) continue;
		const Body *b1 = bodies[id1].get(), *b2 = bodies[id2].get();
		if (!b1 || !b2 || !b1->shape || !b2->shape || b1->isClump() || b2->isClump()) continue;
		const bool block1 = dynamic_cast<const Polygon2D*>(b1->shape.get()), block2 = dynamic_cast<const Polygon2D*>(b2->shape.get());
		if (!block1 && !block2) continue; // YADE's own pairs are YADE's business
		const std::string s1 = b1->shape->getClassName(), s2 = b2->shape->getClassName();
		const std::string pair = block1 ? s1 + " " + s2 : s2 + " " + s1;
		if (std::find(reported.begin(), reported.end(), pair) != reported.end()) continue;
		reported.push_back(pair);
		const std::string other = block1 ? s2 : s1;
		std::cerr << "yade-rbsm: ERROR: RbsmPairCheck: bodies #" + std::to_string(id1) + " (" + s1 + ") and #" + std::to_string(id2) + " (" + s2
		                     + ") meet, but no IGeomFunctor of the InteractionLoop handles Polygon2D and " + other + " (Ig2_Polygon2D_" + other
		                     + "_... is missing): they pass through each other"
		                     + (stopRun ? "; the run stops after step " + std::to_string(scene->iter) : std::string("; the run goes on (stopRun=False)"))
		                     + "\n";
		if (stopRun) rbsm_report::stopAfterThisStep(*scene);
	}
}

} // namespace yade
