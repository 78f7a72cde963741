// Point contact with incremental shear (YADE's ScGeom), the geometry of YADE's sphere laws. Layout
// and the two members the plugin calls, both defined in Debian's libpkg_dem.so; the plugin makes one
// through the class factory (Debian's constructor, which binds radius1/radius2 to refR1/refR2).
#pragma once
#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <pkg/dem/DemXDofGeom.hpp>

namespace yade {
class ScGeom : public GenericSpheresContact {
	Vector3r twist_axis, orthonormal_axis; // the rotation of the contact plane in the last step
public:
	Real &   radius1, &radius2; // refR1, refR2
	Real     penetrationDepth;  // [m], > 0 overlapping
	Vector3r shearInc;          // relative tangential displacement of the last step [m]

	/// Sets normal := currentNormal and, from the two states, the rotation of the contact plane since
	/// the last step and shearInc (relative velocity at contactPoint without its normal part, times
	/// dt; with avoidGranularRatcheting the branch vectors are radius × normal, for spheres only).
	void precompute(const State& rbp1, const State& rbp2, const Scene* scene, const shared_ptr<Interaction>& c, const Vector3r& currentNormal,
	                bool isNew, const Vector3r& shift2, bool avoidGranularRatcheting = true);
	Vector3r& rotate(Vector3r& tangentVector) const;

	ScGeom() = delete;
	~ScGeom() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
