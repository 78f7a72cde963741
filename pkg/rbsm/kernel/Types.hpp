// Basic types of the RBSM kernel. Kept separate so that every kernel header agrees on them
// and so that the YADE plugin can convert to/from its own Vector2r in one place.
#pragma once

#include <Eigen/Core>

namespace rbsm {

using Real = double;
using Vec2 = Eigen::Vector2d;

/// z-component of the 2D cross product a x b (= |a||b| sin(angle from a to b)).
inline Real cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

} // namespace rbsm
