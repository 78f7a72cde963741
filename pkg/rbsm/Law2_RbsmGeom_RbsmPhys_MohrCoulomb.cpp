#include <pkg/rbsm/Law2_RbsmGeom_RbsmPhys_MohrCoulomb.hpp>
#include <pkg/rbsm/kernel/Hydrostatic.hpp>
#include <pkg/rbsm/kernel/MohrCoulombJoint.hpp>
#include <core/Scene.hpp>

#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
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

namespace {
	// The springs' energy of the points as they were at the last step (on its length, contactLength) [J].
	Real storedEnergy(const RbsmPhys& p, const RbsmGeom& g, int n)
	{
		const rbsm::JointParams params { p.kn, p.ks };
		Real                    e = 0;
		for (int k = 0; k < n; k++)
			e += rbsm::detail::springEnergy(params, p.point(k).normalTraction, p.point(k).joint.shearTraction, g.rule->w[k] * p.contactLength * g.thickness);
		return e;
	}

	// The geometry found the blocks apart (RbsmGeom.lost): every point breaks and opens, the joint goes.
	void loseJoint(RbsmPhys& p, int n)
	{
		for (int k = 0; k < n; k++) {
			rbsm::JointPointState& st = p.point(k).joint;
			st.intact = st.slipping = false;
			st.open                 = true;
			st.shearTraction = p.point(k).normalTraction = 0;
		}
		p.normalForce = p.shearForce = p.strength = 0;
	}

	// A frictional contact that grows (a block tipping onto its face) takes in material with no shear
	// displacement: its points' shear tractions, spread over the new length, keep their old force
	// (held, they would create shear force and energy from nothing). Bonded points are the shared
	// edge's material and keep theirs. Returns the shear springs' energy this loses, the area of every
	// point following the length (negative for bonded points that grow; with O.trackEnergy).
	[[gnu::always_inline]] inline Real spreadShearOverGrowth(RbsmPhys& p, const RbsmGeom& g, int n, bool withEnergy)
	{
		const Real old = p.contactLength, length = g.length;
		p.contactLength = length;
		// nothing to spread, and no energy to count (the common cases: no growth, or energy not tracked)
		if (!(old > 0) || length == old || (length < old && !withEnergy)) return 0;
		RbsmPhys::Point* const pts  = p.pointData();
		const Real             keep = length > old ? old / length : Real(1);
		Real                   lost = 0;
		for (int k = 0; k < n; k++) {
			Real&      tau   = pts[k].joint.shearTraction;
			const Real after = pts[k].joint.intact ? tau : tau * keep;
			if (withEnergy && p.ks > 0) lost += g.rule->w[k] * g.thickness * (old * tau * tau - length * after * after) / (2 * p.ks);
			tau = after;
		}
		return lost;
	}

	// The bond is the segment the joint was made on. A segment grows by closing (a face bonded across a
	// small misfit, closing elastically: bonded as it closes) or by sliding (a corner bonded at a point
	// and slid along a face: not bonded). So while the joint has never slipped the bond is the segment
	// less the blocks' tangential travel since the joint formed; after a slip it only shrinks.
	// Returns the bonded share of the current segment, which scales c and σt of the intact points.
	inline Real bondedFraction(RbsmPhys& p, const RbsmGeom& g, const rbsm::SegmentKinematics& kin, const Vector2r& tangent, Real dt)
	{
		p.tangentialTravel += kin.velocity(0.5).dot(tangent) * dt;
		const Real unslid = std::max<Real>(0, g.length - std::abs(p.tangentialTravel));
		if (p.bondedLength < 0 || p.plasticDissipation == 0) p.bondedLength = unslid;
		else p.bondedLength = std::min(p.bondedLength, g.length);
		return g.length > p.bondedLength ? p.bondedLength / g.length : Real(1);
	}

	// What the points of a step share, and what they sum: the force on body 2 and its moment about p0
	// (the torques about the two centroids follow: M_c = M_p0 + (p0 − c) × F), energies, forces.
	struct JointStep {
		rbsm::JointParams             params;
		Real                          area; // of the whole joint [m²]
		bool                          damped;
		rbsm::SegmentKinematics       kin; // the relative motion along the segment (RbsmGeom)
		Vector2r                      tangent, seg;
		Real                          dt;
		bool                          trackEnergy;
	};

	// The share of a step in which a point that is not bonded was in contact, as its dashpot sees it: a point closing
	// by more than its overlap, vn·dt > δ, came into contact within the step (a landing, the growing end of a block
	// tipping onto its face), and its dashpot acts on the part of the closing it took part in, δ, not vn·dt: the rate
	// of max(δ, 0). (At the full rate, a landing's step-dependent first push set runouts: 2.59 m at the default step,
	// 2.37 m at a quarter of it; tests/physics/test_runout.py.) Opening is at the full rate (the next step finds the point open).
	inline Real contactShare(Real overlap, Real vn, Real dt) { return vn * dt > overlap ? overlap / (vn * dt) : Real(1); }

	// The dashpots' work (O.energy's viscDamp). The central-difference step changes the kinetic energy by
	// F·(v⁻ + v⁺)/2 dt, v∓ the velocities half a step before and after the force: a dashpot's work is counted
	// half with the velocity it is computed from (now, forces now), half at the next step with the velocity it
	// acted at (last, forces of the last step). (All of it with v⁻, a damped impact's ledger gained 8-46 % of
	// its energy; with v⁺ it lost 1-32 %: tests/physics/test_damped_impact.py.) Forces: normal, shear of each
	// point, as applied; either may be null.
	Real dashpotWork(const RbsmGeom& g, const rbsm::SegmentKinematics& kin, Real dt, int n, const Real* now, const Real* last)
	{
		const Vector2r t = g.tangent();
		Real           w = 0;
		for (int k = 0; k < n; k++) {
			const Vector2r v  = kin.velocity(g.rule->s[k]);
			const Real     vn = -v.dot(g.normal), vs = v.dot(t);
			if (now) w += now[2 * k] * vn - now[2 * k + 1] * vs;
			if (last) w += last[2 * k] * vn - last[2 * k + 1] * vs;
		}
		return Real(0.5) * w * dt;
	}

	// A joint the geometry has lost: its last step's dashpots' second half, at that step's segment with the
	// blocks' rigid motion now (the geometry no longer updates its kinematics).
	Real lostJointDashpotWork(const Scene& scene, const RbsmGeom& g, const RbsmPhys::DashpotForces& last, const Interaction& I)
	{
		const State &s1 = *scene.bodies->body[I.getId1()]->state, &s2 = *scene.bodies->body[I.getId2()]->state;
		const rbsm::SegmentKinematics kin = rbsm::segmentKinematics(0, 0, g.p0, g.p1, s1.pos.head<2>(), s1.vel.head<2>(), s1.angVel.z(),
		                                                            s2.pos.head<2>(), s2.vel.head<2>(), s2.angVel.z());
		return dashpotWork(g, kin, scene.dt, g.nPoints(), nullptr, last.f.data());
	}
	struct JointSums {
		Vector2r force    = Vector2r::Zero();
		Vector2r firstMoment = Vector2r::Zero(); // Σ s_k f_k: with force, the forces' first moment about any point (strain loads)
		Real     momentP0 = 0, elastic = 0, dissipated = 0, released = 0, viscous = 0, normalForce = 0, shearForce = 0, strength = 0;
		bool     carries  = false;
	};

	// A force f on body 2 at s along the segment: into the resultant and its moment about p0 (and with
	// Strain, the joint of a deformable block, into the first moment that loads its strain; the rigid
	// joints' step is instantiated without it).
	template <bool Strain> [[gnu::always_inline]] inline void addForceAt(const JointStep& j, Real s, const Vector2r& f, JointSums& sum)
	{
		sum.force += f;
		sum.momentP0 += s * cross(j.seg, f); // (x_k − p0) × f, x_k − p0 = s_k (p1 − p0)
		if constexpr (Strain) sum.firstMoment += s * f;
	}

	// What a point adds to the sums: its force (springs fn, fs, with the dashpots' share) at s along the
	// segment, and its law's results r; strength: its Mohr-Coulomb strength times its area.
	template <bool Strain> [[gnu::always_inline]] inline void addToSums(const RbsmGeom& g, const JointStep& j, Real s, Real fn, Real fs, const rbsm::JointPointResult& r,
	                                             bool open, Real strength, JointSums& sum)
	{
		sum.carries |= !open;
		addForceAt<Strain>(j, s, fn * g.normal + fs * j.tangent, sum);
		sum.elastic += r.elasticEnergy;
		sum.dissipated += r.dissipated;
		sum.released += r.released;
		sum.normalForce += r.normalForce;
		sum.shearForce += r.shearForce;
		sum.strength += strength;
	}

	// A point's Mohr-Coulomb strength per unit area at normal traction sn (its cohesion while intact; an
	// elastic weld's is infinite): what RbsmPhys.strength sums.
	inline Real pointStrength(const JointStep& j, bool intact, Real sn) { return (intact ? j.params.cohesion : 0) + std::max<Real>(0, sn) * j.params.tanPhi; }

	// Point k of the rule: the law at the point (rbsm::updateJointPoint) and the viscous damping, added
	// to the sums. (Inlined early, so that the sums can stay in registers.)
	template <bool Strain> [[gnu::always_inline]] inline void addPoint(const RbsmGeom& g, RbsmPhys& p, const JointStep& j, int k, JointSums& sum, Real* dashpots)
	{
		RbsmPhys::Point* const       pts = p.pointData();
		const Real                   s   = g.rule->s[k];
		const Real                   a   = g.rule->w[k] * j.area;
		const Vector2r               v   = j.kin.velocity(s);
		const Real                   vn  = -v.dot(g.normal); // closing is positive, like the overlap
		const Real                   vs  = v.dot(j.tangent);
		const Real                   d   = j.kin.overlap(s);
		rbsm::JointPointState&       st  = pts[k].joint;
		const rbsm::JointPointResult r   = rbsm::updateJointPoint(st, j.params, d, vs * j.dt, a, j.trackEnergy);
		pts[k].normalTraction            = r.normalTraction;
		Real fn = r.normalForce, fs = r.shearForce;
		if (j.damped && !st.open) { // no damping force across an open joint
			// shear damping only on the elastic branch: a slipping point is at its frictional limit
			const Real share = st.intact ? Real(1) : contactShare(d, vn, j.dt); // (a bond's dashpot: the whole jump)
			const Real dn    = share * p.dampingCoefficient * vn * a;
			Real       ds    = st.slipping ? 0 : -share * p.dampingCoefficient * vs * a;
			// the spring and the dashpot together stay within the Mohr-Coulomb strength of the spring's
			// normal force: the dashpot damps, it adds no friction (a landing block is not braked by it)
			const Real limit = (st.intact ? j.params.cohesion : 0) * a + std::max<Real>(0, fn) * p.tanPhi;
			ds               = std::clamp(fs + ds, -limit, limit) - fs;
			fn += dn;
			fs += ds;
			dashpots[2 * k] = dn, dashpots[2 * k + 1] = ds; // (for the energy: dashpotWork)
		}
		addToSums<Strain>(g, j, s, fn, fs, r, st.open, pointStrength(j, st.intact, r.normalTraction) * a, sum);
	}
}

namespace {
	// A frictional joint (no intact point): its points together (rbsm::updateFrictionalPoints), then the
	// dashpots and the sums as addPoint's. The shear dashpots act while the joint sticks, and with the
	// springs they stay within the joint's friction of the springs' normal force. N >= n: the size of
	// the point arrays (small for the common 2 points: they are set up at every step). Count > 0: n is known to
	// be Count (the common 2: the loops unrolled, without copies of the rule's arrays).
	template <int N, bool Strain, int Count = 0> void addFrictionalPoints(const RbsmGeom& g, RbsmPhys& p, const JointStep& j, int nGiven, JointSums& sum, Real* dashpots)
	{
		static_assert(Count >= 0 && Count <= N);
		const int              n   = Count > 0 ? Count : nGiven;
		RbsmPhys::Point* const pts = p.pointData();
		Real                   s[N], a[N], overlap[N], dus[N], vn[N], vs[N];
		for (int k = 0; k < n; k++) {
			s[k]             = g.rule->s[k];
			a[k]             = g.rule->w[k] * j.area;
			const Vector2r v = j.kin.velocity(s[k]);
			vn[k]            = -v.dot(g.normal);
			vs[k]            = v.dot(j.tangent);
			overlap[k]       = j.kin.overlap(s[k]);
			dus[k]           = vs[k] * j.dt;
		}
		rbsm::JointPointResult r[N];
		rbsm::updateFrictionalPoints([pts](int k) -> rbsm::JointPointState& { return pts[k].joint; }, n, j.params, overlap, dus, a, r, j.trackEnergy);
		Real dn[N] = {}, ds[N] = {}, keep = 1;
		if (j.damped) {
			Real springs = 0, dashpots = 0, limit = 0;
			for (int k = 0; k < n; k++) {
				if (pts[k].joint.open) continue; // no damping force across an open point
				const Real c = contactShare(overlap[k], vn[k], j.dt) * p.dampingCoefficient;
				dn[k]        = c * vn[k] * a[k];
				ds[k]        = pts[k].joint.slipping ? 0 : -c * vs[k] * a[k];
				springs += r[k].shearForce;
				dashpots += ds[k];
				limit += r[k].normalForce * p.tanPhi;
			}
			if (std::abs(springs + dashpots) > limit && dashpots != 0) keep = (std::copysign(limit, springs + dashpots) - springs) / dashpots;
		}
		for (int k = 0; k < n; k++) {
			pts[k].normalTraction = r[k].normalTraction;
			addToSums<Strain>(g, j, s[k], r[k].normalForce + dn[k], r[k].shearForce + keep * ds[k], r[k], pts[k].joint.open, r[k].normalForce * p.tanPhi, sum);
		}
		if (j.damped)
			for (int k = 0; k < n; k++)
				dashpots[2 * k] = dn[k], dashpots[2 * k + 1] = keep * ds[k]; // (for the energy: dashpotWork)
	}
}

namespace {
	// A welded joint (a cut of a continuum between two deformable blocks): the penalty acts on the mean of
	// the jump along the segment, and linearShare of it on the jump's linear part. Its points see the mean
	// plus b = √linearShare times their deviation from it, and return their forces through the transpose
	// of that map: the joint stores ½ Σ k a (δ̄² + b² (δ_k − δ̄)²) and its forces are that energy's gradient.
	// The points keep the tractions they apply (what joint_table and block stresses read): their springs'
	// own, τ̄ + (τ − τ̄)/b, are taken back before the update.
	// (Why: a linear jump penalised at every edge of a Voronoi cell over-constrains the cells' linear
	// fields, which then lock in any field but a uniform one: a Brazilian disc's centre carried 0.28 of its
	// tension, tests/deformable/test_disc.py.) Out of line: the common joints' step does not carry it.
	[[gnu::noinline]] JointSums weldedPoints(const RbsmGeom& g, RbsmPhys& p, const JointStep& j, int n, Real* dashpots)
	{
		JointSums              sum;
		constexpr int          N   = rbsm::kMaxIntegrationPoints;
		RbsmPhys::Point* const pts = p.pointData();
		const Real             b   = std::sqrt(p.linearShare);
		Real                   w[N], dn[N], vn[N], vs[N], mean[4] = { 0, 0, 0, 0 }; // means of δn, vn, vs and the applied τ
		for (int k = 0; k < n; k++) {
			const Real     s = g.rule->s[k];
			const Vector2r v = j.kin.velocity(s);
			w[k]             = g.rule->w[k];
			dn[k]            = j.kin.overlap(s);
			vn[k]            = -v.dot(g.normal);
			vs[k]            = v.dot(j.tangent);
			mean[0] += w[k] * dn[k], mean[1] += w[k] * vn[k], mean[2] += w[k] * vs[k], mean[3] += w[k] * pts[k].joint.shearTraction;
		}
		auto toPoint = [b](Real x, Real m) { return m + b * (x - m); };
		rbsm::JointPointResult r[N];
		Real                   fMean[2] = { 0, 0 }, cMean[2] = { 0, 0 }, cn[N] = {}, cs[N] = {}; // spring and dashpot tractions
		for (int k = 0; k < n; k++) {
			pts[k].joint.shearTraction = mean[3] + (pts[k].joint.shearTraction - mean[3]) / b;
			r[k] = rbsm::updateJointPoint(pts[k].joint, j.params, toPoint(dn[k], mean[0]), toPoint(vs[k], mean[2]) * j.dt, w[k] * j.area, j.trackEnergy);
			if (j.damped) {
				cn[k] = p.dampingCoefficient * toPoint(vn[k], mean[1]);
				cs[k] = -p.dampingCoefficient * toPoint(vs[k], mean[2]);
			}
			fMean[0] += w[k] * r[k].normalTraction, fMean[1] += w[k] * r[k].shearTraction;
			cMean[0] += w[k] * cn[k], cMean[1] += w[k] * cs[k];
		}
		for (int k = 0; k < n; k++) {
			const Real sn = toPoint(r[k].normalTraction, fMean[0]), tau = toPoint(r[k].shearTraction, fMean[1]);
			pts[k].normalTraction      = sn;
			pts[k].joint.shearTraction = tau;
			const Real a = w[k] * j.area;
			if (j.damped) dashpots[2 * k] = toPoint(cn[k], cMean[0]) * a, dashpots[2 * k + 1] = toPoint(cs[k], cMean[1]) * a; // (as applied)
			addToSums<true>(g, j, g.rule->s[k], (sn + toPoint(cn[k], cMean[0])) * a, (tau + toPoint(cs[k], cMean[1])) * a, r[k], false,
			          pointStrength(j, pts[k].joint.intact, sn) * a, sum);
		}
		return sum;
	}
}

namespace {
	// Water in the joint: the pore pressure u_k = γw (h(x_k) − y_k) ≥ 0 at each point pushes the blocks
	// apart (force u_k a_k along the normal on body 2, as a compression would), or with sign −1 presses them
	// together (a dry contact in open water); returns Σ ±u_k a_k. With O.trackEnergy, work gets the water's work
	// on the blocks, Σ ±u_k a_k (v_k·n) dt (an opening wet joint: > 0).
	template <bool Strain> Real addWater(const RbsmGeom& g, const JointStep& j, const std::vector<Vector2r>& line, Real gammaW, Real sign, int n, JointSums& sum, Real& work)
	{
		Real total = 0;
		for (int k = 0; k < n; k++) {
			const Real     s = g.rule->s[k];
			const Vector2r x = g.p0 + s * j.seg;
			const Real     u = gammaW * std::max<Real>(0, rbsm::phreaticHeight(line, x.x()) - x.y());
			if (u <= 0) continue;
			const Real pushed = sign * u * g.rule->w[k] * j.area;
			addForceAt<Strain>(j, s, pushed * g.normal, sum);
			total += pushed;
			if (j.trackEnergy) work += pushed * j.kin.velocity(s).dot(g.normal) * j.dt;
		}
		return total;
	}
}

// The joint's forces f_k at x_k = p0 + s_k (p1 − p0) load a deformable block's strain by Σ Bᵀ(r_k) f_k,
// r_k = x_k − c in the block's frame: from their first moment Q = Σ r_k ⊗ f_k = (p0 − c) ⊗ F + (p1 − p0) ⊗ G,
// G = Σ s_k f_k (on body 2; body 1 takes the opposite forces).
void Law2_RbsmGeom_RbsmPhys_MohrCoulomb::addStrainLoads(const Interaction& I, const RbsmGeom& g, const Vector2r& force, const Vector2r& firstMoment)
{
	const auto& bodies = scene->bodies->body;
	for (int side = 1; side <= 2; side++) {
		if (!(g.strainSides & side)) continue;
		const Body::id_t id = side == 1 ? I.getId1() : I.getId2();
		DeformableState* ds = deformableState(bodies[id]->state.get());
		if (!ds) continue;
		const Vector2r          c = side == 1 ? g.centroid1 : g.centroid2;
		Eigen::Matrix<Real, 2, 2> Q = (g.p0 - c) * force.transpose() + (g.p1 - g.p0) * firstMoment.transpose();
		if (side == 1) Q = -Q;
		Real cs, sn;
		planarCosSin(ds->ori, cs, sn);
		Eigen::Matrix<Real, 2, 2> R;
		R << cs, -sn, sn, cs;
		const Eigen::Matrix<Real, 2, 2> local = R.transpose() * Q * R; // Σ (Rᵀr) ⊗ (Rᵀf)
		ds->addStrainLoad(rbsm::strainLoad(local));
	}
}

bool Law2_RbsmGeom_RbsmPhys_MohrCoulomb::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	RbsmGeom& g = static_cast<RbsmGeom&>(*ig);
	RbsmPhys& p = static_cast<RbsmPhys&>(*ip);
	// a joint between rigid blocks has no strain to load and is not welded: its step is compiled without them
	return g.strainSides || p.welded ? deformableJoint(g, p, I) : joint<false>(g, p, I);
}

// (Out of line, so that go's own step for rigid joints is laid out for them alone.) A welded joint whose
// blocks have both yielded beyond its weldBreakStrain is a crack from now on: a Mohr-Coulomb joint, found on
// the blocks' strained shapes from the next step (Ig2), so that a failed mass can slide along it.
[[gnu::noinline]] bool Law2_RbsmGeom_RbsmPhys_MohrCoulomb::deformableJoint(RbsmGeom& g, RbsmPhys& p, Interaction* I)
{
	if (p.welded && p.weldBreakStrain > 0) {
		const auto& bodies  = scene->bodies->body;
		auto        yielded = [&](Body::id_t id) {
                        const DeformableState* ds = deformableState(bodies[size_t(id)]->state.get());
                        return ds && ds->plasticShear > p.weldBreakStrain;
		};
		if (yielded(I->getId1()) && yielded(I->getId2())) p.welded = false;
	}
	return joint<true>(g, p, I);
}

template <bool Strain> bool Law2_RbsmGeom_RbsmPhys_MohrCoulomb::joint(RbsmGeom& g, RbsmPhys& p, Interaction* I)
{
	const int n = g.nPoints();
	if (p.nPoints != n) { // an RbsmPhys set by hand that does not fit its contact
		reportPointMismatch(*I, p.nPoints, n);
		return false; // YADE erases the interaction; the contact is made again, with Ip2's joint
	}
	if (g.lost) {
		if (scene->trackEnergy) {
			scene->energy->add(storedEnergy(p, g, n), "jointRelease", jointReleaseIx, /*cumulative*/ false);
			if (const auto* last = p.lastDashpots.get()) {
				const Real w = lostJointDashpotWork(*scene, g, *last, *I);
				if (w != 0) scene->energy->add(w, "viscDamp", viscDampIx, /*cumulative*/ false);
			}
		}
		loseJoint(p, n);
		return false;
	}

	const Real area = g.length * g.thickness;
	// Viscous damping: ξ times the critical coefficient of the joint's normal spring acting on the
	// reduced mass, 2·sqrt(kn·A·m), spread over the joint area (traction per velocity).
	const bool damped    = dampingRatio > 0 && g.reducedMass > 0 && area > 0;
	p.dampingCoefficient = damped ? dampingRatio * 2 * std::sqrt(p.kn * area * g.reducedMass) / area : 0;
	JointStep j { rbsm::JointParams { p.kn, p.ks, p.cohesion, p.tanPhi, p.tensileStrength, p.ductile }, area, damped, g.template kinematics<Strain>(), g.tangent(), g.p1 - g.p0,
		      scene->dt, scene->trackEnergy };
	Real dashpots[2 * rbsm::kMaxIntegrationPoints]; // the dashpots' forces, written by damped joints only
	if (damped) std::fill_n(dashpots, 2 * n, Real(0)); // (an open point's carries nothing)
	const bool cohesive = p.cohesion != 0 || p.tensileStrength != 0;
	if (Strain && p.welded) { // a cut of a continuum: elastic and unlimited, or as strong as a plastic material
		if (p.weldYields) j.params.ductile = true; // slips on c + σn tan φ, keeps its cohesion
		else j.params.cohesion = std::numeric_limits<Real>::infinity();
		j.params.tensileStrength = std::numeric_limits<Real>::infinity(); // tension: the blocks' cut-off
	}
	else if (cohesive) { // cohesionless joints have no bond to scale
		const Real bonded = bondedFraction(p, g, j.kin, j.tangent, scene->dt);
		j.params.cohesion *= bonded;
		j.params.tensileStrength *= bonded;
	}
	// frictional: no bond left (or none to begin with): the joint slips as a whole
	const bool frictional = !(Strain && p.welded) && (!cohesive || p.nIntact() == 0);
	JointSums sum;
	sum.released = spreadShearOverGrowth(p, g, n, scene->trackEnergy);
	if (frictional) {
		constexpr int two = RbsmPhys::kInlinePoints;
		if (n == two) addFrictionalPoints<two, Strain, two>(g, p, j, n, sum, dashpots);
		else addFrictionalPoints<rbsm::kMaxIntegrationPoints, Strain>(g, p, j, n, sum, dashpots);
	}
	else if (Strain && p.welded && p.linearShare < 1) {
		const Real released = sum.released;
		sum                 = weldedPoints(g, p, j, n, dashpots);
		sum.released += released;
	}
	else
		for (int k = 0; k < n; k++)
			addPoint<Strain>(g, p, j, k, sum, dashpots);
	Real waterWork = 0;
	if (!phreatic.empty()) {
		const bool wet = p.water || waterAll;
		// in open water the faces' pressure is OpenWaterPressure's: a wet joint's faces are in it, a closed dry
		// contact's are taken off (once it opens, the water is in it)
		if (openWater) p.waterForce = wet || g.separation > 1e-9 * (g.h1 + g.h2) ? 0 : addWater<Strain>(g, j, phreatic, waterUnitWeight, -1, n, sum, waterWork);
		else if (wet) p.waterForce = addWater<Strain>(g, j, phreatic, waterUnitWeight, 1, n, sum, waterWork);
		else if (p.waterForce != 0) p.waterForce = 0;
	} else if (p.waterForce != 0) p.waterForce = 0; // the water was taken away
	if (scene->trackEnergy) { // (the dashpots' work: dashpotWork; their forces kept for the next step's half)
		const auto* last = p.lastDashpots.get();
		if (damped || last) sum.viscous += dashpotWork(g, j.kin, j.dt, n, damped ? dashpots : nullptr, last ? last->f.data() : nullptr);
		if (damped) {
			RbsmPhys::DashpotForces kept;
			std::copy_n(dashpots, 2 * n, kept.f.begin());
			p.lastDashpots.set(kept);
		} else p.lastDashpots.reset();
	} else p.lastDashpots.reset();
	const Real torque2 = sum.momentP0 + cross(g.p0 - g.centroid2, sum.force);
	const Real torque1 = -(sum.momentP0 + cross(g.p0 - g.centroid1, sum.force));
	p.normalForce      = sum.normalForce;
	p.shearForce       = sum.shearForce;
	p.strength         = sum.strength;
	p.plasticDissipation += sum.dissipated;

	// (also for a joint that goes now: its last step's dashpots worked over the step just made)
	if (scene->trackEnergy) {
		// copies: the tracker takes references, which would keep all of sum on the stack
		const Real elastic = sum.elastic, dissipated = sum.dissipated, viscous = sum.viscous, released = sum.released;
		scene->energy->add(elastic, "elastPotential", elastPotentialIx, /*reset every step*/ true);
		if (dissipated != 0) scene->energy->add(dissipated, "plastDissip", plastDissipIx, /*cumulative*/ false);
		if (viscous != 0) scene->energy->add(viscous, "viscDamp", viscDampIx, /*cumulative*/ false);
		if (released != 0) scene->energy->add(released, "jointRelease", jointReleaseIx, /*cumulative*/ false);
		if (waterWork != 0) scene->energy->add(-waterWork, "waterWork", waterWorkIx, /*cumulative*/ false);
	}

	// Open everywhere and clearly apart: the joint is gone. "Clearly": beyond round-off of the
	// block size, so that two blocks resting edge to edge with zero overlap keep their contact
	// instead of losing and re-making it every step.
	// A wet joint stays while the geometry keeps it (a crack opening within the contact's reach keeps its
	// water; beyond it the geometry loses the joint and its water goes: Hoek & Bray's V is lost, issue 40).
	if (!sum.carries && p.waterForce == 0 && g.separation > 1e-9 * (g.h1 + g.h2)) return false;

	if constexpr (Strain) addStrainLoads(*I, g, sum.force, sum.firstMoment);
	const Vector3r f3(sum.force.x(), sum.force.y(), 0);
	scene->forces.addForce(I->getId1(), -f3);
	scene->forces.addForce(I->getId2(), f3);
	scene->forces.addTorque(I->getId1(), Vector3r(0, 0, torque1));
	scene->forces.addTorque(I->getId2(), Vector3r(0, 0, torque2));

	return true;
}

} // namespace yade
