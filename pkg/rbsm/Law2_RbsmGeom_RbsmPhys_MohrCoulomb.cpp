#include <pkg/rbsm/Law2_RbsmGeom_RbsmPhys_MohrCoulomb.hpp>
#include <pkg/rbsm/kernel/MohrCoulombJoint.hpp>

#include <pkg/rbsm/StepReport.hpp>

#include <algorithm>
#include <sstream>

namespace yade {

YADE_PLUGIN((Law2_RbsmGeom_RbsmPhys_MohrCoulomb));

namespace {
	inline Real cross(const Vector2r& a, const Vector2r& b) { return a.x() * b.y() - a.y() * b.x(); }

	// Reported, not thrown (StepReport.hpp).
	std::atomic<int> mismatchReports { 0 };
	void             reportPointMismatch(const Interaction& I, int physPoints, int geomPoints)
	{
		rbsm_report::limited(mismatchReports, [&](bool last) {
			std::ostringstream msg;
			msg << "yade-rbsm: WARNING: Law2_RbsmGeom_RbsmPhys_MohrCoulomb: interaction #" << I.getId1() << "+#" << I.getId2() << ": RbsmPhys has "
			    << physPoints << " integration points, its RbsmGeom " << geomPoints << "; the interaction is removed (made again by Ip2 if the blocks touch)"
			    << (last ? "; further such warnings are not shown" : "");
			return msg.str();
		});
	}
}

bool Law2_RbsmGeom_RbsmPhys_MohrCoulomb::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	RbsmGeom& g = static_cast<RbsmGeom&>(*ig);
	RbsmPhys& p = static_cast<RbsmPhys&>(*ip);
	const int n = g.nPoints();
	if (p.nPoints != n) { // an RbsmPhys set by hand that does not fit its contact
		reportPointMismatch(*I, p.nPoints, n);
		return false; // YADE erases the interaction; the contact is made again, with Ip2's joint
	}
	if (g.lost) { // the geometry found the blocks apart: every point breaks and opens, the joint goes
		for (int k = 0; k < n; k++) {
			rbsm::JointPointState& st = p.point(k).joint;
			st.intact = st.slipping = false;
			st.open                 = true;
			st.shearTraction = p.point(k).normalTraction = 0;
		}
		p.normalForce = p.shearForce = p.strength = 0;
		return false;
	}

	const rbsm::JointParams params { p.kn, p.ks, p.cohesion, p.tanPhi, p.tensileStrength, p.ductile };
	const Real              area = g.length * g.thickness; // area of the whole joint [m²]
	// Viscous damping: ξ times the critical coefficient of the joint's normal spring acting on the
	// reduced mass, 2·sqrt(kn·A·m), spread over the joint area (traction per velocity).
	const bool damped = dampingRatio > 0 && g.reducedMass > 0 && area > 0;
	p.dampingCoefficient = damped ? dampingRatio * 2 * std::sqrt(p.kn * area * g.reducedMass) / area : 0;

	// Force on body 2 and its moment about p0 summed over the points; the torques about the two
	// centroids follow from them: M_c = M_p0 + (p0 − c) × F.
	Vector2r       force = Vector2r::Zero();
	Real           momentP0 = 0;
	const Vector2r seg      = g.p1 - g.p0;
	Real           elastic = 0, dissipated = 0, viscous = 0, normalForce = 0, shearForce = 0, strength = 0;
	bool           carries = false;
	// The law samples the relative motion along the segment (linear, RbsmGeom) at its points.
	const rbsm::SegmentKinematics kin = g.kinematics();
	const Vector2r                tangent = g.tangent();
	const Real                    dt  = scene->dt;
	RbsmPhys::Point* const        pts = p.pointData();
	// A frictional contact that grows (a block tipping onto its face) takes in material with no shear
	// displacement: its points' shear tractions, spread over the new length, keep their old force
	// (held, they would create shear force and energy from nothing). Bonded points are the shared
	// edge's material and keep theirs.
	if (p.contactLength > 0 && g.length > p.contactLength) {
		const Real keep = p.contactLength / g.length;
		for (int k = 0; k < n; k++)
			if (!pts[k].joint.intact) pts[k].joint.shearTraction *= keep;
	}
	p.contactLength = g.length;
	for (int k = 0; k < n; k++) {
		const Real                   s   = g.rule->s[k];
		const Real                   a   = g.rule->w[k] * area;
		const Vector2r               v   = kin.velocity(s);
		const Real                   vn  = -v.dot(g.normal); // closing is positive, like the overlap
		const Real                   vs  = v.dot(tangent);
		rbsm::JointPointState&       st  = pts[k].joint;
		const rbsm::JointPointResult r   = rbsm::updateJointPoint(st, params, kin.overlap(s), vs * dt, a, scene->trackEnergy);
		pts[k].normalTraction            = r.normalTraction;
		Real fn = r.normalForce, fs = r.shearForce;
		if (damped && !st.open) { // no damping force across an open joint
			// shear damping only on the elastic branch: a slipping point is at its frictional limit
			const Real dn = p.dampingCoefficient * vn * a;
			Real       ds = st.slipping ? 0 : -p.dampingCoefficient * vs * a;
			// the spring and the dashpot together stay within the Mohr-Coulomb strength
			const Real limit = (st.intact ? p.cohesion : 0) * a + std::max<Real>(0, fn + dn) * p.tanPhi;
			ds               = std::clamp(fs + ds, -limit, limit) - fs;
			fn += dn;
			fs += ds;
			viscous += (dn * vn - ds * vs) * dt;
		}
		carries |= !st.open;
		const Vector2r f = fn * g.normal + fs * tangent;
		force += f;
		momentP0 += s * cross(seg, f); // (x_k − p0) × f, x_k − p0 = s_k (p1 − p0)
		elastic += r.elasticEnergy;
		dissipated += r.dissipated;
		normalForce += r.normalForce;
		shearForce += r.shearForce;
		strength += ((st.intact ? p.cohesion : 0) + std::max<Real>(0, r.normalTraction) * p.tanPhi) * a;
	}
	const Real torque2 = momentP0 + cross(g.p0 - g.centroid2, force);
	const Real torque1 = -(momentP0 + cross(g.p0 - g.centroid1, force));
	p.normalForce = normalForce;
	p.shearForce  = shearForce;
	p.strength    = strength;
	p.plasticDissipation += dissipated;

	// Open everywhere and clearly apart: the joint is gone. "Clearly": beyond round-off of the
	// block size, so that two blocks resting edge to edge with zero overlap keep their contact
	// instead of losing and re-making it every step.
	if (!carries && g.separation > 1e-9 * (g.h1 + g.h2)) return false;

	const Vector3r f3(force.x(), force.y(), 0);
	scene->forces.addForce(I->getId1(), -f3);
	scene->forces.addForce(I->getId2(), f3);
	scene->forces.addTorque(I->getId1(), Vector3r(0, 0, torque1));
	scene->forces.addTorque(I->getId2(), Vector3r(0, 0, torque2));

	if (scene->trackEnergy) {
		scene->energy->add(elastic, "elastPotential", elastPotentialIx, /*reset every step*/ true);
		if (dissipated != 0) scene->energy->add(dissipated, "plastDissip", plastDissipIx, /*cumulative*/ false);
		if (viscous != 0) scene->energy->add(viscous, "viscDamp", viscDampIx, /*cumulative*/ false);
	}
	return true;
}

} // namespace yade
