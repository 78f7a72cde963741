#include <pkg/rbsm/kernel/StrainElement.hpp>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rbsm {

AreaMoments areaMoments(const std::vector<Vec2>& v)
{
	// Green's theorem per edge (the triangle origin-v_i-v_j): exact for any simple polygon.
	AreaMoments m;
	for (size_t i = 0; i < v.size(); ++i) {
		const Vec2& a = v[i];
		const Vec2& b = v[(i + 1) % v.size()];
		const Real  c = cross2(a, b);
		m.area += c / 2;
		m.Ixx += c * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) / 12;
		m.Iyy += c * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) / 12;
		m.Ixy += c * (2 * a.x() * a.y() + a.x() * b.y() + b.x() * a.y() + 2 * b.x() * b.y()) / 24;
	}
	return m;
}

Mat3 elasticityMatrix(Real young, Real poisson, bool planeStrain)
{
	if (!(std::isfinite(young) && young > 0))
		throw std::invalid_argument("elasticityMatrix: Young's modulus must be finite and > 0, got " + std::to_string(young));
	if (!(poisson > -1 && poisson < 0.5))
		throw std::invalid_argument("elasticityMatrix: Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(poisson));
	const Real nu = poisson;
	Mat3       D  = Mat3::Zero();
	if (planeStrain) {
		const Real f = young / ((1 + nu) * (1 - 2 * nu));
		D << 1 - nu, nu, 0, nu, 1 - nu, 0, 0, 0, (1 - 2 * nu) / 2;
		D *= f;
	} else {
		const Real f = young / (1 - nu * nu);
		D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
		D *= f;
	}
	return D;
}

namespace {
	Mat4 assemble(const StrainMass& M)
	{
		Mat4 M4;
		M4 << M.polar, M.thetaStrain.transpose(), M.thetaStrain, M.strain;
		return M4;
	}
} // namespace

StrainMass strainMass(const AreaMoments& m, Real density, Real thickness)
{
	const Real f = density * thickness;
	StrainMass M;
	M.polar       = f * (m.Ixx + m.Iyy);
	M.thetaStrain = f * Vec3(-m.Ixy, m.Ixy, (m.Ixx - m.Iyy) / 2);
	M.strain << m.Ixx, 0, m.Ixy / 2, 0, m.Iyy, m.Ixy / 2, m.Ixy / 2, m.Ixy / 2, (m.Ixx + m.Iyy) / 4;
	M.strain *= f;
	// ∫ NᵀN dA with N = [ẑ×r, B(r)]: a linear field G r vanishing on an area has G = 0, so this is SPD
	// unless the polygon (or ρ t) degenerates.
	const Mat4             M4 = assemble(M);
	const Eigen::LLT<Mat4> llt(M4);
	if (!M4.allFinite() || llt.info() != Eigen::Success || !(M.polar > 0))
		throw std::invalid_argument("strainMass: the (theta, strain) mass is not positive definite (degenerate polygon, or density/thickness <= 0)");
	M.inverse = llt.solve(Mat4::Identity());
	return M;
}

Real ownStrainOmega2(const StrainMass& M, const Mat3& stiffness)
{
	Mat4 K4                      = Mat4::Zero();
	K4.bottomRightCorner<3, 3>() = stiffness;
	const Eigen::GeneralizedSelfAdjointEigenSolver<Mat4> es(K4, assemble(M), Eigen::EigenvaluesOnly);
	if (es.info() != Eigen::Success) throw std::invalid_argument("ownStrainOmega2: the (theta, strain) mass is not positive definite");
	return std::max(Real(0), es.eigenvalues().maxCoeff());
}

} // namespace rbsm
