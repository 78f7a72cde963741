#include <pkg/rbsm/kernel/CriticalTimeStep.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace rbsm {

namespace {
	void checkContact(const std::vector<DynBody>& bodies, const DynContact& c)
	{
		if (c.body1 < 0 || c.body2 < 0 || c.body1 >= int(bodies.size()) || c.body2 >= int(bodies.size()) || c.body1 == c.body2)
			throw std::invalid_argument("criticalTimeStep: bad body index in a contact");
		if (c.points.size() != c.areas.size()) throw std::invalid_argument("criticalTimeStep: points and areas differ in size");
		if (c.kn < 0 || c.ks < 0) throw std::invalid_argument("criticalTimeStep: negative stiffness");
		for (int b : { c.body1, c.body2 })
			if (!bodies[b].fixed && !(bodies[b].mass > 0 && bodies[b].inertia > 0))
				throw std::invalid_argument("criticalTimeStep: free body needs mass > 0 and inertia > 0");
	}
	void check(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts)
	{
		for (const auto& b : bodies)
			if (!b.fixed && !(b.mass > 0 && b.inertia > 0)) throw std::invalid_argument("criticalTimeStep: free body needs mass > 0 and inertia > 0");
		for (const auto& c : contacts)
			checkContact(bodies, c);
	}

	// The stiffness of one contact in 3x3 blocks (DOFs ux, uy, theta of body1, then of body2): a
	// spring kk along d at x_k adds kk b b^T with b = (b1, b2), b1 = -(d, r1 x d), b2 = (d, r2 x d),
	// so K11 += kk b1 b1^T, K22 += kk b2 b2^T, K12 += kk b1 b2^T (and K21 = K12^T).
	struct ContactBlocks {
		Mat3 K11 = Mat3::Zero(), K22 = Mat3::Zero(), K12 = Mat3::Zero();
	};
	ContactBlocks contactStiffness(const std::vector<DynBody>& bodies, const DynContact& c)
	{
		ContactBlocks K;
		const Vec2&   c1 = bodies[c.body1].centroid;
		const Vec2&   c2 = bodies[c.body2].centroid;
		for (size_t k = 0; k < c.points.size(); ++k) {
			const Vec2 r1 = c.points[k] - c1, r2 = c.points[k] - c2;
			for (int dir = 0; dir < 2; ++dir) {
				const Vec2&           d  = dir == 0 ? c.normal : c.tangent;
				const Real            kk = (dir == 0 ? c.kn : c.ks) * c.areas[k];
				const Eigen::Vector3d b1(-d.x(), -d.y(), -cross2(r1, d)), b2(d.x(), d.y(), cross2(r2, d));
				K.K11.noalias() += (kk * b1) * b1.transpose();
				K.K22.noalias() += (kk * b2) * b2.transpose();
				K.K12.noalias() += (kk * b1) * b2.transpose();
			}
		}
		return K;
	}
	Real lambdaMax(const Mat3& S)
	{
		Eigen::SelfAdjointEigenSolver<Mat3> es;
		es.computeDirect(S, Eigen::EigenvaluesOnly); // closed form (3x3): a fraction of the iterative solver's cost
		return std::max(Real(0), es.eigenvalues().maxCoeff());
	}
	Eigen::Vector3d inverseSqrtMass(const DynBody& b) { return Eigen::Vector3d(1 / std::sqrt(b.mass), 1 / std::sqrt(b.mass), 1 / std::sqrt(b.inertia)); }

	// All contacts between the same pair of bodies summed first: contacts sorted by their pair.
	// offOfContact[ci]: contact ci's (lower id, higher id) coupling block. Returns (i<j) -> K_ij.
	template <class Block>
	std::vector<std::pair<std::pair<int, int>, Block>> sumByPair(const std::vector<DynContact>& contacts, const std::vector<Block>& offOfContact)
	{
		auto pairKey = [&](size_t ci) {
			const DynContact& c = contacts[ci];
			return (uint64_t(std::min(c.body1, c.body2)) << 32) | uint64_t(std::max(c.body1, c.body2));
		};
		std::vector<size_t> order(contacts.size());
		for (size_t ci = 0; ci < order.size(); ++ci) order[ci] = ci;
		std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return pairKey(a) < pairKey(b); });
		std::vector<std::pair<std::pair<int, int>, Block>> off;
		off.reserve(order.size());
		for (size_t k = 0; k < order.size(); ++k) {
			const uint64_t key = pairKey(order[k]);
			if (k > 0 && key == pairKey(order[k - 1])) off.back().second += offOfContact[order[k]];
			else off.push_back({ { int(key >> 32), int(key & 0xffffffffu) }, offOfContact[order[k]] });
		}
		return off;
	}

	// The result of the block Gershgorin bound from each free body's row bound and its diagonal part.
	Real gershgorinResult(
	        const std::vector<DynBody>& bodies, const std::vector<Real>& bound, const std::vector<Real>& diagBound, std::vector<Real>* perBody, std::vector<Real>* perBodyDiag)
	{
		const size_t n    = bodies.size();
		Real         lmax = 0;
		for (size_t b = 0; b < n; ++b)
			if (!bodies[b].fixed) lmax = std::max(lmax, bound[b]);
		if (perBodyDiag) perBodyDiag->assign(diagBound.begin(), diagBound.end());
		if (perBody) {
			perBody->assign(n, 0);
			for (size_t b = 0; b < n; ++b)
				if (!bodies[b].fixed) (*perBody)[b] = bound[b];
		}
		return lmax > 0 ? 2 / std::sqrt(lmax) : std::numeric_limits<Real>::infinity();
	}
} // namespace

// ---------------------------------------------------------------------------------------------
// The 6-DOF path, taken only when some free body is deformable. Blocks have 3 rows (rigid) or 6
// (deformable); matrices of at most 6x6 on the stack.
namespace {
	using BlockMat = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
	using BlockVec = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 6, 1>;
	using Mat6     = Eigen::Matrix<Real, 6, 6>;

	int  dofs(const DynBody& b) { return b.deformable ? 6 : 3; }
	bool freeDeformable(const DynBody& b) { return b.deformable && !b.fixed; }
	bool anyFreeDeformable(const std::vector<DynBody>& bodies)
	{
		return std::any_of(bodies.begin(), bodies.end(), freeDeformable);
	}

	Mat4 thetaStrainMass(const DynBody& b)
	{
		Mat4 M;
		M << b.inertia, b.thetaStrainMass.transpose(), b.thetaStrainMass, b.strainMass;
		return M;
	}

	// W_b = L_b^-1 with M_b = L_b L_b^T: S_bc = W_b K_bc W_c^T is similar to M^-1 K, blockwise.
	BlockMat inverseMassFactor(const DynBody& b)
	{
		BlockMat W = BlockMat::Zero(dofs(b), dofs(b));
		W(0, 0) = W(1, 1) = 1 / std::sqrt(b.mass);
		if (!b.deformable) {
			W(2, 2) = 1 / std::sqrt(b.inertia);
			return W;
		}
		const Mat4             M4 = thetaStrainMass(b);
		const Eigen::LLT<Mat4> llt(M4);
		if (!M4.allFinite() || llt.info() != Eigen::Success)
			throw std::invalid_argument("criticalTimeStep: a free deformable body needs a positive definite (theta, strain) mass");
		W.bottomRightCorner(4, 4) = llt.matrixL().solve(Mat4::Identity());
		return W;
	}

	// The coefficients of body b's DOFs in the displacement of its material point at x along d:
	// (d, r x d) and, if deformable, B(R^T r)^T R^T d (the strain in the body's frame).
	BlockVec pointRow(const DynBody& b, const Vec2& x, const Vec2& d)
	{
		const Vec2 r = x - b.centroid;
		BlockVec   row(dofs(b));
		row.head<3>() << d.x(), d.y(), cross2(r, d);
		if (b.deformable) {
			const Real c = b.cosAngle, s = b.sinAngle;
			const Vec2 rl(c * r.x() + s * r.y(), -s * r.x() + c * r.y()), dl(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
			row.tail<3>() << rl.x() * dl.x(), rl.y() * dl.y(), 0.5 * (rl.y() * dl.x() + rl.x() * dl.y());
		}
		return row;
	}

	struct BlockContact {
		BlockMat K11, K22, K12;
	};
	BlockContact blockContactStiffness(const std::vector<DynBody>& bodies, const DynContact& c)
	{
		const DynBody &p = bodies[c.body1], &q = bodies[c.body2];
		BlockContact   K { BlockMat::Zero(dofs(p), dofs(p)), BlockMat::Zero(dofs(q), dofs(q)), BlockMat::Zero(dofs(p), dofs(q)) };
		for (size_t k = 0; k < c.points.size(); ++k)
			for (int dir = 0; dir < 2; ++dir) {
				const Vec2&    d  = dir == 0 ? c.normal : c.tangent;
				const Real     kk = (dir == 0 ? c.kn : c.ks) * c.areas[k];
				const BlockVec b1 = -pointRow(p, c.points[k], d), b2 = pointRow(q, c.points[k], d);
				K.K11.noalias() += (kk * b1) * b1.transpose();
				K.K22.noalias() += (kk * b2) * b2.transpose();
				K.K12.noalias() += (kk * b1) * b2.transpose();
			}
		return K;
	}

	Real lambdaMaxBlock(const BlockMat& S)
	{
		if (S.rows() == 3) return lambdaMax(Mat3(S));
		const Eigen::SelfAdjointEigenSolver<Mat6> es(Mat6(S), Eigen::EigenvaluesOnly);
		return std::max(Real(0), es.eigenvalues().maxCoeff());
	}
	// ||S||_2 from the smaller of the two Gram matrices
	Real normBlock(const BlockMat& S)
	{
		return std::sqrt(S.cols() <= S.rows() ? lambdaMaxBlock(S.transpose() * S) : lambdaMaxBlock(S * S.transpose()));
	}

	void rowBoundsBlocks(const std::vector<DynBody>& bodies, const DynContact& c, Real& add1, Real& add2, Real* diag1, Real* diag2)
	{
		const DynBody &    b1 = bodies[c.body1], &b2 = bodies[c.body2];
		const BlockContact K  = blockContactStiffness(bodies, c);
		const BlockMat     W1 = b1.fixed ? BlockMat() : inverseMassFactor(b1), W2 = b2.fixed ? BlockMat() : inverseMassFactor(b2);
		add1 = b1.fixed ? 0 : lambdaMaxBlock(W1 * K.K11 * W1.transpose());
		add2 = b2.fixed ? 0 : lambdaMaxBlock(W2 * K.K22 * W2.transpose());
		if (diag1) *diag1 = add1;
		if (diag2) *diag2 = add2;
		if (!b1.fixed && !b2.fixed) {
			const Real norm = normBlock(W1 * K.K12 * W2.transpose());
			add1 += norm, add2 += norm;
		}
	}

	Real gershgorinBlocks(
	        const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts, std::vector<Real>* perBody, std::vector<Real>* perBodyDiag)
	{
		const size_t          n = bodies.size();
		std::vector<BlockMat> W(n), diag(n);
		for (size_t b = 0; b < n; ++b) {
			diag[b] = BlockMat::Zero(dofs(bodies[b]), dofs(bodies[b]));
			if (bodies[b].fixed) continue;
			W[b] = inverseMassFactor(bodies[b]);
			if (bodies[b].deformable) diag[b].bottomRightCorner(3, 3) += bodies[b].strainStiffness; // its own K_ee
		}
		std::vector<BlockMat> offOfContact(contacts.size());
		for (size_t ci = 0; ci < contacts.size(); ++ci) {
			const DynContact&  c = contacts[ci];
			const BlockContact K = blockContactStiffness(bodies, c);
			diag[c.body1] += K.K11;
			diag[c.body2] += K.K22;
			offOfContact[ci] = c.body1 < c.body2 ? K.K12 : BlockMat(K.K12.transpose());
		}
		std::vector<Real> bound(n, 0);
		for (size_t b = 0; b < n; ++b)
			if (!bodies[b].fixed) bound[b] = lambdaMaxBlock(W[b] * diag[b] * W[b].transpose());
		const std::vector<Real> diagBound = bound;
		for (const auto& kv : sumByPair(contacts, offOfContact)) {
			const int a = kv.first.first, b = kv.first.second;
			if (bodies[a].fixed || bodies[b].fixed) continue;
			const Real norm2 = normBlock(W[a] * kv.second * W[b].transpose());
			bound[a] += norm2, bound[b] += norm2;
		}
		return gershgorinResult(bodies, bound, diagBound, perBody, perBodyDiag);
	}

	// Dense K x = omega^2 M x with 3 or 6 DOFs per free body.
	Real exactBlocks(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts)
	{
		std::vector<int> dof(bodies.size(), -1);
		int              N = 0;
		for (size_t b = 0; b < bodies.size(); ++b)
			if (!bodies[b].fixed) dof[b] = N, N += dofs(bodies[b]);
		Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N), M = Eigen::MatrixXd::Zero(N, N);
		for (size_t b = 0; b < bodies.size(); ++b) {
			const DynBody& body = bodies[b];
			if (body.fixed) continue;
			inverseMassFactor(body); // validates the (theta, strain) mass
			M(dof[b], dof[b]) = M(dof[b] + 1, dof[b] + 1) = body.mass;
			if (!body.deformable) M(dof[b] + 2, dof[b] + 2) = body.inertia;
			else {
				M.block<4, 4>(dof[b] + 2, dof[b] + 2) = thetaStrainMass(body);
				K.block<3, 3>(dof[b] + 3, dof[b] + 3) = body.strainStiffness;
			}
		}
		for (const DynContact& c : contacts) {
			const BlockContact Kc = blockContactStiffness(bodies, c);
			const int          d1 = dof[c.body1], d2 = dof[c.body2];
			if (d1 >= 0) K.block(d1, d1, Kc.K11.rows(), Kc.K11.cols()) += Kc.K11;
			if (d2 >= 0) K.block(d2, d2, Kc.K22.rows(), Kc.K22.cols()) += Kc.K22;
			if (d1 >= 0 && d2 >= 0) {
				K.block(d1, d2, Kc.K12.rows(), Kc.K12.cols()) += Kc.K12;
				K.block(d2, d1, Kc.K12.cols(), Kc.K12.rows()) += Kc.K12.transpose();
			}
		}
		const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
		if (es.info() != Eigen::Success) throw std::invalid_argument("criticalTimeStepExact: the eigen-solve failed");
		const Real lmax = es.eigenvalues().maxCoeff();
		return lmax > 0 ? 2 / std::sqrt(lmax) : std::numeric_limits<Real>::infinity();
	}
} // namespace

void contactRowBounds(const std::vector<DynBody>& bodies, const DynContact& c, Real& add1, Real& add2, Real* diag1, Real* diag2)
{
	checkContact(bodies, c);
	const DynBody &b1 = bodies[c.body1], &b2 = bodies[c.body2];
	if (freeDeformable(b1) || freeDeformable(b2)) return rowBoundsBlocks(bodies, c, add1, add2, diag1, diag2);
	const ContactBlocks K = contactStiffness(bodies, c);
	add1 = b1.fixed ? 0 : lambdaMax(inverseSqrtMass(b1).asDiagonal() * K.K11 * inverseSqrtMass(b1).asDiagonal());
	add2 = b2.fixed ? 0 : lambdaMax(inverseSqrtMass(b2).asDiagonal() * K.K22 * inverseSqrtMass(b2).asDiagonal());
	if (diag1) *diag1 = add1;
	if (diag2) *diag2 = add2;
	if (!b1.fixed && !b2.fixed) {
		const Mat3 S12  = inverseSqrtMass(b1).asDiagonal() * K.K12 * inverseSqrtMass(b2).asDiagonal();
		const Real norm = std::sqrt(lambdaMax(S12.transpose() * S12));
		add1 += norm, add2 += norm;
	}
}

Real stiffestJointOmega2(const DynBody& body, const std::vector<Vec2>& v, Real En, Real Es, Real partnerN, Real partnerS, Real thickness)
{
	if (body.fixed || v.size() < 3) return 0;
	const std::vector<DynBody> pair = { DynBody { 0, 0, Vec2::Zero(), true }, DynBody { body.mass, body.inertia, Vec2::Zero(), false } };
	const Real                 g    = 0.5 / std::sqrt(3.0); // two Gauss points at 1/2 -+ g
	Real                       best = 0;
	for (size_t i = 0; i < v.size(); ++i) {
		const Vec2 a = v[i], b = v[(i + 1) % v.size()], e = b - a;
		const Real L = e.norm();
		if (!(L > 0)) continue;
		DynContact c;
		c.body1 = 0, c.body2 = 1;
		c.normal  = Vec2(e.y(), -e.x()) / L; // outward
		c.tangent = Vec2(-c.normal.y(), c.normal.x());
		const Real h = std::abs(c.normal.dot(a));
		c.kn = 1 / (h / En + partnerN), c.ks = 1 / (h / Es + partnerS);
		c.points = { a + (0.5 - g) * e, a + (0.5 + g) * e };
		c.areas  = { 0.5 * L * thickness, 0.5 * L * thickness };
		Real add1, add2;
		contactRowBounds(pair, c, add1, add2);
		best = std::max(best, add2);
	}
	return best;
}

std::pair<Vec2, Vec2> closingContact(const Vec2& ref0, const Vec2& ref1, const Vec2& inc0, const Vec2& inc1, const Vec2& p0, const Vec2& p1)
{
	const Real refLen = (ref1 - ref0).norm(), incLen = (inc1 - inc0).norm();
	if (!(refLen > 0 && incLen > 0)) return { p0, p1 };
	const Vec2 t = (ref1 - ref0) / refLen, n(t.y(), -t.x()); // along the reference edge; its outward normal
	// the incident edge laid flat about its deeper end, along the side its other end projects to
	const bool deep0 = n.dot(inc0 - ref0) <= n.dot(inc1 - ref0);
	const Vec2 &deep = deep0 ? inc0 : inc1, &other = deep0 ? inc1 : inc0;
	const Real at = t.dot(deep - ref0), reach = t.dot(other - deep) >= 0 ? incLen : -incLen;
	const Real s0 = std::clamp(std::min(at, at + reach), Real(0), refLen), s1 = std::clamp(std::max(at, at + reach), Real(0), refLen);
	if (s1 - s0 <= (p1 - p0).norm()) return { p0, p1 };
	const Vec2 a = ref0 + s0 * t, b = ref0 + s1 * t;
	return t.dot(p1 - p0) >= 0 ? std::make_pair(a, b) : std::make_pair(b, a); // the segment's own orientation
}

Real densityScale(Real diag, Real off, Real omegaT2)
{
	if (!(omegaT2 > 0) || !(diag + off > omegaT2)) return 1;
	if (!(diag > 0)) return (off / omegaT2) * (off / omegaT2); // off x = omega_T^2
	const Real x = (-off + std::sqrt(off * off + 4 * diag * omegaT2)) / (2 * diag);
	return 1 / (x * x);
}

Real criticalTimeStepGershgorin(
        const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts, std::vector<Real>* perBody, std::vector<Real>* perBodyDiag)
{
	check(bodies, contacts);
	if (anyFreeDeformable(bodies)) return gershgorinBlocks(bodies, contacts, perBody, perBodyDiag);
	const size_t n = bodies.size();
	std::vector<Mat3> diag(n, Mat3::Zero());
	std::vector<Mat3> offOfContact(contacts.size());
	for (size_t ci = 0; ci < contacts.size(); ++ci) {
		const DynContact&   c = contacts[ci];
		const ContactBlocks K = contactStiffness(bodies, c);
		diag[c.body1] += K.K11;
		diag[c.body2] += K.K22;
		offOfContact[ci] = c.body1 < c.body2 ? K.K12 : Mat3(K.K12.transpose()); // the (lower id, higher id) block
	}
	const auto off = sumByPair(contacts, offOfContact); // (i<j) -> K_ij block
	// Scale to S = M^-1/2 K M^-1/2 block by block. Block Gershgorin bound for the rows of each free body b:
	//   lambda_max <= max_b [ lambda_max(S_bb) + sum_{c != b, free} ||S_bc||_2 ].
	std::vector<Real> bound(n, 0);
	for (size_t b = 0; b < n; ++b)
		if (!bodies[b].fixed) bound[b] = lambdaMax(inverseSqrtMass(bodies[b]).asDiagonal() * diag[b] * inverseSqrtMass(bodies[b]).asDiagonal());
	const std::vector<Real> diagBound = bound; // lambda_max(S_bb) alone
	for (const auto& kv : off) {
		const int a = kv.first.first, b = kv.first.second;
		if (bodies[a].fixed || bodies[b].fixed) continue; // fixed DOFs are removed from the system
		const Mat3 Sab   = inverseSqrtMass(bodies[a]).asDiagonal() * kv.second * inverseSqrtMass(bodies[b]).asDiagonal();
		const Real norm2 = std::sqrt(lambdaMax(Sab.transpose() * Sab));
		bound[a] += norm2; // ||S_ab|| = ||S_ba||
		bound[b] += norm2;
	}
	return gershgorinResult(bodies, bound, diagBound, perBody, perBodyDiag);
}

Real criticalTimeStepExact(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts)
{
	check(bodies, contacts);
	if (anyFreeDeformable(bodies)) return exactBlocks(bodies, contacts);
	std::vector<int> dof(bodies.size(), -1);
	int              nf = 0;
	for (size_t b = 0; b < bodies.size(); ++b)
		if (!bodies[b].fixed) dof[b] = 3 * nf++;
	if (nf == 0) return std::numeric_limits<Real>::infinity();
	Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * nf, 3 * nf);
	for (const DynContact& c : contacts) {
		const ContactBlocks Kc   = contactStiffness(bodies, c);
		const int           d1 = dof[c.body1], d2 = dof[c.body2];
		if (d1 >= 0) K.block<3, 3>(d1, d1) += Kc.K11;
		if (d2 >= 0) K.block<3, 3>(d2, d2) += Kc.K22;
		if (d1 >= 0 && d2 >= 0) {
			K.block<3, 3>(d1, d2) += Kc.K12;
			K.block<3, 3>(d2, d1) += Kc.K12.transpose();
		}
	}
	Eigen::VectorXd isq(3 * nf);
	for (size_t b = 0; b < bodies.size(); ++b)
		if (dof[b] >= 0) isq.segment<3>(dof[b]) << 1 / std::sqrt(bodies[b].mass), 1 / std::sqrt(bodies[b].mass), 1 / std::sqrt(bodies[b].inertia);
	const Eigen::MatrixXd                          S = isq.asDiagonal() * K * isq.asDiagonal();
	Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
	const Real                                     lmax = es.eigenvalues().maxCoeff();
	return lmax > 0 ? 2 / std::sqrt(lmax) : std::numeric_limits<Real>::infinity();
}

} // namespace rbsm
