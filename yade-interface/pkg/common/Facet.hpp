// A triangle (YADE's Facet), vertices in its body's frame. Layout only.
#pragma once
#include <core/Shape.hpp>

namespace yade {
class Facet : public Shape {
public:
	Vector3r ne[3]; // derived by Debian's postLoad: edge normals, inscribed radius, vertex data
	Real     icr;
	Real     vl[3];
	Vector3r vu[3];
	std::vector<Vector3r> vertices; // [m], local frame
	Vector3r              normal;   // derived
	Real                  area;     // derived
	Facet() = delete;
	~Facet() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
	YADE_DECLARE_CLASS_INDEX
};
} // namespace yade
