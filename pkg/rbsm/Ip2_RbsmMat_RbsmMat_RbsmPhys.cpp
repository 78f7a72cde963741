#include <pkg/rbsm/Ip2_RbsmMat_RbsmMat_RbsmPhys.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>

namespace yade {

YADE_PLUGIN((RbsmPhys)(Ip2_RbsmMat_RbsmMat_RbsmPhys));

void Ip2_RbsmMat_RbsmMat_RbsmPhys::go(const shared_ptr<Material>& b1, const shared_ptr<Material>& b2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return; // properties are set once, when the joint forms
	const auto* g = dynamic_cast<const RbsmGeom*>(I->geom.get());
	if (!g) throw std::runtime_error("Ip2_RbsmMat_RbsmMat_RbsmPhys: the interaction has no RbsmGeom (use Ig2_Polygon2D_Polygon2D_RbsmGeom)");
	const RbsmMat& m1 = static_cast<const RbsmMat&>(*b1);
	const RbsmMat& m2 = static_cast<const RbsmMat&>(*b2);
	if (m1.planeStrain != m2.planeStrain)
		throw std::invalid_argument(
		        "Ip2_RbsmMat_RbsmMat_RbsmPhys: bodies #" + std::to_string(I->getId1()) + " and #" + std::to_string(I->getId2())
		        + " mix plane strain and plane stress materials");

	// setCohesionNow applies to all contacts made in the step in which it is first seen.
	if (setCohesionNow && cohesionIter < 0) cohesionIter = scene->iter;
	if (setCohesionNow && cohesionIter != scene->iter) {
		setCohesionNow = false;
		cohesionIter   = -1;
	}
	const bool bonded = setCohesionNow || setCohesionOnNewContacts;

	const auto plane = m1.planeStrain ? rbsm::PlaneState::PlaneStrain : rbsm::PlaneState::PlaneStress;
	const auto k     = rbsm::kawaiSpringsTwoMaterials(m1.young, m1.poisson, g->h1, m2.young, m2.poisson, g->h2, plane);

	auto p             = shared_ptr<RbsmPhys>(new RbsmPhys);
	p->kn              = k.kn;
	p->ks              = k.ks;
	p->tanPhi          = std::min(std::tan(m1.frictionAngle), std::tan(m2.frictionAngle));
	p->cohesion        = std::min(m1.cohesion, m2.cohesion);
	p->tensileStrength = std::min(m1.tensileStrength, m2.tensileStrength);
	const size_t n     = g->nPoints();
	p->shearTraction.assign(n, 0);
	p->normalTraction.assign(n, 0);
	p->intact.assign(n, bonded && (p->cohesion > 0 || p->tensileStrength > 0));
	p->slipping.assign(n, false);
	p->open.assign(n, false);
	I->phys = p;
}

} // namespace yade
