// Point-contact geometry common to YADE's sphere laws (GenericSpheresContact). Layout only.
#pragma once
#include <core/IGeom.hpp>

namespace yade {
class GenericSpheresContact : public IGeom {
public:
	Vector3r normal;       // unit, from body 1 to body 2
	Vector3r contactPoint; // [m]
	Real     refR1, refR2; // reference radii [m]
	GenericSpheresContact() = delete;
	~GenericSpheresContact() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
