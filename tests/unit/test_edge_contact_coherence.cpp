// Temporal coherence of the edge contact (SearchMemory, ClipCertificate and followContact,
// ContactMemory.hpp): following a contact from step to step with the memory must give EXACTLY
// (bitwise) what a full separating-axis search with the same hint gives, while skipping most
// searches. Compared along trajectories of two blocks that stay in contact: pairs of rectangles
// sharing an edge (the brick wall of the benchmark), a rectangle rocking on another, a brick sliding
// past a corner, a 12-gon rolling on a brick, a sharp corner sinking obliquely, and random convex
// polygons, with small and large steps of relative rotation and translation.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/ContactMemory.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <random>

using namespace rbsm;

namespace {
// A block: vertices and edge normals in its own frame (centroid at the origin), and its pose.
struct Block {
	std::vector<Vec2> local, localNormals;
	Real              radius = 0;
	Vec2              pos    = Vec2::Zero();
	Real              angle  = 0;
	explicit Block(std::vector<Vec2> v)
	{
		const Vec2 c = massProperties(v).centroid;
		for (auto& p : v) p -= c, radius = std::max(radius, p.norm());
		local = v;
		for (size_t i = 0; i < v.size(); ++i) {
			const Vec2 e = v[(i + 1) % v.size()] - v[i];
			localNormals.push_back(Vec2(e.y(), -e.x()).normalized());
		}
		pos = c;
	}
	// the same world placement as the plugin's Ig2: rotate the stored vertices and normals
	void place(std::vector<Vec2>& v, std::vector<Vec2>& n) const
	{
		const Real c = std::cos(angle), s = std::sin(angle);
		v.resize(local.size());
		n.resize(local.size());
		for (size_t i = 0; i < local.size(); ++i) {
			v[i] = pos + Vec2(c * local[i].x() - s * local[i].y(), s * local[i].x() + c * local[i].y());
			n[i] = Vec2(c * localNormals[i].x() - s * localNormals[i].y(), s * localNormals[i].x() + c * localNormals[i].y());
		}
	}
	BlockPose pose() const { return BlockPose { Pose2(pos, std::cos(angle), std::sin(angle)), radius }; }
};

std::vector<Vec2> rect(Real x0, Real y0, Real w, Real h) { return { { x0, y0 }, { x0 + w, y0 }, { x0 + w, y0 + h }, { x0, y0 + h } }; }

void expectSame(const EdgeContact& a, const EdgeContact& b, int step)
{
	// bitwise: the skip must reproduce the full search's arithmetic, not approximate it
	EXPECT_EQ(a.touching, b.touching) << "step " << step;
	EXPECT_EQ(a.refBody, b.refBody) << "step " << step;
	EXPECT_EQ(a.refEdge, b.refEdge) << "step " << step;
	EXPECT_EQ(a.incEdge, b.incEdge) << "step " << step;
	EXPECT_EQ(a.separation, b.separation) << "step " << step;
	if (!a.touching || !b.touching) return;
	EXPECT_EQ(a.normal, b.normal) << "step " << step;
	EXPECT_EQ(a.p0, b.p0) << "step " << step;
	EXPECT_EQ(a.p1, b.p1) << "step " << step;
	EXPECT_EQ(a.d0, b.d0) << "step " << step;
	EXPECT_EQ(a.d1, b.d1) << "step " << step;
	EXPECT_EQ(a.length, b.length) << "step " << step;
}

// The relative pose a memory was taken at: rewritten by every full search (the pose moves), kept
// when the search is skipped.
bool samePose(const SearchMemory& a, const SearchMemory& b) { return a.rel.p == b.rel.p && a.rel.c == b.rel.c && a.rel.s == b.rel.s; }

// What a caller carries to the next step, as Ig2 does: the contact's edge as the hint, and the memory
// only while the blocks touch.
void carryOver(const EdgeContact& c, ContactHint& hint, bool& haveHint, SearchMemory& memory)
{
	hint     = ContactHint { c.refBody, c.refEdge };
	haveHint = c.touching;
	if (!c.touching) memory = SearchMemory {};
}

// Follows the pair for `steps` steps of random relative motion (translation up to dx, rotation up
// to da per step, with a pull back towards the start so that the blocks stay in touch). Returns the
// fraction of steps where the search was skipped.
double follow(Block A, Block B, int steps, Real dx, Real da, unsigned seed, Real maxSeparation = 0)
{
	std::mt19937_64                  rng(seed);
	std::uniform_real_distribution<> u(-1, 1);
	const Real     minSize = 2 * std::min(A.radius, B.radius), hysteresis = 1e-6;
	const Vec2     a0 = A.pos, b0 = B.pos;
	const Real     aa0 = A.angle, ba0 = B.angle;
	SearchMemory   memory;
	ContactHint    hint;
	bool           haveHint = false;
	int            skipped = 0, compared = 0;
	std::vector<Vec2> va, na, vb, nb;
	for (int step = 0; step < steps; ++step) {
		A.pos += Vec2(u(rng), u(rng)) * dx + 0.05 * (a0 - A.pos);
		B.pos += Vec2(u(rng), u(rng)) * dx + 0.05 * (b0 - B.pos);
		A.angle += u(rng) * da + 0.05 * (aa0 - A.angle);
		B.angle += u(rng) * da + 0.05 * (ba0 - B.angle);
		A.place(va, na);
		B.place(vb, nb);
		const PolygonView pa { va.data(), na.data(), int(va.size()) }, pb { vb.data(), nb.data(), int(vb.size()) };
		const BlockPose   qa = A.pose(), qb = B.pose();
		const SearchMemory before = memory;
		const ContactQuery q { maxSeparation, haveHint ? &hint : nullptr, hysteresis, minSize };
		Coherence          coherence { qa, qb, &memory };
		const EdgeContact  fast = edgeContact(pa, pb, q, &coherence);
		const EdgeContact  full = edgeContact(pa, pb, q);
		expectSame(fast, full, step);
		++compared;
		// the memory is rewritten by every full search (the pose moved), kept by a skip
		if (before.valid && samePose(memory, before)) ++skipped;
		carryOver(fast, hint, haveHint, memory);
	}
	const double fraction = double(skipped) / compared;
	std::printf("    searches skipped: %d of %d steps (%.1f %%)\n", skipped, compared, 100 * fraction);
	return fraction;
}

// The plugin's way (Ig2): the contact in A's frame, A's polygon as stored, B posed relative to it.
// At every step, edgeContact with the memory (its skip rule and clip certificates) and, where it
// decides the step, followContact must give bit for bit what the full search with the same hint
// gives; followContact must also leave the memory as edgeContact leaves it (no search: unchanged).
// Returns the fraction of steps followContact decided. slide, spin: B's anchor moves and turns by
// them at every step.
double followInFrameOfA(Block A, Block B, int steps, Real dx, Real da, unsigned seed, Real maxSeparation = 0, Vec2 slide = Vec2::Zero(), Real spin = 0)
{
	std::mt19937_64                  rng(seed);
	std::uniform_real_distribution<> u(-1, 1);
	const Real        minSize = 2 * std::min(A.radius, B.radius), hysteresis = 1e-6;
	const Vec2        a0 = A.pos;
	Vec2              b0 = B.pos;
	const Real        aa0 = A.angle;
	Real              ba0 = B.angle;
	SearchMemory      memory;
	ContactHint       hint;
	bool              haveHint = false;
	int               decided = 0;
	std::vector<Vec2> placed(2 * B.local.size());
	const PolygonView ownA { A.local.data(), A.localNormals.data(), int(A.local.size()) };
	for (int step = 0; step < steps; ++step) {
		b0 += slide;
		ba0 += spin;
		A.pos += Vec2(u(rng), u(rng)) * dx + 0.05 * (a0 - A.pos);
		B.pos += Vec2(u(rng), u(rng)) * dx + 0.05 * (b0 - B.pos);
		A.angle += u(rng) * da + 0.05 * (aa0 - A.angle);
		B.angle += u(rng) * da + 0.05 * (ba0 - B.angle);
		const Real ca = std::cos(A.angle), sa = std::sin(A.angle), cb = std::cos(B.angle), sb = std::sin(B.angle);
		const Vec2 d = B.pos - A.pos;
		const PosedPolygon posedB { PolygonView { B.local.data(), B.localNormals.data(), int(B.local.size()) },
			                    Pose2(Vec2(ca * d.x() + sa * d.y(), -sa * d.x() + ca * d.y()), ca * cb + sa * sb, ca * sb - sa * cb) };
		const BlockPose    qa { Pose2(), A.radius }, qb { posedB.pose, B.radius };
		SearchMemory       afterFull = memory;
		const PolygonView  placedB   = posedB.place(placed.data());
		const ContactQuery q { maxSeparation, haveHint ? &hint : nullptr, hysteresis, minSize };
		const EdgeContact  full = edgeContact(ownA, placedB, q);
		Coherence          withFull { qa, qb, &afterFull };
		expectSame(edgeContact(ownA, placedB, q, &withFull), full, step);
		// what the caller's contact held before (Ig2: the frozen contact it decided against) must not
		// leak into a decided step
		EdgeContact fast;
		fast.touching = true, fast.length = 1, fast.d0 = fast.d1 = 1, fast.incEdge = 7;
		if (haveHint && followContact(ownA, posedB, q, Coherence { qa, qb, &memory }, fast)) {
			expectSame(fast, full, step);
			EXPECT_TRUE(samePose(afterFull, memory))
			        << "step " << step << ": followContact decided a step where edgeContact searched";
			++decided;
		}
		memory = afterFull;
		carryOver(full, hint, haveHint, memory);
	}
	const double fraction = double(decided) / steps;
	std::printf("    steps decided by followContact: %d of %d (%.1f %%)\n", decided, steps, 100 * fraction);
	return fraction;
}
} // namespace

// Two bricks, one on the other, sharing half an edge (a staggered wall): the other brick's twin edge
// has the same separation as the reference, so it is a rival watched exactly. Overlap 1e-5 m (a joint
// under load) and micro-motions (5e-8 of the size per step, rotations 1e-7 rad) as in a settled wall:
// nearly every step skips the search.
TEST(EdgeContactCoherence, SharedEdgeMicroMotion)
{
	const double skipped = follow(Block(rect(0, 0, 0.2, 0.1)), Block(rect(0.1, 0.1 - 1e-5, 0.2, 0.1)), 2000, 1e-8, 1e-7, 1);
	EXPECT_GT(skipped, 0.9) << "the skip should be taken at nearly every step of a resting pair";
	// and followContact, from a few vertices of the upper brick, decides nearly every step (either
	// brick as body 1)
	EXPECT_GT(followInFrameOfA(Block(rect(0, 0, 0.2, 0.1)), Block(rect(0.1, 0.1 - 1e-5, 0.2, 0.1)), 2000, 1e-8, 1e-7, 1), 0.9);
	EXPECT_GT(followInFrameOfA(Block(rect(0.1, 0.1 - 1e-5, 0.2, 0.1)), Block(rect(0, 0, 0.2, 0.1)), 2000, 1e-8, 1e-7, 1), 0.9);
	// bricks side by side (a head joint), flush at both ends of the edge
	EXPECT_GT(followInFrameOfA(Block(rect(0, 0, 0.2, 0.1)), Block(rect(0.2 - 1e-5, 0, 0.2, 0.1)), 2000, 1e-8, 1e-7, 5), 0.9);
}

// Larger motions (1e-4 of the size, 1e-3 rad per step): the skip is taken less often, and whenever it
// is, the result still equals the full search.
TEST(EdgeContactCoherence, SharedEdgeLargerMotion)
{
	const double skipped = follow(Block(rect(0, 0, 0.2, 0.1)), Block(rect(0.1, 0.1 - 1e-5, 0.2, 0.1)), 2000, 2e-5, 1e-3, 2);
	EXPECT_GT(skipped, 0.05); // both paths compared
	EXPECT_LT(skipped, 0.95);
	// the certificates outgrown, renewed by searches: both paths compared
	const double decided = followInFrameOfA(Block(rect(0, 0, 0.2, 0.1)), Block(rect(0.1, 0.1 - 1e-5, 0.2, 0.1)), 2000, 2e-5, 1e-3, 2);
	EXPECT_GT(decided, 0.05);
	EXPECT_LT(decided, 0.95);
}

// A block rocking on another of the same width (a column): relative rotations of 0.01 rad per step
// make the reference switch between the two blocks' edges; the skip must never hide a switch.
TEST(EdgeContactCoherence, RockingBlock)
{
	const double skipped = follow(Block(rect(-0.3, -1, 0.6, 1)), Block(rect(-0.3, -1e-3, 0.6, 1.5)), 3000, 1e-4, 1e-2, 3);
	EXPECT_GT(skipped, 0.05); // both paths compared
	EXPECT_LT(skipped, 0.95);
	followInFrameOfA(Block(rect(-0.3, -1, 0.6, 1)), Block(rect(-0.3, -1e-3, 0.6, 1.5)), 3000, 1e-4, 1e-2, 3); // compared where decided
}

// A brick sliding along a block's top edge past its acute corner, and a block with an acute corner
// sliding along a brick: the facing edge's end crosses the side of the reference block, where the
// clip by that side (iii), certified quiet while the end was inside, starts to act; and the feet on
// the reference line cross the side of the incident block (iv). followContact must hand such steps
// over (certificates outgrown) rather than skip a clip that acts.
TEST(EdgeContactCoherence, SlidingPastAcuteCorner)
{
	const std::vector<Vec2> wedge { { -0.5, -0.5 }, { 0.3, -0.5 }, { 0.5, 0 }, { -0.5, 0 } }; // 68° corner at (0.5, 0)
	// the brick's end 0.05 m from the corner: it crosses long before the skip rule's own bound
	// (the next best edge's separation) forces a search
	const double decided1 = followInFrameOfA(Block(wedge), Block(rect(0.05, -1e-4, 0.4, 0.2)), 1500, 1e-7, 1e-6, 6, 0, Vec2(2e-4, 0));
	const double decided2 = followInFrameOfA(Block(rect(0.05, -1e-4, 0.4, 0.2)), Block(wedge), 1500, 1e-7, 1e-6, 7, 0, Vec2(-2e-4, 0));
	EXPECT_GT(decided1, 0.5);
	EXPECT_GT(decided2, 0.5);
}

// A regular 12-gon rolling on a brick (turning about its centre): the facing edge changes every
// 30°, each change announced by the facing dots' lead shrinking below the rotation since the search.
TEST(EdgeContactCoherence, RollingPolygon)
{
	std::vector<Vec2> gon;
	for (int i = 0; i < 12; ++i)
		gon.push_back(0.3 * Vec2(std::cos(M_PI * (2 * i + 1) / 12), std::sin(M_PI * (2 * i + 1) / 12) + std::cos(M_PI / 12)) - Vec2(0, 0.01));
	const double decided1 = followInFrameOfA(Block(rect(-2, -1, 4, 1)), Block(gon), 3000, 1e-7, 1e-7, 8, 0, Vec2::Zero(), 1e-3);
	const double decided2 = followInFrameOfA(Block(gon), Block(rect(-2, -1, 4, 1)), 3000, 1e-7, 1e-7, 9, 0, Vec2::Zero(), 1e-3);
	EXPECT_GT(decided1, 0.3);
	EXPECT_GT(decided2, 0.3);
}

// A block with a 30° corner sinking into a flat block, its facing edge tilted so that the sharp
// corner is the last to go in: where the corner is below the reference line, the line passes
// outside the block above it and the foot clip (iv) by the corner's other side cuts off the part
// of the facing edge near the corner. That clip is idle while the corner is above the line, by
// less and less as it sinks: a certificate may call it quiet only with the margin that the drift
// bound cannot eat up before the certificate is renewed (2 radii). Sinking straight down, the clip's
// value moves at 0.87 of the drift, so it can go from idle to active within one certificate; four
// start heights put the renewals at different distances from the crossing. A quiet margin of half a
// radius fails here; one radius or more passes (a translation moves the foot, not the side: the
// second radius is for rotations, which move both).
TEST(EdgeContactCoherence, AcuteCornerSinking)
{
	const Real c = 0.4 * std::cos(M_PI / 6), s = 0.4 * std::sin(M_PI / 6);
	const std::vector<Vec2> leaning { { 0, 0 }, { 0.5, 0 }, { 0.5 + c, s }, { c, s } }; // 30° at (0, 0)
	double                  decided = 0;
	for (int k = 0; k < 4; ++k) {
		// tilted by 0.06 rad about its obtuse corner (0.5, 0), which starts 1.0-1.9 cm deep; the sharp
		// corner starts 2.0-1.1 cm above the line and, 3 cm lower, ends 1.0-1.9 cm below it
		const Real        tilt = -0.06, gap = 0.01 + 0.003 * k;
		std::vector<Vec2> b;
		for (const Vec2& v : leaning) {
			const Vec2 r = v - Vec2(0.5, 0);
			b.push_back(Vec2(0.5, -gap) + Vec2(std::cos(tilt) * r.x() - std::sin(tilt) * r.y(), std::sin(tilt) * r.x() + std::cos(tilt) * r.y()));
		}
		decided += followInFrameOfA(Block(rect(-1, -0.5, 2, 0.5)), Block(b), 3000, 1e-8, 1e-8, 20 + k, 0, Vec2(0, -1e-5)) / 4;
	}
	EXPECT_GT(decided, 0.5);
}

// Random convex polygons (3-8 vertices) overlapping slightly, followed with random motions; with an
// interaction distance too, so that contacts open within reach.
TEST(EdgeContactCoherence, RandomPolygons)
{
	std::mt19937_64                  rng(4);
	std::uniform_real_distribution<> u(0, 1);
	auto                             randomPolygon = [&](Real size) {
                std::vector<Vec2> pts;
                const int         n = 3 + int(u(rng) * 6);
                for (int i = 0; i < n; ++i) {
                        const Real a = 2 * M_PI * (i + 0.8 * u(rng)) / n;
                        pts.push_back(size * Vec2(std::cos(a), std::sin(a)) * (0.7 + 0.3 * u(rng)));
                }
                return pts; // CCW, convex (points on a star-shaped ring sorted by angle are not always convex: checked below)
	};
	int    tested       = 0;
	double decidedSteps = 0;
	for (int trial = 0; trial < 200 && tested < 60; ++trial) {
		auto pa = randomPolygon(1), pb = randomPolygon(0.3 + u(rng));
		if (!polygonProblem(pa).empty() || !polygonProblem(pb).empty()) continue;
		Block A(pa), B(pb);
		// put B just above A along a random direction, touching
		const Real ang = 2 * M_PI * u(rng);
		const Vec2 dir(std::cos(ang), std::sin(ang));
		B.pos = A.pos + dir * (A.radius + B.radius);
		std::vector<Vec2> va, na, vb, nb;
		for (int it = 0; it < 200; ++it) { // move B towards A until they touch
			A.place(va, na);
			B.place(vb, nb);
			if (edgeContact(va, vb, 0).touching) break;
			B.pos -= dir * 0.01 * B.radius;
		}
		follow(A, B, 300, 1e-4, 1e-3, 100 + trial, 1e-3);
		decidedSteps += followInFrameOfA(A, B, 300, 1e-4, 1e-3, 100 + trial, 1e-3) * 300;
		++tested;
	}
	EXPECT_GE(tested, 30);
	EXPECT_GT(decidedSteps, 1000) << "followContact should decide some of the random polygons' steps";
}
