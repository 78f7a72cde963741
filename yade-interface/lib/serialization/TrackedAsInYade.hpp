// Archive format of YADE's base classes inside the plugin.
//
// boost::serialization tracks an object (writes object_id="_N") only if its class is also
// serialized through a pointer somewhere *in the same module*: it asks whether a pointer
// serializer for that class was instantiated. In libyade.so every base class (Serializable,
// Shape, Material, Functor, ...) is saved through shared_ptr somewhere, so YADE tracks them; the
// plugin's own copy of, say, the Shape serializer (instantiated by base_object<Shape> in
// Polygon2D::serialize) would not, and a scene mixing spheres and polygons would be unreadable.
// Instantiating the pointer serializers for those classes here makes the plugin write and read
// them exactly as YADE does.
#pragma once
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/archive/detail/iserializer.hpp>
#include <boost/archive/detail/oserializer.hpp>
#include <boost/archive/xml_iarchive.hpp>
#include <boost/archive/xml_oarchive.hpp>
#include <boost/serialization/singleton.hpp>

namespace yade {
namespace detail {
	template <class T> struct TrackedAsInYade {
		TrackedAsInYade()
		{
			using namespace boost::archive;
			using boost::serialization::singleton;
			singleton<boost::archive::detail::pointer_oserializer<xml_oarchive, T>>::get_const_instance();
			singleton<boost::archive::detail::pointer_oserializer<binary_oarchive, T>>::get_const_instance();
			singleton<boost::archive::detail::pointer_iserializer<xml_iarchive, T>>::get_const_instance();
			singleton<boost::archive::detail::pointer_iserializer<binary_iarchive, T>>::get_const_instance();
		}
	};
} // namespace detail
} // namespace yade
