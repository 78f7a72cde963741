#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((Polygon2D));

void Polygon2D::postLoad(Polygon2D& p)
{
	if (!(std::isfinite(p.thickness) && p.thickness > 0)) {
		std::ostringstream msg;
		msg << "Polygon2D.thickness: must be a finite number > 0 (got " << p.thickness << ")";
		throw std::invalid_argument(msg.str());
	}
	if (p.vertices.empty()) throw std::invalid_argument("Polygon2D.vertices: a polygon needs at least 3 vertices (got none)");
	const std::vector<rbsm::Vec2> v(p.vertices.begin(), p.vertices.end());
	const std::string problem = rbsm::polygonProblem(v);
	if (!problem.empty()) throw std::invalid_argument("Polygon2D.vertices: " + problem);
	const rbsm::MassProperties mp = rbsm::massProperties(v);
	// Off-centre vertices would put the centre of mass away from State::pos: refuse them rather
	// than silently produce wrong dynamics. Tolerance relative to the polygon size.
	const Real size = rbsm::polygonSize(v);
	if (mp.centroid.norm() > 1e-9 * size) {
		std::ostringstream msg; // (%g-like: an offset of 1e-8 m must not print as 0.000000)
		msg << "Polygon2D.vertices: the centroid must be at the origin of the body frame, it is at (" << mp.centroid.x() << ", "
		    << mp.centroid.y() << "), " << mp.centroid.norm() / size << " of the polygon's size (tolerance 1e-9); yade_rbsm.polygon2d() builds a body from world-frame vertices";
		throw std::invalid_argument(msg.str());
	}
	p.area         = mp.area;
	p.polarMoment  = mp.polarMoment;
	p.circumradius = 0;
	for (const auto& x : v)
		p.circumradius = std::max(p.circumradius, x.norm());
	p.inradius     = rbsm::centroidInradius(v);
	p.edgeNormals  = rbsm::edgeNormals(v);
	if (!p.madeFromVertices.empty() && (p.madeFromVertices != p.vertices || p.madeFromThickness != p.thickness)) p.revision++;
	p.madeFromVertices  = p.vertices;
	p.madeFromThickness = p.thickness;
}

Vector2r Polygon2D::worldVertex(size_t i, const Vector2r& pos, Real angle) const
{
	return rbsm::Pose2(pos, std::cos(angle), std::sin(angle)).apply(vertices[i]);
}

std::vector<Vector2r> Polygon2D::pyWorldVertices(const Vector3r& pos, const Quaternionr& ori) const
{
	std::vector<Vector2r> out;
	out.reserve(vertices.size());
	for (size_t i = 0; i < vertices.size(); i++)
		out.push_back(worldVertex(i, pos.head<2>(), planarAngle(ori)));
	return out;
}

} // namespace yade
