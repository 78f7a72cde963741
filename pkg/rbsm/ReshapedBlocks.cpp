#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/ReshapedBlocks.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <core/Interaction.hpp>
#include <core/State.hpp>

namespace yade {

namespace {
	// The joints' reduced masses (contact damping) from the blocks' masses of now.
	void updateReducedMasses(const Body& b, const BodyContainer& bodies)
	{
		for (const auto& idI : b.intrs) {
			const Interaction& I = *idI.second;
			if (!I.geom || I.geom->getClassIndex() != RbsmGeom::getClassIndexStatic()) continue;
			const Body* b1 = bodies.body[I.getId1()].get();
			const Body* b2 = bodies.body[I.getId2()].get();
			if (b1 && b2) static_cast<RbsmGeom&>(*I.geom).reducedMass = RbsmGeom::reducedMassOf(*b1->state, *b2->state);
		}
	}
}

bool followReshapeChange(Body& b, const BodyContainer& bodies)
{
	Polygon2D& p = static_cast<Polygon2D&>(*b.shape);
	State&     s = *b.state;
	if (p.followed.revision < 0) // first seen (new, or after O.load): the joints' reduced masses of these masses
		updateReducedMasses(b, bodies); // (a mass set by a script before O.save; the same values otherwise)
	else if (p.revision == p.followed.revision) { // mass or inertia set by a script, or the block fixed or released
		updateReducedMasses(b, bodies);
		p.followed.mass = s.mass, p.followed.inertia = s.inertia.z(), p.followed.fixed = fixedBlock(s);
		return true;
	}
	const Real volume = p.thickness * p.area, polar = p.thickness * p.polarMoment;
	const bool rescale = p.followed.revision >= 0 && p.followed.volume > 0 && p.followed.polar > 0;
	if (rescale) {
		s.mass *= volume / p.followed.volume;
		s.inertia *= polar / p.followed.polar;
		updateReducedMasses(b, bodies);
	}
	p.followed = Polygon2D::Followed { p.revision, volume, polar, s.mass, s.inertia.z(), fixedBlock(s) };
	return rescale;
}

bool reshapePending(const Body& b)
{
	if (!b.shape || !b.state || b.shape->getClassIndex() != Polygon2D::getClassIndexStatic()) return false;
	const Polygon2D& p = static_cast<const Polygon2D&>(*b.shape);
	return p.followed.revision >= 0 && !asFollowed(p, *b.state);
}

} // namespace yade
