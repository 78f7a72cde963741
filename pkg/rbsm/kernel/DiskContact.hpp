// Contact of a disk (a sphere moving in the x-y plane) with a convex polygon: the closest feature
// of the polygon's boundary to the disk's centre, as a point contact.
//
// For a convex CCW polygon P with vertices v_i and outward unit edge normals n_i (edge i: v_i -> v_i+1)
// and a disk of centre c and radius r:
//  * c outside P: the closest boundary point q is the nearest of the feet of c on the edge segments,
//        q_i = v_i + clamp(t_i, 0, 1) (v_i+1 − v_i),  t_i = (c − v_i)·(v_i+1 − v_i) / |v_i+1 − v_i|²,
//    the signed distance is s = |c − q| > 0 and the normal n = (c − q)/s (an edge's normal, or the
//    direction from a corner);
//  * c inside P (or on its boundary): s = max_i n_i·(c − v_i) ≤ 0, the distance to the nearest edge
//    line, whose foot q = c − s n_i lies on that edge (convexity), and n = n_i.
// Overlap (penetration) δ = r − s (> 0 when they overlap). The normal points from the polygon to the
// disk; the contact point is the middle of the overlap along n, x = q − (δ/2) n, YADE's convention for
// ScGeom.contactPoint.
#pragma once

#include <pkg/rbsm/kernel/EdgeContact.hpp>
#include <pkg/rbsm/kernel/Types.hpp>

namespace rbsm {

struct DiskContact {
	Real distance = 0;           ///< signed distance s of the disk's centre from the polygon's boundary (m; < 0 inside)
	Real overlap  = 0;           ///< δ = r − s (m; > 0 penetration)
	Vec2 normal   = Vec2::Zero(); ///< unit, from the polygon to the disk
	Vec2 closest  = Vec2::Zero(); ///< q: the point of the polygon's boundary closest to the centre
	Vec2 point    = Vec2::Zero(); ///< contact point q − (δ/2) n
	int  edge     = -1;           ///< edge i whose segment holds q (for a corner: the edge that starts or ends there)
};

/// The disk (centre c, radius r ≥ 0) against the convex CCW polygon P (vertices and outward unit edge
/// normals, any frame). Corners within 1e-12 × the polygon's size of the centre take the normal of
/// the edge line the centre is farthest outside of, so that a disk whose centre lies on the boundary
/// still gets a unit normal.
DiskContact diskPolygonContact(const PolygonView& P, const Vec2& c, Real r);

} // namespace rbsm
