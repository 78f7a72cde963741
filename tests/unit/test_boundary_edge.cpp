// Rigid boundaries as polygons (pkg/rbsm/kernel/BoundaryEdge.hpp): the rectangles are valid CCW
// polygons with the trace as their edge facing the block, and a triangle's trace in a plane.
#include <pkg/rbsm/kernel/BoundaryEdge.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/EdgeContact.hpp>

#include <gtest/gtest.h>

using namespace rbsm;

TEST(BoundaryEdge, RectangleIsCounterClockwiseWhateverTheEdgeOrder)
{
	for (int flip = 0; flip < 2; flip++) {
		const Vec2              a(0, 0), b(3, 1);
		const Vec2              m = Vec2(-1, 3).normalized(); // towards the block, ⟂ a→b
		const std::vector<Vec2> r = flip ? boundaryRectangle(b, a, m, 2) : boundaryRectangle(a, b, m, 2);
		EXPECT_EQ(polygonProblem(r), "");
		// the edge facing the block (outward normal m) is the trace a-b
		const auto n = edgeNormals(r);
		int        facing = 0;
		for (size_t i = 0; i < r.size(); i++)
			if ((n[i] - m).norm() < 1e-12) {
				facing++;
				EXPECT_NEAR(m.dot(r[i] - a), 0, 1e-12);
			}
		EXPECT_EQ(facing, 1);
	}
}

TEST(BoundaryEdge, BlockOnAWallRectangleTouchesAlongItsWholeBottom)
{
	// a 4 x 1 block resting 1 mm into a wall y = 0 (normal +y): the contact is the block's bottom
	const std::vector<Vec2> block { { 1, -0.001 }, { 5, -0.001 }, { 5, 0.999 }, { 1, 0.999 } };
	const auto              wall = wallRectangle(Vec2(-7, 0), Vec2(0, 1), Vec2(3, 0.499), std::sqrt(4.25));
	EXPECT_EQ(polygonProblem(wall), "");
	const EdgeContact c = edgeContact(block, wall, 0);
	ASSERT_TRUE(c.touching);
	EXPECT_NEAR(c.length, 4, 1e-12);
	EXPECT_NEAR(c.d0, 0.001, 1e-12);
	EXPECT_NEAR(c.d1, 0.001, 1e-12);
	EXPECT_NEAR(c.normal.y(), -1, 1e-12); // from the block (body 1) to the wall
}

TEST(BoundaryEdge, TriangleTraceInAPlane)
{
	const Eigen::Vector3d tri[3] = { { 0, 0, -1 }, { 2, 0, 1 }, { 0, 2, 1 } };
	Vec2                  a, b;
	ASSERT_TRUE(planeTrace(tri, 0, a, b));
	const Vec2 p(1, 0), q(0, 1);
	EXPECT_TRUE(((a - p).norm() < 1e-15 && (b - q).norm() < 1e-15) || ((a - q).norm() < 1e-15 && (b - p).norm() < 1e-15));
	EXPECT_FALSE(planeTrace(tri, 2, a, b)); // above it
	const Eigen::Vector3d flat[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
	EXPECT_FALSE(planeTrace(flat, 0, a, b)); // lying in it
	const Eigen::Vector3d edgeIn[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 1 } };
	ASSERT_TRUE(planeTrace(edgeIn, 0, a, b)); // an edge in the plane
	EXPECT_NEAR((a - b).norm(), 1, 1e-15);
}
