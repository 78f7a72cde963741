// BlockStrainIntegrator: the strain of deformable blocks, integrated in the step with their rigid motion.
#pragma once
#include <core/Body.hpp>
#include <core/GlobalEngine.hpp>
#include <pkg/rbsm/kernel/StrainElement.hpp>

#include <vector>

namespace yade {

class DeformableState;
class Polygon2D;
class RbsmMat;

class BlockStrainIntegrator : public GlobalEngine {
public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(BlockStrainIntegrator, GlobalEngine,
		"Integrates the strain of deformable blocks (:yref:`DeformableState`, :yref:`RbsmMat.deformable`), the seed paper's eq. (4): "
		"for each block the generalized mass of (θ, ε) about its centroid, [[M_θθ, M_θεᵀ], [M_θε, M_εε]] (from its polygon's second moments "
		"and its mass: the rotation-strain coupling M_θε of an unsymmetric block is kept), is driven by the joints' torque and their load on "
		"the strain (Σ Bᵀ(r)f, added by the joint law) less the block's own stress, A·t·D·ε. The strain is integrated like NewtonIntegrator's "
		"velocities and positions (central differences, the same O.dt), with NewtonIntegrator's damping (Cundall's, per strain component); "
		"the coupled angular acceleration is handed to NewtonIntegrator as a torque (NewtonIntegrator stays YADE's). Energies (O.trackEnergy): "
		"strainKinetic (the strain modes' kinetic energy beyond the rigid rotation's) and strainElastic (½ A t εₑᵀDεₑ, εₑ = ε − εᵖ); the damping's work goes to nonviscDamp, the yield of plastic blocks (:yref:`RbsmMat.plastic`, "
		"held to Mohr-Coulomb by FLAC's explicit return after the step) to plastDissip. "
		"A fixed block (all DOFs blocked) keeps its strain. Place it right before :yref:`NewtonIntegrator` (yade_rbsm.engines() does "
		"when a material is deformable); it does nothing while no DeformableState exists. Under yade.mpy it integrates its rank's "
		"blocks (Body.subdomain), as NewtonIntegrator does.",
		((Real, maxStrain, 0.5, , "Largest principal strain (in magnitude) a block may reach [-]: the constant-strain element and its strained shape are small-strain kinematics, so a block strained beyond stops the run with a message naming it (a plastic block too weak for its loads flows without bound: a 3 mm block of a random pile reached 700 % and exploded). > 0."))
		((long, deformableSeen, -1, (Attr::readonly | Attr::noSave), "DeformableState objects alive at the last check of the joints' strainSides (a change: the joints are marked again).")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on

private:
	struct Energies {
		Real kinetic = 0, elastic = 0, damped = 0, plastic = 0;
	};
	struct Torque {
		Body::id_t id;
		Real       value;
	};
	//! One block's step; returns the torque NewtonIntegrator must see (its joints' torque corrected for the coupling).
	Real stepBlock(const Body& b, DeformableState& ds, const Polygon2D& poly, const RbsmMat& mat, Real damping, Real scale, Energies& e);
	//! The (θ, ε) step of a free block; returns the torque for NewtonIntegrator.
	Real integrate(DeformableState& ds, const rbsm::StrainMass& M, Real torque, const Vector3r& load, Real damping, Energies& e);
	//! The stress s of a plastic block held to its yield surface; its plastic strain updated.
	Vector3r yieldBlock(DeformableState& ds, const RbsmMat& mat, const rbsm::Mat3& D, const Vector3r& s, Real volume, Energies& e);
	//! Sets RbsmGeom.strainSides of every joint from its blocks' states (blocks made deformable after their joints).
	void markStrainSides();
	std::vector<Torque> corrections;
	int                 energyIds[4] = { -1, -1, -1, -1 };
};
REGISTER_SERIALIZABLE(BlockStrainIntegrator);

} // namespace yade
