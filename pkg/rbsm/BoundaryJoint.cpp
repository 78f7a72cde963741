#include <pkg/rbsm/BoundaryJoint.hpp>
#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/MixedMaterials.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>
#include <pkg/rbsm/kernel/SegmentKinematics.hpp>

namespace yade {
namespace rbsm_boundary {

	namespace {
		std::atomic<int> materialReports { 0 };
		constexpr Real   kHysteresis = 1e-6; // Ig2_Polygon2D_Polygon2D_RbsmGeom.hysteresis's default
	}

	bool blockOnBoundary(const char* who, int nIP, Real interactionDistance, const Polygon2D& block, const State& s1,
	                     const std::vector<rbsm::Vec2>& boundary, const State& s2, const shared_ptr<Interaction>& I, Scene& scene)
	{
		const std::vector<rbsm::Vec2> A(block.vertices.begin(), block.vertices.end());
		const std::vector<rbsm::Vec2> blockWorld = rbsm::toWorld(A, s1.pos.head<2>(), planarAngle(s1.ori));
		RbsmGeom*                     g          = static_cast<RbsmGeom*>(I->geom.get());
		rbsm::ContactHint             hint;
		if (g) hint = rbsm::ContactHint { g->refBody, g->refEdge };
		const rbsm::EdgeContact c = rbsm::edgeContact(blockWorld, boundary, interactionDistance, g ? &hint : nullptr, kHysteresis, 2 * block.circumradius);
		if (!g) {
			if (!(c.touching && c.length > 0)) return false;
			if (!rbsm_mixed::materialsAccepted(materialReports, scene, who, *I, rbsm_mixed::Role::Block, rbsm_mixed::Role::Boundary)) return false;
			auto geom = shared_ptr<RbsmGeom>(new RbsmGeom);
			geom->setIntegrationPoints(nIP);
			geom->thickness = block.thickness;
			geom->reducedMass = RbsmGeom::reducedMassOf(s1, s2); // (the block-block joints' formula)
			geom->strainSides = deformableState(&s1) ? 1 : 0;
			if (geom->strainSides) geom->recordStrainsMade(s1, s2);
			I->geom           = geom;
			g                 = geom.get();
		} else if (!c.touching) {
			g->lost       = true; // the law ends the joint (see Ig2_Polygon2D_Polygon2D_RbsmGeom)
			g->separation = c.separation;
			return true;
		}
		g->lost         = false;
		g->frozen.reset();
		g->frozenSteps  = 0;
		g->normal       = c.normal;
		g->p0           = c.p0;
		g->p1           = c.p1;
		g->length       = c.length;
		g->separation   = c.separation;
		g->refBody      = c.refBody;
		g->refEdge      = c.refEdge;
		g->centroid1    = s1.pos.head<2>();
		g->centroid2    = s2.pos.head<2>();
		g->h1           = rbsm::distanceToLine(g->centroid1, c.p0, c.normal);
		g->h2           = 0; // rigid boundary
		const rbsm::SegmentKinematics k
		        = rbsm::segmentKinematics(c.d0, c.d1, c.p0, c.p1, g->centroid1, s1.vel.head<2>(), s1.angVel.z(), g->centroid2, s2.vel.head<2>(), s2.angVel.z());
		g->d0                      = k.d0;
		g->d1                      = k.d1;
		g->relativeVelocity        = k.v0;
		g->relativeAngularVelocity = s2.angVel.z() - s1.angVel.z();
		if (g->strainSides) g->addStrainMotion(s1, s2);
		return true;
	}

} // namespace rbsm_boundary
} // namespace yade
