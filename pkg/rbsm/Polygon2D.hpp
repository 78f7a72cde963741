// Polygon2D: the shape of an RBSM block, a rigid convex polygon in the x-y plane.
#pragma once
#include <core/Shape.hpp>
#include <pkg/rbsm/kernel/Pose2.hpp>

namespace yade {

/* The vertices are given in the body's local frame, counter-clockwise, with the centroid at the
 * origin, so that State::pos is the block's centre of mass and State::ori (a rotation about z) its
 * orientation. Derived quantities (area, polar moment) are per unit thickness and unit density;
 * yade_rbsm.polygon2d() turns world-frame vertices into a body with mass and inertia. */
class Polygon2D : public Shape {
public:
	//! Vertex i in world coordinates (x, y) for a body at pos with rotation angle about z.
	Vector2r worldVertex(size_t i, const Vector2r& pos, Real angle) const;
	//! Checks the vertices and computes the derived quantities; throws std::invalid_argument naming the problem.
	void postLoad(Polygon2D&);
	//! Python: world vertices of this shape for the given body state.
	std::vector<Vector2r> pyWorldVertices(const Vector3r& pos, const Quaternionr& ori) const;

	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Polygon2D, Shape,
		"Rigid convex polygon in the x-y plane: the block of the Rigid-Bodies-Spring Model (Kawai 1977). "
		"Its motion is planar: x, y translation and rotation about z (yade_rbsm.polygon2d blocks 'zXY').",
		((std::vector<Vector2r>, vertices, , Attr::triggerPostLoad,
			"Vertices [m] in the body's local frame: convex, counter-clockwise, centroid at the origin. "
			"Setting them checks the polygon and updates :yref:`area<Polygon2D.area>` and :yref:`polarMoment<Polygon2D.polarMoment>`; "
			"a non-convex, clockwise, degenerate or off-centre polygon raises ValueError."))
		((Real, thickness, 1, Attr::triggerPostLoad, "Out-of-plane thickness [m] (> 0); 1 m gives forces and masses per metre of width, as in plane-strain slope analysis."))
		((Real, area, 0, (Attr::readonly | Attr::noSave), "Area [m²] (derived from vertices)."))
		((Real, polarMoment, 0, (Attr::readonly | Attr::noSave),
			"Polar second moment of area about the centroid, J = ∫(x²+y²)dA [m⁴] (derived); "
			"the polar inertia of a block is density·thickness·J [kg·m²]."))
		((Real, circumradius, 0, (Attr::readonly | Attr::noSave), "Largest distance of a vertex from the centroid [m] (derived)."))
		((Real, inradius, 0, (Attr::readonly | Attr::noSave), "Distance from the centroid to the nearest edge line [m] (derived): half the thickness of a thin block, the least half-width (a contact deeper than the thinner block's half-width along its normal stops the run: one block would pass through the other)."))
		((std::vector<Vector2r>, edgeNormals, , (Attr::readonly | Attr::noSave),
			"Outward unit normals of the edges (edge i from vertex i to i+1) in the body's local frame (derived); the contact "
			"geometry rotates them with the block instead of normalising every edge at every step."))
		((long, revision, 0, (Attr::readonly | Attr::noSave),
			"How many times the vertices or the thickness were changed after they were first set (0 after a load). A change "
			"mid-run is followed at the next step: :yref:`RbsmTimeStepper` scales the body's mass and inertia with the new "
			"area and polar moment, and the block's joints are made anew from the new shape (as new, unbonded contacts).")),
		/*ctor*/ createIndex();,
		/*py*/ .def("worldVertices", &Polygon2D::pyWorldVertices, (boost::python::arg("pos"), boost::python::arg("ori")),
			"World coordinates of the vertices for a body at *pos* with orientation *ori* (e.g. ``b.state.pos, b.state.ori``).")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(Polygon2D, Shape);

	/// What followReshape (ReshapedBlocks.hpp) last saw of this shape: revision (-1: nothing yet),
	/// thickness·area and thickness·polarMoment, and its body's mass, polar inertia and whether it was
	/// fixed (all six DOFs blocked). Not saved.
	struct Followed {
		long revision = -1;
		Real volume = 0, polar = 0;
		Real mass = 0, inertia = 0;
		bool fixed = false;
	} followed;

private:
	// the vertices and thickness the derived data were made from: a change bumps revision
	std::vector<Vector2r> madeFromVertices;
	Real                  madeFromThickness = 0;
};
REGISTER_SERIALIZABLE(Polygon2D);

//! Rotation angle about z of a planar orientation (rad, counter-clockwise).
inline Real planarAngle(const Quaternionr& q) { return 2 * std::atan2(q.z(), q.w()); }

//! cos and sin of the rotation about z of a planar orientation q = (cos θ/2, 0, 0, sin θ/2),
//! without trigonometric calls: cos θ = w² − z², sin θ = 2wz (divided by w² + z² for a q that
//! NewtonIntegrator's normalisation left slightly off unit length).
inline void planarCosSin(const Quaternionr& q, Real& c, Real& s)
{
	const Real w = q.w(), z = q.z(), n = w * w + z * z;
	c = (w * w - z * z) / n;
	s = 2 * w * z / n;
}

//! The planar pose of a body at pos with orientation q (rbsm::Pose2, planarCosSin).
inline rbsm::Pose2 planarPose(const Vector3r& pos, const Quaternionr& q)
{
	rbsm::Pose2 pose(pos.head<2>(), 1, 0);
	planarCosSin(q, pose.c, pose.s);
	return pose;
}

} // namespace yade
