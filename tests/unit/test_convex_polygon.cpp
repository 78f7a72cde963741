// Polygon checks and mass properties, compared with closed forms.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace rbsm;

namespace {
std::vector<Vec2> rect(Real x0, Real y0, Real w, Real h) { return { { x0, y0 }, { x0 + w, y0 }, { x0 + w, y0 + h }, { x0, y0 + h } }; }
bool contains(const std::string& s, const std::string& sub) { return s.find(sub) != std::string::npos; }
} // namespace

// Unit square: A = 1, centroid (0.5, 0.5), J = (a^4)/6 = 1/6.
TEST(MassProperties, UnitSquare)
{
	const auto m = massProperties(rect(0, 0, 1, 1));
	EXPECT_NEAR(m.area, 1.0, 1e-14);
	EXPECT_NEAR(m.centroid.x(), 0.5, 1e-14);
	EXPECT_NEAR(m.centroid.y(), 0.5, 1e-14);
	EXPECT_NEAR(m.polarMoment, 1.0 / 6.0, 1e-14);
}

// Rectangle b x h far from the origin: A = bh, centroid at the centre, J = bh(b^2+h^2)/12.
TEST(MassProperties, RectangleFarFromOrigin)
{
	const Real b = 3, h = 0.5, x0 = 1e5, y0 = -2e5;
	const auto m = massProperties(rect(x0, y0, b, h));
	EXPECT_NEAR(m.area, b * h, 1e-9);
	EXPECT_NEAR(m.centroid.x(), x0 + b / 2, 1e-9);
	EXPECT_NEAR(m.centroid.y(), y0 + h / 2, 1e-9);
	EXPECT_NEAR(m.polarMoment, b * h * (b * b + h * h) / 12, 1e-9);
}

// Right triangle with legs a, b: A = ab/2, centroid (a/3, b/3),
// J about centroid = Ixx + Iyy = ab^3/36 + ba^3/36 = ab(a^2+b^2)/36.
TEST(MassProperties, RightTriangle)
{
	const Real a = 4, b = 3;
	const auto m = massProperties({ { 0, 0 }, { a, 0 }, { 0, b } });
	EXPECT_NEAR(m.area, a * b / 2, 1e-13);
	EXPECT_NEAR(m.centroid.x(), a / 3, 1e-13);
	EXPECT_NEAR(m.centroid.y(), b / 3, 1e-13);
	EXPECT_NEAR(m.polarMoment, a * b * (a * a + b * b) / 36, 1e-12);
}

// Equilateral triangle side s: A = sqrt(3)/4 s^2, J = sqrt(3)/48 s^4 (= A s^2 / 12).
TEST(MassProperties, EquilateralTriangleRotatedAndMoved)
{
	const Real s = 2;
	const std::vector<Vec2> loc = { { 0, 0 }, { s, 0 }, { s / 2, s * std::sqrt(3.0) / 2 } };
	const auto m = massProperties(toWorld(loc, Vec2(7, -3), 0.7));
	EXPECT_NEAR(m.area, std::sqrt(3.0) / 4 * s * s, 1e-13);
	EXPECT_NEAR(m.polarMoment, std::sqrt(3.0) / 48 * std::pow(s, 4), 1e-13);
	const Vec2 c = localToWorld(Vec2(s / 2, s * std::sqrt(3.0) / 6), Vec2(7, -3), 0.7);
	EXPECT_NEAR((m.centroid - c).norm(), 0, 1e-13);
}

TEST(Transform, RoundTripAndRotation)
{
	const Vec2 p(1, 0);
	EXPECT_NEAR((rotate(p, M_PI / 2) - Vec2(0, 1)).norm(), 0, 1e-15);
	const Vec2 w = localToWorld(Vec2(0.3, -2), Vec2(5, 6), 1.1);
	EXPECT_NEAR((worldToLocal(w, Vec2(5, 6), 1.1) - Vec2(0.3, -2)).norm(), 0, 1e-14);
}

TEST(PolygonProblem, ValidPolygonsAtAllScales)
{
	for (Real L : { 1e-3, 1.0, 100.0 }) {
		EXPECT_EQ(polygonProblem(rect(0, 0, L, L)), "") << L;
		EXPECT_EQ(polygonProblem(rect(0, 0, L, L / 100)), "") << L; // slender, aspect 100
	}
	EXPECT_EQ(polygonProblem({ { 0, 0 }, { 1, 0 }, { 0, 1 } }), "");
}

TEST(PolygonProblem, TooFewVertices)
{
	EXPECT_TRUE(contains(polygonProblem({ { 0, 0 }, { 1, 0 } }), "at least 3"));
	EXPECT_TRUE(contains(polygonProblem({}), "at least 3"));
}

TEST(PolygonProblem, NonFiniteNamesTheVertex)
{
	auto v = rect(0, 0, 1, 1);
	v[2].y() = std::numeric_limits<Real>::quiet_NaN();
	const auto s = polygonProblem(v);
	EXPECT_TRUE(contains(s, "non-finite")) << s;
	EXPECT_TRUE(contains(s, "vertex 2")) << s;
	v[2].y() = 1;
	v[1].x() = std::numeric_limits<Real>::infinity();
	EXPECT_TRUE(contains(polygonProblem(v), "vertex 1"));
}

TEST(PolygonProblem, RepeatedVertex)
{
	const auto s = polygonProblem({ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 1, 1 }, { 0, 1 } });
	EXPECT_TRUE(contains(s, "repeated")) << s;
	EXPECT_TRUE(contains(s, "vertex 3")) << s;
	// relative tolerance: 1e-12 apart on a 1 mm polygon is still "repeated"
	const auto t = polygonProblem({ { 0, 0 }, { 1e-3, 0 }, { 1e-3, 1e-3 }, { 1e-3 + 1e-15, 1e-3 }, { 0, 1e-3 } });
	EXPECT_TRUE(contains(t, "repeated")) << t;
}

TEST(PolygonProblem, CollinearConsecutive)
{
	const auto s = polygonProblem({ { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } });
	EXPECT_TRUE(contains(s, "collinear")) << s;
	EXPECT_TRUE(contains(s, "vertex 1")) << s;
}

TEST(PolygonProblem, Clockwise)
{
	const auto s = polygonProblem({ { 0, 0 }, { 0, 1 }, { 1, 1 }, { 1, 0 } });
	EXPECT_TRUE(contains(s, "clockwise")) << s;
}

TEST(PolygonProblem, NonConvexNamesReflexVertex)
{
	// arrow-head: vertex 2 is reflex
	const auto s = polygonProblem({ { 0, 0 }, { 2, 0 }, { 1, 0.5 }, { 2, 1 }, { 0, 1 } });
	EXPECT_TRUE(contains(s, "non-convex")) << s;
	EXPECT_TRUE(contains(s, "vertex 2")) << s;
}

TEST(PolygonProblem, SelfIntersecting)
{
	// bow-tie
	const auto s = polygonProblem({ { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } });
	EXPECT_TRUE(contains(s, "self-intersecting")) << s;
	// pentagram: every turn has the same sign, only the crossing test catches it
	std::vector<Vec2> star;
	for (int k = 0; k < 5; ++k) star.emplace_back(std::cos(4 * M_PI * k / 5), std::sin(4 * M_PI * k / 5));
	const auto t = polygonProblem(star);
	EXPECT_TRUE(contains(t, "self-intersecting")) << t;
}

// Outward normals of a CCW polygon: a unit square gives -y, +x, +y, -x (edges bottom, right, top,
// left); a right triangle's hypotenuse gives (1, 1)/sqrt 2.
TEST(EdgeNormals, SquareAndTriangle)
{
	const auto sq = edgeNormals({ { 0, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 } });
	ASSERT_EQ(sq.size(), 4u);
	EXPECT_EQ(sq[0], Vec2(0, -1));
	EXPECT_EQ(sq[1], Vec2(1, 0));
	EXPECT_EQ(sq[2], Vec2(0, 1));
	EXPECT_EQ(sq[3], Vec2(-1, 0));
	const auto tri = edgeNormals({ { 0, 0 }, { 1, 0 }, { 0, 1 } });
	EXPECT_NEAR(tri[1].x(), 1 / std::sqrt(2.0), 1e-15);
	EXPECT_NEAR(tri[1].y(), 1 / std::sqrt(2.0), 1e-15);
}

// Issue 15: a 1e9:1 sliver was called a "repeated vertex" (two of its corners are 1e-9 of its size
// apart); it is named a sliver, with its area and size.
TEST(PolygonProblem, SliverNamedSliver)
{
	const auto s = polygonProblem({ { 0, 0 }, { 1, 0 }, { 1, 1e-9 }, { 0, 1e-9 } });
	EXPECT_TRUE(contains(s, "sliver")) << s;
	EXPECT_FALSE(contains(s, "repeated")) << s;
}
