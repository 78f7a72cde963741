// VtkRecorderGuard: keeps YADE's VTKRecorder from crashing on RBSM blocks.
#pragma once
#include <core/Engine.hpp>
#include <core/Scene.hpp>

#include <vector>

namespace yade {

/* YADE's VTKRecorder reads every contact as a sphere contact (static casts to ScGeom, FrictPhys,
 * NormShearPhys, GenericSpheresContact) for its recorders 'intr', 'stress', 'bstresses', 'all' and
 * the model-specific ones (cpm, wpm, jcfpm, ...): on RBSM joints it reads other memory and crashes
 * YADE (segfault in Shop::getStressForEachBody or vtkXMLWriter) or writes garbage. The plugin cannot
 * change YADE's casts, so when the engine list changes it switches such a VTKRecorder off (dead) in
 * a scene with Polygon2D blocks, and says so, before the recorder runs. */
class VtkRecorderGuard {
public:
	/// Checks scene.engines if they changed since the last call (cheap otherwise). Serial code only.
	void check(Scene& scene);
	/// The recorders of YADE's VTKRecorder that read contacts as sphere contacts.
	static bool unsafeRecorder(const std::string& name);

private:
	std::vector<const Engine*> seen;
};

} // namespace yade
