#include <pkg/rbsm/Bo1_Polygon2D_Aabb.hpp>

#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/StepReport.hpp>
#include <core/Scene.hpp>

#include <atomic>
#include <iostream>
#include <mutex>

namespace yade {

YADE_PLUGIN((Bo1_Polygon2D_Aabb));

namespace {
	std::atomic<int> periodicReports { 0 };
}

void Bo1_Polygon2D_Aabb::postLoad(Bo1_Polygon2D_Aabb&)
{
	if (!(std::isfinite(enlarge) && enlarge >= 0))
		throw std::invalid_argument("Bo1_Polygon2D_Aabb.enlarge: must be a finite distance >= 0 (got " + std::to_string(enlarge) + ")");
}

void Bo1_Polygon2D_Aabb::go(const shared_ptr<Shape>& shape, shared_ptr<Bound>& bound, const Se3r& se3, const Body* body)
{
	const Polygon2D& p = static_cast<const Polygon2D&>(*shape);
	if (!bound) bound = shared_ptr<Bound>(new Aabb);
	if (scene && scene->isPeriodic) {
		// Refused at the first step, before any contact: blocks as thick as the cell (the natural 2D
		// set-up) fail YADE's collider assertion, and blocks wider than the cell are silently missed.
		rbsm_report::stopForBody(periodicReports, *scene, "Bo1_Polygon2D_Aabb", body ? body->id : -1,
		                         "is in a periodic cell (O.periodic): Polygon2D blocks do not support periodic cells");
		bound->min = bound->max = se3.position; // meets nothing, within any cell
		return;
	}
	if (p.vertices.empty()) {
		// A Polygon2D made without vertices (Polygon2D() in a script). Throwing here would abort
		// YADE (the collider runs functors in parallel), so the body gets a point bound, meets
		// nothing, and the problem is reported once.
		static std::once_flag reported;
		std::call_once(reported, [&] {
			std::cerr << "yade-rbsm: ERROR: body #" << (body ? body->id : -1)
			          << " has a Polygon2D without vertices; it takes part in no contact (give Polygon2D.vertices)" << std::endl;
		});
		bound->min = bound->max = se3.position;
		return;
	}
	const rbsm::Pose2 pose = planarPose(se3.position, se3.orientation);
	Vector2r          lo = Vector2r::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
	const DeformableState* ds = body ? deformableState(body->state.get()) : nullptr; // (its strained shape)
	for (const Vector2r& v : p.vertices) {
		const Vector2r w = pose.rotate(ds ? Vector2r(v + rbsm::strainDisplacement(v, ds->strain)) : v);
		lo = lo.cwiseMin(w);
		hi = hi.cwiseMax(w);
	}
	// Blocks of an assembly share edges exactly, so their boxes touch exactly; the collider only
	// pairs boxes that overlap, so every box is enlarged by a round-off margin of its own size.
	const Real     margin = enlarge + 1e-6 * p.circumradius;
	const Vector3r pos    = se3.position;
	bound->min         = Vector3r(pos.x() + lo.x() - margin, pos.y() + lo.y() - margin, pos.z() - 0.5 * p.thickness);
	bound->max         = Vector3r(pos.x() + hi.x() + margin, pos.y() + hi.y() + margin, pos.z() + 0.5 * p.thickness);
}

} // namespace yade
