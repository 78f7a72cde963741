#include "AbiProbe.hpp"
#include <pkg/common/ElastMat.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((AbiProbe));

namespace py = boost::python;

void AbiProbe::action()
{
	calls++;
	if (forceBody >= 0) scene->forces.addForce(forceBody, force);
}

static Scene& currentScene() { return *Omega::instance().getScene(); }

static const shared_ptr<Body>& bodyById(int id)
{
	const auto& bodies = currentScene().bodies->body;
	if (id < 0 || size_t(id) >= bodies.size() || !bodies[id]) throw std::out_of_range("AbiProbe: no body #" + std::to_string(id));
	return bodies[id];
}

py::dict AbiProbe::sceneInfo() const
{
	const Scene& s = currentScene();
	py::dict     d;
	d["dt"]           = s.dt;
	d["iter"]         = s.iter;
	d["time"]         = s.time;
	d["stopAtIter"]   = s.stopAtIter;
	d["trackEnergy"]  = s.trackEnergy;
	d["isPeriodic"]   = s.isPeriodic;
	d["selectedBody"] = s.selectedBody;
	d["tags"]         = py::list();
	for (const auto& t : s.tags)
		py::extract<py::list>(d["tags"])().append(t);
	d["nBodies"]       = s.bodies->size();
	d["nInteractions"] = s.interactions->size();
	d["nEngines"]      = s.engines.size();
	d["nMaterials"]    = s.materials.size();
	d["thisIsEngine"]  = bool(!s.engines.empty() && std::find(s.engines.begin(), s.engines.end(), shared_from_this()) != s.engines.end());
	return d;
}

void AbiProbe::setScene(Real dt_, long iter_, Real time_) const
{
	Scene& s = currentScene();
	s.dt     = dt_;
	s.iter   = iter_;
	s.time   = time_;
}

py::dict AbiProbe::bodyInfo(int id) const
{
	const Body& b = *bodyById(id);
	py::dict    d;
	d["id"]        = b.id;
	d["groupMask"] = b.groupMask;
	d["clumpId"]   = b.clumpId;
	d["flags"]     = b.flags;
	d["iterBorn"]  = b.iterBorn;
	d["timeBorn"]  = b.timeBorn;
	d["shape"]     = b.shape;    // the same object: Python compares identity through an attribute
	d["material"]  = b.material;
	d["bound"]     = b.bound;
	d["shapeClass"]    = b.shape ? b.shape->getClassName() : std::string();
	d["materialClass"] = b.material ? b.material->getClassName() : std::string();
	if (b.shape) {
		d["color"] = b.shape->color;
		d["wire"]  = b.shape->wire;
		d["highlight"] = b.shape->highlight;
	}
	if (b.material) {
		d["materialId"] = b.material->id;
		d["materialLabel"] = b.material->label;
		d["density"] = b.material->density;
	}
	const State& st   = *b.state;
	d["pos"]          = st.pos;
	d["ori"]          = st.ori;
	d["se3pos"]       = st.se3.position;
	d["vel"]          = st.vel;
	d["angVel"]       = st.angVel;
	d["angMom"]       = st.angMom;
	d["mass"]         = st.mass;
	d["inertia"]      = st.inertia;
	d["refPos"]       = st.refPos;
	d["refOri"]       = st.refOri;
	d["blockedDOFs"]  = st.blockedDOFs;
	d["isDamped"]     = st.isDamped;
	d["densityScaling"] = st.densityScaling;
	d["isDynamic"]    = b.isDynamic();
	d["nIntrs"]       = b.intrs.size();
	return d;
}

void AbiProbe::setState(
        int id, const Vector3r& pos, const Quaternionr& ori, const Vector3r& vel, const Vector3r& angVel, Real mass, const Vector3r& inertia, unsigned blockedDOFs)
        const
{
	State& st      = *bodyById(id)->state;
	st.pos         = pos;
	st.ori         = ori;
	st.vel         = vel;
	st.angVel      = angVel;
	st.mass        = mass;
	st.inertia     = inertia;
	st.blockedDOFs = blockedDOFs;
}

void AbiProbe::setBody(int id, int groupMask, const shared_ptr<Shape>& shape, const shared_ptr<Material>& material) const
{
	Body& b     = *bodyById(id);
	b.groupMask = groupMask;
	b.shape     = shape;
	b.material  = material;
}

py::dict AbiProbe::interactionInfo(int id1, int id2) const
{
	const shared_ptr<Interaction>& I = currentScene().interactions->find(id1, id2);
	py::dict                       d;
	d["exists"] = bool(I);
	if (!I) return d;
	d["id1"]          = I->getId1();
	d["id2"]          = I->getId2();
	d["isReal"]       = I->isReal();
	d["iterMadeReal"] = I->iterMadeReal;
	d["iterBorn"]     = I->iterBorn;
	d["cellDist"]     = I->cellDist;
	d["geom"]         = I->geom;
	d["phys"]         = I->phys;
	d["geomClass"]    = I->geom ? I->geom->getClassName() : std::string();
	d["physClass"]    = I->phys ? I->phys->getClassName() : std::string();
	// the interaction is in both bodies' maps, found through Body's declaration
	d["inBody1"] = bodyById(id1)->intrs.count(id2) == 1;
	return d;
}

void AbiProbe::addForce(int id, const Vector3r& f, const Vector3r& t) const
{
	Scene& s = currentScene();
	s.forces.addForce(id, f);
	s.forces.addTorque(id, t);
}

py::dict AbiProbe::sizes() const
{
	py::dict d;
	d["ForceContainer"] = sizeof(ForceContainer);
	d["Scene"]          = sizeof(Scene);
	d["AbiProbe"]       = sizeof(AbiProbe);
	return d;
}

} // namespace yade

namespace yade {
// The fields of YADE's DEM classes that the plugin reads or writes (pkg/common, pkg/dem declarations).
// By class name, not dynamic_cast: the probe links to libyade.so only.
static py::dict fieldsOf(const Serializable* o)
{
	py::dict d;
	if (!o) return d;
	const std::string c = o->getClassName();
	if (c == "Sphere") d["radius"] = static_cast<const Sphere&>(*o).radius;
	if (c == "Wall") {
		const auto& w = static_cast<const Wall&>(*o);
		d["sense"] = w.sense, d["axis"] = w.axis, d["color"] = w.color;
	}
	if (c == "Facet") {
		const auto& f = static_cast<const Facet&>(*o);
		py::list    v;
		for (const auto& x : f.vertices) v.append(x);
		d["vertices"] = v, d["normal"] = f.normal, d["area"] = f.area;
	}
	if (c == "FrictMat" || c == "ElastMat") {
		const auto& m = static_cast<const ElastMat&>(*o);
		d["young"] = m.young, d["poisson"] = m.poisson, d["density"] = m.density;
		if (c == "FrictMat") d["frictionAngle"] = static_cast<const FrictMat&>(*o).frictionAngle;
	}
	if (c == "ScGeom") {
		const auto& g = static_cast<const ScGeom&>(*o);
		d["normal"] = g.normal, d["contactPoint"] = g.contactPoint, d["refR1"] = g.refR1, d["refR2"] = g.refR2;
		d["radius1"] = g.radius1, d["radius2"] = g.radius2, d["penetrationDepth"] = g.penetrationDepth, d["shearInc"] = g.shearInc;
	}
	if (c == "FrictPhys") {
		const auto& p = static_cast<const FrictPhys&>(*o);
		d["kn"] = p.kn, d["ks"] = p.ks, d["normalForce"] = p.normalForce, d["shearForce"] = p.shearForce;
		d["tangensOfFrictionAngle"] = p.tangensOfFrictionAngle;
	}
	return d;
}

py::dict AbiProbe::demFields(const shared_ptr<Serializable>& o) const { return fieldsOf(o.get()); }

// Python hands a ScGeom or FrictPhys over as a Serializable wrongly (boost.python's cast chain through
// Debian's registration), so the interaction's parts are read from the interaction.
py::dict AbiProbe::demInteractionFields(int id1, int id2) const
{
	const shared_ptr<Interaction>& I = currentScene().interactions->find(id1, id2);
	py::dict                       d;
	if (!I) return d;
	d["geom"] = fieldsOf(I->geom.get());
	d["phys"] = fieldsOf(I->phys.get());
	return d;
}
} // namespace yade
