// The deformable block of the seed's eq. (4) (Takeuchi's hybrid-type penalty method): a rigid
// motion plus a constant strain per block. In the block's own frame, r = x − c from its centroid,
//   u(r) = d + θ ẑ × r + B(r) ε,   ε = (εxx, εyy, γxy),   B(r) = [[rx, 0, ry/2], [0, ry, rx/2]],
// six numbers per block. Per unit density and thickness the (θ, ε) part of the mass matrix is
//   M_θθ = Ixx + Iyy,  M_θε = ∫(−ry, rx)·B dA = (−Ixy, Ixy, (Ixx − Iyy)/2),
//   M_εε = ∫BᵀB dA = [[Ixx, 0, Ixy/2], [0, Iyy, Ixy/2], [Ixy/2, Ixy/2, (Ixx + Iyy)/4]],
// Ixx = ∫rx² dA, Iyy = ∫ry² dA, Ixy = ∫rx ry dA (M_dθ = M_dε = 0 about the centroid). The block's own
// stiffness on ε is K_εε = A t D, D the plane elasticity matrix (engineering shear strain).
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

#include <Eigen/Core>
#include <vector>

namespace rbsm {

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Vec4 = Eigen::Matrix<Real, 4, 1>;
using Mat4 = Eigen::Matrix<Real, 4, 4>;

/// Area and second moments of a polygon about its centroid (vertices CCW about the centroid).
struct AreaMoments {
	Real area = 0; ///< m²
	Real Ixx  = 0; ///< ∫ rx² dA [m⁴] (the x-spread: the moment about the y axis)
	Real Iyy  = 0; ///< ∫ ry² dA [m⁴]
	Real Ixy  = 0; ///< ∫ rx ry dA [m⁴]
};
AreaMoments areaMoments(const std::vector<Vec2>& verticesAboutCentroid);

/// Plane elasticity (σxx, σyy, σxy) = D (εxx, εyy, γxy): plane strain or plane stress, E > 0, −1 < ν < 0.5.
Mat3 elasticityMatrix(Real young, Real poisson, bool planeStrain);

/// The displacement B(r) ε of the strain at r (block frame).
inline Vec2 strainDisplacement(const Vec2& r, const Vec3& eps)
{
	return Vec2(r.x() * eps[0] + 0.5 * r.y() * eps[2], r.y() * eps[1] + 0.5 * r.x() * eps[2]);
}

/// The load Bᵀ Q on ε of forces f_k at r_k, from their first moment Q = Σ r_k ⊗ f_k (Q(a, b) = Σ r_a f_b,
/// block frame): (Qxx, Qyy, (Qxy + Qyx)/2).
inline Vec3 strainLoad(const Eigen::Matrix<Real, 2, 2>& Q) { return Vec3(Q(0, 0), Q(1, 1), 0.5 * (Q(0, 1) + Q(1, 0))); }

/// The (θ, ε) mass of a block of density ρ and thickness t, and what the integration needs of it.
struct StrainMass {
	Real polar       = 0;            ///< M_θθ = ρ t (Ixx + Iyy) [kg m²]
	Vec3 thetaStrain = Vec3::Zero(); ///< M_θε [kg m²]
	Mat3 strain      = Mat3::Zero(); ///< M_εε [kg m²]
	Mat4 inverse     = Mat4::Zero(); ///< [[M_θθ, M_θεᵀ], [M_θε, M_εε]]⁻¹
};
StrainMass strainMass(const AreaMoments& m, Real density, Real thickness);

/// The accelerations (θ̈, ε̈) of the coupled (θ, ε) equation under the torque T and the strain load P.
inline Vec4 strainAccelerations(const StrainMass& M, Real torque, const Vec3& load)
{
	return M.inverse * Vec4(torque, load[0], load[1], load[2]);
}

/// ω² of the block's own strain modes alone, K_εε = A t D, with θ free and coupled: the largest
/// eigenvalue of the 4×4 problem with no stiffness on θ, λ_max((M_εε − M_θε M_θεᵀ / M_θθ)⁻¹ K_εε)
/// (λ_max(M_εε⁻¹ K_εε) only where M_θε = 0) [rad²/s²].
Real ownStrainOmega2(const StrainMass& M, const Mat3& stiffness);

} // namespace rbsm
