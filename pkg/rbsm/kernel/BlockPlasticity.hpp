// Mohr–Coulomb plasticity of a deformable block (issue 39): the explicit return map FLAC's zones use,
// once per block and step. Plane stresses (σxx, σyy, σxy), tension positive; in principal stresses
// σ1 ≥ σ3 (σ1 the least compressive) the block may not exceed
//   shear    f = (σ1 − σ3)/2 + (σ1 + σ3)/2 · sin φ − c cos φ ≤ 0,
//   tension  σ1 ≤ σt (at most the apex c cot φ),
// with the plastic potential g = (σ1 − σ3)/2 + (σ1 + σ3)/2 · sin ψ (ψ = 0: no plastic change of area).
// The out-of-plane stress is taken as the intermediate one (plane strain), as in plane limit analysis.
#pragma once

#include <pkg/rbsm/kernel/StrainElement.hpp>

namespace rbsm {

/// The strength of a block's material.
struct MohrCoulombStrength {
	Real cohesion        = 0; ///< c [Pa], ≥ 0
	Real frictionAngle   = 0; ///< φ [rad], in [0, π/2)
	Real tensileStrength = 0; ///< σt [Pa], ≥ 0 (the apex c cot φ if lower)
	Real dilatancy       = 0; ///< ψ [rad], in [0, φ]
};

/// Which part of the yield surface a stress was returned to.
enum class YieldMode : int { elastic = 0, shear = 1, tension = 2, corner = 3 };

struct PlasticReturn {
	Vec3      stress;                ///< the admissible stress (σxx, σyy, σxy) [Pa]
	Vec3      plasticStrain;         ///< the plastic strain of the return, D⁻¹(σ_trial − σ) (εxx, εyy, γxy)
	Real      plasticShear = 0;      ///< its largest shear, |Δε1ᵖ − Δε3ᵖ| (the accumulated measure's increment)
	YieldMode mode = YieldMode::elastic;
};

/// f of a plane stress (> 0: outside the shear surface) [Pa].
Real mohrCoulombShear(const Vec3& stress, const MohrCoulombStrength& s);

/// The return of an elastic trial stress onto the Mohr–Coulomb surface with its tension cut-off, for an
/// isotropic plane elasticity D (elasticityMatrix): the stress itself where it is admissible.
PlasticReturn mohrCoulombReturn(const Vec3& trialStress, const Mat3& D, const MohrCoulombStrength& s);

} // namespace rbsm
