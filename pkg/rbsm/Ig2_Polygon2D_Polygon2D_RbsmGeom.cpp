#include <pkg/rbsm/Ig2_Polygon2D_Polygon2D_RbsmGeom.hpp>
#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>
#include <pkg/rbsm/MixedMaterials.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <core/Scene.hpp>
#include <pkg/rbsm/kernel/ContactMemory.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/FrozenContact.hpp>

#include <algorithm>
#include <atomic>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((Ig2_Polygon2D_Polygon2D_RbsmGeom));

void Ig2_Polygon2D_Polygon2D_RbsmGeom::postLoad(Ig2_Polygon2D_Polygon2D_RbsmGeom&)
{
	rbsm_report::checkContactAttributes("Ig2_Polygon2D_Polygon2D_RbsmGeom", nIP, interactionDistance);
	if (!(std::isfinite(hysteresis) && hysteresis >= 0))
		throw std::invalid_argument("Ig2_Polygon2D_Polygon2D_RbsmGeom.hysteresis: must be a finite number >= 0 (got " + std::to_string(hysteresis) + ")");
	// The range the verification scenes were run in (tests/physics/test_update_tolerance.py); beyond it a
	// runout strays: 3e-3 +0.6 %, 1e-2 -5 % (and gains 2.6 % of gravity's work), 0.09 -30 %.
	if (!(std::isfinite(updateTolerance) && updateTolerance >= 0 && updateTolerance <= 1e-3))
		throw std::invalid_argument("Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance: must be a fraction of the block size in [0, 0.001], "
		                            "the range in which the verification answers hold (got "
		                            + std::to_string(updateTolerance) + "; 0 = exact geometry at every step; 0.01 moved a runout by -5 %)");
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


	// A deformable block as it is now: the element's field is affine, so its shape is the polygon of its
	// vertices moved by B(r)ε, convex as before; its normals are made anew in the caller's buffer.
	[[gnu::noinline]] rbsm::PolygonView strainedPolygon(const Polygon2D& shape, const Vector3r& strain, rbsm::Vec2* stack, std::vector<rbsm::Vec2>& heap)
	{
		const int   n   = int(shape.vertices.size());
		rbsm::Vec2* out = stack;
		if (n > kStackVertices) {
			heap.resize(2 * size_t(n));
			out = heap.data();
		}
		for (int i = 0; i < n; i++)
			out[i] = shape.vertices[size_t(i)] + rbsm::strainDisplacement(shape.vertices[size_t(i)], strain);
		for (int i = 0; i < n; i++) {
			const rbsm::Vec2 e = out[(i + 1) % n] - out[i];
			out[n + i]         = rbsm::Vec2(e.y(), -e.x()).normalized();
		}
		return rbsm::PolygonView { out, out + n, n };
	}
	inline rbsm::PolygonView shapeNow(const Polygon2D& shape, const State& state, rbsm::Vec2* stack, std::vector<rbsm::Vec2>& heap)
	{
		if (const DeformableState* ds = deformableState(&state)) return strainedPolygon(shape, ds->strain, stack, heap);
		return ownFramePolygon(shape, stack, heap);
	}

	std::atomic<int> periodicReports { 0 }, materialReports { 0 }; // (StepReport.hpp)

	// Overlaps deeper than this fraction of the smaller block are outside what the small-strain
	// joint springs represent: reported (a few times per run), like UDEC's "contact overlap too great".
	constexpr Real   deepOverlap = 0.05;
	// A wet joint is followed while it opens by this fraction of the smaller block's size: an opening crack keeps
	// its water through the onset of sliding (strength reduction's runaway criterion is 5 % of a block).
	constexpr Real   wetReach = 0.1;
	std::atomic<int> deepOverlapReports { 0 }, passThroughReports { 0 }, pinchReports { 0 };
	// After the first five reports an overlap is reported again when it is twice the deepest reported so
	// far (as a fraction of the smaller block): overlaps that keep growing do not go unnoticed.
	std::atomic<double> deepestReported { 0 };
	bool                deepestSoFar(double fraction, double factor)
	{
		double seen = deepestReported.load();
		while (fraction > factor * seen)
			if (deepestReported.compare_exchange_weak(seen, fraction)) return true;
		return false;
	}
	std::string overlapLine(const Interaction& I, Real overlap, double fraction, bool atSetUp, long iter, const char* tail)
	{
		std::ostringstream msg;
		msg << "yade-rbsm: WARNING: bodies #" << I.getId1() << " and #" << I.getId2() << " overlap by " << overlap << " m, "
		    << 100 * fraction << " % of the smaller block's diameter, at step " << iter
		    << (atSetUp ? " when their contact is made (blocks placed overlapping? check the input geometry)"
		                : " (impact too violent for the time step, or blocks too soft?)")
		    << tail;
		return msg.str();
	}
	void reportDeepOverlap(const Interaction& I, Real overlap, Real size, bool atSetUp, long iter)
	{
		const double fraction = double(overlap / size);
		if (deepOverlapReports.load() < 5) {
			deepestSoFar(fraction, 1);
			rbsm_report::limited(deepOverlapReports, [&](bool last) {
				return overlapLine(I, overlap, fraction, atSetUp, iter, last ? "; further overlap warnings only for twice the deepest before" : "");
			});
		} else if (deepestSoFar(fraction, 2))
			std::cerr << overlapLine(I, overlap, fraction, atSetUp, iter, "; twice the deepest overlap reported before: overlaps are growing") + "\n";
	}
}

// One block passing through the other: an impact (a thin wall hit) stops the run after this step, a pinched
// block is reported (a few times per run).
void Ig2_Polygon2D_Polygon2D_RbsmGeom::passThrough(const Interaction& I, Real depth, Real halfWidth, bool impact) const
{
	std::ostringstream problem;
	problem << "overlap by " << depth << " m, deeper than the thinner block's half-width along the contact normal " << halfWidth
	        << " m: " << (impact ? "one is passing through the other" : "the thinner one is pinched through")
	        << " (make the joints stiffer, RbsmMat.young or jointKn, the thin block thicker, or the impact slower)";
	if (impact) {
		rbsm_report::stopForPair(passThroughReports, *scene, "Ig2_Polygon2D_Polygon2D_RbsmGeom", I.getId1(), I.getId2(), problem.str().c_str());
		return;
	}
	rbsm_report::limited(pinchReports, [&](bool last) {
		return "yade-rbsm: WARNING: Ig2_Polygon2D_Polygon2D_RbsmGeom: bodies #" + std::to_string(I.getId1()) + " and #"
		        + std::to_string(I.getId2()) + " " + problem.str() + " at step " + std::to_string(scene->iter)
		        + (last ? "; further such warnings are not shown" : "");
	});
}

// The contact is computed in block 1's frame: its vertices and normals are used as stored, only
// block 2 is placed (rotation by θ2 − θ1, translation by R(−θ1)(x2 − x1): rel), and the result is
// turned back to the world frame (RbsmGeom::update). Half the transforms, and coordinates of the
// block's size (less round-off far from the origin).
struct Ig2_Polygon2D_Polygon2D_RbsmGeom::Pair {
	const Polygon2D&  A;
	const Polygon2D&  B;
	const rbsm::Pose2 rel;     ///< block 2 in block 1's frame
	const Real        minSize; ///< the smaller block's diameter (m)
};

// A block reshaped since this joint was made (Polygon2D.revision): the joint's edge numbers and
// search memory belong to the old shape. It is searched afresh on the new shape and gets new
// springs (Ip2 makes its phys again: a bonded joint becomes frictional); a joint that no longer
// touches is handed to the law as lost. RbsmTimeStepper scales the mass.
[[gnu::always_inline]] inline void Ig2_Polygon2D_Polygon2D_RbsmGeom::forgetOldShapes(Interaction& I, const Polygon2D& A, const Polygon2D& B)
{
	auto* old = static_cast<RbsmGeom*>(I.geom.get());
	if (old->shapeRevision1 != A.revision || old->shapeRevision2 != B.revision) {
		old->forgetShapes(A.revision, B.revision);
		I.phys.reset();
	}
}

// New contacts need touch or closeness. An existing joint is followed while it opens as far
// as its intact springs can hold tension (σt/kn, doubled as margin) so that the law, not the
// geometry, breaks it; a wet joint a tenth of the smaller block's size (wetReach), so that an opening crack keeps
// its water (Hoek & Bray's V). The same distance trims the facing edge to the part that touches.
[[gnu::always_inline]] inline Real Ig2_Polygon2D_Polygon2D_RbsmGeom::reach(const Interaction& I, bool existing, Real minSize) const
{
	Real maxSeparation = interactionDistance;
	if (existing) {
		// class index instead of dynamic_cast: this runs for every contact at every step
		const IPhys* ip = I.phys.get();
		const auto*  ph = (ip && ip->getClassIndex() == RbsmPhys::getClassIndexStatic()) ? static_cast<const RbsmPhys*>(ip) : nullptr;
		if (ph && ph->kn > 0 && ph->tensileStrength > 0 && ph->nIntact() > 0) maxSeparation += 2 * ph->tensileStrength / ph->kn;
		if (ph && ph->waterForce > 0) maxSeparation = std::max(maxSeparation, wetReach * minSize);
	}
	return maxSeparation;
}

// A welded joint (RbsmPhys.welded, two deformable blocks) is a cut of a continuum: its sides are the
// same material points for as long as it is welded, and its springs see their jump (rigid motion and
// strain), not the undeformed shapes, which overlap or part as the blocks strain (at 5 % plastic strain a
// clip of them turned the joints and a Tresca plate carried 12 × its strength).
[[gnu::always_inline]] inline bool weldedJoint(const Interaction& I, const RbsmGeom& g)
{
	if (g.strainSides != 3) return false; // (rigid joints: one field of the geometry, no phys read)
	const IPhys* ip = I.phys.get();
	return ip && ip->getClassIndex() == RbsmPhys::getClassIndexStatic() && static_cast<const RbsmPhys*>(ip)->welded;
}

// Frozen kinematics (updateTolerance > 0): a joint that has moved little since its last exact
// update is followed as material points, without search or clipping, as long as the exact
// contact would not trim it either: every overlap within reach, d ≥ −maxSeparation (with the
// kernel's round-off slop). A joint opening beyond gets the exact geometry. A welded joint is
// followed so from its first exact step after welding on, however far it moves. True with c if followed.
[[gnu::always_inline]] inline bool Ig2_Polygon2D_Polygon2D_RbsmGeom::followFrozen(const Pair& pair, const Interaction& I, const RbsmGeom& g, rbsm::EdgeContact& c) const
{
	if (g.frozen.get() && !g.lost && weldedJoint(I, g)) {
		c = rbsm::frozenContact(*g.frozen.get(), pair.rel);
		return true;
	}
	const rbsm::FrozenContact* frozen = updateTolerance > 0 && !g.lost ? g.frozen.get() : nullptr;
	if (!(frozen && rbsm::frozenDrift(*frozen, pair.rel, pair.A.circumradius, pair.B.circumradius) <= updateTolerance * pair.minSize))
		return false;
	c               = rbsm::frozenContact(*frozen, pair.rel);
	const Real slop = rbsm::roundOffSlop(pair.minSize), dMin = std::min(c.d0, c.d1);
	return dMin >= -slop || dMin >= -(reach(I, true, pair.minSize) + slop); // (reach ≥ 0: asked only for an opening joint)
}

// The exact contact (search and clip, rbsm::edgeContact, or rbsm::followContact where the joint's
// search memory certifies the step); a new contact gets its RbsmGeom (g) here.
[[gnu::always_inline]] inline Ig2_Polygon2D_Polygon2D_RbsmGeom::Outcome Ig2_Polygon2D_Polygon2D_RbsmGeom::exactContact(
        const Pair& pair, const State& state1, const State& state2, const shared_ptr<Interaction>& I, RbsmGeom*& g, rbsm::EdgeContact& c)
{
	const bool               existing = g != nullptr;
	rbsm::Vec2               ownA[2 * kStackVertices], ownB[2 * kStackVertices];
	std::vector<rbsm::Vec2>  heapA, heapB;
	// deformable blocks meet as they are, strained (their welded joints are followed frozen instead)
	const bool               strained = deformableState(&state1) || deformableState(&state2);
	const rbsm::PolygonView  va = strained ? shapeNow(pair.A, state1, ownA, heapA) : ownFramePolygon(pair.A, ownA, heapA);
	const rbsm::PosedPolygon pb { strained ? shapeNow(pair.B, state2, ownB, heapB) : ownFramePolygon(pair.B, ownB, heapB), pair.rel }; // block 2 in block 1's frame
	const Real               maxSeparation = reach(*I, existing, pair.minSize);
	rbsm::ContactHint        hint;
	if (g) hint = rbsm::ContactHint { g->refBody, g->refEdge };
	const rbsm::ContactQuery query { maxSeparation, g ? &hint : nullptr, hysteresis, pair.minSize };
	rbsm::Coherence          coherence { { rbsm::Pose2(), pair.A.circumradius }, { pair.rel, pair.B.circumradius }, g ? &g->searchMemory : nullptr };
	// A potential interaction (bounding boxes overlap) whose blocks are clearly apart: no search, and mostly
	// not even block 2 placed whole (the edges facing the centroids decide; else separatedBeyond, below).
	if (!g && !strained && rbsm::separatedAlongCentres(va, pb, maxSeparation, pair.minSize)) return Outcome::Apart;
	// A followed joint whose search memory certifies this step: from the few vertices it needs
	// (rbsm::followContact, bit for bit edgeContact's result; its certificate holds for rigid shapes only).
	// Otherwise block 2 is placed whole.
	if (!(g && !strained && rbsm::followContact(va, pb, query, coherence, c))) {
		rbsm::Vec2              stackB[2 * kStackVertices];
		std::vector<rbsm::Vec2> placedHeap;
		if (pb.local.n > kStackVertices) placedHeap.resize(2 * size_t(pb.local.n));
		const rbsm::PolygonView vb = pb.place(pb.local.n > kStackVertices ? placedHeap.data() : stackB);
		if (!g && rbsm::separatedBeyond(va, vb, maxSeparation, pair.minSize)) return Outcome::Apart;
		rbsm::SearchMemory newMemory; // a new contact's first search; kept in the geometry if it is made
		if (!g) coherence.memory = &newMemory;
		c = rbsm::edgeContact(va, vb, query, &coherence);
		if (!g) {
			if (!(c.touching && c.length > 0)) return Outcome::Apart; // no new contact
			g = newGeom(pair, state1, state2, *I, newMemory);
			if (!g) return Outcome::Apart;
		}
	}
	if (existing && !c.touching) {
		// The blocks of an existing joint no longer face each other within reach: YADE expects the
		// law, not the geometry, to end an interaction, so the joint is handed over as lost.
		g->markLost(c.separation);
		return Outcome::Lost;
	}
	const bool freeze = updateTolerance > 0 || weldedJoint(*I, *g);
	g->exactAt(c, pair.rel, freeze);
	g->onStrainedShapes = strained;
	if (strained && freeze) g->recordStrainsMade(state1, state2); // (a frozen step adds the strain since)
	return Outcome::Touching;
}

// The geometry of a new contact (null if the blocks' materials are refused).
RbsmGeom* Ig2_Polygon2D_Polygon2D_RbsmGeom::newGeom(const Pair& pair, const State& state1, const State& state2, Interaction& I, const rbsm::SearchMemory& memory)
{
	// blocks of another material would meet an IPhys dispatch without functor (an abort)
	if (!rbsm_mixed::materialsAccepted(materialReports, *scene, "Ig2_Polygon2D_Polygon2D_RbsmGeom", I, rbsm_mixed::Role::Block, rbsm_mixed::Role::Block))
		return nullptr;
	auto geom = shared_ptr<RbsmGeom>(new RbsmGeom);
	geom->setIntegrationPoints(nIP);
	geom->thickness      = std::min(pair.A.thickness, pair.B.thickness);
	geom->reducedMass    = RbsmGeom::reducedMassOf(state1, state2);
	geom->shapeRevision1 = pair.A.revision;
	geom->shapeRevision2 = pair.B.revision;
	geom->searchMemory   = memory;
	geom->strainSides    = (deformableState(&state1) ? 1 : 0) | (deformableState(&state2) ? 2 : 0);
	if (geom->strainSides) geom->recordStrainsMade(state1, state2);
	I.geom               = geom;
	return geom.get();
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
	if (rbsm_report::acrossPeriodicCell(periodicReports, *scene, "Ig2_Polygon2D_Polygon2D_RbsmGeom", *I, shift2)) return false;
	const Polygon2D& A = static_cast<const Polygon2D&>(*s1);
	const Polygon2D& B = static_cast<const Polygon2D&>(*s2);
	if (A.vertices.empty() || B.vertices.empty()) return false; // reported by Bo1_Polygon2D_Aabb

	const rbsm::Pose2 pose1 = planarPose(state1.pos, state1.ori);
	const Pair        pair { A, B, pose1.relative(planarPose(state2.pos, state2.ori)), 2 * std::min(A.circumradius, B.circumradius) };
	if (I->geom && !force) forgetOldShapes(*I, A, B);
	const bool        existing = I->geom && !force;
	RbsmGeom*         g        = existing ? static_cast<RbsmGeom*>(I->geom.get()) : nullptr;
	rbsm::EdgeContact c;
	if (g && followFrozen(pair, *I, *g, c)) g->frozenSteps++, g->onStrainedShapes = false;
	else {
		const Outcome o = exactContact(pair, state1, state2, I, g, c);
		if (o != Outcome::Touching) return o == Outcome::Lost; // a lost joint goes to the law
	}
	g->update(c, pose1, state1, state2);
	if (g->strainSides) g->addStrainMotion(state1, state2);
	const Real depth = std::max(c.d0, c.d1);
	// Deeper than the thinner block's half-width along the contact normal, the blocks have passed its middle:
	// the axis search then prefers the other side and the springs push one block through the other. (Never
	// below the inradius, the least half-width: a cheap filter.) An impact that closes a tenth of that
	// half-width per step is a block going through (stopped); a slow squeeze is a pinched block (reported).
	if (depth > std::min(A.inradius, B.inradius)) {
		const Real w = std::min(rbsm::halfWidthAlong(A.vertices, c.normal), rbsm::halfWidthAlong(B.vertices, pair.rel.unrotate(c.normal)));
		if (depth > w) passThrough(*I, depth, w, -g->relativeVelocity.dot(g->normal) * scene->dt > 0.1 * w);
	}
	if (depth > deepOverlap * pair.minSize) {
		// The input is to blame if the contact is made at the first step of the younger block.
		const auto& bodies  = scene->bodies->body;
		const long  born    = std::max(bodies[I->getId1()]->iterBorn, bodies[I->getId2()]->iterBorn);
		const bool  atSetUp = !existing && scene->iter <= std::max(born, 0L);
		reportDeepOverlap(*I, depth, pair.minSize, atSetUp, scene->iter);
	}
	return true;
}

} // namespace yade
