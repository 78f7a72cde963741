#include <pkg/rbsm/Ig2_Polygon2D_Sphere_ScGeom.hpp>
#include <pkg/rbsm/MixedMaterials.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/DiskContact.hpp>
#include <lib/factory/ClassFactory.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

#include <sstream>

namespace yade {

YADE_PLUGIN((Ig2_Polygon2D_Sphere_ScGeom));

namespace {
	std::atomic<int> periodicReports { 0 }, materialReports { 0 }, planeReports { 0 }, insideReports { 0 };
}

bool Ig2_Polygon2D_Sphere_ScGeom::go(
        const shared_ptr<Shape>& s1,
        const shared_ptr<Shape>& s2,
        const State&             state1,
        const State&             state2,
        const Vector3r&          shift2,
        const bool&              force,
        const shared_ptr<Interaction>& I)
{
	if (rbsm_report::acrossPeriodicCell(periodicReports, *scene, "Ig2_Polygon2D_Sphere_ScGeom", *I, shift2)) return false;
	const Polygon2D& block = static_cast<const Polygon2D&>(*s1);
	const Real       r     = static_cast<const Sphere&>(*s2).radius;
	if (block.vertices.empty() || block.edgeNormals.size() != block.vertices.size()) return false; // reported by Bo1_Polygon2D_Aabb

	// The sphere's centre in the block's frame, x ↦ R(−θ)(x − x1); the contact back to the world frame.
	const rbsm::Pose2       pose1 = planarPose(state1.pos, state1.ori);
	const Vector2r          local = pose1.applyInverse(state2.pos.head<2>());
	const rbsm::DiskContact c = rbsm::diskPolygonContact(rbsm::PolygonView { block.vertices.data(), block.edgeNormals.data(), int(block.vertices.size()) }, local, r);

	const bool isNew = !I->geom;
	if (isNew && c.overlap < 0 && !force) return false;
	// the blocks move in their plane: a sphere free in z or tilting about x, y drifts out of it, silently
	// (every step: blockedDOFs cleared or a velocity out of the plane set later is as silent; two compares)
	constexpr unsigned planar = State::DOF_Z | State::DOF_RX | State::DOF_RY;
	if ((state2.blockedDOFs & planar) != planar) {
		rbsm_report::stopForPair(planeReports, *scene, "Ig2_Polygon2D_Sphere_ScGeom", I->getId1(), I->getId2(),
		                         "meet, but the sphere is free to leave the plane of the blocks (a sphere next to Polygon2D blocks "
		                         "moves in their plane: set its state.blockedDOFs = 'zXY')");
		return false;
	}
	if (state2.vel.z() != 0 || state2.angVel.x() != 0 || state2.angVel.y() != 0) { // blocked DOFs keep a velocity given
		std::ostringstream msg;
		msg << "meet, but the sphere moves out of the plane of the blocks (vel.z " << state2.vel.z() << " m/s, angVel.x, y " << state2.angVel.x()
		    << ", " << state2.angVel.y() << " rad/s: NewtonIntegrator keeps a velocity given along a blocked DOF): set them to 0";
		rbsm_report::stopForPair(planeReports, *scene, "Ig2_Polygon2D_Sphere_ScGeom", I->getId1(), I->getId2(), msg.str().c_str());
		return false;
	}
	// a centre already inside the block: the spring, compressed by more than the radius, would shoot the
	// sphere out through whatever lies behind (a floor: 791 m/s, y = -562 m), silently
	if (isNew && c.distance < 0) {
		std::ostringstream msg;
		msg << "meet with the sphere's centre inside the block (" << -c.distance << " m from its nearest edge, radius " << r
		    << " m): place the sphere outside the block";
		rbsm_report::stopForPair(insideReports, *scene, "Ig2_Polygon2D_Sphere_ScGeom", I->getId1(), I->getId2(), msg.str().c_str());
		return false;
	}
	// placed deeper than half its radius (centre outside): the spring, compressed that far, shoots it out (a sphere
	// placed 70 % deep gained 140 times its energy); an impact is never that deep in the step it is first seen
	if (isNew && c.overlap > 0.5 * r) {
		std::ostringstream msg;
		msg << "meet overlapping by " << c.overlap << " m, " << 100 * c.overlap / r << " % of its radius " << r
		    << " m: its spring would shoot the sphere out; place it outside the block";
		rbsm_report::stopForPair(insideReports, *scene, "Ig2_Polygon2D_Sphere_ScGeom", I->getId1(), I->getId2(), msg.str().c_str());
		return false;
	}
	if (isNew && !rbsm_mixed::materialsAccepted(materialReports, *scene, "Ig2_Polygon2D_Sphere_ScGeom", *I, rbsm_mixed::Role::Block, rbsm_mixed::Role::Grain))
		return false;
	if (isNew) I->geom = boost::static_pointer_cast<ScGeom>(ClassFactory::instance().createShared("ScGeom")); // Debian's constructor
	ScGeom&        g = static_cast<ScGeom&>(*I->geom);
	const Vector2r normal2 = pose1.rotate(c.normal);
	const Vector3r normal(normal2.x(), normal2.y(), 0);
	const Vector2r point = pose1.apply(c.point);
	g.contactPoint       = Vector3r(point.x(), point.y(), state2.pos.z());
	g.penetrationDepth   = c.overlap;
	g.refR1 = g.refR2 = r;
	// false: branch vectors from the contact point, the block being no sphere (as YADE's box-sphere contact)
	g.precompute(state1, state2, scene, I, normal, isNew, shift2, false);
	return true;
}

} // namespace yade
