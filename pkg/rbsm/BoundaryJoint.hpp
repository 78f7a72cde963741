// The joint of a block on a rigid boundary (Wall, Facet): the boundary as a polygon in the plane
// (kernel/BoundaryEdge.hpp) and the same edge-to-edge contact and RbsmGeom as between two blocks, so
// that Law2_RbsmGeom_RbsmPhys_MohrCoulomb acts on it unchanged. Shared by Ig2_Polygon2D_Wall_RbsmGeom
// and Ig2_Polygon2D_Facet_RbsmGeom.
#pragma once
#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/kernel/Types.hpp>

#include <vector>

namespace yade {
namespace rbsm_boundary {
	/// The block (body 1) against the boundary (body 2) given as a CCW polygon in world coordinates.
	/// Makes the RbsmGeom of a new contact (when they touch and both materials are accepted: the functor
	/// `who` reports a refused pair) or updates the existing one, as Ig2_Polygon2D_Polygon2D_RbsmGeom
	/// does (an existing joint that no longer touches is handed to the law as lost). The boundary is
	/// rigid: h2 = 0 (its half of the joint adds no compliance). Returns what an IGeomFunctor returns.
	bool blockOnBoundary(const char* who, int nIP, Real interactionDistance, const Polygon2D& block, const State& blockState,
	                     const std::vector<rbsm::Vec2>& boundary, const State& boundaryState, const shared_ptr<Interaction>& I, Scene& scene);
} // namespace rbsm_boundary
} // namespace yade
