// Still water on a block: the pore pressure u = γw (h(x) − y) ≥ 0 below a phreatic polyline h, and its
// resultant on a polygon's boundary. Free of YADE: the joint law and the open-water engine share it.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

#include <string>
#include <vector>

namespace rbsm {

/// The height of the phreatic polyline (x strictly increasing) at x, level beyond its ends.
Real phreaticHeight(const std::vector<Vec2>& line, Real x);

/// Throws std::invalid_argument naming `who` (e.g. "OpenWaterPressure") unless γw is finite and >= 0 and the water
/// table's points are finite with strictly increasing x.
void checkWaterTable(const std::string& who, const std::vector<Vec2>& line, Real gammaW);

struct WaterLoad {
	Vec2 force  = Vec2::Zero(); ///< Σ of −u n ds (n the outward normal) [N per unit thickness]
	Real moment = 0;            ///< about the given point [N·m per unit thickness]
};

/// The still water's pressure on the closed boundary of a polygon (vertices counter-clockwise): the force
/// −∮ u n ds and its moment about `about`, exactly for the piecewise-linear u of a polyline water table (each
/// edge cut where u changes slope or reaches 0; Simpson's rule is exact for the moment's quadratic). Below a level
/// water table it is Archimedes' γw·(submerged area) upwards through the submerged part's centroid.
WaterLoad hydrostaticLoad(const std::vector<Vec2>& polygon, const std::vector<Vec2>& line, Real gammaW, const Vec2& about);

} // namespace rbsm
