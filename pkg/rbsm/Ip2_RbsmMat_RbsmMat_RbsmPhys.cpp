#include <pkg/rbsm/Ip2_RbsmMat_RbsmMat_RbsmPhys.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>

#include <pkg/rbsm/MixedPhys.hpp>
#include <pkg/rbsm/StepReport.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <sstream>
#include <utility>

namespace yade {

YADE_PLUGIN((RbsmPhys)(Ip2_RbsmMat_RbsmMat_RbsmPhys));

namespace {
	std::atomic<int> mixedReports { 0 };
	void             reportMixedPlaneStates(const Interaction& I, Scene& scene)
	{
		rbsm_report::stopForPair(mixedReports, scene, "Ip2_RbsmMat_RbsmMat_RbsmPhys", I.getId1(), I.getId2(),
		                         "mix plane strain and plane stress materials (RbsmMat.planeStrain)");
	}
	std::atomic<int> geomReports { 0 };
	void             reportUnknownGeometry(const Interaction& I, Scene& scene)
	{
		rbsm_report::stopForPair(geomReports, scene, "Ip2_RbsmMat_RbsmMat_RbsmPhys", I.getId1(), I.getId2(),
		                         ("have a " + I.geom->getClassName() + " contact, which it cannot give properties (only RbsmGeom and ScGeom)").c_str());
	}

	// Once per process, at the first joint: a hand-built engine list without the plugin's step checks runs
	// any O.dt (1000 x the stable step exploded, 0 stood still) and lets unhandled pairs pass, silently.
	void warnOfMissingChecks(const Scene& scene)
	{
		bool stepper = false, pairCheck = false;
		for (const auto& e : scene.engines) {
			if (!e) continue;
			const std::string name = e->getClassName();
			stepper                = stepper || name == "RbsmTimeStepper";
			pairCheck              = pairCheck || name == "RbsmPairCheck";
		}
		std::string missing;
		if (!stepper)
			missing += " RbsmTimeStepper (nothing checks O.dt against the stable step of the joints: a larger one explodes, "
			           "O.dt = 0 stands still; nor the blocks' states and motions);";
		if (!pairCheck) missing += " RbsmPairCheck (a pair that no functor handles, e.g. a sphere and a block, passes through silently);";
		if (missing.empty()) return;
		std::cerr << "yade-rbsm: WARNING: O.engines lacks" + missing
		                     + " yade_rbsm.engines() has both (RbsmTimeStepper, then RbsmPairCheck, before NewtonIntegrator)\n";
	}
}

void Ip2_RbsmMat_RbsmMat_RbsmPhys::go(const shared_ptr<Material>& b1, const shared_ptr<Material>& b2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return; // properties are set once, when the joint forms
	makePhys(b1, b2, I);
}

// (Out of line: InteractionLoop calls go for every contact at every step, and the early return above
// then does not pay for the saved registers and stack frame of this body.)
[[gnu::noinline]] void Ip2_RbsmMat_RbsmMat_RbsmPhys::makePhys(const shared_ptr<Material>& b1, const shared_ptr<Material>& b2, const shared_ptr<Interaction>& I)
{
	if (jointsMade.fetch_add(1, std::memory_order_relaxed) == 0) warnOfMissingChecks(*scene);
	const auto* g = dynamic_cast<const RbsmGeom*>(I->geom.get());
	if (!g) {
		// A point contact of YADE's sphere laws (a sphere of RbsmMat against a block, a wall or a sphere):
		// FrictPhys, the RbsmMat read as a FrictMat (Ip2_RbsmMat_FrictMat_FrictPhys's rule). Any other
		// geometry is reported, not thrown: this runs inside InteractionLoop's OpenMP loop.
		Real       R1 = 1, R2 = 1;
		const bool point = rbsm_mixed::pointContactRadii(I->geom.get(), R1, R2);
		if (!point) reportUnknownGeometry(*I, *scene);
		I->phys = rbsm_mixed::frictPhys(R1, R2, point ? rbsm_mixed::elasticOf(*b1) : rbsm_mixed::Elastic {}, point ? rbsm_mixed::elasticOf(*b2) : rbsm_mixed::Elastic {});
		return;
	}
	const RbsmMat& m1 = static_cast<const RbsmMat&>(*b1);
	const RbsmMat& m2 = static_cast<const RbsmMat&>(*b2);
	if (m1.planeStrain != m2.planeStrain) {
		// No joint stiffness follows from two plane states. Reported, not thrown (StepReport.hpp); the
		// joint carries nothing in this step and the run stops after it, so that no step runs with the
		// joint missing.
		reportMixedPlaneStates(*I, *scene);
		auto p = shared_ptr<RbsmPhys>(new RbsmPhys); // kn = ks = 0, every point broken
		p->initPoints(g->nPoints(), false);
		I->phys = p;
		return;
	}

	// setCohesionNow applies to all contacts made in the step in which it is first seen.
	if (setCohesionNow && cohesionIter < 0) cohesionIter = scene->iter;
	if (setCohesionNow && cohesionIter != scene->iter) {
		setCohesionNow = false;
		cohesionIter   = -1;
	}
	const bool bonded = setCohesionNow || setCohesionOnNewContacts;

	const auto plane = m1.planeStrain ? rbsm::PlaneState::PlaneStrain : rbsm::PlaneState::PlaneStress;
	// a deformable block carries its own elasticity: its side of the joint adds h/(penalty E′), not h/E′
	const Real h1 = m1.deformable ? g->h1 / m1.penalty : g->h1, h2 = m2.deformable ? g->h2 / m2.penalty : g->h2;
	const auto k  = rbsm::kawaiSpringsTwoMaterials(m1.young, m1.poisson, h1, m2.young, m2.poisson, h2, plane);

	auto p             = shared_ptr<RbsmPhys>(new RbsmPhys);
	p->kn              = rbsm_mixed::givenOr(m1.jointKn, m2.jointKn, k.kn);
	p->ks              = rbsm_mixed::givenOr(m1.jointKs, m2.jointKs, k.ks);
	p->tanPhi          = std::min(std::tan(m1.frictionAngle), std::tan(m2.frictionAngle));
	p->cohesion        = std::min(m1.cohesion, m2.cohesion);
	p->tensileStrength = std::min(m1.tensileStrength, m2.tensileStrength);
	p->ductile         = m1.ductile && m2.ductile;
	// the as-built joints of a deformable continuum are its cuts, welded; any other joint is a discontinuity
	p->welded = bonded && m1.deformable && m2.deformable;
	// its mean jump takes the penalty, its bending (the jump's linear part) Kawai's springs of the materials
	if (p->welded && p->kn > 0) p->linearShare = std::min<Real>(1, rbsm::kawaiSpringsTwoMaterials(m1.young, m1.poisson, g->h1, m2.young, m2.poisson, g->h2, plane).kn / p->kn);
	p->weldYields = p->welded && m1.plastic && m2.plastic && m1.weldYields && m2.weldYields; // as strong as the material, no more
	if (p->welded && m1.weldBreakStrain > 0 && m2.weldBreakStrain > 0) p->weldBreakStrain = std::max(m1.weldBreakStrain, m2.weldBreakStrain);
	p->initPoints(g->nPoints(), p->welded || (bonded && (p->cohesion > 0 || p->tensileStrength > 0)));
	I->phys = p;
}

// ---- RbsmPhys: Python's per-point lists and the saved form of the points ----

namespace {
	template <class F> boost::python::list pointList(const RbsmPhys& p, F f)
	{
		boost::python::list l;
		for (int k = 0; k < p.nPoints; k++)
			l.append(f(p.point(k)));
		return l;
	}
	template <class F> std::vector<Real> pointValues(const RbsmPhys& p, F f)
	{
		std::vector<Real> v(p.nPoints);
		for (int k = 0; k < p.nPoints; k++)
			v[k] = f(p.point(k));
		return v;
	}
}

boost::python::list RbsmPhys::pyIntact() const { return pointList(*this, [](const Point& q) { return q.joint.intact; }); }
boost::python::list RbsmPhys::pySlipping() const { return pointList(*this, [](const Point& q) { return q.joint.slipping; }); }
boost::python::list RbsmPhys::pyOpen() const { return pointList(*this, [](const Point& q) { return q.joint.open; }); }
std::vector<Real>   RbsmPhys::pyShearTraction() const { return pointValues(*this, [](const Point& q) { return q.joint.shearTraction; }); }
std::vector<Real>   RbsmPhys::pyNormalTraction() const { return pointValues(*this, [](const Point& q) { return q.normalTraction; }); }

void RbsmPhys::pySetShearTraction(const std::vector<Real>& tau)
{
	if (int(tau.size()) != nPoints)
		throw std::invalid_argument(
		        "RbsmPhys.shearTraction: one value per integration point (" + std::to_string(nPoints) + "), got " + std::to_string(tau.size()));
	for (int k = 0; k < nPoints; k++)
		if (!std::isfinite(tau[k])) throw std::invalid_argument("RbsmPhys.shearTraction: value " + std::to_string(k) + " is not finite");
	for (int k = 0; k < nPoints; k++)
		point(k).joint.shearTraction = tau[k];
}

void RbsmPhys::preSave(RbsmPhys&)
{
	shearTraction  = pyShearTraction();
	normalTraction = pyNormalTraction();
	intact.resize(nPoints), slipping.resize(nPoints), open.resize(nPoints);
	for (int k = 0; k < nPoints; k++) {
		intact[k]   = point(k).joint.intact;
		slipping[k] = point(k).joint.slipping;
		open[k]     = point(k).joint.open;
	}
	if (const auto* d = lastDashpots.get()) dashpotForces.assign(d->f.begin(), d->f.begin() + 2 * nPoints);
}

void RbsmPhys::postSave(RbsmPhys&) { shearTraction.clear(), normalTraction.clear(), intact.clear(), slipping.clear(), open.clear(), dashpotForces.clear(); }

void RbsmPhys::checkValue(const char* name, Real v)
{
	if (std::isfinite(v) && v >= 0) return;
	std::ostringstream msg; // (%g-like: 1e-8 must not print as 0.000000)
	msg << "RbsmPhys." << name << ": must be a finite number >= 0 (got " << v << ")";
	throw std::invalid_argument(msg.str());
}

// After a load, or a constructor from Python with some of these given: the non-empty ones set the
// points (all of one length). Otherwise kn or ks was set from Python (or updateAttrs ran): checked
// (the caller puts the old value back when this throws) and counted, so that the stepper sees a
// stiffer joint before it moves anything.
void RbsmPhys::postLoad(RbsmPhys& self)
{
	for (const auto& [name, v] : { std::pair<const char*, Real> { "kn", kn }, { "ks", ks }, { "cohesion", cohesion }, { "tanPhi", tanPhi }, { "tensileStrength", tensileStrength } })
		checkValue(name, v);
	if (!(linearShare > 0 && linearShare <= 1)) // (its square root divides the welded points' tractions)
		throw std::invalid_argument("RbsmPhys.linearShare: must be in (0, 1] (got " + std::to_string(linearShare) + ")");
	const size_t sizes[] = { shearTraction.size(), normalTraction.size(), intact.size(), slipping.size(), open.size() };
	const size_t n       = *std::max_element(std::begin(sizes), std::end(sizes));
	if (n == 0) { // not a load
		edits.fetch_add(1, std::memory_order_relaxed);
		return;
	}
	for (size_t m : sizes)
		if (m != 0 && m != n) throw std::invalid_argument("RbsmPhys: the per-point values (shearTraction, normalTraction, intact, slipping, open) differ in length");
	if (n > size_t(rbsm::kMaxIntegrationPoints)) throw std::invalid_argument("RbsmPhys: more than 8 integration points (" + std::to_string(n) + ")");
	if (nPoints != int(n)) initPoints(int(n), true);
	for (size_t k = 0; k < n; k++) {
		Point& q = point(k);
		if (!shearTraction.empty()) q.joint.shearTraction = shearTraction[k];
		if (!normalTraction.empty()) q.normalTraction = normalTraction[k];
		if (!intact.empty()) q.joint.intact = intact[k] != 0;
		if (!slipping.empty()) q.joint.slipping = slipping[k] != 0;
		if (!open.empty()) q.joint.open = open[k] != 0;
	}
	if (!dashpotForces.empty()) { // (a scene saved with contact damping while energy was tracked)
		if (dashpotForces.size() != 2 * n) throw std::invalid_argument("RbsmPhys.dashpotForces: two values per point expected");
		DashpotForces d;
		std::copy(dashpotForces.begin(), dashpotForces.end(), d.f.begin());
		lastDashpots.set(d);
	} else lastDashpots.reset();
	postSave(self); // the points hold the state now
}

} // namespace yade
