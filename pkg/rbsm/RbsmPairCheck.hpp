// RbsmPairCheck: reports pairs of bodies with a block that the InteractionLoop has no geometry functor for.
#pragma once
#include <core/GlobalEngine.hpp>
#include <core/Interaction.hpp>

#include <map>

namespace yade {

class RbsmPairCheck : public GlobalEngine {
public:
	void action() override;

private:
	void        checkEngineList();
	std::size_t enginesSeen = 0; // O.engines' length at the last check of the list

public:
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RbsmPairCheck, GlobalEngine,
		"No silent pass-through: a pair of bodies, one of them a :yref:`Polygon2D`, whose bounds overlap but for whose shapes "
		"the :yref:`InteractionLoop` has no :yref:`IGeomFunctor` (a block next to a :yref:`Box`, or an Ig2 functor missing "
		"from a hand-written engine list) never interacts: the two pass through each other. This engine (before "
		"NewtonIntegrator in yade_rbsm.engines() and mixed_engines()) looks for such pairs at every step and reports each pair of shape "
		"classes once, naming the bodies and the functor that is missing; with :yref:`stopRun<RbsmPairCheck.stopRun>` the "
		"run stops after that step. Only pairs with a bound on both bodies are seen: a shape without a bound functor in "
		"the collider collides with nothing.\n\n"
		"A pair with a block that is about to touch (bounds overlap, a geometry functor exists) whose materials have no "
		":yref:`IPhysFunctor` in the loop would end the process at their first contact (YADE throws inside its OpenMP "
		"loop); it is reported the same way (asked once per material pair, through yade_rbsm.dispatch) and the run always "
		"stops after the step. A pair that touches in the step it first overlaps is not seen in time.\n\n"
		"It also stops a run whose O.engines holds more than one NewtonIntegrator (each would move the bodies by the step).",
		((bool, stopRun, true, , "Stop the run after the step in which a pair is found (True), or only report it (False)."))
		((std::vector<std::string>, reported, , Attr::readonly, "The shape pairs reported so far, as 'Polygon2D Box', and the material pairs without IPhys functor, as 'RbsmMat FrictMat' (each once).")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on
private:
	void                                checkPhys(const Interaction& I);
	std::map<std::pair<int, int>, bool> physChecked;
	long                                lastIter = -2; // step of the last call (not saved: after a load every pair is checked again) // material class indices -> an IPhys functor exists (not saved: asked again after a load)
};
REGISTER_SERIALIZABLE(RbsmPairCheck);

} // namespace yade
