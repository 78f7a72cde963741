#include <pkg/rbsm/MixedPhys.hpp>
#include <lib/factory/ClassFactory.hpp>
#include <pkg/common/ElastMat.hpp>
#include <pkg/dem/DemXDofGeom.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>

#include <algorithm>
#include <cmath>

namespace yade {
namespace rbsm_mixed {

	Elastic elasticOf(const Material& m)
	{
		Elastic e;
		if (const auto* r = dynamic_cast<const RbsmMat*>(&m)) {
			e = Elastic { r->young, r->poisson, r->frictionAngle, r->cohesion, r->tensileStrength, true, r->jointKn, r->jointKs, r->ductile };
		} else if (const auto* f = dynamic_cast<const FrictMat*>(&m)) {
			e = Elastic { f->young, f->poisson, f->frictionAngle, 0, 0, false };
		}
		return e;
	}

	bool pointContactRadii(const IGeom* geom, Real& R1, Real& R2)
	{
		const auto* g = dynamic_cast<const GenericSpheresContact*>(geom);
		if (!g) return false;
		R1 = g->refR1 > 0 ? g->refR1 : g->refR2; // as Ip2_FrictMat_FrictMat_FrictPhys
		R2 = g->refR2 > 0 ? g->refR2 : g->refR1;
		return true;
	}

	shared_ptr<IPhys> frictPhys(Real R1, Real R2, const Elastic& m1, const Elastic& m2)
	{
		const Real  kn1 = m1.young * R1, kn2 = m2.young * R2, ks1 = kn1 * m1.poisson, ks2 = kn2 * m2.poisson;
		auto        p = boost::static_pointer_cast<FrictPhys>(ClassFactory::instance().createShared("FrictPhys")); // Debian's constructor
		p->kn                     = kn1 + kn2 > 0 ? 2 * kn1 * kn2 / (kn1 + kn2) : 0;
		p->ks                     = ks1 + ks2 > 0 ? 2 * ks1 * ks2 / (ks1 + ks2) : 0;
		p->tangensOfFrictionAngle = std::tan(std::min(m1.frictionAngle, m2.frictionAngle));
		return p;
	}

	shared_ptr<RbsmPhys> boundaryJointPhys(const RbsmGeom& g, const Elastic& block, bool blockIsBody1, const Elastic& boundary, bool planeStrain)
	{
		const Real h     = blockIsBody1 ? g.h1 : g.h2;
		const auto plane = planeStrain ? rbsm::PlaneState::PlaneStrain : rbsm::PlaneState::PlaneStress;
		const auto k     = rbsm::kawaiSpringsTwoMaterials(block.young, block.poisson, h, block.young, block.poisson, 0, plane);
		auto       p     = shared_ptr<RbsmPhys>(new RbsmPhys);
		p->kn              = givenOr(block.jointKn, 0, k.kn);
		p->ks              = givenOr(block.jointKs, 0, k.ks);
		p->ductile         = block.ductile;
		p->tanPhi          = std::min(std::tan(block.frictionAngle), std::tan(boundary.frictionAngle));
		p->cohesion        = std::min(block.cohesion, boundary.cohesion);
		p->tensileStrength = std::min(block.tensileStrength, boundary.tensileStrength);
		p->initPoints(g.nPoints(), false);
		return p;
	}

} // namespace rbsm_mixed
} // namespace yade
