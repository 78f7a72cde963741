#include <pkg/rbsm/Gl1_RbsmPhys.hpp>

#include <core/InteractionContainer.hpp>
#include <core/Scene.hpp>

#include <GL/gl.h>
#include <algorithm>

namespace yade {

YADE_PLUGIN((Gl1_RbsmPhys));

Real Gl1_RbsmPhys::referenceForce()
{
	if (refForce > 0) return refForce;
	if (!scene) return 0;
	// once per drawn iteration, not per joint: the view redraws a paused scene many times
	if (scene != forceScene || scene->iter != forceIter) {
		forceMax = 0;
		for (const auto& I : *scene->interactions)
			if (I && I->phys)
				if (const RbsmPhys* p = dynamic_cast<const RbsmPhys*>(I->phys.get())) forceMax = std::max(forceMax, p->normalForce);
		forceScene = scene;
		forceIter  = scene->iter;
	}
	return forceMax;
}

void Gl1_RbsmPhys::go(const shared_ptr<IPhys>& ip, const shared_ptr<Interaction>& I, const shared_ptr<Body>&, const shared_ptr<Body>&, bool)
{
	const RbsmPhys& p = static_cast<const RbsmPhys&>(*ip);
	const RbsmGeom* g = I ? dynamic_cast<const RbsmGeom*>(I->geom.get()) : nullptr;
	if (!g || !(g->length > 0) || !g->rule || g->rule->n != p.nPoints) return; // no segment to cut into the points' pieces
	Real width = lineWidth > 0 ? lineWidth : 1;
	if (maxWidth > width) {
		const Real ref = referenceForce();
		if (ref > 0) width += (maxWidth - width) * std::clamp(p.normalForce / ref, Real(0), Real(1));
	}
	glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_CURRENT_BIT);
	glDisable(GL_LIGHTING);
	glDisable(GL_DEPTH_TEST); // the segment lies on the blocks' edges: draw it over them
	glLineWidth(GLfloat(width));
	glBegin(GL_LINES);
	Real from = 0; // piece k runs over [w_0 + ... + w_(k-1), w_0 + ... + w_k] of p0 -> p1
	for (int k = 0; k < p.nPoints; k++) {
		const rbsm::JointPointState& s = p.point(k).joint;
		const Vector3r& c  = s.open ? openColor : s.slipping ? slippingColor : !s.intact ? brokenColor : intactColor;
		const Real      to = (k + 1 == p.nPoints) ? 1 : from + g->rule->w[k];
		const Vector2r  a = g->p0 + from * (g->p1 - g->p0), b = g->p0 + to * (g->p1 - g->p0);
		glColor3d(c.x(), c.y(), c.z());
		glVertex3d(a.x(), a.y(), 0);
		glVertex3d(b.x(), b.y(), 0);
		from = to;
	}
	glEnd();
	glPopAttrib();
}

} // namespace yade
