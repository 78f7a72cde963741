// Stability limit of the explicit central-difference scheme for rigid 2D blocks joined by
// RBSM springs: dt_crit = 2 / omega_max, omega_max^2 = largest eigenvalue of M^-1 K
// (undamped; damping only lowers the limit further, the caller applies a safety factor).
//
// DOFs per block: (ux, uy, theta); mass matrix diag(m, m, I). A fixed block has no DOFs.
// Every integration point k of a contact is a pair of springs (normal, tangential) of stiffness
// k_n a_k and k_s a_k (N/m) joining the material points of both blocks at x_k. The relative
// displacement of body 2 w.r.t. body 1 along a unit direction d at x_k is B q with
//   B = [ -d^T, -(r1 x d), d^T, (r2 x d) ],  r_i = x_k - c_i,  (r x d) = r.x d.y - r.y d.x,
// (small rotation theta moves a point by theta * (-r.y, r.x)), so K = sum k a B^T B.
//
// A deformable block (StrainElement.hpp) has 6 DOFs (ux, uy, theta, exx, eyy, gxy), the strain in its
// own frame R: its point x_k moves by an extra R B(R^T r) eps, so its part of B gains
// (B(R^T r)^T R^T d) with the sign of its rigid terms; its mass is blockdiag(m, m, [[I, M_te^T],
// [M_te, M_ee]]) and its own K_ee adds to its diagonal block. With no deformable body every function
// below runs the 3-DOF code alone (same numbers, same cost).
#pragma once

#include <pkg/rbsm/kernel/StrainElement.hpp>
#include <pkg/rbsm/kernel/Types.hpp>

#include <utility>
#include <vector>

namespace rbsm {

struct DynBody {
	Real mass    = 0;             ///< kg
	Real inertia = 0;             ///< polar moment of inertia about the centroid, kg m^2
	Vec2 centroid = Vec2::Zero(); ///< m
	bool fixed   = false;         ///< all DOFs prescribed (3, or 6 if deformable)
	bool deformable = false;      ///< the block carries strain DOFs (exx, eyy, gxy) in its own frame
	Real cosAngle = 1, sinAngle = 0;     ///< rotation of the block's frame (the strain's frame) in the world
	Vec3 thetaStrainMass = Vec3::Zero(); ///< M_te [kg m^2] (inertia above is M_tt)
	Mat3 strainMass = Mat3::Zero();      ///< M_ee [kg m^2]
	Mat3 strainStiffness = Mat3::Zero(); ///< K_ee = A t D [N m] (the block's own stiffness on eps)
};

struct DynContact {
	int               body1 = -1, body2 = -1; ///< indices into the body list
	Vec2              normal  = Vec2::Zero(); ///< unit, body 1 -> body 2
	Vec2              tangent = Vec2::Zero(); ///< unit, (-n.y, n.x)
	Real              kn = 0, ks = 0;         ///< Pa/m (per unit area)
	std::vector<Vec2> points;                 ///< integration points, world (m)
	std::vector<Real> areas;                  ///< tributary areas (m^2), same size as points
};

/// Rigorous lower bound of dt_crit from the BLOCK Gershgorin theorem (Feingold & Varga 1962)
/// applied to the symmetric matrix S = M^-1/2 K M^-1/2 (same eigenvalues as M^-1 K), with one
/// 3x3 block per free body (6x6 for a deformable one, S = L^-1 K L^-T with M_b = L_b L_b^T, the
/// block's own K_ee included in S_bb): every eigenvalue lies within sum_{c != b} ||S_bc||_2 of an eigenvalue
/// of some diagonal block S_bb, hence
///     omega_max^2 <= max_b [ lambda_max(S_bb) + sum_{c != b} ||S_bc||_2 ].
/// Unlike the scalar Gershgorin bound this is invariant under rotations of the xy frame and exact
/// for a single block on fixed supports. K is assembled exactly per body pair (all contacts
/// between the same pair summed first, by sorting the contacts by pair). Fixed bodies' DOFs are
/// removed. Cost O(#integration points + #contacts log #contacts), one closed-form 3x3 eigenvalue
/// per block and per body pair. Returns +inf if nothing is stiff. Throws std::invalid_argument on bad input.
///
/// perBody (optional): the bound of each body's rows, lambda_max(S_bb) + sum ||S_bc|| [rad^2/s^2]
/// (0 for fixed bodies): every eigenvalue lies below one of them (the highest is the result's).
/// perBodyDiag (optional): the part lambda_max(S_bb) of each of those bounds (the rest couples b to
/// its neighbours), for densityScale. Throws std::invalid_argument if a free deformable body's
/// (theta, eps) mass is not positive definite.
Real criticalTimeStepGershgorin(
        const std::vector<DynBody>&    bodies,
        const std::vector<DynContact>& contacts,
        std::vector<Real>*             perBody     = nullptr,
        std::vector<Real>*             perBodyDiag = nullptr);

/// Density scaling of one block for a target omega_T^2 = (2/dt_target)^2: the factor s >= 1 by which
/// its mass and inertia may be multiplied so that its Gershgorin row bound, diag + off, falls to
/// omega_T^2. Scaling b by s divides its diagonal block of S = M^-1/2 K M^-1/2 by s and each coupling
/// block S_bc by sqrt(s s_c) >= sqrt(s) (neighbours are scaled by s_c >= 1 or not at all), so
/// diag/s + off/sqrt(s) <= omega_T^2 suffices: with x = 1/sqrt(s), diag x^2 + off x = omega_T^2.
/// 1 if the block is already below the target (or has no joints). A deformable block scales its whole
/// mass (mass, inertia, thetaStrainMass, strainMass) by s.
Real densityScale(Real diag, Real off, Real omegaT2);

/// How much one contact raises the block Gershgorin bound of its two bodies' rows (the perBody
/// values above): lambda_max(S_bb) + ||S_12|| for each side (0 for a fixed body; the coupling term
/// only between two free bodies). Both terms are subadditive over contacts, so adding these to the
/// bounds of an earlier estimate bounds the estimate with the contact included: a contact made
/// between two estimates is accounted for at once, without a new estimate (a deformable block's own
/// K_ee is in the estimate's diagonal already, not here). diag1, diag2 (optional): the
/// lambda_max(S_bb) terms alone (the perBodyDiag increments, for densityScale).
void contactRowBounds(
        const std::vector<DynBody>& bodies, const DynContact& contact, Real& add1, Real& add2, Real* diag1 = nullptr, Real* diag2 = nullptr);

/// omega^2 of the stiffest single joint a RIGID block can form (body.deformable is ignored): one of its edges in full contact with a
/// fixed partner (two Gauss points: the exact integral, an upper bound for every rule), the springs
/// of that edge kn = 1/(h/En + partnerN), ks = 1/(h/Es + partnerS) with h the distance from the
/// centroid to the edge line (Kawai's h of this side) and partnerN, partnerS the least compliance
/// the other side can add (its h over its moduli). vertices: CCW about the centroid, any rotation
/// (the bound does not depend on it). thickness: out-of-plane [m]. Two free blocks meeting have
/// omega^2 <= the sum of their values (lambda_max of a PSD block matrix <= the sum of its diagonal
/// blocks'), a block meeting a fixed one its own.
Real stiffestJointOmega2(const DynBody& body, const std::vector<Vec2>& vertices, Real En, Real Es, Real partnerN, Real partnerS, Real thickness);


/// The contact segment a joint can reach within a few steps (world, m). A corner of the incident
/// block on the reference edge closes by rotation until the incident edge lies flat: a joint
/// estimated at its present, short length would soon be many times stiffer. The incident edge is
/// laid flat on the reference line about its deeper end, towards the side its other end lies on,
/// and clipped to the reference edge; that segment is returned where it is longer than p0-p1. A flat
/// joint keeps its segment (bricks in running bond: the laid edge covers what it covers now), and so
/// does a corner that only meets a corner (diagonal neighbours in a grid: the laid edge points away
/// from the reference edge). ref0-ref1: the reference edge, CCW on its block; inc0-inc1: the
/// incident edge.
std::pair<Vec2, Vec2> closingContact(const Vec2& ref0, const Vec2& ref1, const Vec2& inc0, const Vec2& inc1, const Vec2& p0, const Vec2& p1);

/// Exact dt_crit = 2 / sqrt(lambda_max(M^-1 K)) from a dense symmetric eigen-solve; O(N^3) in the
/// number of free bodies, meant for tests and small systems (e.g. the two-block closed form). With
/// deformable bodies: the generalized problem K x = omega^2 M x, 6 DOFs each.
Real criticalTimeStepExact(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts);

} // namespace rbsm
