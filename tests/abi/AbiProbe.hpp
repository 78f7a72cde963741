// AbiProbe: a test-only engine (libabi_probe.so, never installed) that reads and writes YADE's
// objects through this project's declarations in yade-interface/, so that test_runtime.py can
// compare every field with what YADE's own Python accessors see. A wrong member offset in a
// declaration shows up as a value that differs between the two sides.
#pragma once
#include <core/GlobalEngine.hpp>
#include <core/Scene.hpp>

namespace yade {

class AbiProbe : public GlobalEngine {
public:
	void action() override;

	boost::python::dict sceneInfo() const;
	void                setScene(Real dt, long iter, Real time) const;
	boost::python::dict bodyInfo(int id) const;
	void setState(int id, const Vector3r& pos, const Quaternionr& ori, const Vector3r& vel, const Vector3r& angVel, Real mass, const Vector3r& inertia,
	              unsigned blockedDOFs) const;
	void                setBody(int id, int groupMask, const shared_ptr<Shape>& shape, const shared_ptr<Material>& material) const;
	boost::python::dict interactionInfo(int id1, int id2) const;
	void                addForce(int id, const Vector3r& f, const Vector3r& t) const;
	boost::python::dict sizes() const;
	boost::python::dict demFields(const shared_ptr<Serializable>& object) const;
	boost::python::dict demInteractionFields(int id1, int id2) const;

	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(AbiProbe, GlobalEngine,
		"Test-only engine of the ABI guard tests: accessors through the project's declarations of YADE's classes.",
		((int, forceBody, -1, , "Body that action() pushes with :yref:`force<AbiProbe.force>` (none if -1)."))
		((Vector3r, force, Vector3r::Zero(), , "Force added by action() to :yref:`forceBody<AbiProbe.forceBody>`."))
		((long, calls, 0, , "How many times action() ran.")),
		/*ctor*/,
		/*py*/
		.def("sceneInfo", &AbiProbe::sceneInfo, "dt, iter, time, body and interaction counts, read in C++.")
		.def("setScene", &AbiProbe::setScene, (boost::python::arg("dt"), boost::python::arg("iter"), boost::python::arg("time")))
		.def("bodyInfo", &AbiProbe::bodyInfo, boost::python::arg("id"))
		.def("setState", &AbiProbe::setState,
		     (boost::python::arg("id"), boost::python::arg("pos"), boost::python::arg("ori"), boost::python::arg("vel"), boost::python::arg("angVel"),
		      boost::python::arg("mass"), boost::python::arg("inertia"), boost::python::arg("blockedDOFs")))
		.def("setBody", &AbiProbe::setBody, (boost::python::arg("id"), boost::python::arg("groupMask"), boost::python::arg("shape"), boost::python::arg("material")))
		.def("interactionInfo", &AbiProbe::interactionInfo, (boost::python::arg("id1"), boost::python::arg("id2")))
		.def("addForce", &AbiProbe::addForce, (boost::python::arg("id"), boost::python::arg("f"), boost::python::arg("t")))
		.def("sizes", &AbiProbe::sizes, "sizeof of some declared classes, as compiled into the probe.")
		.def("demInteractionFields", &AbiProbe::demInteractionFields, (boost::python::arg("id1"), boost::python::arg("id2")), "demFields of the interaction's geom and phys.")
		.def("demFields", &AbiProbe::demFields, boost::python::arg("object"), "Fields of a Sphere, Wall, Facet, FrictMat, ScGeom or FrictPhys read through the project's declarations.")
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(AbiProbe);

} // namespace yade
