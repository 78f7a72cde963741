#include <pkg/rbsm/OpenWaterPressure.hpp>
#include <core/Scene.hpp>
#include <pkg/rbsm/BlockStateCheck.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/kernel/Hydrostatic.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace yade {

YADE_PLUGIN((OpenWaterPressure));

void OpenWaterPressure::postLoad(OpenWaterPressure&) { rbsm::checkWaterTable("OpenWaterPressure", phreatic, waterUnitWeight); }

void OpenWaterPressure::action()
{
	if (phreatic.empty() || waterUnitWeight == 0) return;
	Real top = phreatic.front().y(); // above it nothing is wet: most dry blocks leave at their first vertex
	for (const Vector2r& p : phreatic)
		top = std::max(top, p.y());
	Real                  work = 0;
	std::vector<Vector2r> world;
	if (scene->trackEnergy) lastLoad.resize(scene->bodies->size(), Vector3r::Constant(std::numeric_limits<Real>::quiet_NaN()));
	for (const auto& b : scene->bodies->body) {
		if (!b || !b->state || b->subdomain != scene->subdomain || fixedBlock(*b->state)) continue; // (yade.mpy: this rank's)
		const auto* poly = dynamic_cast<const Polygon2D*>(b->shape.get());
		if (!poly) continue;
		const rbsm::Pose2 pose = planarPose(b->state->pos, b->state->ori);
		world.clear();
		Real lowest = std::numeric_limits<Real>::infinity();
		for (const Vector2r& v : poly->vertices) {
			world.push_back(pose.apply(v));
			lowest = std::min(lowest, world.back().y());
		}
		// (a block above the water takes none, but its last step's work from the load it left with still counts)
		const rbsm::WaterLoad load = lowest < top ? rbsm::hydrostaticLoad(world, phreatic, waterUnitWeight, b->state->pos.head<2>()) : rbsm::WaterLoad {};
		const Real            t    = poly->thickness;
		const Vector3r        now(load.force.x() * t, load.force.y() * t, load.moment * t);
		if (lowest < top) {
			scene->forces.addForce(b->id, Vector3r(now.x(), now.y(), 0));
			scene->forces.addTorque(b->id, Vector3r(0, 0, now.z()));
		}
		if (scene->trackEnergy) {
			// the last step's work: its move (velocity × dt) by the mean of the loads at its ends (second order:
			// the load at one end alone left 3 % of a floating block's heave energy after three cycles)
			Vector3r&      last = lastLoad[size_t(b->id)];
			const Vector3r mean = std::isnan(last.x()) ? now : Vector3r(0.5 * (last + now));
			work += (mean.x() * b->state->vel.x() + mean.y() * b->state->vel.y() + mean.z() * b->state->angVel.z()) * scene->dt;
			last = now;
		}
	}
	if (work != 0) scene->energy->add(-work, "waterWork", waterWorkIx, /*cumulative*/ false);
}

} // namespace yade
