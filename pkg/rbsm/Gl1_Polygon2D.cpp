#include <pkg/rbsm/Gl1_Polygon2D.hpp>

#include <GL/gl.h>

namespace yade {

YADE_PLUGIN((Gl1_Polygon2D));

void Gl1_Polygon2D::go(const shared_ptr<Shape>& shape, const shared_ptr<State>&, bool wire, const GLViewInfo&)
{
	const Polygon2D& p = static_cast<const Polygon2D&>(*shape);
	if (p.vertices.size() < 3) return; // a Polygon2D without vertices (Bo1 reports it): nothing to draw
	// Restores what is changed here, so the view's other functors find YADE's state (lighting on).
	glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_POLYGON_BIT | GL_CURRENT_BIT);
	glDisable(GL_LIGHTING);
	const Vector3r& c = shape->color;
	if (!wire) {
		// pushed back in depth, so that the outline (and the joints) on the same plane stay visible
		glEnable(GL_POLYGON_OFFSET_FILL);
		glPolygonOffset(1, 1);
		glColor3d(c.x(), c.y(), c.z());
		glNormal3d(0, 0, 1);
		glBegin(GL_POLYGON); // convex and counter-clockwise (Polygon2D checks it)
		for (const Vector2r& v : p.vertices)
			glVertex3d(v.x(), v.y(), 0);
		glEnd();
	}
	if (wire || outline) {
		const Vector3r& o = wire ? c : outlineColor;
		glLineWidth(GLfloat(outlineWidth > 0 ? outlineWidth : 1));
		glColor3d(o.x(), o.y(), o.z());
		glBegin(GL_LINE_LOOP);
		for (const Vector2r& v : p.vertices)
			glVertex3d(v.x(), v.y(), 0);
		glEnd();
	}
	glPopAttrib();
}

} // namespace yade
