// A Python __init__ that receives all positional and keyword arguments, as YADE's classes have:
// `Polygon2D(vertices=[...], color=(1,0,0))`. boost::python's make_constructor wraps a factory
// taking (tuple, dict); the dispatcher below unpacks Python's raw (args, kw) into that call.
#pragma once
#include <boost/python.hpp>
#include <boost/python/raw_function.hpp>
#include <limits>

namespace yade {
namespace detail {
	class RawConstructorDispatcher {
	public:
		explicit RawConstructorDispatcher(boost::python::object constructor)
		        : constructor_(std::move(constructor))
		{
		}
		PyObject* operator()(PyObject* args, PyObject* kw)
		{
			namespace py = boost::python;
			py::tuple all(py::borrowed(args));
			py::object self = all[0];
			py::tuple  rest(all.slice(1, py::len(all)));
			py::dict   keywords = kw ? py::dict(py::borrowed(kw)) : py::dict();
			return py::incref(constructor_(self, rest, keywords).ptr());
		}

	private:
		boost::python::object constructor_;
	};
} // namespace detail

template <class Factory> boost::python::object raw_constructor(Factory factory)
{
	namespace py = boost::python;
	return py::detail::make_raw_function(py::objects::py_function(
	        detail::RawConstructorDispatcher(py::make_constructor(factory)),
	        boost::mpl::vector2<void, py::object>(),
	        1,
	        std::numeric_limits<unsigned>::max()));
}
} // namespace yade
