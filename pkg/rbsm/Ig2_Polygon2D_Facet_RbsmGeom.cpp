#include <pkg/rbsm/Ig2_Polygon2D_Facet_RbsmGeom.hpp>
#include <pkg/rbsm/BoundaryJoint.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <pkg/rbsm/kernel/BoundaryEdge.hpp>
#include <pkg/common/Facet.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((Ig2_Polygon2D_Facet_RbsmGeom));

void Ig2_Polygon2D_Facet_RbsmGeom::postLoad(Ig2_Polygon2D_Facet_RbsmGeom&)
{
	rbsm_report::checkContactAttributes("Ig2_Polygon2D_Facet_RbsmGeom", nIP, interactionDistance);
}

namespace {
	std::atomic<int> periodicReports { 0 }, planeReports { 0 };
}

bool Ig2_Polygon2D_Facet_RbsmGeom::go(
        const shared_ptr<Shape>& s1,
        const shared_ptr<Shape>& s2,
        const State&             stateBlock,
        const State&             stateBoundary,
        const Vector3r&          shift2,
        const bool&              /*force*/,
        const shared_ptr<Interaction>& I)
{
	if (rbsm_report::acrossPeriodicCell(periodicReports, *scene, "Ig2_Polygon2D_Facet_RbsmGeom", *I, shift2)) return false;
	const Polygon2D& block = static_cast<const Polygon2D&>(*s1);
	if (block.vertices.empty() || !(block.circumradius > 0)) return false; // reported by Bo1_Polygon2D_Aabb
	const Facet& f = static_cast<const Facet&>(*s2);
	if (f.vertices.size() != 3) return false;
	Eigen::Vector3d world[3];
	for (int i = 0; i < 3; i++)
		world[i] = stateBoundary.pos + stateBoundary.ori * f.vertices[i];
	// a facet parallel to the blocks' plane (in it, or off it by any amount, round-off included) has no trace
	// there and would let the block through without a word
	const Real z0     = stateBlock.pos.z();
	const Real zSpan  = std::max({ world[0].z(), world[1].z(), world[2].z() }) - std::min({ world[0].z(), world[1].z(), world[2].z() });
	const Real extent = std::max({ (world[1] - world[0]).norm(), (world[2] - world[1]).norm(), (world[0] - world[2]).norm() });
	if (zSpan <= 1e-9 * extent) {
		const bool         inPlane = std::abs(world[0].z() - z0) <= 1e-9 * extent;
		std::ostringstream msg;
		msg << "meet, but the Facet lies " << (inPlane ? "in the plane of the blocks" : "parallel to the plane of the blocks")
		    << (inPlane ? "" : " (at z = " + std::to_string(world[0].z()) + ", the blocks at z = " + std::to_string(z0) + ")")
		    << " and cannot hold them (stand it across the plane, its normal in the x-y plane: its trace on the plane is the "
		       "boundary the blocks meet; or use a Wall with axis 0 or 1)";
		rbsm_report::stopForPair(planeReports, *scene, "Ig2_Polygon2D_Facet_RbsmGeom", I->getId1(), I->getId2(), msg.str().c_str());
		return false;
	}
	rbsm::Vec2 a, b;
	if (!rbsm::planeTrace(world, z0, a, b)) return false; // the facet does not cross the block's plane
	// the trace's normal towards the block's centroid
	const rbsm::Vec2 t = (b - a).normalized();
	rbsm::Vec2       m(-t.y(), t.x());
	if (m.dot(stateBlock.pos.head<2>() - a) < 0) m = -m;
	const auto boundary = rbsm::boundaryRectangle(a, b, m, 2 * block.circumradius);
	return rbsm_boundary::blockOnBoundary("Ig2_Polygon2D_Facet_RbsmGeom", nIP, interactionDistance, block, stateBlock, boundary, stateBoundary, I, *scene);
}

} // namespace yade
