// Numeric types of YADE 2023.02a built with double precision (YADE_REAL_BIT=64).
// Eigen is neither vectorised nor aligned in Debian's build (EIGEN_DONT_ALIGN), which changes
// layouts (State is 320 bytes with it): the definitions come from cmake/YadeDebian.cmake.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <boost/serialization/is_bitwise_serializable.hpp>
#include <boost/serialization/nvp.hpp>
#include <boost/shared_ptr.hpp>
#include <boost/make_shared.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#ifndef EIGEN_DONT_ALIGN
#error "Debian's YADE is built with EIGEN_DONT_ALIGN; configure through CMakeLists.txt"
#endif

namespace yade {
using Real = double;
using Vector2r = Eigen::Matrix<Real, 2, 1>;
using Vector2i = Eigen::Matrix<int, 2, 1>;
using Vector3r = Eigen::Matrix<Real, 3, 1>;
using Vector3i = Eigen::Matrix<int, 3, 1>;
using Matrix2r = Eigen::Matrix<Real, 2, 2>;
using Matrix3r = Eigen::Matrix<Real, 3, 3>;
using Quaternionr = Eigen::Quaternion<Real>;
using AngleAxisr = Eigen::AngleAxis<Real>;

using boost::shared_ptr;
using std::string;
using std::vector;

const Real NaN = std::numeric_limits<Real>::quiet_NaN();
const Real Mathr_PI = 3.14159265358979323846;

// Position and orientation of a body (YADE's Se3<Real>): layout is position, then orientation.
template <class Scalar> class Se3 {
public:
	Eigen::Matrix<Scalar, 3, 1> position;
	Eigen::Quaternion<Scalar>   orientation;
	Se3() = default;
	Se3(const Eigen::Matrix<Scalar, 3, 1>& p, const Eigen::Quaternion<Scalar>& q)
	        : position(p)
	        , orientation(q)
	{
	}
};
using Se3r = Se3<Real>;

using mask_t = int; // YADE_MASK_ARBITRARY is not defined in Debian's build
} // namespace yade

// YADE writes its Eigen types member by member in XML (names x, y, z / w, x, y, z) and bitwise in
// binary archives; keep both so scenes saved with the plugin load in plain YADE and back.
BOOST_IS_BITWISE_SERIALIZABLE(yade::Vector2r)
BOOST_IS_BITWISE_SERIALIZABLE(yade::Vector2i)
BOOST_IS_BITWISE_SERIALIZABLE(yade::Vector3r)
BOOST_IS_BITWISE_SERIALIZABLE(yade::Vector3i)
BOOST_IS_BITWISE_SERIALIZABLE(yade::Quaternionr)
BOOST_IS_BITWISE_SERIALIZABLE(yade::Se3r)
BOOST_IS_BITWISE_SERIALIZABLE(yade::Matrix3r)

namespace boost {
namespace serialization {
	template <class Archive> void serialize(Archive& ar, yade::Vector2r& v, const unsigned int)
	{
		yade::Real &x = v[0], &y = v[1];
		ar& BOOST_SERIALIZATION_NVP(x) & BOOST_SERIALIZATION_NVP(y);
	}
	template <class Archive> void serialize(Archive& ar, yade::Vector3r& v, const unsigned int)
	{
		yade::Real &x = v[0], &y = v[1], &z = v[2];
		ar& BOOST_SERIALIZATION_NVP(x) & BOOST_SERIALIZATION_NVP(y) & BOOST_SERIALIZATION_NVP(z);
	}
	template <class Archive> void serialize(Archive& ar, yade::Vector3i& v, const unsigned int)
	{
		int &x = v[0], &y = v[1], &z = v[2];
		ar& BOOST_SERIALIZATION_NVP(x) & BOOST_SERIALIZATION_NVP(y) & BOOST_SERIALIZATION_NVP(z);
	}
	template <class Archive> void serialize(Archive& ar, yade::Se3r& g, const unsigned int)
	{
		ar& boost::serialization::make_nvp("position", g.position) & boost::serialization::make_nvp("orientation", g.orientation);
	}
	template <class Archive> void serialize(Archive& ar, yade::Quaternionr& q, const unsigned int)
	{
		yade::Real &w = q.w(), &x = q.x(), &y = q.y(), &z = q.z();
		ar& BOOST_SERIALIZATION_NVP(w) & BOOST_SERIALIZATION_NVP(x) & BOOST_SERIALIZATION_NVP(y) & BOOST_SERIALIZATION_NVP(z);
	}
} // namespace serialization
} // namespace boost
