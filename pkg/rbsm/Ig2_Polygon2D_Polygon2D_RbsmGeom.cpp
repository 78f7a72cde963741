#include <pkg/rbsm/Ig2_Polygon2D_Polygon2D_RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>
#include <pkg/rbsm/MixedMaterials.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/FrozenContact.hpp>
#include <pkg/rbsm/kernel/KawaiSprings.hpp>
#include <pkg/rbsm/kernel/SegmentKinematics.hpp>

#include <algorithm>
#include <atomic>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RbsmGeom)(Ig2_Polygon2D_Polygon2D_RbsmGeom));

void Ig2_Polygon2D_Polygon2D_RbsmGeom::postLoad(Ig2_Polygon2D_Polygon2D_RbsmGeom&)
{
	if (nIP < 1 || nIP > 8) throw std::invalid_argument("Ig2_Polygon2D_Polygon2D_RbsmGeom.nIP: must be 1..8 (got " + std::to_string(nIP) + ")");
	if (!(std::isfinite(interactionDistance) && interactionDistance >= 0))
		throw std::invalid_argument(
		        "Ig2_Polygon2D_Polygon2D_RbsmGeom.interactionDistance: must be a finite distance >= 0 (got " + std::to_string(interactionDistance) + ")");
	if (!(std::isfinite(hysteresis) && hysteresis >= 0))
		throw std::invalid_argument("Ig2_Polygon2D_Polygon2D_RbsmGeom.hysteresis: must be a finite number >= 0 (got " + std::to_string(hysteresis) + ")");
	if (!(std::isfinite(updateTolerance) && updateTolerance >= 0 && updateTolerance < 0.1))
		throw std::invalid_argument(
		        "Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance: must be a finite fraction of the block size in [0, 0.1) (got "
		        + std::to_string(updateTolerance) + "; 0 = exact geometry at every step)");
}

namespace {
	// A block in its own frame: its vertices and outward edge normals as stored by Polygon2D (no
	// copy). A shape whose derived data were not made (built in C++ without postLoad) gets its normals
	// computed into the caller's buffer (the heap beyond kStackVertices vertices).
	constexpr int kStackVertices = 16;
	[[gnu::noinline]] rbsm::PolygonView normalsMade(const Polygon2D& shape, rbsm::Vec2* stack, std::vector<rbsm::Vec2>& heap)
	{
		const int   n   = int(shape.vertices.size());
		rbsm::Vec2* out = stack;
		if (n > kStackVertices) {
			heap.resize(2 * size_t(n));
			out = heap.data();
		}
		const std::vector<Vector2r> normals = rbsm::edgeNormals(shape.vertices);
		std::copy(shape.vertices.begin(), shape.vertices.end(), out);
		std::copy(normals.begin(), normals.end(), out + n);
		return rbsm::PolygonView { out, out + n, n };
	}
	inline rbsm::PolygonView ownFramePolygon(const Polygon2D& shape, rbsm::Vec2* stack, std::vector<rbsm::Vec2>& heap)
	{
		const auto &v = shape.vertices, &e = shape.edgeNormals;
		if (e.size() == v.size()) return rbsm::PolygonView { v.data(), e.data(), int(v.size()) };
		return normalsMade(shape, stack, heap);
	}


	// Periodic cells are not supported: reported (StepReport.hpp) and the run stopped at the end of
	// this step, so that no step runs with the contacts across the cell's boundary missing.
	std::atomic<int> periodicReports { 0 }, materialReports { 0 };
	void             reportPeriodic(const Interaction& I, Scene& scene)
	{
		rbsm_report::stopForPair(periodicReports, scene, "Ig2_Polygon2D_Polygon2D_RbsmGeom", I.getId1(), I.getId2(),
		                         "meet across the boundary of a periodic cell (O.periodic): periodic cells are not supported");
	}

	// Overlaps deeper than this fraction of the smaller block are outside what the small-strain
	// joint springs represent: reported (a few times per run), like UDEC's "contact overlap too great".
	constexpr Real   deepOverlap = 0.05;
	std::atomic<int> deepOverlapReports { 0 };
	void             reportDeepOverlap(const Interaction& I, Real overlap, Real size, bool atSetUp, long iter)
	{
		rbsm_report::limited(deepOverlapReports, [&](bool last) {
			std::ostringstream msg;
			msg << "yade-rbsm: WARNING: bodies #" << I.getId1() << " and #" << I.getId2() << " overlap by " << overlap << " m, "
			    << 100 * overlap / size << " % of the smaller block's diameter, at step " << iter
			    << (atSetUp ? " when their contact is made (blocks placed overlapping? check the input geometry)"
			                : " (impact too violent for the time step, or blocks too soft?)")
			    << (last ? "; further overlap warnings are not shown" : "");
			return msg.str();
		});
	}
}

bool Ig2_Polygon2D_Polygon2D_RbsmGeom::go(
        const shared_ptr<Shape>& s1,
        const shared_ptr<Shape>& s2,
        const State&             state1,
        const State&             state2,
        const Vector3r&          shift2,
        const bool&              force,
        const shared_ptr<Interaction>& I)
{
	if (shift2 != Vector3r::Zero()) { // a contact across a periodic cell's boundary
		reportPeriodic(*I, *scene);
		return false;
	}
	const Polygon2D& A = static_cast<const Polygon2D&>(*s1);
	const Polygon2D& B = static_cast<const Polygon2D&>(*s2);
	if (A.vertices.empty() || B.vertices.empty()) return false; // reported by Bo1_Polygon2D_Aabb

	// The contact is computed in block 1's frame: its vertices and normals are used as stored, only
	// block 2 is placed (rotation by θ2 − θ1, translation by R(−θ1)(x2 − x1)), and the result is
	// turned back to the world frame. Half the transforms, and coordinates of the block's size
	// (less round-off far from the origin).
	const rbsm::Pose2 pose1   = planarPose(state1.pos, state1.ori);
	const rbsm::Pose2 relPose = pose1.relative(planarPose(state2.pos, state2.ori)); // R(−θ1)(x2 − x1), θ2 − θ1
	// A block reshaped since this joint was made (Polygon2D.revision): the joint's edge numbers and
	// search memory belong to the old shape. It is searched afresh on the new shape and gets new
	// springs (Ip2 makes its phys again: a bonded joint becomes frictional); a joint that no longer
	// touches is handed to the law as lost. RbsmTimeStepper scales the mass.
	if (I->geom && !force) {
		auto* old = static_cast<RbsmGeom*>(I->geom.get());
		if (old->shapeRevision1 != A.revision || old->shapeRevision2 != B.revision) {
			old->forgetShapes(A.revision, B.revision);
			I->phys.reset();
		}
	}
	const bool               existing = I->geom && !force;
	RbsmGeom*                g        = existing ? static_cast<RbsmGeom*>(I->geom.get()) : nullptr;
	const Real               minSize  = 2 * std::min(A.circumradius, B.circumradius); // the smaller block's diameter
	rbsm::EdgeContact        c;

	// New contacts need touch or closeness. An existing joint is followed while it opens as far
	// as its intact springs can hold tension (σt/kn, doubled as margin) so that the law, not the
	// geometry, breaks it. The same distance trims the facing edge to the part that touches.
	auto reach = [&]() {
		Real maxSeparation = interactionDistance;
		if (existing) {
			// class index instead of dynamic_cast: this runs for every contact at every step
			const IPhys* ip = I->phys.get();
			const auto*  ph = (ip && ip->getClassIndex() == RbsmPhys::getClassIndexStatic()) ? static_cast<const RbsmPhys*>(ip) : nullptr;
			if (ph && ph->kn > 0 && ph->tensileStrength > 0 && ph->nIntact() > 0) maxSeparation += 2 * ph->tensileStrength / ph->kn;
		}
		return maxSeparation;
	};

	// Frozen kinematics (updateTolerance > 0): a joint that has moved little since its last exact
	// update is followed as material points, without search or clipping, as long as the exact
	// contact would not trim it either: every overlap within reach, d ≥ −maxSeparation (with the
	// kernel's round-off slop). A joint opening beyond gets the exact geometry.
	bool frozen = false;
	if (g && updateTolerance > 0 && g->frozen.valid && !g->lost
	    && rbsm::frozenDrift(g->frozen, relPose, A.circumradius, B.circumradius) <= updateTolerance * minSize) {
		c               = rbsm::frozenContact(g->frozen, relPose);
		const Real slop = rbsm::roundOffSlop(minSize), dMin = std::min(c.d0, c.d1);
		frozen          = dMin >= -slop || dMin >= -(reach() + slop); // (reach() ≥ 0: asked only for an opening joint)
	}
	if (!frozen) {
		rbsm::Vec2              ownA[2 * kStackVertices], ownB[2 * kStackVertices];
		std::vector<rbsm::Vec2> heapA, heapB;
		const rbsm::PolygonView  va = ownFramePolygon(A, ownA, heapA);
		const rbsm::PosedPolygon pb { ownFramePolygon(B, ownB, heapB), relPose }; // block 2 in block 1's frame

		const Real            maxSeparation = reach();
		const rbsm::BlockPose poseA { rbsm::Pose2(), A.circumradius }; // block 1's frame
		const rbsm::BlockPose poseB { relPose, B.circumradius };
		rbsm::ContactHint     hint;
		if (g) hint = rbsm::ContactHint { g->refBody, g->refEdge };
		// A followed joint whose search memory certifies this step: from the few vertices it needs
		// (rbsm::followContact, bit for bit edgeContact's result). Otherwise block 2 is placed whole.
		if (!(g && rbsm::followContact(va, pb, maxSeparation, hint, hysteresis, minSize, poseA, poseB, g->searchMemory, c))) {
			rbsm::Vec2              stackB[2 * kStackVertices];
			std::vector<rbsm::Vec2> placedHeap;
			if (pb.local.n > kStackVertices) placedHeap.resize(2 * size_t(pb.local.n));
			const rbsm::PolygonView vb = pb.place(pb.local.n > kStackVertices ? placedHeap.data() : stackB);
			// a potential interaction (bounding boxes overlap) whose blocks are clearly apart: no search
			if (!g && rbsm::separatedBeyond(va, vb, maxSeparation, minSize)) return false;
			rbsm::SearchMemory  newMemory; // a new contact's first search; kept in the geometry if it is made
			rbsm::SearchMemory& memory = g ? g->searchMemory : newMemory;
			c                          = rbsm::edgeContact(va, vb, maxSeparation, g ? &hint : nullptr, hysteresis, minSize, &poseA, &poseB, &memory);
			if (!g) {
				if (!(c.touching && c.length > 0)) return false; // no new contact
				// blocks of another material would meet an IPhys dispatch without functor (an abort)
				if (!rbsm_mixed::materialsAccepted(materialReports, *scene, "Ig2_Polygon2D_Polygon2D_RbsmGeom", *I, rbsm_mixed::Role::Block,
				                                   rbsm_mixed::Role::Block))
					return false;
				auto geom = shared_ptr<RbsmGeom>(new RbsmGeom);
				geom->setIntegrationPoints(nIP);
				geom->thickness    = std::min(A.thickness, B.thickness);
				geom->reducedMass  = RbsmGeom::reducedMassOf(state1, state2);
				geom->shapeRevision1 = A.revision;
				geom->shapeRevision2 = B.revision;
				geom->searchMemory = newMemory;
				I->geom            = geom;
				g                  = geom.get();
			}
		}
		if (existing && !c.touching) {
			// The blocks of an existing joint no longer face each other within reach: YADE expects the
			// law, not the geometry, to end an interaction, so the joint is handed over as lost.
			g->lost         = true;
			g->separation   = c.separation;
			g->frozen.valid = false;
			return true;
		}
		if (updateTolerance > 0) g->frozen = rbsm::freezeContact(c, relPose);
		else g->frozen.valid = false;
		g->frozenSteps = 0;
	} else
		g->frozenSteps++;
	g->lost = false;
	// back to the world frame: x ↦ x1 + R(θ1) x for points, R(θ1) for directions
	c.normal = pose1.rotate(c.normal);
	c.p0     = pose1.apply(c.p0);
	c.p1     = pose1.apply(c.p1);

	g->normal     = c.normal;
	g->p0         = c.p0;
	g->p1         = c.p1;
	g->length     = c.length;
	g->separation = c.separation;
	g->refBody    = c.refBody;
	g->refEdge    = c.refEdge;
	if (c.incEdge >= 0) g->incEdge = c.incEdge; // (a frozen step keeps the last exact one)
	g->centroid1  = state1.pos.head<2>();
	g->centroid2  = state2.pos.head<2>();
	g->h1         = rbsm::distanceToLine(g->centroid1, c.p0, c.normal);
	g->h2         = rbsm::distanceToLine(g->centroid2, c.p0, c.normal);

	if (std::max(c.d0, c.d1) > deepOverlap * minSize) {
		// The input is to blame if the contact is made at the first step of the younger block.
		const auto& bodies  = scene->bodies->body;
		const long  born    = std::max(bodies[I->getId1()]->iterBorn, bodies[I->getId2()]->iterBorn);
		const bool  atSetUp = !existing && scene->iter <= std::max(born, 0L);
		reportDeepOverlap(*I, std::max(c.d0, c.d1), minSize, atSetUp, scene->iter);
	}

	// The relative motion along the segment, which the law samples at its points (SegmentKinematics):
	// block 2's velocity relative to block 1's at p0, v2 + ω2 × (p0 − c2) − v1 − ω1 × (p0 − c1).
	const rbsm::SegmentKinematics k = rbsm::segmentKinematics(
	        c.d0, c.d1, c.p0, c.p1, g->centroid1, state1.vel.head<2>(), state1.angVel.z(), g->centroid2, state2.vel.head<2>(), state2.angVel.z());
	g->d0                      = k.d0;
	g->d1                      = k.d1;
	g->relativeVelocity        = k.v0;
	g->relativeAngularVelocity = state2.angVel.z() - state1.angVel.z();
	return true;
}

// ---- RbsmGeom: the rule after a load, and Python's per-point lists ----

void RbsmGeom::postLoad(RbsmGeom&)
{
	frozen = rbsm::unpackFrozen(frozenState);
	if (nIP > 0) setIntegrationPoints(nIP); // throws for a file with nIP outside 1..8
	else rule = nullptr;
}

Vector2r RbsmGeom::point(int k) const
{
	if (k < 0 || k >= nPoints()) throw std::out_of_range("RbsmGeom.point: index " + std::to_string(k) + " outside 0.." + std::to_string(nPoints() - 1));
	return p0 + rule->s[k] * (p1 - p0);
}

namespace {
	template <class F> std::vector<Real> perPoint(const RbsmGeom& g, F f)
	{
		std::vector<Real> v(g.nPoints());
		for (int k = 0; k < g.nPoints(); k++)
			v[k] = f(k, g.rule->s[k]);
		return v;
	}
}

std::vector<Real> RbsmGeom::pyPositions() const { return perPoint(*this, [](int, Real s) { return s; }); }
std::vector<Real> RbsmGeom::pyWeights() const { return perPoint(*this, [this](int k, Real) { return rule->w[k]; }); }
std::vector<Real> RbsmGeom::pyDeltaN() const { return perPoint(*this, [k = kinematics()](int, Real s) { return k.overlap(s); }); }
std::vector<Real> RbsmGeom::pyNormalVelocity() const
{
	return perPoint(*this, [k = kinematics(), this](int, Real s) { return -k.velocity(s).dot(normal); });
}
std::vector<Real> RbsmGeom::pyShearVelocity() const
{
	return perPoint(*this, [k = kinematics(), this](int, Real s) { return k.velocity(s).dot(tangent()); });
}
std::vector<Real> RbsmGeom::pyShearIncrement() const
{
	const Real dt = Omega::instance().getScene()->dt;
	return perPoint(*this, [k = kinematics(), dt, this](int, Real s) { return k.velocity(s).dot(tangent()) * dt; });
}

} // namespace yade
