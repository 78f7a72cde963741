#include <pkg/rbsm/Ip2_RbsmMat_FrictMat_FrictPhys.hpp>
#include <pkg/rbsm/Ip2_RbsmMat_RbsmMat_RbsmPhys.hpp>
#include <pkg/rbsm/MixedPhys.hpp>
#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <pkg/common/ElastMat.hpp>

namespace yade {

YADE_PLUGIN((Ip2_RbsmMat_FrictMat_FrictPhys));

namespace {
	std::atomic<int> geomReports { 0 };
}

void Ip2_RbsmMat_FrictMat_FrictPhys::go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return;
	const rbsm_mixed::Elastic e1 = rbsm_mixed::elasticOf(*m1), e2 = rbsm_mixed::elasticOf(*m2);
	if (const auto* g = dynamic_cast<const RbsmGeom*>(I->geom.get())) {
		// the block (RbsmMat, body 1) on a FrictMat wall or facet: an RBSM joint, which RbsmTimeStepper
		// adds to its block's rows (and density scale) at the step it is made, as the RbsmMat pair's
		Ip2_RbsmMat_RbsmMat_RbsmPhys::jointsMade.fetch_add(1, std::memory_order_relaxed);
		I->phys = rbsm_mixed::boundaryJointPhys(*g, e1, true, e2, static_cast<const RbsmMat&>(*m1).planeStrain);
		return;
	}
	Real R1, R2;
	if (rbsm_mixed::pointContactRadii(I->geom.get(), R1, R2)) {
		I->phys = rbsm_mixed::frictPhys(R1, R2, e1, e2);
		return;
	}
	rbsm_report::stopForPair(geomReports, *scene, "Ip2_RbsmMat_FrictMat_FrictPhys", I->getId1(), I->getId2(),
	                         ("have a " + I->geom->getClassName() + " contact, which it cannot give properties (only ScGeom and RbsmGeom)").c_str());
	I->phys = rbsm_mixed::frictPhys(1, 1, rbsm_mixed::Elastic {}, rbsm_mixed::Elastic {}); // carries nothing (kn = ks = 0)
}

} // namespace yade
