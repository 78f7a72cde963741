// Still water on a polygon (pkg/rbsm/kernel/Hydrostatic.hpp): Archimedes under a level water table (the force
// is γw·(submerged area) upwards, through the submerged part's centroid), nothing above it, a fully submerged
// block the same at any depth, and the polyline water table's head followed across its vertices.
#include <pkg/rbsm/kernel/Hydrostatic.hpp>

#include <cmath>
#include <gtest/gtest.h>

using rbsm::hydrostaticLoad;
using rbsm::Real;
using rbsm::Vec2;

namespace {
const Real g = 9810;
std::vector<Vec2> level(Real y) { return { Vec2(-100, y), Vec2(100, y) }; }
std::vector<Vec2> rotatedRectangle(Real w, Real h, Real angle, const Vec2& c)
{
	std::vector<Vec2> out;
	const Real cs = std::cos(angle), sn = std::sin(angle);
	for (const Vec2& p : { Vec2(-w / 2, -h / 2), Vec2(w / 2, -h / 2), Vec2(w / 2, h / 2), Vec2(-w / 2, h / 2) })
		out.push_back(c + Vec2(cs * p.x() - sn * p.y(), sn * p.x() + cs * p.y()));
	return out;
}
}

TEST(Hydrostatic, HalfSubmergedTiltedBlockIsArchimedes)
{
	// a 2 x 1 block tilted 35°, the water level through its centroid: half its area under water, by symmetry
	const Vec2 c(3, 2);
	const auto poly = rotatedRectangle(2, 1, 35 * M_PI / 180, c);
	const auto load = hydrostaticLoad(poly, level(c.y()), g, c);
	EXPECT_NEAR(load.force.x(), 0, 1e-9 * g);
	EXPECT_NEAR(load.force.y(), g * 1.0, 1e-9 * g); // γw · (2 · 1 / 2)
}

TEST(Hydrostatic, BuoyancyActsThroughTheSubmergedCentroid)
{
	// a 2 x 1 block level, water at 0.3 m above its base: submerged rectangle 2 x 0.3, centroid (cx, base + 0.15)
	const Vec2 c(0, 0);
	const auto poly = rotatedRectangle(2, 1, 0, c);
	const auto load = hydrostaticLoad(poly, level(-0.2), g, Vec2(0.7, -0.35));
	EXPECT_NEAR(load.force.y(), g * 2 * 0.3, 1e-9 * g);
	// about a point at the submerged centroid's height and 0.7 m right of it: the upward force's arm is −0.7
	EXPECT_NEAR(load.moment, -0.7 * g * 0.6, 1e-9 * g);
	// tilted: the line of action passes through the submerged part's centroid
	const auto tilted = rotatedRectangle(2, 1, 0.4, c);
	const auto l1 = hydrostaticLoad(tilted, level(0.1), g, Vec2(0, 0));
	const Real x = l1.moment / l1.force.y(); // the line of action's x (moment = x F_y - y F_x, F_x = 0)
	// the submerged part's centroid x, by a fine strip integration of the polygon below y = 0.1
	Real A = 0, Ax = 0;
	const int N = 20000;
	for (int i = 0; i < N; ++i) {
		const Real xs = -1.2 + (i + 0.5) * 2.4 / N;
		// the rotated rectangle's vertical extent at xs, clipped at the water
		Real lo = 1e9, hi = -1e9;
		for (int k = 0; k < 4; ++k) {
			const Vec2 &a = tilted[k], &b = tilted[(k + 1) % 4];
			if ((a.x() - xs) * (b.x() - xs) <= 0 && a.x() != b.x()) {
				const Real y = a.y() + (b.y() - a.y()) * (xs - a.x()) / (b.x() - a.x());
				lo = std::min(lo, y), hi = std::max(hi, y);
			}
		}
		if (hi > lo) {
			const Real h = std::max<Real>(0, std::min(hi, 0.1) - lo);
			A += h * 2.4 / N, Ax += h * xs * 2.4 / N;
		}
	}
	EXPECT_NEAR(l1.force.y(), g * A, 1e-5 * g);
	EXPECT_NEAR(x, Ax / A, 1e-4);
}

TEST(Hydrostatic, DryAboveAndTheSameAtAnyDepth)
{
	const auto poly = rotatedRectangle(1.5, 0.5, 1.0, Vec2(0, 0));
	const auto dry  = hydrostaticLoad(poly, level(-1), g, Vec2(0, 0));
	EXPECT_EQ(dry.force, Vec2::Zero());
	EXPECT_EQ(dry.moment, 0);
	const auto shallow = hydrostaticLoad(poly, level(2), g, Vec2(0, 0));
	const auto deep    = hydrostaticLoad(poly, level(200), g, Vec2(0, 0));
	EXPECT_NEAR(shallow.force.y(), g * 0.75, 1e-9 * g);
	EXPECT_NEAR(deep.force.y(), g * 0.75, 1e-7 * g); // (round-off of 200 m of head)
	EXPECT_NEAR(deep.force.x(), 0, 1e-7 * g);
	EXPECT_NEAR(deep.moment, 0, 1e-7 * g);
}

TEST(Hydrostatic, SlopingWaterTableFollowsItsVertices)
{
	// a 1 x 1 block under a water table with a kink above it: the head is linear on either side of the kink, and
	// the net force is −∮ u n: horizontally the difference of the heads on the two vertical faces
	const std::vector<Vec2> line { Vec2(-10, 2), Vec2(0.3, 2), Vec2(10, 1) };
	const auto poly = rotatedRectangle(1, 1, 0, Vec2(0, 0));
	const auto load = hydrostaticLoad(poly, line, g, Vec2(0, 0));
	const Real hL = 2, hR = 2 + (1 - 2) * (0.5 - 0.3) / (10 - 0.3);
	// left face (x = −0.5): ∫ γw (hL − y) dy from −0.5 to 0.5 pushes +x; right face pushes −x
	EXPECT_NEAR(load.force.x(), g * (hL - hR), 1e-9 * g);
	// vertical: the bottom's head minus the top's, each integrated across the kink
	auto head = [&](Real x) { return rbsm::phreaticHeight(line, x); };
	Real bottom = 0, top = 0;
	const int N = 100000;
	for (int i = 0; i < N; ++i) {
		const Real x = -0.5 + (i + 0.5) / N;
		bottom += g * (head(x) + 0.5) / N, top += g * (head(x) - 0.5) / N;
	}
	EXPECT_NEAR(load.force.y(), bottom - top, 1e-6 * g);
}

TEST(Hydrostatic, WaterTableCheckNamesTheProblem)
{
	EXPECT_NO_THROW(rbsm::checkWaterTable("W", level(1), g));
	for (const auto& bad : { std::vector<Vec2> { Vec2(0, 0), Vec2(0, 1) }, std::vector<Vec2> { Vec2(0, 0), Vec2(NAN, 1) } }) {
		try {
			rbsm::checkWaterTable("W", bad, g);
			ADD_FAILURE() << "accepted";
		} catch (const std::invalid_argument& e) {
			EXPECT_NE(std::string(e.what()).find("W.phreatic: point 1"), std::string::npos) << e.what();
		}
	}
	EXPECT_THROW(rbsm::checkWaterTable("W", level(1), -1), std::invalid_argument);
	EXPECT_THROW(rbsm::checkWaterTable("W", level(1), INFINITY), std::invalid_argument);
}
