// Gl1_RbsmPhys: draws an RBSM joint in YADE's qt view (Renderer.intrPhys), coloured by the state of
// its integration points, optionally with the normal force as line width.
#pragma once
#include <pkg/common/GLDrawFunctors.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>

namespace yade {

class Gl1_RbsmPhys : public GlIPhysFunctor {
public:
	void go(const shared_ptr<IPhys>& phys, const shared_ptr<Interaction>& I, const shared_ptr<Body>& b1, const shared_ptr<Body>& b2, bool wire) override;
	static inline Vector3r intactColor   = Vector3r(0, 0.8, 0);
	static inline Vector3r brokenColor   = Vector3r(0.2, 0.4, 1);
	static inline Vector3r slippingColor = Vector3r(1, 0, 0);
	static inline Vector3r openColor     = Vector3r(1, 0.85, 0);
	static inline Real     lineWidth     = 3;
	static inline Real     maxWidth      = 0;
	static inline Real     refForce      = 0;
	//! The force drawn at maxWidth: refForce, or the largest compressive normal force of the scene's joints.
	Real referenceForce();
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Gl1_RbsmPhys, GlIPhysFunctor,
		"Renders an RBSM joint (:yref:`RbsmPhys`) when the renderer's ``intrPhys`` is on: the contact segment, cut into one "
		"piece per integration point (piece k is w_k of the length), each piece coloured by the state of its point: "
		"intact (``Gl1_RbsmPhys.intactColor``, green), broken but closed, carrying friction only (``brokenColor``, blue), "
		"slipping this step (``slippingColor``, red), open (``openColor``, yellow). Line width ``Gl1_RbsmPhys.lineWidth`` "
		"(pixels, default 3); with ``Gl1_RbsmPhys.maxWidth`` > lineWidth the width grows with the joint's normal force "
		"(compression), reaching maxWidth at ``Gl1_RbsmPhys.refForce`` [N] (0: the largest normal force of the scene).",
		/*attrs*/,
		/*ctor*/,
		/*py*/
		.add_static_property("intactColor", +[]() { return intactColor; }, +[](const Vector3r& v) { intactColor = v; })
		.add_static_property("brokenColor", +[]() { return brokenColor; }, +[](const Vector3r& v) { brokenColor = v; })
		.add_static_property("slippingColor", +[]() { return slippingColor; }, +[](const Vector3r& v) { slippingColor = v; })
		.add_static_property("openColor", +[]() { return openColor; }, +[](const Vector3r& v) { openColor = v; })
		.add_static_property("lineWidth", +[]() { return lineWidth; }, +[](Real v) { lineWidth = v; })
		.add_static_property("maxWidth", +[]() { return maxWidth; }, +[](Real v) { maxWidth = v; })
		.add_static_property("refForce", +[]() { return refForce; }, +[](Real v) { refForce = v; })
	);
	// clang-format on
	RENDERS(RbsmPhys);

private:
	const Scene* forceScene = nullptr; // referenceForce() computed for this scene at this iteration
	long         forceIter  = -1;
	Real         forceMax   = 0;
};
REGISTER_SERIALIZABLE(Gl1_RbsmPhys);

} // namespace yade
