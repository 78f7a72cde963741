// Gl1_Polygon2D: draws a Polygon2D block in YADE's qt view.
#pragma once
#include <pkg/common/GLDrawFunctors.hpp>
#include <pkg/rbsm/Polygon2D.hpp>

namespace yade {

class Gl1_Polygon2D : public GlShapeFunctor {
public:
	void go(const shared_ptr<Shape>& shape, const shared_ptr<State>& state, bool wire, const GLViewInfo& info) override;
	// Drawing options for every block (static, like YADE's Gl1_* options: the view makes its own functors).
	static inline bool     outline      = true;
	static inline Real     outlineWidth = 1;
	static inline Vector3r outlineColor = Vector3r(0.15, 0.15, 0.15);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Gl1_Polygon2D, GlShapeFunctor,
		"Renders a :yref:`Polygon2D` block in the qt view: the polygon filled in the shape's :yref:`color<Shape.color>` "
		"(unlit, so the colour on screen is the colour set), in the x-y plane at z = 0 of the body's frame (the view places it "
		"at the body's position and orientation), with its outline; with :yref:`wire<Shape.wire>` (or the renderer's ``wire``) "
		"only the outline, in the body's colour. Class-wide options (like YADE's other ``Gl1_*``): ``Gl1_Polygon2D.outline`` "
		"(draw the outline of filled blocks, default True), ``Gl1_Polygon2D.outlineWidth`` (pixels, default 1), "
		"``Gl1_Polygon2D.outlineColor`` (outline of filled blocks, default dark grey).",
		/*attrs*/,
		/*ctor*/,
		/*py*/
		.add_static_property("outline", +[]() { return outline; }, +[](bool v) { outline = v; })
		.add_static_property("outlineWidth", +[]() { return outlineWidth; }, +[](Real v) { outlineWidth = v; })
		.add_static_property("outlineColor", +[]() { return outlineColor; }, +[](const Vector3r& v) { outlineColor = v; })
	);
	// clang-format on
	RENDERS(Polygon2D);
};
REGISTER_SERIALIZABLE(Gl1_Polygon2D);

} // namespace yade
