#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>

#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((RbsmGeom));

void RbsmGeom::freeze(const rbsm::EdgeContact& c, const rbsm::Pose2& rel) { holdFrozen(rbsm::freezeContact(c, rel)); }

void RbsmGeom::holdFrozen(const rbsm::FrozenContact& f)
{
	if (f.valid) frozen.set(f);
	else frozen.reset();
}

void RbsmGeom::markLost(Real separationNow)
{
	lost       = true;
	separation = separationNow;
	frozen.reset();
}

void RbsmGeom::preSave(RbsmGeom&)
{
	frozenState = frozen.get() ? rbsm::packFrozen(*frozen.get()) : std::vector<Real>();
	strainsMadeState.clear();
	if (const StrainsMade* m = strainsMade.get())
		for (const Vector3r* e : { &m->block1, &m->block2 })
			strainsMadeState.insert(strainsMadeState.end(), e->data(), e->data() + 3);
}

void RbsmGeom::recordStrainsMade(const State& state1, const State& state2)
{
	StrainsMade m;
	if (const DeformableState* d = (strainSides & 1) ? deformableState(&state1) : nullptr) m.block1 = d->strain;
	if (const DeformableState* d = (strainSides & 2) ? deformableState(&state2) : nullptr) m.block2 = d->strain;
	if (m.block1.isZero(0) && m.block2.isZero(0)) strainsMade.reset(); // (unstrained: nothing to keep)
	else strainsMade.set(m);
}

void RbsmGeom::postLoad(RbsmGeom&)
{
	if (strainsMadeState.size() == 6) strainsMade.set(StrainsMade { Vector3r(strainsMadeState.data()), Vector3r(strainsMadeState.data() + 3) });
	else strainsMade.reset();
	holdFrozen(rbsm::unpackFrozen(frozenState));
	if (nIP > 0) setIntegrationPoints(nIP); // throws for a file with nIP outside 1..8
	else rule = nullptr;
}

void RbsmGeom::addStrainMotion(const State& state1, const State& state2)
{
	strainSlope.setZero();
	for (int side = 1; side <= 2; side++) {
		const DeformableState* ds = (strainSides & side) ? deformableState(side == 1 ? &state1 : &state2) : nullptr;
		if (!ds) continue;
		const rbsm::Pose2 pose = planarPose(ds->pos, ds->ori);
		// the displacement (or velocity) of the strain e at the world point x: R B(Rᵀ(x − c)) e
		auto       field = [&](const Vector2r& x, const Vector3r& e) { return pose.rotate(rbsm::strainDisplacement(pose.applyInverse(x), e)); };
		const Real sign  = side == 2 ? 1 : -1; // block 2's motion relative to block 1's
		const StrainsMade* made   = strainsMade.get();
		const Vector3r     strain = made ? Vector3r(ds->strain - (side == 1 ? made->block1 : made->block2)) : ds->strain;
		if (!onStrainedShapes) {
			d0 -= sign * normal.dot(field(p0, strain));
			d1 -= sign * normal.dot(field(p1, strain));
		}
		const Vector2r v0 = field(p0, ds->strainRate);
		relativeVelocity += sign * v0;
		strainSlope += sign * (field(p1, ds->strainRate) - v0);
	}
}

Vector2r RbsmGeom::point(int k) const
{
	if (k < 0 || k >= nPoints()) throw std::out_of_range("RbsmGeom.point: index " + std::to_string(k) + " outside 0.." + std::to_string(nPoints() - 1));
	return p0 + rule->s[k] * (p1 - p0);
}

namespace {
	template <class F> std::vector<Real> perPoint(const RbsmGeom& g, F f)
	{
		std::vector<Real> v(g.nPoints());
		for (int k = 0; k < g.nPoints(); k++)
			v[k] = f(k, g.rule->s[k]);
		return v;
	}
}

std::vector<Real> RbsmGeom::pyPositions() const { return perPoint(*this, [](int, Real s) { return s; }); }
std::vector<Real> RbsmGeom::pyWeights() const { return perPoint(*this, [this](int k, Real) { return rule->w[k]; }); }
std::vector<Real> RbsmGeom::pyDeltaN() const { return perPoint(*this, [k = kinematics()](int, Real s) { return k.overlap(s); }); }
std::vector<Real> RbsmGeom::pyNormalVelocity() const
{
	return perPoint(*this, [k = kinematics(), this](int, Real s) { return -k.velocity(s).dot(normal); });
}
std::vector<Real> RbsmGeom::pyShearVelocity() const
{
	return perPoint(*this, [k = kinematics(), this](int, Real s) { return k.velocity(s).dot(tangent()); });
}
std::vector<Real> RbsmGeom::pyShearIncrement() const
{
	const Real dt = Omega::instance().getScene()->dt;
	return perPoint(*this, [k = kinematics(), dt, this](int, Real s) { return k.velocity(s).dot(tangent()) * dt; });
}

} // namespace yade
