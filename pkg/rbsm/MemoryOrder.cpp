#include <pkg/rbsm/MemoryOrder.hpp>

#include <core/Scene.hpp>

#include <vector>

namespace yade {

namespace {
	bool hasSubdomains(const Scene& scene)
	{
		for (const auto& b : scene.bodies->body)
			if (b && (b->flags & Body::FLAG_SUBDOMAIN)) return true;
		return false;
	}

	// a new Interaction object with the state of I (the geometry and physics are shared, not copied)
	shared_ptr<Interaction> relocated(const Interaction& I)
	{
		auto J          = shared_ptr<Interaction>(new Interaction(I.id1, I.id2));
		J->isActive     = I.isActive;
		J->functorCache = I.functorCache;
		J->iterMadeReal = I.iterMadeReal;
		J->iterLastSeen = I.iterLastSeen;
		J->geom         = I.geom;
		J->phys         = I.phys;
		J->cellDist     = I.cellDist;
		J->iterBorn     = I.iterBorn;
		return J;
	}
} // namespace

long orderInteractionsInMemory(Scene& scene)
{
	InteractionContainer& intrs = *scene.interactions;
	if (intrs.size() == 0 || hasSubdomains(scene)) return 0;
	// all new objects first, while the old ones still hold their memory: the new ones then come
	// from fresh, consecutive memory instead of the holes the old ones leave
	std::vector<shared_ptr<Interaction>> moved;
	moved.reserve(intrs.size());
	for (const auto& I : intrs)
		if (I) moved.push_back(relocated(*I));
	intrs.clear(); // also the bodies' maps (their nodes are made anew, in order, by insert)
	for (const auto& J : moved)
		intrs.insert(J);
	return static_cast<long>(moved.size());
}
} // namespace yade
