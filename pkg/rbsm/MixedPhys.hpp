// Contact properties of blocks with YADE's own bodies, shared by the IPhys functors of the material
// pairs (Ip2_RbsmMat_RbsmMat_RbsmPhys, Ip2_RbsmMat_FrictMat_FrictPhys).
#pragma once
#include <core/Interaction.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>

namespace yade {
class Material;
namespace rbsm_mixed {
	/// Young's modulus, Poisson's ratio, friction angle, cohesion and tensile strength of an RbsmMat or
	/// a FrictMat (which has no cohesion or tensile strength: 0).
	struct Elastic {
		Real young = 0, poisson = 0, frictionAngle = 0, cohesion = 0, tensileStrength = 0;
		bool rbsm = false;
		Real jointKn = 0, jointKs = 0; ///< RbsmMat's given joint stiffness (0: Kawai's)
		bool ductile = false;
	};

	/// A joint stiffness given by the materials (> 0): the smaller of two, or the one given; else kawai.
	inline Real givenOr(Real a, Real b, Real kawai)
	{
		if (a > 0 && b > 0) return a < b ? a : b;
		if (a > 0) return a;
		if (b > 0) return b;
		return kawai;
	}
	Elastic elasticOf(const Material& m);

	/// The reference radii (refR1, refR2) of a point contact of YADE's sphere laws (a GenericSpheresContact
	/// such as ScGeom); false for any other geometry.
	bool pointContactRadii(const IGeom* geom, Real& R1, Real& R2);

	/// YADE's FrictPhys of a point contact exactly as Ip2_FrictMat_FrictMat_FrictPhys makes it from two
	/// FrictMats: k_i = E_i R_i, kn = 2 k1 k2/(k1 + k2), ks the same with E_i ν_i, tan of the smaller
	/// friction angle. Made by the class factory (Debian's constructor).
	shared_ptr<IPhys> frictPhys(Real R1, Real R2, const Elastic& m1, const Elastic& m2);

	/// The joint of a block on a rigid boundary (Wall, Facet): Kawai's springs of the block's half only
	/// (the boundary's distance h to the contact line is 0: it adds no compliance), the weaker friction,
	/// cohesion and tensile strength of the two materials; frictional (never bonded).
	shared_ptr<RbsmPhys> boundaryJointPhys(const RbsmGeom& g, const Elastic& block, bool blockIsBody1, const Elastic& boundary, bool planeStrain);
} // namespace rbsm_mixed
} // namespace yade
