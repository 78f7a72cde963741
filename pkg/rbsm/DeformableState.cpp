#include <pkg/rbsm/DeformableState.hpp>
#include <pkg/rbsm/Polygon2D.hpp>

#include <omp.h>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((DeformableState));

DeformableState::~DeformableState() { alive.fetch_sub(1, std::memory_order_relaxed); }

void DeformableState::initLoads()
{
	alive.fetch_add(1, std::memory_order_relaxed);
	threadLoads.assign(size_t(std::max(1, omp_get_max_threads())), Vector3r::Zero());
}

void DeformableState::addStrainLoad(const Vector3r& load)
{
	const size_t t = size_t(omp_get_thread_num());
	if (t < threadLoads.size()) {
		threadLoads[t] += load;
		return;
	}
	std::lock_guard<std::mutex> lock(updateMutex); // (more threads than at construction: shared slot)
	threadLoads[0] += load;
}

Vector3r DeformableState::takeStrainLoad()
{
	Vector3r sum = Vector3r::Zero();
	for (Vector3r& l : threadLoads) {
		sum += l;
		l.setZero();
	}
	strainLoad = sum;
	return sum;
}

const rbsm::StrainMass& DeformableState::strainMass(const Polygon2D& shape)
{
	const MassKey key { shape.revision, mass, inertia.z(), shape.area, shape.thickness };
	if (key.revision == massKey.revision && key.mass == massKey.mass && key.inertia == massKey.inertia && key.area == massKey.area
	    && key.thickness == massKey.thickness)
		return massCache;
	const std::vector<rbsm::Vec2> vertices(shape.vertices.begin(), shape.vertices.end());
	const rbsm::AreaMoments       m = rbsm::areaMoments(vertices);
	if (!(mass > 0 && m.area > 0 && shape.thickness > 0))
		throw std::invalid_argument("DeformableState: a deformable block needs a mass > 0 and a polygon of area > 0 (got mass " + std::to_string(mass) + ")");
	// the density the block's mass gives (a mass set by hand is kept); its polar inertia as set
	rbsm::StrainMass M = rbsm::strainMass(m, mass / (m.area * shape.thickness), shape.thickness);
	if (inertia.z() > 0 && inertia.z() != M.polar) {
		M.polar = inertia.z();
		rbsm::Mat4 full;
		full << M.polar, M.thetaStrain.transpose(), M.thetaStrain, M.strain;
		M.inverse = full.inverse();
	}
	massCache = M;
	massKey   = key;
	return massCache;
}

} // namespace yade
