// Ip2_RbsmMat_FrictMat_FrictPhys: contact properties of an RbsmMat body and a FrictMat one (sphere, wall, facet).
#pragma once
#include <core/Dispatching.hpp>

namespace yade {

class Ip2_RbsmMat_FrictMat_FrictPhys : public IPhysFunctor {
public:
	void go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I) override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ip2_RbsmMat_FrictMat_FrictPhys, IPhysFunctor,
		"Contact properties of an :yref:`RbsmMat` body (body 1) and a :yref:`FrictMat` one (body 2), by the kind of contact "
		"geometry. YADE's IPhys dispatch needs the materials in this order (Debian's build asserts it): the block is body 1 "
		"of :yref:`Ig2_Polygon2D_Sphere_ScGeom`, :yref:`Ig2_Polygon2D_Wall_RbsmGeom` and :yref:`Ig2_Polygon2D_Facet_RbsmGeom`, "
		"the wall or facet body 1 of YADE's Ig2_Wall_Sphere_ScGeom and Ig2_Facet_Sphere_ScGeom. (Two spheres, one of RbsmMat "
		"and one of FrictMat, come in either order: give the spheres of a scene one material class.)\n\n"
		"* a point contact (:yref:`ScGeom`: a sphere against a block, or a FrictMat sphere against an RbsmMat wall, facet "
		"or sphere): :yref:`FrictPhys` as :yref:`Ip2_FrictMat_FrictMat_FrictPhys` makes it, the RbsmMat's young, poisson "
		"and frictionAngle read as a FrictMat's: kn = 2 k1 k2/(k1 + k2), k_i = E_i R_i; ks likewise with E_i ν_i; "
		"tan of the smaller friction angle. For :yref:`Law2_ScGeom_FrictPhys_CundallStrack`.\n"
		"* an edge contact (:yref:`RbsmGeom`: a block on a FrictMat :yref:`Wall` or :yref:`Facet`): :yref:`RbsmPhys` of a "
		"rigid boundary, Kawai's springs of the block's half of the joint (kn = E′/h, ks = 2G/h, h the distance from the "
		"block's centroid to the contact line), the smaller friction angle, no cohesion or tensile strength (FrictMat has "
		"none). For :yref:`Law2_RbsmGeom_RbsmPhys_MohrCoulomb`.",
		/*attrs*/,
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(RbsmMat, FrictMat);
};
REGISTER_SERIALIZABLE(Ip2_RbsmMat_FrictMat_FrictPhys);

} // namespace yade
