// Disk against a convex polygon (rbsm::diskPolygonContact): hand-computed closest features (edge,
// corner, inside), the contact point in the middle of the overlap, and invariance under a rigid
// motion and under relabelling the vertices.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/DiskContact.hpp>

#include <gtest/gtest.h>
#include <cmath>

using namespace rbsm;

namespace {
struct Poly {
	std::vector<Vec2> v, n;
	explicit Poly(std::vector<Vec2> vertices)
	        : v(std::move(vertices))
	        , n(edgeNormals(v))
	{
	}
	PolygonView view() const { return PolygonView { v.data(), n.data(), int(v.size()) }; }
};
Poly square() { return Poly({ { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } }); } // side 2, centred
void expectVec(const Vec2& a, const Vec2& b, Real tol) { EXPECT_NEAR((a - b).norm(), 0, tol) << a.transpose() << " vs " << b.transpose(); }
}

TEST(DiskContact, AboveAnEdgeTheNormalIsTheEdgeNormal)
{
	const Poly  P = square();
	DiskContact c = diskPolygonContact(P.view(), Vec2(0.3, 1.4), 0.5);
	EXPECT_NEAR(c.distance, 0.4, 1e-15);
	EXPECT_NEAR(c.overlap, 0.1, 1e-15);
	expectVec(c.normal, Vec2(0, 1), 1e-15);
	expectVec(c.closest, Vec2(0.3, 1), 1e-15);
	expectVec(c.point, Vec2(0.3, 0.95), 1e-15); // middle of the overlap [0.9, 1]
	EXPECT_EQ(c.edge, 2);
}

TEST(DiskContact, BeyondACornerTheNormalPointsFromTheCorner)
{
	const Poly  P = square();
	DiskContact c = diskPolygonContact(P.view(), Vec2(1.3, 1.4), 1.0);
	EXPECT_NEAR(c.distance, 0.5, 1e-15); // (0.3, 0.4) from the corner (1, 1)
	expectVec(c.normal, Vec2(0.6, 0.8), 1e-15);
	expectVec(c.closest, Vec2(1, 1), 1e-15);
	EXPECT_NEAR(c.overlap, 0.5, 1e-15);
}

TEST(DiskContact, CentreInsideTakesTheNearestEdgeLine)
{
	const Poly  P = square();
	DiskContact c = diskPolygonContact(P.view(), Vec2(0.2, -0.9), 0.25);
	EXPECT_NEAR(c.distance, -0.1, 1e-15);
	expectVec(c.normal, Vec2(0, -1), 1e-15);
	expectVec(c.closest, Vec2(0.2, -1), 1e-15);
	EXPECT_NEAR(c.overlap, 0.35, 1e-15);
	EXPECT_EQ(c.edge, 0);
}

TEST(DiskContact, CentreOnACornerStillHasAUnitNormal)
{
	const Poly  P = square();
	DiskContact c = diskPolygonContact(P.view(), Vec2(1, 1), 0.1);
	EXPECT_NEAR(c.normal.norm(), 1, 1e-15);
	EXPECT_NEAR(c.distance, 0, 1e-15);
	EXPECT_NEAR(c.overlap, 0.1, 1e-15);
}

TEST(DiskContact, ApartGivesANegativeOverlap)
{
	const Poly  P = square();
	DiskContact c = diskPolygonContact(P.view(), Vec2(-3, 0), 0.5);
	EXPECT_NEAR(c.overlap, -1.5, 1e-15);
	expectVec(c.normal, Vec2(-1, 0), 1e-15);
}

TEST(DiskContact, RigidMotionAndRelabellingMoveTheContactWithThePolygon)
{
	const Poly        P({ { -1.2, -0.7 }, { 1.5, -0.9 }, { 1.1, 0.8 }, { -0.2, 1.3 }, { -1.3, 0.4 } });
	const Vec2        T(123.4, -56.7);
	const Real        a = 0.77;
	const Poly        M(toWorld(P.v, T, a));
	std::vector<Vec2> shifted(P.v.begin() + 2, P.v.end());
	shifted.insert(shifted.end(), P.v.begin(), P.v.begin() + 2);
	const Poly S(shifted);
	for (Real x = -2.5; x <= 2.5; x += 0.25)
		for (Real y = -2.5; y <= 2.5; y += 0.25) {
			const Vec2        c(x, y);
			const DiskContact d0 = diskPolygonContact(P.view(), c, 0.3);
			const DiskContact dm = diskPolygonContact(M.view(), localToWorld(c, T, a), 0.3);
			const DiskContact ds = diskPolygonContact(S.view(), c, 0.3);
			EXPECT_NEAR(dm.overlap, d0.overlap, 1e-12);
			expectVec(dm.normal, rotate(d0.normal, a), 1e-12);
			expectVec(dm.point, localToWorld(d0.point, T, a), 1e-12);
			EXPECT_NEAR(ds.overlap, d0.overlap, 1e-15);
			expectVec(ds.normal, d0.normal, 1e-15);
			expectVec(ds.point, d0.point, 1e-15);
		}
}
