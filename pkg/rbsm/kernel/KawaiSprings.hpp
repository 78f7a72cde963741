// Spring stiffness of an RBSM joint (Kawai's rigid bodies-spring model), per unit length and
// unit thickness of the joint: traction (Pa) per relative displacement (m), i.e. Pa/m = N/m^3.
//
//   plane stress:  kn = E / ((1 - nu^2) h)                 ks = E / ((1 + nu) h) = 2G/h
//   plane strain:  kn = E (1 - nu) / ((1 + nu)(1 - 2 nu) h)  ks = E / ((1 + nu) h) = 2G/h
//
// h = h1 + h2, h_i = distance from the centroid of block i to the contact line (m).
// Source: T. Kawai, "New discrete models and their application to seismic response analysis
// of structures", Nuclear Engineering and Design 48 (1978) 207-229, and Kawai (1977), the
// reference [1] of the seed paper. (The corpora reachable from this project only hold the
// abstract of Kawai 1978, not the formula text; the formulas are therefore ALSO verified here
// by the consistency argument below and by tests/unit/test_kawai_springs.cpp.)
//
// Why these values (consistency with a uniform strain field; the blocks' centroids move with
// the continuum, and the rigid rotation of each block equals the continuum's rotation):
//  * normal: a uniform strain eps across the joint (laterally constrained, eps_tt = 0) moves
//    the two centroids apart by eps*h, so sigma = kn*eps*h = E'*eps with E' = E/(1-nu^2)
//    (plane stress) or E(1-nu)/((1+nu)(1-2nu)) (plane strain): the constrained moduli.
//  * shear: pure shear gamma (symmetric gradient, no rotation) moves the two centroids
//    relative to each other by gamma*h/2 along the joint, so tau = ks*gamma*h/2 = G*gamma with
//    G = E/(2(1+nu)) in both plane states.
//
// Sign conventions belong to the joint law (MohrCoulombJoint.hpp); these are magnitudes > 0.
#pragma once

#include <pkg/rbsm/kernel/Types.hpp>

#include <stdexcept>

namespace rbsm {

enum class PlaneState { PlaneStress, PlaneStrain };

struct SpringStiffness {
	Real kn; ///< normal stiffness per unit joint area, Pa/m
	Real ks; ///< shear  stiffness per unit joint area, Pa/m
};

/// Plane strain needs 1 − 2ν at least this (ν ≤ 0.5 − 5e-9), see checkElastic.
constexpr Real kMinOneMinusTwoNu = 1e-8;

namespace detail {
	inline void checkElastic(Real E, Real nu, PlaneState ps)
	{
		if (!(E > 0)) throw std::invalid_argument("Kawai springs: Young's modulus must be > 0");
		const Real nuMax = (ps == PlaneState::PlaneStrain) ? 0.5 : 1.0;
		if (!(nu > -1 && nu < nuMax)) throw std::invalid_argument("Kawai springs: Poisson's ratio out of range (-1, 0.5) plane strain / (-1, 1) plane stress");
		// Nearer to 0.5, 1 − 2ν keeps fewer than half of its digits and E′ exceeds 1e8·E: a solid that
		// incompressible has no stable explicit step (it came out as O.dt = 0 or 1e-24 s).
		if (ps == PlaneState::PlaneStrain && !(1 - 2 * nu >= kMinOneMinusTwoNu))
			throw std::invalid_argument("Kawai springs: Poisson's ratio too close to 0.5 in plane strain (1 - 2 nu < 1e-8: nearly incompressible, no stable explicit step)");
	}
} // namespace detail

/// Constrained (oedometric) modulus E' of the plane state, Pa (see above).
inline Real constrainedModulus(Real E, Real nu, PlaneState ps)
{
	detail::checkElastic(E, nu, ps);
	return (ps == PlaneState::PlaneStress) ? E / (1 - nu * nu) : E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
}

/// Shear modulus G = E / (2 (1 + nu)), Pa.
inline Real shearModulus(Real E, Real nu) { return E / (2 * (1 + nu)); }

/// Kawai springs for one material on both sides; h = h1 + h2 > 0 (m).
inline SpringStiffness kawaiSprings(Real E, Real nu, Real h, PlaneState ps)
{
	if (!(h > 0)) throw std::invalid_argument("Kawai springs: h = h1 + h2 must be > 0");
	return SpringStiffness { constrainedModulus(E, nu, ps) / h, 2 * shearModulus(E, nu) / h };
}

/// Two different materials meeting at the joint: block i contributes a spring of length h_i of
/// its own material, and the two halves act in SERIES (the same traction crosses both):
///   1/kn = h1/E1' + h2/E2'        1/ks = h1/(2 G1) + h2/(2 G2)
/// which reduces to kawaiSprings(E, nu, h1 + h2) when both materials are equal. h1, h2 >= 0 with
/// h1 + h2 > 0 (a half of zero length, e.g. a rigid wall face, adds no compliance).
inline SpringStiffness kawaiSpringsTwoMaterials(Real E1, Real nu1, Real h1, Real E2, Real nu2, Real h2, PlaneState ps)
{
	if (!(h1 >= 0 && h2 >= 0 && h1 + h2 > 0)) throw std::invalid_argument("Kawai springs: need h1, h2 >= 0 and h1 + h2 > 0");
	const Real cn = h1 / constrainedModulus(E1, nu1, ps) + h2 / constrainedModulus(E2, nu2, ps);
	const Real cs = h1 / (2 * shearModulus(E1, nu1)) + h2 / (2 * shearModulus(E2, nu2));
	return SpringStiffness { 1 / cn, 1 / cs };
}

/// h_i: distance (m) from a block centroid to the contact line through point p with unit normal n.
inline Real distanceToLine(const Vec2& centroid, const Vec2& p, const Vec2& n) { return std::abs(n.dot(centroid - p)); }

} // namespace rbsm
