// Ip2_RbsmMat_RbsmMat_RbsmPhys: joint properties of two RbsmMat blocks.
#pragma once
#include <core/Dispatching.hpp>
#include <pkg/rbsm/RbsmMat.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>

#include <atomic>

namespace yade {

class Ip2_RbsmMat_RbsmMat_RbsmPhys : public IPhysFunctor {
public:
	void go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I) override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ip2_RbsmMat_RbsmMat_RbsmPhys, IPhysFunctor,
		"Joint springs and strength of two :yref:`RbsmMat` blocks.\n\n"
		"Springs per unit area (Kawai 1978, Nucl. Eng. Des. 48:207; Kawai 1977), h_i the distance from block i's centroid "
		"to the contact line:\n\n"
		"* plane strain: kn = E(1−ν)/((1+ν)(1−2ν) h), ks = E/((1+ν) h)\n"
		"* plane stress: kn = E/((1−ν²) h), ks = E/((1+ν) h)\n\n"
		"with h = h1 + h2 for one material; for two materials the halves act in series, "
		"1/kn = h1/E1′ + h2/E2′, 1/ks = h1/(2G1) + h2/(2G2). A uniform strain ε across the joint then gives σ = E′ε, and a "
		"pure shear γ gives τ = Gγ (patch test).\n\n"
		"Strength: the weaker material governs, c = min(c1, c2), tanφ = min(tanφ1, tanφ2), σt = min(σt1, σt2). Joints are "
		"intact (cohesive, tensile) only if made while :yref:`setCohesionNow<Ip2_RbsmMat_RbsmMat_RbsmPhys.setCohesionNow>` or "
		":yref:`setCohesionOnNewContacts<Ip2_RbsmMat_RbsmMat_RbsmPhys.setCohesionOnNewContacts>` is set: the joints of a block "
		"assembly are bonded at the start, contacts made later (blocks sliding onto others) are frictional.",
		((bool, setCohesionNow, false, , "Make the contacts created during the next step that creates contacts intact (bonded), normally the first step of a block assembly; reset to False after that step. (Set while no contact forms, it waits for the first step that makes one.)"))
		((bool, setCohesionOnNewContacts, false, , "Make every new contact intact (bonded)."))
		((long, cohesionIter, -1, Attr::hidden, "Step at which setCohesionNow took effect (saved: a scene saved while setCohesionNow is pending must not bond the contacts of the first step after the load).")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(RbsmMat, RbsmMat);
	//! Joints made so far (any scene): RbsmTimeStepper looks for new joints only when it has grown.
	static inline std::atomic<long> jointsMade { 0 };

private:
	//! The joint's properties (go, once per contact: when it has none yet).
	void makePhys(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I);
};
REGISTER_SERIALIZABLE(Ip2_RbsmMat_RbsmMat_RbsmPhys);

} // namespace yade
