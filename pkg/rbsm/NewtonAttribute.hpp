// An attribute of YADE's NewtonIntegrator as the plugin's engines read it (the plugin does not
// declare YADE's integrator): through its Python attributes, under Python's lock.
#pragma once
#include <core/Scene.hpp>

#include <boost/python.hpp>

namespace yade {

//! NewtonIntegrator's attribute `name` in `scene`, or `fallback` without an integrator or such a value.
template <class T> T newtonAttribute(const Scene& scene, const char* name, const T& fallback)
{
	for (const auto& e : scene.engines) {
		if (!e || e->getClassName() != "NewtonIntegrator") continue;
		const PyGILState_STATE gil   = PyGILState_Ensure();
		T                      value = fallback;
		try {
			value = boost::python::extract<T>(e->pyDict()[name]);
		} catch (const boost::python::error_already_set&) {
			PyErr_Clear();
		}
		PyGILState_Release(gil);
		return value;
	}
	return fallback;
}

} // namespace yade
