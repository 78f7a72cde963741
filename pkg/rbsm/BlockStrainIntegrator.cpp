#include <pkg/rbsm/BlockStrainIntegrator.hpp>
#include <core/Scene.hpp>
#include <pkg/rbsm/BlockStateCheck.hpp>
#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/NewtonAttribute.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/RbsmTimeStepper.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <pkg/rbsm/kernel/BlockPlasticity.hpp>

#include <sstream>

namespace yade {

YADE_PLUGIN((BlockStrainIntegrator));

namespace {
	std::atomic<int> blockReports { 0 };

	// The density scales RbsmTimeStepper puts on the bodies' inertia (null: none): the strain's mass takes them too.
	const std::vector<Real>* massScales(const Scene& scene)
	{
		for (const auto& e : scene.engines)
			if (const auto* ts = dynamic_cast<const RbsmTimeStepper*>(e.get())) return ts->densityScaling ? &ts->massScale : nullptr;
		return nullptr;
	}
}

void BlockStrainIntegrator::action()
{
	const long alive = DeformableState::alive.load(std::memory_order_relaxed);
	if (alive == 0) return; // a rigid scene: nothing to do
	if (alive != deformableSeen) markStrainSides(), deformableSeen = alive;
	const Real               damping = newtonAttribute<Real>(*scene, "damping", 0);
	const std::vector<Real>* scales  = massScales(*scene);
	scene->forces.sync();
	corrections.clear();
	Energies e;
	for (const auto& b : scene->bodies->body) {
		if (!b || !b->state || !b->shape || b->subdomain != scene->subdomain) continue; // (yade.mpy: this rank's blocks, as NewtonIntegrator)
		DeformableState* ds = deformableState(b->state.get());
		if (!ds) continue;
		const auto* poly = dynamic_cast<const Polygon2D*>(b->shape.get());
		const auto* mat  = dynamic_cast<const RbsmMat*>(b->material.get());
		if (!poly || !mat) {
			rbsm_report::stopForBody(blockReports, *scene, "BlockStrainIntegrator", b->id,
			                         "has a DeformableState but is not a Polygon2D block of an RbsmMat: it cannot deform (give it a plain State)");
			continue;
		}
		const Real scale  = scales && size_t(b->id) < scales->size() ? (*scales)[size_t(b->id)] : 1;
		const Real torque = stepBlock(*b, *ds, *poly, *mat, b->state->isDamped ? damping : 0, scale, e);
		const Vector3r& s = ds->strain; // its largest principal strain in magnitude
		if (const Real largest = std::abs(s[0] + s[1]) / 2 + std::hypot((s[0] - s[1]) / 2, s[2] / 2); !(largest <= maxStrain)) {
			std::ostringstream msg;
			msg << "strains by " << largest << " (principal), beyond maxStrain = " << maxStrain
			    << " of the small-strain element: its material is too weak or too soft for its loads (plastic shear " << ds->plasticShear << ")";
			rbsm_report::stopForBody(blockReports, *scene, "BlockStrainIntegrator", b->id, msg.str());
		}
		corrections.push_back({ b->id, torque - scene->forces.getTorque(b->id).z() });
	}
	for (const Torque& t : corrections) // (after the pass: an addTorque unsyncs the container)
		if (t.value != 0) scene->forces.addTorque(t.id, Vector3r(0, 0, t.value));
	if (scene->trackEnergy) {
		scene->energy->add(e.kinetic, "strainKinetic", energyIds[0], /*reset every step*/ true);
		scene->energy->add(e.elastic, "strainElastic", energyIds[1], /*reset every step*/ true);
		if (e.damped != 0) scene->energy->add(e.damped, "nonviscDamp", energyIds[2], /*cumulative*/ false);
		if (e.plastic != 0) scene->energy->add(e.plastic, "plastDissip", energyIds[3], /*cumulative*/ false);
	}
}

Real BlockStrainIntegrator::stepBlock(const Body& b, DeformableState& ds, const Polygon2D& poly, const RbsmMat& mat, Real damping, Real scale, Energies& e)
{
	const Real             torque = scene->forces.getTorque(b.id).z();
	const Vector3r         joints = ds.takeStrainLoad();
	const rbsm::Mat3       D      = rbsm::elasticityMatrix(mat.young, mat.poisson, mat.planeStrain);
	const Real             volume = poly.area * poly.thickness;
	const Vector3r         sigma  = D * (ds.strain - ds.plasticStrain); // block frame
	const rbsm::StrainMass& M     = ds.strainMass(poly);
	const Vector3r         load   = joints - volume * sigma;
	if (scene->trackEnergy) { // before the update, as NewtonIntegrator's: ε̇ and ω at t − dt/2 (its kinetic), ε at t (the joints' springs)
		e.kinetic += 0.5 * ds.strainRate.dot(M.strain * ds.strainRate) + ds.angVel.z() * M.thetaStrain.dot(ds.strainRate);
		e.elastic += 0.5 * volume * (ds.strain - ds.plasticStrain).dot(sigma);
	}
	Real                   jTheta = torque; // the torque NewtonIntegrator must see
	if (!fixedBlock(ds)) jTheta = integrate(ds, M, torque, load / scale, damping, e);
	// the stress after the step (held to the yield surface), in the world frame
	Vector3r s = D * (ds.strain - ds.plasticStrain);
	if (mat.plastic) s = yieldBlock(ds, mat, D, s, volume, e);
	Real           c, sn;
	planarCosSin(ds.ori, c, sn);
	Eigen::Matrix<Real, 2, 2> R, S;
	R << c, -sn, sn, c;
	S << s[0], s[2], s[2], s[1];
	S          = R * S * R.transpose();
	ds.stress  = Vector3r(S(0, 0), S(1, 1), S(0, 1));
	ds.szz     = mat.planeStrain ? mat.poisson * (s[0] + s[1]) : 0;
	return jTheta;
}

// FLAC's explicit return: the elastic trial stress s back onto Mohr–Coulomb; the difference becomes plastic
// strain. The dissipation recorded is the stored energy the return removes, ½V(s + σ)·Δεᵖ, so O.energy closes.
Vector3r BlockStrainIntegrator::yieldBlock(DeformableState& ds, const RbsmMat& mat, const rbsm::Mat3& D, const Vector3r& s, Real volume, Energies& e)
{
	const rbsm::MohrCoulombStrength strength { mat.cohesion, mat.frictionAngle, mat.tensileStrength, std::min(mat.dilatancy, mat.frictionAngle) };
	const rbsm::PlasticReturn       r = rbsm::mohrCoulombReturn(s, D, strength);
	ds.yieldMode                      = int(r.mode);
	if (r.mode == rbsm::YieldMode::elastic) return s;
	ds.plasticStrain += r.plasticStrain;
	ds.plasticShear += r.plasticShear;
	e.plastic += 0.5 * volume * (s + r.stress).dot(r.plasticStrain);
	return r.stress;
}

// The (θ, ε) step of one block under the torque T and the strain load P (both divided by the block's density
// scale). Cundall's damping acts on these generalized forces, each by the sign of its power at the predicted
// mid-step velocity (NewtonIntegrator's 2nd-order rule), so that it dissipates whatever the coupled mass.
// Returns the torque whose θ̈ = T/J NewtonIntegrator, damping it again by its own rule, turns into this θ̈.
Real BlockStrainIntegrator::integrate(DeformableState& ds, const rbsm::StrainMass& M, Real torque, const Vector3r& load, Real damping, Energies& e)
{
	const Real dt    = scene->dt;
	const bool turns = !(ds.blockedDOFs & State::DOF_RZ); // a prescribed rotation: θ̈ = 0 drives the strain
	auto       accelerations = [&](const rbsm::Vec4& f) -> rbsm::Vec4 {
                if (turns) return M.inverse * f;
                rbsm::Vec4 a;
                a << 0, M.strain.ldlt().solve(f.tail<3>());
                return a;
	};
	rbsm::Vec4 f(torque, load[0], load[1], load[2]);
	const rbsm::Vec4 v(ds.angVel.z(), ds.strainRate[0], ds.strainRate[1], ds.strainRate[2]);
	if (damping > 0) {
		const rbsm::Vec4 mid = v + 0.5 * dt * accelerations(f);
		for (int i = turns ? 0 : 1; i < 4; i++) {
			const Real before = f[i];
			f[i] *= 1 - damping * (f[i] * mid[i] > 0 ? 1 : f[i] * mid[i] < 0 ? -1 : 0);
			if (i > 0) e.damped += std::abs(before - f[i]) * std::abs(mid[i]) * dt; // (the rotation's: NewtonIntegrator's record)
		}
	}
	const rbsm::Vec4 a = accelerations(f);
	ds.strainRate += dt * a.tail<3>();
	ds.strain += dt * ds.strainRate;
	if (!turns) return torque;
	// NewtonIntegrator: θ̈ = (T/J)(1 − d sign(θ̈ (ω + θ̈ dt/2))); the T giving a[0] after that
	for (Real sign : { 1.0, -1.0, 0.0 }) {
		const Real T = M.polar * a[0] / (1 - damping * sign), acc = T / M.polar, power = acc * (ds.angVel.z() + 0.5 * dt * acc);
		if (damping == 0 || sign == (power > 0 ? 1 : power < 0 ? -1 : 0)) return T;
	}
	return M.polar * a[0];
}

void BlockStrainIntegrator::markStrainSides()
{
	const auto& bodies = scene->bodies->body;
	for (const auto& I : *scene->interactions) {
		auto* g = I && I->geom ? dynamic_cast<RbsmGeom*>(I->geom.get()) : nullptr;
		if (!g) continue;
		auto deformable = [&](Body::id_t id) { return size_t(id) < bodies.size() && bodies[id] && deformableState(bodies[id]->state.get()); };
		const int sides = (deformable(I->getId1()) ? 1 : 0) | (deformable(I->getId2()) ? 2 : 0);
		if (sides == g->strainSides) continue;
		g->strainSides = sides;
		if (sides) g->recordStrainsMade(*bodies[I->getId1()]->state, *bodies[I->getId2()]->state);
	}
}

} // namespace yade
