// Edge-to-edge contact: hand-computed configurations (penetration, segment, length) and
// invariances (A-B vs B-A, rigid motion, scale).
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <gtest/gtest.h>
#include <cmath>
#include <iostream>
#include <random>

using namespace rbsm;

namespace {
std::vector<Vec2> rect(Real x0, Real y0, Real w, Real h) { return { { x0, y0 }, { x0 + w, y0 }, { x0 + w, y0 + h }, { x0, y0 + h } }; }
std::vector<Vec2> scaled(std::vector<Vec2> v, Real s)
{
	for (auto& p : v) p *= s;
	return v;
}
// rigid motion x -> R(a) x + t
std::vector<Vec2> moved(const std::vector<Vec2>& v, const Vec2& t, Real a) { return toWorld(v, t, a); }
void expectVec(const Vec2& a, const Vec2& b, Real tol) { EXPECT_NEAR((a - b).norm(), 0, tol) << a.transpose() << " vs " << b.transpose(); }
// invariants every contact must satisfy
void expectConventions(const EdgeContact& c)
{
	ASSERT_TRUE(c.touching);
	EXPECT_NEAR(c.normal.norm(), 1, 1e-14);
	expectVec(c.tangent, Vec2(-c.normal.y(), c.normal.x()), 1e-15);
	EXPECT_GE((c.p1 - c.p0).dot(c.tangent), -1e-15);
	EXPECT_NEAR(c.length, (c.p1 - c.p0).norm(), 1e-15);
	EXPECT_NEAR((c.p1 - c.p0).dot(c.normal), 0, 1e-12 * (1 + c.length)); // segment is along t
}
} // namespace

// Unit square A, square B shifted by (0.2, 0.9): overlap 0.1 in y over x in [0.2, 1].
// Reference: A's top edge (y = 1, tie with B's bottom edge broken in favour of A).
TEST(EdgeContact, OverlappingSquares)
{
	const auto c = edgeContact(rect(0, 0, 1, 1), rect(0.2, 0.9, 1, 1), 0);
	expectConventions(c);
	EXPECT_EQ(c.refBody, 1);
	EXPECT_EQ(c.refEdge, 2);
	expectVec(c.normal, Vec2(0, 1), 1e-15);
	EXPECT_NEAR(c.length, 0.8, 1e-14);
	EXPECT_NEAR(c.d0, 0.1, 1e-14);
	EXPECT_NEAR(c.d1, 0.1, 1e-14);
	// t = (-1, 0): p0 is the right end, both on the reference line y = 1
	expectVec(c.p0, Vec2(1, 1), 1e-14);
	expectVec(c.p1, Vec2(0.2, 1), 1e-14);
	EXPECT_NEAR(c.separation, -0.1, 1e-14);
}

// (Clip points where d = 0 move by the documented 1e-12*size round-off slop: tolerance 1e-11.)
// Triangle tip (0.5, 0.9) into the top of the unit square. Reference: square top (y = 1).
// Incident: the triangle edge (-0.2,1.5)->(0.5,0.9), clipped to d >= 0: it crosses y = 1 at
// x = -0.2 + 0.7*5/6. Overlap is 0.1 at the tip and 0 at the crossing.
TEST(EdgeContact, TriangleVertexIntoSquare)
{
	const std::vector<Vec2> tri = { { 0.5, 0.9 }, { 1.0, 1.5 }, { -0.2, 1.5 } };
	ASSERT_EQ(polygonProblem(tri), "");
	const auto c = edgeContact(rect(0, 0, 1, 1), tri, 0);
	expectConventions(c);
	EXPECT_EQ(c.refBody, 1);
	expectVec(c.normal, Vec2(0, 1), 1e-15);
	const Real xc = -0.2 + 0.7 * 5.0 / 6.0;
	expectVec(c.p0, Vec2(0.5, 1), 1e-11);
	expectVec(c.p1, Vec2(xc, 1), 1e-11);
	EXPECT_NEAR(c.d0, 0.1, 1e-11);
	EXPECT_NEAR(c.d1, 0.0, 1e-11);
	EXPECT_NEAR(c.length, 0.5 - xc, 1e-11);
}

// Exactly shared edge: d0 = d1 = 0 and the length is the shared length.
TEST(EdgeContact, SharedEdgeFullAndPartial)
{
	auto c = edgeContact(rect(0, 0, 1, 1), rect(0, 1, 1, 1), 0);
	expectConventions(c);
	EXPECT_NEAR(c.length, 1, 1e-15);
	EXPECT_NEAR(c.d0, 0, 1e-15);
	EXPECT_NEAR(c.d1, 0, 1e-15);
	c = edgeContact(rect(0, 0, 1, 1), rect(0.3, 1, 1, 1), 0);
	expectConventions(c);
	EXPECT_NEAR(c.length, 0.7, 1e-15);
	EXPECT_NEAR(c.d0, 0, 1e-15);
	expectVec(c.normal, Vec2(0, 1), 1e-15);
}

// Shared edge after a random rigid motion of both: round-off must not make it "not touching",
// and the reference must not flip between steps (hysteresis, with or without a hint).
TEST(EdgeContact, SharedEdgeIsStableUnderRoundOff)
{
	std::mt19937 rng(42);
	std::uniform_real_distribution<Real> U(-1, 1);
	for (int trial = 0; trial < 50; ++trial) {
		const Vec2 t(100 * U(rng), 100 * U(rng));
		const Real a = M_PI * U(rng);
		const auto A = moved(rect(0, 0, 1, 1), t, a), B = moved(rect(0.25, 1, 2, 0.5), t, a);
		const auto c0 = edgeContact(A, B, 0);
		expectConventions(c0);
		EXPECT_NEAR(c0.length, 0.75, 1e-12);
		EXPECT_NEAR(c0.d0, 0, 1e-12);
		EXPECT_NEAR(c0.d1, 0, 1e-12);
		// tiny wobble of B (1e-9 rad about the edge midpoint), hint from the previous step
		ContactHint h { c0.refBody, c0.refEdge };
		for (int k = 0; k < 10; ++k) {
			const Real       w   = (k % 2 ? 1 : -1) * 1e-9;
			std::vector<Vec2> Bw = B;
			const Vec2       mid = localToWorld(Vec2(0.625, 1), t, a);
			for (auto& p : Bw) p = mid + rotate(p - mid, w);
			const auto c = edgeContact(A, Bw, 0, &h);
			ASSERT_TRUE(c.touching);
			EXPECT_EQ(c.refBody, c0.refBody);
			EXPECT_EQ(c.refEdge, c0.refEdge);
			h = { c.refBody, c.refEdge };
		}
	}
}

// A hint within tolerance is honoured (B's bottom edge, index 0); a clearly worse one is not.
TEST(EdgeContact, HintHysteresis)
{
	const auto A = rect(0, 0, 1, 1), B = rect(0.2, 0.9, 1, 1);
	ContactHint good { 2, 0 };
	auto c = edgeContact(A, B, 0, &good);
	expectConventions(c);
	EXPECT_EQ(c.refBody, 2);
	EXPECT_EQ(c.refEdge, 0);
	expectVec(c.normal, Vec2(0, 1), 1e-15); // still from A to B
	EXPECT_NEAR(c.p0.y(), 0.9, 1e-15);      // on B's bottom line
	EXPECT_NEAR(c.length, 0.8, 1e-14);
	EXPECT_NEAR(c.d0, 0.1, 1e-14);
	ContactHint bad { 1, 3 }; // A's left edge, separation -1.2
	c = edgeContact(A, B, 0, &bad);
	EXPECT_EQ(c.refBody, 1);
	EXPECT_EQ(c.refEdge, 2);
}

// Corner on corner: touching at a single point, zero length, zero overlap.
TEST(EdgeContact, CornerOnCorner)
{
	const auto c = edgeContact(rect(0, 0, 1, 1), rect(1, 1, 1, 1), 0);
	ASSERT_TRUE(c.touching);
	EXPECT_NEAR(c.length, 0, 1e-14);
	EXPECT_NEAR(c.d0, 0, 1e-14);
	expectVec(c.p0, Vec2(1, 1), 1e-14);
	// overlapping corners by 0.1 x 0.1: a 0.1-long contact with overlap 0.1
	const auto d = edgeContact(rect(0, 0, 1, 1), rect(0.9, 0.9, 1, 1), 0);
	expectConventions(d);
	EXPECT_NEAR(d.length, 0.1, 1e-14);
	EXPECT_NEAR(d.d0, 0.1, 1e-14);
	EXPECT_NEAR(d.d1, 0.1, 1e-14);
}

// Small gap g: no contact when g > maxSeparation; otherwise d0 = d1 = -g.
TEST(EdgeContact, SmallGap)
{
	const Real g = 1e-3;
	const auto A = rect(0, 0, 1, 1), B = rect(0, 1 + g, 1, 1);
	EXPECT_FALSE(edgeContact(A, B, 0).touching);
	EXPECT_FALSE(edgeContact(A, B, 0.5 * g).touching);
	const auto c = edgeContact(A, B, 2 * g);
	expectConventions(c);
	EXPECT_NEAR(c.d0, -g, 1e-15);
	EXPECT_NEAR(c.d1, -g, 1e-15);
	EXPECT_NEAR(c.length, 1, 1e-15);
	EXPECT_NEAR(c.separation, g, 1e-15);
	// far apart
	EXPECT_FALSE(edgeContact(A, rect(5, 5, 1, 1), 0.1).touching);
}

// Tilted block: only the part within maxSeparation counts. B's bottom edge goes from overlap
// 0.1 at x = 0 to a gap of 0.1 at x = 1 (linear); with maxSeparation = 0 the contact is x in [0, 0.5].
TEST(EdgeContact, TiltedEdgeClippedByGap)
{
	const std::vector<Vec2> B = { { 0, 0.9 }, { 1, 1.1 }, { 1, 2 }, { 0, 2 } };
	ASSERT_EQ(polygonProblem(B), "");
	const auto c = edgeContact(rect(-1, 0, 3, 1), B, 0);
	expectConventions(c);
	EXPECT_EQ(c.refBody, 1);
	EXPECT_NEAR(c.length, 0.5, 1e-11);
	// t = (-1,0): p0 at x = 0.5 (overlap 0), p1 at x = 0 (overlap 0.1)
	expectVec(c.p0, Vec2(0.5, 1), 1e-11);
	EXPECT_NEAR(c.d0, 0, 1e-11);
	EXPECT_NEAR(c.d1, 0.1, 1e-11);
}

// Swapping the bodies gives the same segment with the opposite normal (p0<->p1, d0<->d1),
// for configurations where the reference edge is unambiguous or shared.
TEST(EdgeContact, SwapSymmetry)
{
	const std::vector<Vec2> tri = { { 0.5, 0.9 }, { 1.0, 1.5 }, { -0.2, 1.5 } };
	const std::vector<std::pair<std::vector<Vec2>, std::vector<Vec2>>> cases = {
		{ rect(0, 0, 1, 1), tri }, { rect(0, 0, 1, 1), rect(0.3, 1, 1, 1) }, { rect(0, 0, 2, 1), rect(2, 0.5, 1, 1) }
	};
	for (const auto& ab : cases) {
		const auto c = edgeContact(ab.first, ab.second, 0), r = edgeContact(ab.second, ab.first, 0);
		expectConventions(c);
		expectConventions(r);
		expectVec(r.normal, -c.normal, 1e-15);
		expectVec(r.p0, c.p1, 1e-14);
		expectVec(r.p1, c.p0, 1e-14);
		EXPECT_NEAR(r.d0, c.d1, 1e-14);
		EXPECT_NEAR(r.d1, c.d0, 1e-14);
		EXPECT_NEAR(r.length, c.length, 1e-14);
	}
}

// A random rigid motion of both polygons moves the contact with them and changes nothing else.
TEST(EdgeContact, RigidMotionInvariance)
{
	const std::vector<Vec2> tri = { { 0.5, 0.9 }, { 1.0, 1.5 }, { -0.2, 1.5 } };
	const std::vector<std::pair<std::vector<Vec2>, std::vector<Vec2>>> cases = {
		{ rect(0, 0, 1, 1), rect(0.2, 0.9, 1, 1) }, { rect(0, 0, 1, 1), tri }, { rect(-1, 0, 3, 1), { { 0, 0.9 }, { 1, 1.1 }, { 1, 2 }, { 0, 2 } } }
	};
	std::mt19937 rng(7);
	std::uniform_real_distribution<Real> U(-1, 1);
	for (const auto& ab : cases) {
		const auto c = edgeContact(ab.first, ab.second, 0);
		for (int k = 0; k < 20; ++k) {
			const Vec2 t(1000 * U(rng), 1000 * U(rng));
			const Real a = M_PI * U(rng);
			const auto m = edgeContact(moved(ab.first, t, a), moved(ab.second, t, a), 0);
			expectConventions(m);
			EXPECT_EQ(m.refBody, c.refBody);
			EXPECT_EQ(m.refEdge, c.refEdge);
			expectVec(m.normal, rotate(c.normal, a), 1e-12);
			expectVec(m.p0, localToWorld(c.p0, t, a), 1e-9);
			expectVec(m.p1, localToWorld(c.p1, t, a), 1e-9);
			EXPECT_NEAR(m.d0, c.d0, 1e-10);
			EXPECT_NEAR(m.d1, c.d1, 1e-10);
			EXPECT_NEAR(m.length, c.length, 1e-10);
		}
	}
}

// Scaling all coordinates by L scales lengths and overlaps by L (1 mm ... 100 m).
TEST(EdgeContact, ScaleInvariance)
{
	const auto A = rect(0, 0, 1, 1), B = rect(0.2, 0.9, 1, 1);
	for (Real L : { 1e-3, 1e-1, 1.0, 10.0, 100.0 }) {
		const auto c = edgeContact(scaled(A, L), scaled(B, L), 0);
		expectConventions(c);
		EXPECT_NEAR(c.length / L, 0.8, 1e-13) << L;
		EXPECT_NEAR(c.d0 / L, 0.1, 1e-13) << L;
		EXPECT_NEAR(c.d1 / L, 0.1, 1e-13) << L;
		expectVec(c.p0 / L, Vec2(1, 1), 1e-13);
		EXPECT_FALSE(edgeContact(scaled(A, L), scaled(rect(0, 1.001, 1, 1), L), 0).touching) << L;
	}
}

// A 1 mm block pressed 10 um into a 100 m block, and the other way round.
TEST(EdgeContact, VeryDifferentSizes)
{
	// coordinates up to 100 m: round-off ~ 1e-14 m on the 1 mm length
	const auto big = rect(-50, -100, 100, 100), small = rect(0.3, -1e-5, 1e-3, 1e-3);
	auto c = edgeContact(big, small, 0);
	expectConventions(c);
	expectVec(c.normal, Vec2(0, 1), 1e-15);
	EXPECT_NEAR(c.length, 1e-3, 1e-13);
	EXPECT_NEAR(c.d0, 1e-5, 1e-13);
	EXPECT_NEAR(c.d1, 1e-5, 1e-15);
	c = edgeContact(small, big, 0);
	expectConventions(c);
	expectVec(c.normal, Vec2(0, -1), 1e-15);
	EXPECT_NEAR(c.length, 1e-3, 1e-13);
	EXPECT_NEAR(c.d0, 1e-5, 1e-15);
}

// Slender blocks (aspect 100) stacked with an offset: overlap 0.01 over x in [10, 100].
TEST(EdgeContact, SlenderBlocks)
{
	const auto c = edgeContact(rect(0, 0, 100, 1), rect(10, 0.99, 100, 1), 0);
	expectConventions(c);
	EXPECT_NEAR(c.length, 90, 1e-12);
	EXPECT_NEAR(c.d0, 0.01, 1e-12);
	EXPECT_NEAR(c.d1, 0.01, 1e-12);
	// standing slender block on its short edge
	const auto s = edgeContact(rect(0, 0, 100, 1), rect(50, 0.999, 1, 100), 0);
	expectConventions(s);
	EXPECT_NEAR(s.length, 1, 1e-12);
	EXPECT_NEAR(s.d0, 1e-3, 1e-12);
}

// Deep overlap (80 % of the block): still a finite, sensible answer.
TEST(EdgeContact, DeepOverlapIsFinite)
{
	const auto c = edgeContact(rect(0, 0, 1, 1), rect(0.1, 0.2, 0.8, 1), 0);
	expectConventions(c);
	EXPECT_TRUE(std::isfinite(c.d0) && std::isfinite(c.d1) && std::isfinite(c.length));
	EXPECT_NEAR(c.d0, 0.8, 1e-14);
	EXPECT_NEAR(c.length, 0.8, 1e-14);
	expectVec(c.normal, Vec2(0, 1), 1e-15);
}

namespace {
// Depth of q inside the convex CCW polygon P (> 0 inside): min over edges of -n_i.(q - P_i).
Real insideDepth(const std::vector<Vec2>& P, const Vec2& q)
{
	Real m = INFINITY;
	for (size_t i = 0; i < P.size(); ++i) {
		const Vec2 e = P[(i + 1) % P.size()] - P[i];
		m            = std::min(m, -Vec2(e.y(), -e.x()).normalized().dot(q - P[i]));
	}
	return m;
}
// Every overlap of the contact is a chord of the intersection: at both ends, the point p on the
// reference line and the incident point p + d * (into the reference body) lie in both polygons.
void expectChordsInBoth(const EdgeContact& c, const std::vector<Vec2>& A, const std::vector<Vec2>& B, Real tol)
{
	const Vec2 inward = c.refBody == 1 ? Vec2(-c.normal) : c.normal;
	for (const auto& [p, d] : { std::make_pair(c.p0, c.d0), std::make_pair(c.p1, c.d1) }) {
		if (d <= 0) continue;
		for (const Vec2& q : { p, Vec2(p + d * inward) }) {
			EXPECT_GE(insideDepth(A, q), -tol) << q.transpose();
			EXPECT_GE(insideDepth(B, q), -tol) << q.transpose();
		}
	}
}
} // namespace

// A sharp corner of B pokes through A's sloped shoulder next to A's short top edge (the mechanism
// of the fuzzer's cgal_depth violations, e.g. seed 1 pair 0). A = (0,0) (1,0) (1,0.6) (0.6,1) (0,1):
// top edge y = 1 for x in [0, 0.6], shoulder x + y = 1.6. B's corner v = (0.55, 0.95) with edges
// along (1.45, 0.25) (e0, facing down) and (1.45, 0.65) (e2, facing up-left). Both cross the
// shoulder at x > 0.6: e0 at X1 = v + (1/17)(1.45, 0.25), e2 at X2 = v + (1/21)(1.45, 0.65), so
// A n B is the triangle v X1 X2, whose extent along y is 0.65/21 = 0.031.
// Separating axes: A's top -0.05 (v), shoulder -0.1/sqrt2 = -0.0707, B's e0 -0.143: the top edge is
// the reference of the axis search. The kernel used to report the depth of v below the top line,
// 0.05 > 0.031: the top line passes outside B above v (B's corner leans away), so that is no overlap.
// Now: no chord of A n B ends on the top edge nor on B's e0, and the contact is on the edge that
// B crossed, the shoulder (normal (1,1)/sqrt2), from X2 to X1. Its overlap is the chord of the
// triangle along the normal: 0 at X1, and at X2 the distance to the point q of e0 whose foot on the
// shoulder is X2: q = v + (2/63)(1.45, 0.25) (q + d n = X2 in x, with d = (0.1 - 1.7 lambda)/sqrt2
// gives 0.6 lambda = 1.45/21 - 0.05), d = (0.1 - 1.7 * 2/63)/sqrt2 = 2.9/(63 sqrt2) = 0.03255.
// Length |X1 - X2| = sqrt2 * 1.45 (1/17 - 1/21) = sqrt2 * 5.8/357.
TEST(EdgeContact, SharpCornerThroughShoulderGivesTheChord)
{
	const std::vector<Vec2> A = { { 0, 0 }, { 1, 0 }, { 1, 0.6 }, { 0.6, 1 }, { 0, 1 } };
	const Vec2              v(0.55, 0.95);
	const std::vector<Vec2> B = { v, { 2.0, 1.2 }, { 2.0, 1.6 } };
	ASSERT_EQ(polygonProblem(A), "");
	ASSERT_EQ(polygonProblem(B), "");
	const Vec2 X1 = v + Vec2(1.45, 0.25) / 17, X2 = v + Vec2(1.45, 0.65) / 21;
	const Real dX2 = 2.9 / (63 * std::sqrt(2.0)), len = std::sqrt(2.0) * 5.8 / 357;
	for (int order = 0; order < 2; ++order) {
		const auto c = order == 0 ? edgeContact(A, B, 0) : edgeContact(B, A, 0);
		expectConventions(c);
		EXPECT_EQ(c.refBody, order == 0 ? 1 : 2);
		EXPECT_EQ(c.refEdge, 2); // the shoulder (1,0.6) -> (0.6,1)
		expectVec(c.normal, Vec2(1, 1).normalized() * (order == 0 ? 1 : -1), 1e-14);
		EXPECT_NEAR(c.separation, -0.1 / std::sqrt(2.0), 1e-14);
		EXPECT_NEAR(c.length, len, 1e-11);
		// d = dX2 at X2, 0 at X1 (t = (-1,1)/sqrt2 for A-B: p0 = X1; the opposite for B-A)
		const Vec2 pX1 = order == 0 ? c.p0 : c.p1, pX2 = order == 0 ? c.p1 : c.p0;
		const Real dX1 = order == 0 ? c.d0 : c.d1, dAtX2 = order == 0 ? c.d1 : c.d0;
		expectVec(pX1, X1, 1e-11);
		expectVec(pX2, X2, 1e-11);
		EXPECT_NEAR(dX1, 0, 1e-11);
		EXPECT_NEAR(dAtX2, dX2, 1e-11);
		EXPECT_LE(std::max(c.d0, c.d1), 0.1 / std::sqrt(2.0)); // within the triangle's extent along n
		expectChordsInBoth(c, A, B, 1e-11); // the clips allow the 1e-12 * size round-off slop
	}
}

// The fuzzer's seed-1 pair 0 itself (coordinates as printed by RBSM_FUZZ_VERBOSE=1): B's corner
// B[4] pierces A's thin tip. The axis search picks A's short edge 1; the kernel reported B[4]'s
// depth below that line, 0.0025263, more than the extent of A n B along its normal (0.0024644,
// CGAL). Every overlap reported must now be a chord of A n B (both ends in both polygons).
TEST(EdgeContact, FuzzSeed1Pair0OverlapIsAChord)
{
	const std::vector<Vec2> A = { { -2.3756776885897177, 0.78033980987356322 }, { -2.3723190884371057, 0.78059469790267677 },
		{ -2.3624161691668153, 0.78364456067969468 }, { -2.2980851655033203, 0.81374680537255828 }, { -2.2400857544651189, 0.8541485453878046 } };
	const std::vector<Vec2> B = { { -2.2895228859720103, 0.77951335075117445 }, { -2.3107472745591102, 0.78612902745370006 },
		{ -2.3175711416365004, 0.78823637569291982 }, { -2.3460283595431157, 0.78814748363517084 }, { -2.3673991854671677, 0.78475330731147386 },
		{ -2.3331451112432973, 0.77890974909371502 } };
	for (int order = 0; order < 2; ++order) {
		const auto c = order == 0 ? edgeContact(A, B, 0, nullptr, 1e-6) : edgeContact(B, A, 0, nullptr, 1e-6);
		expectConventions(c);
		EXPECT_GT(std::max(c.d0, c.d1), 0);
		EXPECT_LT(std::max(c.d0, c.d1), 0.0024644);
		expectChordsInBoth(c, order == 0 ? A : B, order == 0 ? B : A, 1e-12); // slop 1e-12 * 0.078
	}
}

// separatedBeyond (the early rejection of potential interactions) must never reject a pair that
// edgeContact finds touching, and must reject pairs that are apart by more than the slop: random
// rectangles and rotated regular polygons at random poses, from deep overlap to clearly apart,
// including exactly shared edges moved apart by tiny gaps.
TEST(EdgeContact, SeparatedBeyondAgreesWithTheFullSearch)
{
	std::mt19937                         rng(11);
	std::uniform_real_distribution<Real> u(0, 1);
	auto                                 regular = [](int n, Real r) {
                std::vector<Vec2> v;
                for (int k = 0; k < n; ++k) v.push_back(r * Vec2(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)));
                return v;
	};
	int rejected = 0, apart = 0;
	for (int trial = 0; trial < 20000; ++trial) {
		const std::vector<Vec2> a0 = trial % 2 ? rect(-0.5, -0.25, 1.0, 0.5) : regular(3 + trial % 5, 0.5);
		const std::vector<Vec2> b0 = trial % 3 ? rect(-0.3, -0.2, 0.6, 0.4) : regular(3 + trial % 7, 0.4);
		std::vector<Vec2>       A  = moved(a0, Vec2(u(rng), u(rng)), 2 * M_PI * u(rng));
		std::vector<Vec2>       B;
		if (trial % 4 == 0) { // B on top of a rectangle A, its bottom edge on A's top edge, lifted by a gap
			A = rect(0, 0, 1, 0.5);
			const Real gap = std::pow(10.0, -15 + 14 * u(rng)) * (u(rng) < 0.5 ? -1 : 1);
			B = rect(u(rng) - 0.5, 0.5 + gap, 0.6, 0.4);
		} else
			B = moved(b0, Vec2(2.5 * u(rng) - 0.75, 2.5 * u(rng) - 0.75), 2 * M_PI * u(rng));
		const std::vector<Vec2> nA = edgeNormals(A), nB = edgeNormals(B);
		const PolygonView       va { A.data(), nA.data(), int(A.size()) }, vb { B.data(), nB.data(), int(B.size()) };
		const Real              minSize = std::min(polygonSize(A), polygonSize(B)), maxSep = trial % 5 == 0 ? 1e-3 : 0.0;
		const bool              rej     = separatedBeyond(va, vb, maxSep, minSize);
		const EdgeContact       c       = edgeContact(va, vb, ContactQuery { maxSep, nullptr, 1e-6, minSize });
		if (rej) {
			++rejected;
			EXPECT_FALSE(c.touching) << "trial " << trial << " separation " << c.separation;
		}
		if (c.separation > maxSep + 2e-12 * minSize) {
			++apart;
			EXPECT_TRUE(rej) << "trial " << trial << ": apart by " << c.separation << " but not rejected";
		}
	}
	EXPECT_GT(rejected, 5000); // the test must exercise both outcomes
	EXPECT_LT(rejected, 15000);
	EXPECT_EQ(rejected, apart);
}

// separatedAlongCentres (the cheap first try of Ig2's rejection of a potential interaction: the edge of either
// block that faces the other's centroid, tested with the other block's vertices placed one by one) answers only
// "apart" and only where separatedBeyond on the placed polygons does too; it must catch most apart pairs, or
// it is work for nothing. Random convex shapes (rectangles, regular 3- to 9-gons, sizes 0.05-5) at random poses.
TEST(EdgeContact, SeparatedAlongCentresIsSeparatedBeyondWhereItAnswers)
{
	std::mt19937                         rng(7);
	std::uniform_real_distribution<Real> u(0, 1);
	auto                                 shape = [&](int trial, Real size) {
                std::vector<Vec2> v;
                if (trial % 3 == 0) return rect(-0.5 * size, -0.2 * size, size, 0.4 * size);
                const int n = 3 + trial % 7;
                for (int k = 0; k < n; ++k) v.push_back(0.5 * size * Vec2(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)));
                return v;
	};
	int apart = 0, caught = 0;
	for (int trial = 0; trial < 20000; ++trial) {
		const Real              sa = std::pow(10.0, 2 * u(rng) - 1.3), sb = std::pow(10.0, 2 * u(rng) - 1.3);
		const std::vector<Vec2> A = shape(trial, sa), Bl = shape(trial / 3, sb);
		const std::vector<Vec2> nA = edgeNormals(A), nB = edgeNormals(Bl);
		const Real              dist = (0.5 * (sa + sb)) * (0.3 + 1.2 * u(rng)), dir = 2 * M_PI * u(rng), turn = 2 * M_PI * u(rng);
		const PosedPolygon      B { PolygonView { Bl.data(), nB.data(), int(Bl.size()) },
                               Pose2(dist * Vec2(std::cos(dir), std::sin(dir)), std::cos(turn), std::sin(turn)) };
		std::vector<Vec2>       placed(2 * Bl.size());
		const PolygonView       va { A.data(), nA.data(), int(A.size()) }, vb = B.place(placed.data());
		const Real              minSize = std::min(sa, sb), maxSep = trial % 5 == 0 ? 1e-3 * minSize : 0.0;
		const bool              full = separatedBeyond(va, vb, maxSep, minSize), quick = separatedAlongCentres(va, B, maxSep, minSize);
		if (quick) EXPECT_TRUE(full) << "trial " << trial;
		apart += full, caught += quick;
	}
	EXPECT_GT(apart, 3000);
	EXPECT_GT(caught, 0.8 * apart) << caught << " of " << apart << " apart pairs caught";
	std::cout << "separatedAlongCentres: " << caught << " of " << apart << " apart pairs\n";
}
