// ReshapedBlocks: a Polygon2D changed mid-run (new vertices or thickness) gets the mass and inertia
// of its new shape.
#pragma once
#include <core/Body.hpp>
#include <core/BodyContainer.hpp>

namespace yade {

/* If b's Polygon2D changed since this was last called for it, b's mass and polar inertia are
 * scaled by the ratios of thickness·area and thickness·polarMoment, new over old: the block keeps
 * its density. Returns true then, and also when b's mass or polar inertia was set since (by a
 * script: a lighter block needs a shorter step at once; its joints' reduced masses follow). Its joints are made anew by Ig2 from the new shape (RbsmGeom
 * remembers the Polygon2D.revision it was made for). A shape met for the first time (new, or after
 * O.load) is taken as it is; what was seen is kept in the shape (not saved), so a body id that YADE
 * reuses for another block starts afresh. Called by RbsmTimeStepper for every body at every step. */
/// The joints that Ig2 made anew this step had their reduced mass from the old mass: it is updated.
bool followReshape(Body& b, const BodyContainer& bodies);

} // namespace yade
