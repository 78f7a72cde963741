#include <pkg/rbsm/Gl1_RbsmGeom.hpp>

#include <GL/gl.h>

namespace yade {

YADE_PLUGIN((Gl1_RbsmGeom));

void Gl1_RbsmGeom::go(const shared_ptr<IGeom>& ig, const shared_ptr<Interaction>&, const shared_ptr<Body>&, const shared_ptr<Body>&, bool)
{
	const RbsmGeom& g = static_cast<const RbsmGeom&>(*ig);
	if (!(g.length > 0)) return; // not made yet (a potential contact) or degenerate: nothing to draw
	glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_CURRENT_BIT);
	glDisable(GL_LIGHTING);
	glDisable(GL_DEPTH_TEST); // the segment lies on the blocks' edges: draw it over them
	glLineWidth(GLfloat(lineWidth > 0 ? lineWidth : 1));
	glColor3d(color.x(), color.y(), color.z());
	const Vector2r mid = 0.5 * (g.p0 + g.p1), tip = mid + normalLength * g.length * g.normal;
	glBegin(GL_LINES);
	glVertex3d(g.p0.x(), g.p0.y(), 0);
	glVertex3d(g.p1.x(), g.p1.y(), 0);
	if (normalLength > 0) {
		glVertex3d(mid.x(), mid.y(), 0);
		glVertex3d(tip.x(), tip.y(), 0);
	}
	glEnd();
	glPopAttrib();
}

} // namespace yade
