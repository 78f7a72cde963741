// ReshapedBlocks: a Polygon2D changed mid-run (new vertices or thickness) gets the mass and inertia
// of its new shape; a mass or inertia set by a script is seen.
#pragma once
#include <core/Body.hpp>
#include <core/BodyContainer.hpp>
#include <core/State.hpp>
#include <pkg/rbsm/BlockStateCheck.hpp>
#include <pkg/rbsm/Polygon2D.hpp>

namespace yade {

/// followReshape's work once something changed (out of line: the per-step check stays inline).
bool followReshapeChange(Body& b, const BodyContainer& bodies);

/// b's shape, mass, polar inertia and fixity are what followReshape last saw of them (false for a shape
/// it has not seen yet: its revision is not the followed -1).
inline bool asFollowed(const Polygon2D& p, const State& s)
{
	return p.revision == p.followed.revision && s.mass == p.followed.mass && s.inertia.z() == p.followed.inertia
	        && fixedBlock(s) == p.followed.fixed;
}

/* If b's Polygon2D changed since this was last called for it, b's mass and polar inertia are
 * scaled by the ratios of thickness·area and thickness·polarMoment, new over old: the block keeps
 * its density. Returns true then, and also when b's mass or polar inertia was set since, or b was
 * fixed or released (by a script: a lighter block, or one released, needs a shorter step at once; its
 * joints' reduced masses follow). Its joints are made anew by Ig2 from the new shape (RbsmGeom
 * remembers the Polygon2D.revision it was made for). A shape met for the first time (new, or after O.load) is taken as it is (its joints'
 * reduced masses recomputed from its mass: the same values, unless a script set the mass before O.save);
 * what was seen is kept in the shape (not saved), so a body id that YADE reuses for another block starts
 * afresh. Called by RbsmTimeStepper for every body at every step. */
inline bool followReshape(Body& b, const BodyContainer& bodies)
{
	if (!b.shape || !b.state || b.shape->getClassIndex() != Polygon2D::getClassIndexStatic()) return false;
	if (asFollowed(static_cast<const Polygon2D&>(*b.shape), *b.state)) return false; // the usual block
	return followReshapeChange(b, bodies);
}

/// True when followReshape would act on b at the next step (a shape, mass, inertia or fixity changed since it
/// last saw b): RbsmTimeStepper saves a pending full estimate then (the record of what was seen is not
/// saved, so a loaded scene could not tell).
bool reshapePending(const Body& b);

} // namespace yade
