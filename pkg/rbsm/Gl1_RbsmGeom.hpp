// Gl1_RbsmGeom: draws the contact segment of an RBSM joint in YADE's qt view (Renderer.intrGeom).
#pragma once
#include <pkg/common/GLDrawFunctors.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>

namespace yade {

class Gl1_RbsmGeom : public GlIGeomFunctor {
public:
	void go(const shared_ptr<IGeom>& geom, const shared_ptr<Interaction>& I, const shared_ptr<Body>& b1, const shared_ptr<Body>& b2, bool wire) override;
	static inline Vector3r color        = Vector3r(1, 1, 1);
	static inline Real     lineWidth    = 2;
	static inline Real     normalLength = 0.2;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Gl1_RbsmGeom, GlIGeomFunctor,
		"Renders the geometry of an RBSM joint (:yref:`RbsmGeom`) when the renderer's ``intrGeom`` is on: the contact segment "
		"p0–p1 and a tick along the normal (from body 1 to body 2) at its middle. Class-wide options: ``Gl1_RbsmGeom.color`` "
		"(default white), ``Gl1_RbsmGeom.lineWidth`` (pixels, default 2), ``Gl1_RbsmGeom.normalLength`` (length of the normal "
		"tick as a fraction of the contact length, default 0.2; 0 hides it).",
		/*attrs*/,
		/*ctor*/,
		/*py*/
		.add_static_property("color", +[]() { return color; }, +[](const Vector3r& v) { color = v; })
		.add_static_property("lineWidth", +[]() { return lineWidth; }, +[](Real v) { lineWidth = v; })
		.add_static_property("normalLength", +[]() { return normalLength; }, +[](Real v) { normalLength = v; })
	);
	// clang-format on
	RENDERS(RbsmGeom);
};
REGISTER_SERIALIZABLE(Gl1_RbsmGeom);

} // namespace yade
