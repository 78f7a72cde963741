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
	using Mat3 = Eigen::Matrix3d;

	void check(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts)
	{
		for (const auto& b : bodies)
			if (!b.fixed && !(b.mass > 0 && b.inertia > 0)) throw std::invalid_argument("criticalTimeStep: free body needs mass > 0 and inertia > 0");
		for (const auto& c : contacts) {
			if (c.body1 < 0 || c.body2 < 0 || c.body1 >= int(bodies.size()) || c.body2 >= int(bodies.size()) || c.body1 == c.body2)
				throw std::invalid_argument("criticalTimeStep: bad body index in a contact");
			if (c.points.size() != c.areas.size()) throw std::invalid_argument("criticalTimeStep: points and areas differ in size");
			if (c.kn < 0 || c.ks < 0) throw std::invalid_argument("criticalTimeStep: negative stiffness");
		}
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
} // namespace

Real criticalTimeStepGershgorin(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts, std::vector<Real>* perBody)
{
	check(bodies, contacts);
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
	// All contacts between the same pair of bodies summed first: contacts sorted by their pair.
	auto pairKey = [&](size_t ci) {
		const DynContact& c = contacts[ci];
		return (uint64_t(std::min(c.body1, c.body2)) << 32) | uint64_t(std::max(c.body1, c.body2));
	};
	std::vector<size_t> order(contacts.size());
	for (size_t ci = 0; ci < order.size(); ++ci) order[ci] = ci;
	std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return pairKey(a) < pairKey(b); });
	std::vector<std::pair<std::pair<int, int>, Mat3>> off; // (i<j) -> K_ij block
	off.reserve(order.size());
	for (size_t k = 0; k < order.size(); ++k) {
		const uint64_t key = pairKey(order[k]);
		if (k > 0 && key == pairKey(order[k - 1])) off.back().second += offOfContact[order[k]];
		else off.push_back({ { int(key >> 32), int(key & 0xffffffffu) }, offOfContact[order[k]] });
	}
	// Scale to S = M^-1/2 K M^-1/2 block by block.
	auto isq = [&](size_t b) { return Eigen::Vector3d(1 / std::sqrt(bodies[b].mass), 1 / std::sqrt(bodies[b].mass), 1 / std::sqrt(bodies[b].inertia)); };
	// Block Gershgorin bound for the rows of each free body b:
	//   lambda_max <= max_b [ lambda_max(S_bb) + sum_{c != b, free} ||S_bc||_2 ].
	std::vector<Real> bound(n, 0);
	for (size_t b = 0; b < n; ++b) {
		if (bodies[b].fixed) continue;
		const Mat3                                     Sbb = isq(b).asDiagonal() * diag[b] * isq(b).asDiagonal();
		Eigen::SelfAdjointEigenSolver<Mat3>            es;
		es.computeDirect(Sbb, Eigen::EigenvaluesOnly); // closed form (3x3): a fraction of the iterative solver's cost
		bound[b] = std::max(Real(0), es.eigenvalues().maxCoeff());
	}
	for (const auto& kv : off) {
		const int a = kv.first.first, b = kv.first.second;
		if (bodies[a].fixed || bodies[b].fixed) continue; // fixed DOFs are removed from the system
		const Mat3                                     Sab = isq(a).asDiagonal() * kv.second * isq(b).asDiagonal();
		Eigen::SelfAdjointEigenSolver<Mat3>            es;
		es.computeDirect(Sab.transpose() * Sab, Eigen::EigenvaluesOnly);
		const Real                                     norm2 = std::sqrt(std::max(Real(0), es.eigenvalues().maxCoeff()));
		bound[a] += norm2; // ||S_ab|| = ||S_ba||
		bound[b] += norm2;
	}
	Real lmax = 0;
	for (size_t b = 0; b < n; ++b)
		if (!bodies[b].fixed) lmax = std::max(lmax, bound[b]);
	if (perBody) {
		perBody->assign(n, 0);
		for (size_t b = 0; b < n; ++b)
			if (!bodies[b].fixed) (*perBody)[b] = bound[b];
	}
	return lmax > 0 ? 2 / std::sqrt(lmax) : std::numeric_limits<Real>::infinity();
}

Real criticalTimeStepExact(const std::vector<DynBody>& bodies, const std::vector<DynContact>& contacts)
{
	check(bodies, contacts);
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
