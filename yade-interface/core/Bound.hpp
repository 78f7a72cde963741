// Approximate extent of a body for the collider (YADE's Bound); Aabb is the axis-aligned box.
#pragma once
#include <lib/multimethods/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>

namespace yade {
class Bound : public Serializable, public Indexable {
public:
	~Bound() override;
	YADE_BUILTIN_CLASS(Bound, Serializable,
		((int, lastUpdateIter, 0, Attr::readonly, ""))
		((Vector3r, refPos, Vector3r(NaN, NaN, NaN), Attr::readonly, ""))
		((Real, sweepLength, 0, Attr::readonly, ""))
		((Vector3r, color, Vector3r(1, 1, 1), , ""))
		((Vector3r, min, Vector3r(NaN, NaN, NaN), (Attr::noSave | Attr::readonly), "Lower corner of the box."))
		((Vector3r, max, Vector3r(NaN, NaN, NaN), (Attr::noSave | Attr::readonly), "Upper corner of the box.")),
		/*ctor*/)
	YADE_DECLARE_INDEX_COUNTER
};
} // namespace yade
