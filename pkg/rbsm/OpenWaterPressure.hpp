// OpenWaterPressure: still open water's pressure on the faces of the blocks below a water table.
#pragma once
#include <core/GlobalEngine.hpp>

#include <vector>

namespace yade {

class OpenWaterPressure : public GlobalEngine {
public:
	void action() override;
	void postLoad(OpenWaterPressure&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(OpenWaterPressure, GlobalEngine,
		"Blocks standing in open water (a reservoir, a flooded toe, a block submerged in a lake): every Polygon2D block gets the "
		"still water's pressure u = γw·(h(x) − y) ≥ 0 on its whole boundary below the :yref:`phreatic<OpenWaterPressure.phreatic>` "
		"surface, −∮ u n ds and its moment (exactly for the polyline water table): Archimedes' buoyancy, and the pressure on the faces of "
		"its joints. The joint law must then know it (:yref:`Law2_RbsmGeom_RbsmPhys_MohrCoulomb.openWater`): a wet joint adds no pressure "
		"of its own, a closed dry contact takes its faces' pressure off (the water around presses it shut). yade_rbsm.slope.set_water"
		"(phreatic, open_water=True) sets both with one water table. The water stays as given (no flow); its work on the blocks is "
		"O.energy's waterWork. On a deformable block the pressure loads its rigid motion, not its strain. Place it before "
		":yref:`NewtonIntegrator`. Fixed blocks are skipped.",
		((std::vector<Vector2r>, phreatic, , Attr::triggerPostLoad, "The water table [m], a polyline of strictly increasing x, level beyond its ends; empty: no water."))
		((Real, waterUnitWeight, 9810, Attr::triggerPostLoad, "Unit weight of the water γw [N/m³]."))
		((int, waterWorkIx, -1, (Attr::hidden | Attr::noSave), "Index of waterWork in O.energy.")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on

private:
	std::vector<Vector3r> lastLoad; // each block's (fx, fy, moment) of the last step: the work by the trapezoid rule
};
REGISTER_SERIALIZABLE(OpenWaterPressure);

} // namespace yade
