#include <pkg/rbsm/Ig2_Polygon2D_Wall_RbsmGeom.hpp>
#include <pkg/rbsm/BoundaryJoint.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <pkg/rbsm/kernel/BoundaryEdge.hpp>
#include <pkg/common/Wall.hpp>

#include <cmath>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((Ig2_Polygon2D_Wall_RbsmGeom));

void Ig2_Polygon2D_Wall_RbsmGeom::postLoad(Ig2_Polygon2D_Wall_RbsmGeom&)
{
	rbsm_report::checkContactAttributes("Ig2_Polygon2D_Wall_RbsmGeom", nIP, interactionDistance);
}

namespace {
	std::atomic<int> periodicReports { 0 }, axisReports { 0 };
}

bool Ig2_Polygon2D_Wall_RbsmGeom::go(
        const shared_ptr<Shape>& s1,
        const shared_ptr<Shape>& s2,
        const State&             stateBlock,
        const State&             stateBoundary,
        const Vector3r&          shift2,
        const bool&              /*force*/,
        const shared_ptr<Interaction>& I)
{
	if (rbsm_report::acrossPeriodicCell(periodicReports, *scene, "Ig2_Polygon2D_Wall_RbsmGeom", *I, shift2)) return false;
	const Polygon2D& block = static_cast<const Polygon2D&>(*s1);
	if (block.vertices.empty() || !(block.circumradius > 0)) return false; // reported by Bo1_Polygon2D_Aabb
	const Wall& w = static_cast<const Wall&>(*s2);
	if (w.axis != 0 && w.axis != 1) {
		rbsm_report::stopForPair(axisReports, *scene, "Ig2_Polygon2D_Wall_RbsmGeom", I->getId1(), I->getId2(),
		                         ("meet, but the wall's axis is " + std::to_string(w.axis) + ": a Wall with axis 2 lies in the plane of the blocks (use axis 0 or 1)").c_str());
		return false;
	}
	// the wall's normal towards the block: the side of the block's centroid, or the wall's sense
	const rbsm::Vec2 e    = w.axis == 0 ? rbsm::Vec2(1, 0) : rbsm::Vec2(0, 1);
	const Real       side = w.sense != 0 ? Real(w.sense) : (e.dot(stateBlock.pos.head<2>() - stateBoundary.pos.head<2>()) >= 0 ? 1 : -1);
	const auto       boundary = rbsm::wallRectangle(stateBoundary.pos.head<2>(), side * e, stateBlock.pos.head<2>(), block.circumradius);
	return rbsm_boundary::blockOnBoundary("Ig2_Polygon2D_Wall_RbsmGeom", nIP, interactionDistance, block, stateBlock, boundary, stateBoundary, I, *scene);
}

} // namespace yade
