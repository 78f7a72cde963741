#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/VtkRecorderGuard.hpp>
#include <core/BodyContainer.hpp>

#include <boost/python.hpp>
#include <iostream>
#include <set>

namespace yade {

bool VtkRecorderGuard::unsafeRecorder(const std::string& name)
{
	static const std::set<std::string> unsafe { "all", "intr", "stress", "bstresses", "cpm", "wpm", "jcfpm", "liquidcontrol", "hertz", "lubrication" };
	return unsafe.count(name) > 0;
}

namespace {
	bool hasBlocks(const Scene& scene)
	{
		for (const auto& b : scene.bodies->body)
			if (b && b->shape && b->shape->getClassIndex() == Polygon2D::getClassIndexStatic()) return true;
		return false;
	}

	// The recorders of a VTKRecorder, read through YADE's own Python accessor (its layout is not declared here).
	std::vector<std::string> recordersOf(const Engine& e)
	{
		namespace py = boost::python;
		std::vector<std::string> out;
		const PyGILState_STATE   gil = PyGILState_Ensure();
		try {
			py::list l = py::extract<py::list>(e.pyDict()["recorders"]);
			for (py::ssize_t i = 0; i < py::len(l); i++)
				out.push_back(py::extract<std::string>(l[i]));
		} catch (const py::error_already_set&) {
			PyErr_Clear();
		}
		PyGILState_Release(gil);
		return out;
	}
} // namespace

void VtkRecorderGuard::check(Scene& scene)
{
	std::vector<const Engine*> now;
	for (const auto& e : scene.engines)
		now.push_back(e.get());
	if (now == seen) return;
	bool blocks = false, looked = false;
	for (size_t k = 0; k < scene.engines.size(); k++) {
		Engine* e = scene.engines[k].get();
		if (!e || e->dead || e->getClassName() != "VTKRecorder") continue;
		if (!looked) blocks = hasBlocks(scene), looked = true;
		if (!blocks) return; // checked again at the next step: blocks may come later
		std::string bad;
		for (const std::string& r : recordersOf(*e))
			if (unsafeRecorder(r)) bad += (bad.empty() ? "'" : ", '") + r + "'";
		if (bad.empty()) continue;
		e->dead = true;
		std::cerr << "yade-rbsm: ERROR: VTKRecorder (O.engines[" << k << "]) with recorders " << bad
		          << " reads contacts as sphere contacts and would crash YADE on RBSM joints: it is switched off (dead=True). "
		             "Record blocks and joints with yade_rbsm.vtkexport.recorder(...) (VTK of blocks, joints, stresses), or keep "
		             "VTKRecorder to the safe recorders (e.g. 'velocity', 'ids', 'mass', 'coordNumber')."
		          << std::endl;
	}
	seen = now;
}

} // namespace yade
