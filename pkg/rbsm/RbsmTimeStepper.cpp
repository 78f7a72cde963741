#include <core/Omega.hpp>
#include <pkg/rbsm/BlockStateCheck.hpp>
#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/DistributedRun.hpp>
#include <pkg/rbsm/Ip2_RbsmMat_RbsmMat_RbsmPhys.hpp>
#include <pkg/rbsm/MemoryOrder.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>
#include <pkg/rbsm/RbsmTimeStepper.hpp>
#include <pkg/rbsm/NewtonAttribute.hpp>
#include <pkg/rbsm/ReshapedBlocks.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>
#include <core/Scene.hpp>

#include <boost/python.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iostream>
#include <sstream>

namespace yade {

YADE_PLUGIN((RbsmTimeStepper));

namespace {
	// rowBounds per body: the Gershgorin bounds of its rows, ω² (springs) and λ (dashpots), and a slot
	// that older builds filled (Σ min(kn, ks)·A): a file with it is estimated anew (postLoad)
	constexpr size_t kRow = 3;

	rbsm::DynBody dynBody(const State& s) { return rbsm::DynBody { s.mass, s.inertia.z(), s.pos.head<2>(), fixedBlock(s) }; }

	const Polygon2D* polygonOf(const Body& b)
	{
		const Shape* s = b.shape.get();
		return s && s->getClassIndex() == Polygon2D::getClassIndexStatic() ? static_cast<const Polygon2D*>(s) : nullptr;
	}

	// An end of an RBSM joint. A block's state was checked by the per-body pass (BlockStateCheck).
	// The other end of a joint on a Wall or a Facet is a rigid boundary (h2 = 0) that may be left
	// unfixed with no mass or inertia (utils.wall/facet give none): as in RbsmGeom::reducedMassOf it
	// counts as infinite mass, and a missing polar inertia as a rotation that the joint cannot drive,
	// instead of a division by zero (the kernel refuses a free body without mass).
	// A deformable block's strain degrees of freedom: its (θ, ε) mass and own stiffness A t D, in its frame.
	void addStrainModes(const Body& b, const Polygon2D& poly, rbsm::DynBody& d)
	{
		DeformableState* ds  = deformableState(b.state.get());
		const auto*      mat = dynamic_cast<const RbsmMat*>(b.material.get());
		if (!ds || !mat) return;
		const rbsm::StrainMass& M = ds->strainMass(poly);
		d.deformable              = true;
		planarCosSin(ds->ori, d.cosAngle, d.sinAngle);
		d.inertia         = M.polar;
		d.thetaStrainMass = M.thetaStrain;
		d.strainMass      = M.strain;
		d.strainStiffness = poly.area * poly.thickness * rbsm::elasticityMatrix(mat->young, mat->poisson, mat->planeStrain);
	}

	rbsm::DynBody dynBody(const Body& b)
	{
		const State& s = *b.state;
		if (const Polygon2D* poly = polygonOf(b)) {
			rbsm::DynBody d = dynBody(s);
			if (DeformableState::alive.load(std::memory_order_relaxed) > 0 && !d.fixed) addStrainModes(b, *poly, d); // (rigid scenes: no cast)
			return d;
		}
		rbsm::DynBody d = dynBody(s);
		if (!(s.mass > 0)) d.fixed = true;
		if (!(s.inertia.z() > 0)) d.inertia = std::numeric_limits<Real>::infinity();
		return d;
	}

	// the RBSM joint of an interaction, or false (class indices: this runs over every interaction)
	bool rbsmJoint(const Interaction& I, const RbsmGeom*& g, const RbsmPhys*& p)
	{
		if (!I.isReal()) return false;
		const IGeom* ig = I.geom.get();
		const IPhys* ip = I.phys.get();
		if (!ig || !ip || ig->getClassIndex() != RbsmGeom::getClassIndexStatic() || ip->getClassIndex() != RbsmPhys::getClassIndexStatic()) return false;
		g = static_cast<const RbsmGeom*>(ig);
		p = static_cast<const RbsmPhys*>(ip);
		return true;
	}

	Vector2r worldVertex(const Polygon2D& poly, const State& s, int i)
	{
		return planarPose(s.pos, s.ori).apply(poly.vertices[size_t(i)]);
	}

	std::atomic<int> motionReports { 0 };
}

void RbsmTimeStepper::postLoad(RbsmTimeStepper&)
{
	if (!(safetyFactor > 0 && safetyFactor <= 1))
		throw std::invalid_argument("RbsmTimeStepper.safetyFactor: must be in (0, 1] (got " + std::to_string(safetyFactor) + ")");
	if (!(impactSafety > 0 && impactSafety <= 1))
		throw std::invalid_argument("RbsmTimeStepper.impactSafety: must be in (0, 1] (got " + std::to_string(impactSafety) + ")");
	if (!(std::isfinite(targetDt) && targetDt >= 0))
		throw std::invalid_argument("RbsmTimeStepper.targetDt: must be a finite step >= 0 [s] (got " + std::to_string(targetDt) + "; 0 = the median block's step)");
	if (interval < 1) throw std::invalid_argument("RbsmTimeStepper.interval: must be >= 1 (got " + std::to_string(interval) + ")");
	if (!(maxDt > 0)) throw std::invalid_argument("RbsmTimeStepper.maxDt: must be > 0 (got " + std::to_string(maxDt) + ")");
	if (!(std::isfinite(maxStepMotion) && maxStepMotion >= 0))
		throw std::invalid_argument("RbsmTimeStepper.maxStepMotion: must be a finite fraction >= 0 (got " + std::to_string(maxStepMotion) + "; 0 = no check)");
	// rows of an older build (its dashpot slots meant other sums): a full estimate at the next step
	for (size_t k = 2; k < rowBounds.size(); k += kRow)
		if (rowBounds[k] != 0) {
			rowBounds.clear(), lastCheck = -1;
			break;
		}
}

// The uninterrupted run makes a full estimate at its next step after a joint's kn, ks or a block's mass,
// inertia or shape were set from Python (action()); neither RbsmPhys::edits nor Polygon2D::followed is
// saved, so the file says it (a kn x 100 set before O.save ran at the old step after O.load and tore the
// bond). The live engine keeps its lastCheck; only the file changes.
void RbsmTimeStepper::preSave(RbsmTimeStepper&)
{
	savedLastCheck = lastCheck;
	bool pending   = jointEdits() != editsSeen;
	// the scene being saved is Omega's: this engine's own pointer is set at its scene's first step, and
	// an engine just loaded (O.loadTmp, then O.saveTmp before a step) still points to the scene it replaced
	const Scene* saved = Omega::instance().getScene().get();
	if (!pending && saved)
		for (const auto& b : saved->bodies->body)
			if (b && reshapePending(*b)) {
				pending = true;
				break;
			}
	if (pending) lastCheck = -1;
}

void RbsmTimeStepper::postSave(RbsmTimeStepper&) { lastCheck = savedLastCheck; }

// The joint as the kernel's stiffness sees it: the segment it reaches once a closing corner lies flat
// (rbsm::closingContact), at the rule's points.
bool RbsmTimeStepper::jointAsDynContact(const Interaction& I, int body1, int body2, rbsm::DynContact& c) const
{
	const RbsmGeom* g;
	const RbsmPhys* p;
	if (!rbsmJoint(I, g, p) || !g->rule) return false;
	c.body1   = body1;
	c.body2   = body2;
	c.normal  = g->normal;
	c.tangent = g->tangent();
	c.kn      = p->kn;
	c.ks      = p->ks;
	if (mayImpact(*p)) { // its ω scaled so that safetyFactor gives impactSafety's step
		const Real s = (safetyFactor / impactSafety) * (safetyFactor / impactSafety);
		c.kn *= s, c.ks *= s;
	}
	Vector2r q0 = g->p0, q1 = g->p1;
	const auto&      bodies = scene->bodies->body;
	const Body&      ref    = *bodies[g->refBody == 2 ? I.getId2() : I.getId1()];
	const Body&      inc    = *bodies[g->refBody == 2 ? I.getId1() : I.getId2()];
	const Polygon2D *R = polygonOf(ref), *N = polygonOf(inc);
	if (R && N && g->refEdge >= 0 && g->incEdge >= 0 && g->refEdge < int(R->vertices.size()) && g->incEdge < int(N->vertices.size())) {
		const int nr = int(R->vertices.size()), ni = int(N->vertices.size());
		std::tie(q0, q1) = rbsm::closingContact(
		        worldVertex(*R, *ref.state, g->refEdge),
		        worldVertex(*R, *ref.state, (g->refEdge + 1) % nr),
		        worldVertex(*N, *inc.state, g->incEdge),
		        worldVertex(*N, *inc.state, (g->incEdge + 1) % ni),
		        q0,
		        q1);
	}
	const Real length = (q1 - q0).norm();
	c.points.clear(), c.areas.clear(); // (their capacity is kept)
	for (int k = 0; k < g->nPoints(); k++) {
		c.points.push_back(q0 + g->rule->s[k] * (q1 - q0));
		c.areas.push_back(g->rule->w[k] * length * g->thickness);
	}
	return true;
}

// A frictional joint can open and close: an impact, which the central-difference step resolves
// accurately only in many steps (impactSafety). Bonded joints never open unbroken, and a damped
// (quasi-static) stage needs equilibrium, not restitution: safetyFactor is enough for them.
// Accuracy, not stability: only the step the stepper sets (setDt) takes it; a checked O.dt is not refused for it.
bool RbsmTimeStepper::impactsMatter() const { return setDt && impactSafety < safetyFactor && !(newtonDamping > 0); }

// A first contact is an impact: its fraction of the stable step.
Real RbsmTimeStepper::firstContactSafety() const { return impactsMatter() ? impactSafety : safetyFactor; }

bool RbsmTimeStepper::mayImpact(const RbsmPhys& p) const { return impactsMatter() && p.nIntact() == 0; }

// Joint dashpots (Law2's dampingRatio) lower the limit of the central-difference scheme, whose
// velocity is half a step behind: dt ≤ (2/ω)(√(1+ξ²) − ξ) = 2/(√(ω²+γ²) + γ) for a mode of frequency
// ω and decay rate γ = ξω (m ẍ + C ẋ + K x: γ = C/2m), which falls as ω or γ grows. So the Gershgorin
// bounds of both, ω̂_b² of M^-½ K M^-½ and λ̂_b of M^-½ C M^-½ (C the dashpots at their largest until
// the next estimate, jointDashpots), γ̂_b = λ̂_b/2, give each block's step. This is an estimate, not a
// bound (the modes of K and C differ). A corner's dashpot is stiff per area but acts on almost no
// area: that c on the length its springs reach once flat (ξ_b = c/k ω̂/2) took the step of a corner
// landing 100 times down (tests/robustness/test_timestep.py).
Real RbsmTimeStepper::blockDt(size_t id) const
{
	const Real w2 = rowBounds[kRow * id], gamma = rowBounds[kRow * id + 1] / 2;
	if (!(w2 > 0)) return std::numeric_limits<Real>::infinity();
	// (hypot: no overflow of γ² for a stiff dashpot, which is a short step, not an infinitely stiff joint)
	return 2 / (std::hypot(std::sqrt(w2), gamma) + gamma);
}

// The joint's dashpots as the kernel's stiffness sees springs (kn = ks per area), on the springs' points
// and areas (*springs*: jointAsDynContact's, the length a closing corner reaches once flat): the law's
// c = 2ξ√(kn A m)/A on the present area A acts as 2ξ√(kn A m) in all, which grows as √A while the corner
// closes between two estimates; c √(A/A_flat) on A_flat is its value once flat, the largest on the way.
// False without dashpots.
bool RbsmTimeStepper::jointDashpots(const Interaction& I, const rbsm::DynContact& springs, rbsm::DynContact& c) const
{
	const RbsmGeom* g;
	const RbsmPhys* p;
	if (!rbsmJoint(I, g, p) || !(p->dampingCoefficient > 0)) return false;
	Real flat = 0;
	for (Real a : springs.areas) flat += a;
	const Real now = g->length * g->thickness;
	if (!(flat > 0)) return false;
	c       = springs;
	c.kn    = p->dampingCoefficient * std::sqrt(std::min(Real(1), now / flat));
	c.ks    = c.kn;
	return true;
}

void RbsmTimeStepper::boundsHold(size_t nBodies)
{
	if (rowBounds.size() < kRow * nBodies) rowBounds.resize(kRow * nBodies, 0);
}

// The joints in the order of their body ids: the container's order depends on when the collider ran
// (an erased interaction is replaced by the last one), and the sums of the bounds must not (a loaded
// scene continues bit for bit, tests/robustness/test_persistence.py).
template <class Keep> const std::vector<const Interaction*>& RbsmTimeStepper::jointsByIds(Keep keep)
{
	sortedJoints.clear();
	for (const auto& I : *scene->interactions)
		if (I->isReal() && keep(*I)) sortedJoints.push_back(I.get());
	std::sort(sortedJoints.begin(), sortedJoints.end(), [](const Interaction* a, const Interaction* b) {
		return std::make_pair(a->getId1(), a->getId2()) < std::make_pair(b->getId1(), b->getId2());
	});
	return sortedJoints;
}

Real RbsmTimeStepper::estimate()
{
	const auto& bodies = scene->bodies->body;
	dynBodies.clear(), dynIds.clear();
	dynIndex.assign(bodies.size(), -1); // body id -> index in dynBodies
	rowBounds.assign(kRow * bodies.size(), 0);
	size_t nContacts = 0, nDashpots = 0;
	for (const Interaction* I : jointsByIds([](const Interaction&) { return true; })) {
		const RbsmGeom* g;
		const RbsmPhys* p;
		if (!rbsmJoint(*I, g, p)) continue;
		int ends[2];
		for (int side = 0; side < 2; side++) {
			const Body::id_t id = side == 0 ? I->getId1() : I->getId2();
			if (dynIndex[id] < 0) {
				dynIndex[id] = int(dynBodies.size());
				dynBodies.push_back(dynBody(*bodies[id]));
				dynIds.push_back(id);
			}
			ends[side] = dynIndex[id];
		}
		if (dynContacts.size() <= nContacts) dynContacts.emplace_back();
		rbsm::DynContact& c = dynContacts[nContacts];
		if (!jointAsDynContact(*I, ends[0], ends[1], c)) continue;
		nContacts++;
		if (dashpots.size() <= nDashpots) dashpots.emplace_back();
		if (jointDashpots(*I, c, dashpots[nDashpots])) nDashpots++;
	}
	dynContacts.resize(nContacts);
	dashpots.resize(nDashpots);
	std::vector<Real> omega2, diag2; // Gershgorin bound of each block's rows, and its own block's share
	rbsm::criticalTimeStepGershgorin(dynBodies, dynContacts, &omega2, densityScaling ? &diag2 : nullptr);
	std::vector<Real> lambdaC; // the dashpots' bound of each block's rows (only where there are any)
	if (nDashpots > 0) rbsm::criticalTimeStepGershgorin(dynBodies, dashpots, &lambdaC);
	criticalDt   = std::numeric_limits<Real>::infinity();
	criticalBody = -1;
	if (densityScaling) rowDiag.assign(bodies.size(), 0);
	for (size_t b = 0; b < dynIds.size(); b++) {
		const size_t id         = size_t(dynIds[b]);
		rowBounds[kRow * id] = omega2[b];
		if (nDashpots > 0) rowBounds[kRow * id + 1] = lambdaC[b];
		if (densityScaling) rowDiag[id] = diag2[b];
		if (!ownedHere(*scene, *bodies[id])) continue;
		const Real dt = blockDt(id);
		if (dt < criticalDt) criticalDt = dt, criticalBody = int(id);
	}
	return criticalDt;
}

// A joint made since the last full estimate raises the Gershgorin bounds of its two blocks by its
// own terms (rbsm::contactRowBounds), at the step it is made: no step runs with it unaccounted for.
void RbsmTimeStepper::addJointsMadeThisStep()
{
	const auto& bodies = scene->bodies->body;
	boundsHold(bodies.size());
	rbsm::DynContact                 c, d;
	const Real                       inf     = std::numeric_limits<Real>::infinity();
	const bool                       rescale = scalesHold(bodies.size()); // density scaling: the joints' blocks too
	for (const Interaction* I : jointsByIds([this](const Interaction& J) { return J.iterMadeReal == scene->iter; })) {
		const Body::id_t                 id1 = I->getId1(), id2 = I->getId2();
		const std::vector<rbsm::DynBody> pair { dynBody(*bodies[id1]), dynBody(*bodies[id2]) };
		if (!jointAsDynContact(*I, 0, 1, c)) continue;
		Real add[2], diag[2], addC[2] = { 0, 0 };
		rbsm::contactRowBounds(pair, c, add[0], add[1], &diag[0], &diag[1]);
		if (jointDashpots(*I, c, d)) rbsm::contactRowBounds(pair, d, addC[0], addC[1]);
		for (int side = 0; side < 2; side++) {
			const Body::id_t id = side == 0 ? id1 : id2;
			rowBounds[kRow * id] += add[side];
			rowBounds[kRow * id + 1] += addC[side];
			if (rescale) { // its rows grew: its scale again, at the same target
				rowDiag[id] += diag[side];
				raiseMassScale(size_t(id), massScaleOf(size_t(id)));
			}
			if (!ownedHere(*scene, *bodies[id])) continue;
			const Real dt = blockDt(size_t(id));
			if (dt < criticalDt || !(criticalDt < inf)) {
				if (dt < inf) criticalDt = dt, criticalBody = id;
			}
		}
	}
}

// The stiffest single joint each free block without joints can form: one of its edges in full contact
// with the partner that adds the least compliance (the smallest inner radius over modulus of any other block).
Real RbsmTimeStepper::firstContactEstimate()
{
	struct Candidate {
		Real value = std::numeric_limits<Real>::infinity();
		long id    = -1;
	};
	struct Block {
		long                  id;
		const Polygon2D*      poly;
		Real                  En, Es, r;
	};
	std::vector<Block> blocks;
	Candidate          bestN[2], bestS[2]; // the two least compliances r/E′ and r/2G, by different blocks
	auto               keep = [](Candidate (&best)[2], Real v, long id) {
                if (v < best[0].value) best[1] = best[0], best[0] = Candidate { v, id };
                else if (v < best[1].value) best[1] = Candidate { v, id };
	};
	for (const auto& b : scene->bodies->body) {
		if (!b) continue;
		const Polygon2D* poly = polygonOf(*b);
		const auto*      mat  = dynamic_cast<const RbsmMat*>(b->material.get());
		if (!poly || !mat || poly->vertices.size() < 3) continue;
		Real En, Es;
		try {
			const auto plane = mat->planeStrain ? rbsm::PlaneState::PlaneStrain : rbsm::PlaneState::PlaneStress;
			En               = rbsm::constrainedModulus(mat->young, mat->poisson, plane);
			Es               = 2 * rbsm::shearModulus(mat->young, mat->poisson);
		} catch (const std::invalid_argument&) {
			continue; // a material the joints refuse is reported where they meet it
		}
		const Real r = poly->inradius;
		// a given joint stiffness: compliance at most 1/(2 kn) per block, so a pair is at least kn stiff
		if (mat->jointKn > 0) En = std::max(En, 2 * mat->jointKn * r);
		if (mat->jointKs > 0) Es = std::max(Es, 2 * mat->jointKs * r);
		keep(bestN, r / En, b->id);
		keep(bestS, r / Es, b->id);
		blocks.push_back(Block { b->id, poly, En, Es, r });
	}
	// A YADE Wall or Facet is a rigid boundary (h2 = 0, issue 17's joints): a partner that adds no
	// compliance (without it a block above a wall alone had no first contact, and O.dt stayed 1e-8).
	for (const auto& b : scene->bodies->body)
		if (b && b->shape && !polygonOf(*b) && (b->shape->getClassName() == "Wall" || b->shape->getClassName() == "Facet")) {
			keep(bestN, 0, -2);
			keep(bestS, 0, -2);
			break;
		}
	Real top[2] = { 0, 0 }; // the two largest ω² of free blocks
	firstOmega2.clear();
	for (const Block& k : blocks) {
		const State& s = *scene->bodies->body[size_t(k.id)]->state;
		// a block with joints is bounded by them (a bonded sliver is not assumed to meet another
		// sliver); a joint it makes later is added at the step it is made
		if (fixedBlock(s) || !ownedHere(*scene, *scene->bodies->body[size_t(k.id)]) || (size_t(kRow * k.id) < rowBounds.size() && rowBounds[kRow * k.id] > 0))
			continue;
		const Real partnerN = bestN[0].id != k.id ? bestN[0].value : bestN[1].value;
		const Real partnerS = bestS[0].id != k.id ? bestS[0].value : bestS[1].value;
		if (!std::isfinite(partnerN) || !std::isfinite(partnerS)) continue; // nothing to meet
		const Real w2 = rbsm::stiffestJointOmega2(dynBody(s), k.poly->vertices, k.En, k.Es, partnerN, partnerS, k.poly->thickness);
		if (w2 > 0) firstOmega2.push_back(w2);
		if (w2 > top[0]) top[1] = top[0], top[0] = w2;
		else if (w2 > top[1]) top[1] = w2;
	}
	const Real w2 = top[0] + top[1]; // two free blocks meeting: at most the sum of their own ω²
	return w2 > 0 ? 2 / std::sqrt(w2) : std::numeric_limits<Real>::infinity();
}

void RbsmTimeStepper::fullCheck()
{
	lastCheck = scene->iter;
	if (DeformableState::alive.load(std::memory_order_relaxed) > 0) requireStrainIntegrator();
	const Real d   = newtonAttribute<Real>(*scene, "damping", 0);
	newtonDamping  = std::isfinite(d) && d > 0 ? d : 0; // (read first: the estimate asks whether impacts matter)
	estimate();
	firstContactDt = firstContactEstimate();
	densityScale.readGravityAgain(); // NewtonIntegrator.gravity, once per full estimate
	if (densityScaling) scaleMasses();
}

// Density scaling (quasi-static stages, DensityScaling.hpp): every block whose own stable step is below
// the common one (targetDt, or the median block's) gets its inertia scaled so that all run at it.
void RbsmTimeStepper::scaleMasses()
{
	const auto& bodies = scene->bodies->body;
	massScale.assign(bodies.size(), 1);
	scaledTarget = targetDt;
	std::vector<Real> own; // each jointed block's own stable step
	for (size_t id = 0; id < bodies.size() && kRow * id < rowBounds.size(); id++)
		if (rowBounds[kRow * id] > 0) own.push_back(safetyFactor * blockDt(id) / std::sqrt(1 + newtonDamping));
	// and each free block without joints, its first contact's step: the median of the jointed blocks
	// alone was that of the few that had landed in a pile being dropped (one block touching a wall at
	// a corner: 0.15 s), at which the others, still falling, passed through their neighbours
	for (Real w2 : firstOmega2)
		own.push_back(firstContactSafety() * 2 / std::sqrt(w2) / std::sqrt(1 + newtonDamping));
	scaledDt = DensityScaling::commonStep(own, targetDt);
	if (own.empty()) return;
	for (size_t id = 0; id < bodies.size() && kRow * id < rowBounds.size(); id++)
		massScale[id] = massScaleOf(id);
}

// Sets body id's scale to s where a joint is made, slowing the block if it rises. Not at the full
// estimates: there the scales of sliding blocks go up and down by a few per cent, and slowing at every
// rise damped the runaway of failing strength-reduction trials (1200 blocks: 2.54x -> 1.68x).
void RbsmTimeStepper::raiseMassScale(size_t id, Real s)
{
	const Real s0 = massScale[id];
	massScale[id] = s;
	const auto& bodies = scene->bodies->body;
	if (id < bodies.size() && bodies[id] && bodies[id]->state) DensityScaling::slowOnRise(*bodies[id]->state, s0, s);
}

// The scale that lets body id's rows (rowBounds, rowDiag) run at scaledDt.
Real RbsmTimeStepper::massScaleOf(size_t id) const
{
	return DensityScaling::scaleFor(rowBounds[kRow * id], rowDiag[id], blockDt(id), scaledDt, safetyFactor, newtonDamping);
}

// Density scaling with the rows of a full estimate (saved with the scene; a file of an older build
// has none: a full estimate then), grown to nBodies for bodies added since.
bool RbsmTimeStepper::scalesHold(size_t nBodies)
{
	if (!densityScaling || !massScaled || rowDiag.empty() || !std::isfinite(scaledDt)) return false;
	if (rowDiag.size() < nBodies) rowDiag.resize(nBodies, 0);
	if (massScale.size() < nBodies) massScale.resize(nBodies, 1);
	return true;
}

void RbsmTimeStepper::reportMotion(const Body& b, Real motion, Real r)
{
	const State& s = *b.state;
	rbsm_report::stopAfterThisStep(*scene);
	rbsm_report::limited(motionReports, [&](bool last) {
		std::ostringstream msg;
		msg << "yade-rbsm: ERROR: RbsmTimeStepper: body #" << b.id << " moves by " << motion << " m in one step at step " << scene->iter
		    << " (velocity " << s.vel.head<2>().norm() << " m/s, angular velocity " << s.angVel.z() << " rad/s, O.dt = " << scene->dt
		    << " s), more than maxStepMotion = " << maxStepMotion << " of its inner radius " << r
		    << " m: it can pass through other blocks (tunnelling) or the scene is exploding";
		// a block without joints is not scaled: it falls at the median block's step (a 0.1 mm pebble)
		if (densityScaling && !(size_t(kRow * b.id) < rowBounds.size() && rowBounds[kRow * b.id] > 0))
			msg << " (densityScaling runs every block at the step of the median one, " << scaledDt
			    << " s, and this free block has no joint to scale it by yet: a smaller targetDt, or no such small free blocks)";
		msg << "; the run stops after step " << scene->iter
		    << (last ? "; further such errors are not shown" : "");
		return msg.str();
	});
}

// Both per-body checks of every step for one block (BlockMotionWatch; in action()'s pass over the bodies).
[[gnu::always_inline]] inline void RbsmTimeStepper::watchBody(const Body& b, Real& travelDt, bool& runCollider)
{
	const Polygon2D* poly = polygonOf(b);
	if (!poly || !ownedHere(*scene, b)) return;
	if (b.bound) motionWatch.keepBoundAhead(*scene, b, *poly, runCollider);
	Real motion, r;
	if (maxStepMotion > 0 && !fixedBlock(*b.state) && motionWatch.movesTooFar(*scene, b, *poly, maxStepMotion, travelDt, motion, r)) reportMotion(b, motion, r);
}

// Deformable blocks whose strain nobody integrates would be rigid blocks with soft joints: refused, not run.
void RbsmTimeStepper::requireStrainIntegrator()
{
	for (const auto& e : scene->engines)
		if (e && e->getClassName() == "BlockStrainIntegrator") return;
	for (const auto& b : scene->bodies->body)
		if (b && deformableState(b->state.get()))
			throw std::runtime_error("RbsmTimeStepper: body #" + std::to_string(b->id)
			                         + " is a deformable block (DeformableState) but O.engines has no BlockStrainIntegrator to integrate its strain: "
			                           "put one right before NewtonIntegrator (yade_rbsm.engines() does when a material is deformable, or engines(deformable=True)).");
}

Real RbsmTimeStepper::stableDt() const
{
	// the blocks below it are scaled up to it; without a jointed block (a pile dropped, scaledDt inf)
	// the unscaled step of the first contacts, as without scaling (inf left O.dt at YADE's 1e-8)
	if (densityScaling && massScaled && std::isfinite(scaledDt)) return scaledDt;
	return std::min(safetyFactor * criticalDt, firstContactSafety() * firstContactDt) / std::sqrt(1 + newtonDamping);
}

Real RbsmTimeStepper::limit()
{
	fullCheck();
	return stableDt();
}

// YADE's idiom for a step of one's own is O.dt = x, which stops YADE's time steppers: a step set
// between two steps that this engine set is the script's from then on, and is checked, not replaced
// (it was replaced silently: a user's smaller step for accuracy was lost at the next step).
void RbsmTimeStepper::takeScriptDt()
{
	if (!setDt) {
		dtSet = 0; // a later setDt = True starts afresh
		return;
	}
	if (!(dtSet > 0) || scene->dt == dtSet) return;
	setDt = false;
	std::cerr << "yade-rbsm: note: RbsmTimeStepper: O.dt = " << scene->dt << " s was set from outside the time stepper before step " << scene->iter
	          << " (it had set " << dtSet << " s): the step is the script's from now on, checked against the stable limit (setDt is now False; "
	          << "RbsmTimeStepper.setDt = True lets the stepper choose it again)\n";
	dtSet = 0;
}

long RbsmTimeStepper::jointEdits() { return RbsmPhys::edits.load(std::memory_order_relaxed); }

// One pass over the bodies at every step, on this thread (at 10⁵ blocks a pass streams every Body,
// State, Shape and Bound from memory: two passes cost 39 ns per contact-step, one 29 ns).
// - issue 15: a reshaped block gets the mass of its new shape, and a mass or inertia set by a
//   script, or a block fixed or released, is seen (ReshapedBlocks.hpp); a block whose state the
//   model cannot integrate refuses the step by id before NewtonIntegrator (BlockStateCheck.hpp), so the
//   scene stays as it was (integrated, a massless block's position became NaN), without the estimate
//   that follows, which would throw without naming the body: false then.
// - watchBody (unless watchLater): the collider trigger and the motion check, which read the velocities.
// - split: yade.mpy's Subdomain bodies are in the scene (the master of a split scene has them too).
bool RbsmTimeStepper::checkBlocks(bool watchLater, Real& travelDt, bool& runCollider, bool& split)
{
	std::string refusal; // of the first bad block
	long        bad = 0;
	reshapedIds.clear();
	for (const auto& b : scene->bodies->body) {
		if (!b) continue;
		const bool changed = followReshape(*b, *scene->bodies);
		if (!(b->state && blockStateSurelyFine(*b->state))) { // (the usual block, without a call)
			const std::string problem = blockStateProblem(*b);
			if (!problem.empty()) {
				if (bad++ == 0) refusal = "RbsmTimeStepper: body #" + std::to_string(b->id) + " " + problem;
				continue;
			}
			split = split || (b->flags & Body::FLAG_SUBDOMAIN); // (massless: never a usual block)
		}
		if (changed) reshapedIds.push_back(b->id);
		else if (!watchLater) watchBody(*b, travelDt, runCollider);
	}
	if (bad) {
		if (bad > 1) refusal += " (and " + std::to_string(bad - 1) + " other block" + (bad > 2 ? "s" : "") + ")";
		refuseStep(refusal + " at step " + std::to_string(scene->iter) + "; the step was refused before integration.", deferErrors, error);
		return false;
	}
	// a lighter block may need a shorter step now, its joints were made anew (their phys again,
	// without a new iterMadeReal) and its inner radius changed: a full estimate now (a mass set by
	// hand: 0.1 x mid-interval tore a bonded joint before the next estimate)
	if (!reshapedIds.empty()) lastCheck = -1;
	return true;
}

// A full estimate every interval steps and whenever what it read has changed; in between, the joints
// made (jointsMade moved from jointsSeen) are added to the bounds at this step.
void RbsmTimeStepper::updateBounds(long made)
{
	// (iter < lastCheck: O.iter was set back, e.g. a scene saved by a later run: estimate now)
	if (densityScaling != massScaled) lastCheck = -1, massScaled = densityScaling; // switched: estimate now
	if (densityScaling && targetDt != scaledTarget) lastCheck = -1;                 // a new target: estimate now
	if (const long edits = jointEdits(); edits != editsSeen) lastCheck = -1, editsSeen = edits; // a joint's kn, ks set: estimate now
	if (!densityScaling) massScale.clear();
	// once per engine object, at the first step with interactions (or after O.load: the stepper is in
	// every RBSM engine list, old saved scenes too); not again: the objects freed by one sort would
	// hand the next one its memory in reverse (malloc reuses freed blocks last-in first-out)
	if (orderInteractions && orderedAt < 0 && orderInteractionsInMemory(*scene) != 0) orderedAt = scene->iter;
	if (lastCheck < 0 || scene->iter < lastCheck || scene->iter - lastCheck >= interval) fullCheck();
	// a joint made since: its rows (and scales) grow by bounds, at this step; without the rows of a
	// full estimate (a scene saved by an older build), an estimate now
	else if (made != jointsSeen) densityScaling && !scalesHold(scene->bodies->body.size()) ? fullCheck() : addJointsMadeThisStep();
	jointsSeen = made;
}

// O.dt: the stable step (or less, for travelDt and maxDt) with setDt; otherwise the script's, refused
// above the stable one.
void RbsmTimeStepper::chooseStep(Real travelDt)
{
	const Real limit = stableDt();
	std::ostringstream msg;
	msg << "RbsmTimeStepper: ";
	if (std::isnan(limit) || limit <= 0) {
		msg << "the stable time step is " << limit << " s at step " << scene->iter << " (joints of body #" << criticalBody
		    << "): a joint is infinitely stiff or damped (Poisson's ratio at 0.5 in plane strain? dampingRatio?); the step was refused.";
		return refuseStep(msg.str(), deferErrors, error);
	}
	// The travel limit never takes the step below a tenth of the stable one: a block exploding
	// (thrown at km/s) is reported by the motion watch, not run in slow motion.
	stepDt = std::min({ limit, maxDt, std::max(travelDt, limit / 10) });
	if (setDt) {
		if (std::isfinite(stepDt)) scene->dt = dtSet = stepDt;
		return;
	}
	if (!(scene->dt > 0)) {
		msg << "O.dt = " << scene->dt << " s at step " << scene->iter << ": time would not advance; the step was refused. Set O.dt > 0 or RbsmTimeStepper.setDt=True.";
		return refuseStep(msg.str(), deferErrors, error);
	}
	// The estimate moves with the geometry by round-off from one step to the next: a step set to
	// the stable step must not be refused for that (the safety factor is the margin).
	if (scene->dt <= limit * (1 + 1e-6)) return;
	msg << "O.dt = " << scene->dt << " s exceeds the stable limit of the RBSM system at step " << scene->iter << " (" << safetyFactor
	    << " x critical step " << std::min(criticalDt, firstContactDt) << " s";
	if (newtonDamping > 0) msg << " / sqrt(1 + NewtonIntegrator.damping " << newtonDamping << ")";
	msg << " = " << limit << " s; "
	    << (criticalDt <= firstContactDt ? "the joints of body #" + std::to_string(criticalBody) : std::string("the first contact a block can form"))
	    << "); the step was refused before integration. Reduce O.dt or set RbsmTimeStepper.setDt=True.";
	refuseStep(msg.str(), deferErrors, error);
}

// Under yade.mpy (deferErrors) a refusal of the last step that no sync engine took is thrown first
// (DistributedRun.hpp). Joints made under density scaling slow their blocks (raiseMassScale): the motion
// watch then follows the estimate, as it does for reshaped blocks (their inner radius changes).
void RbsmTimeStepper::action()
{
	throwUnclaimedRefusal(error);
	stepDt = std::numeric_limits<Real>::infinity();
	takeScriptDt();
	// in every step: the one serial place of an RBSM step that sees a VTKRecorder added to O.engines
	// (first: also in a step that a bad block below ends early, since the recorder would still run)
	vtkRecorderGuard.check(*scene);
	const auto& bodies = scene->bodies->body;
	motionWatch.grow(bodies.size());
	const long made        = Ip2_RbsmMat_RbsmMat_RbsmPhys::jointsMade.load(std::memory_order_relaxed);
	const bool watchLater  = densityScaling && made != jointsSeen;
	Real       travelDt    = std::numeric_limits<Real>::infinity();
	bool       runCollider = false;
	bool       split       = scene->subdomain > 0;
	if (!checkBlocks(watchLater, travelDt, runCollider, split)) return;
	requireSyncEngine(split, deferErrors);
	if (split) requireSyncEachStep(scene->iter, splitSince, syncedAt);
	updateBounds(made);
	if (watchLater)
		for (const auto& b : bodies) {
			if (b) watchBody(*b, travelDt, runCollider);
		}
	else
		for (const Body::id_t id : reshapedIds) watchBody(*bodies[size_t(id)], travelDt, runCollider);
	if (runCollider) scene->doSort = true;
	if (densityScaling) densityScale.applyTo(*scene, massScale);
	chooseStep(travelDt);
}

} // namespace yade
