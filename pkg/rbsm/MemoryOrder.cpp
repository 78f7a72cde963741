#include <pkg/rbsm/MemoryOrder.hpp>

#include <core/Scene.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>
#include <pkg/rbsm/RbsmPhys.hpp>

#include <algorithm>
#include <typeinfo>
#include <vector>

namespace yade {

namespace {
	bool hasSubdomains(const Scene& scene)
	{
		for (const auto& b : scene.bodies->body)
			if (b && (b->flags & Body::FLAG_SUBDOMAIN)) return true;
		return false;
	}

	bool idsBefore(const Interaction& a, const Interaction& b) { return a.id1 < b.id1 || (a.id1 == b.id1 && a.id2 < b.id2); }

	// held only by its owner (use_count: the owner's pointer + `extra` known ones): safe to replace
	template <class P> bool ownedOnly(const shared_ptr<P>& p, long extra = 0) { return p.use_count() == 1 + extra; }

	// a copy of an RBSM part nobody else holds, or the part itself (other classes: no copy constructor
	// known here; held elsewhere: a copy would leave that reference stale)
	template <class Rbsm, class Base> shared_ptr<Base> nextToIt(const shared_ptr<Base>& part)
	{
		if (!part || typeid(*part) != typeid(Rbsm) || !ownedOnly(part)) return part;
		return shared_ptr<Base>(new Rbsm(static_cast<const Rbsm&>(*part)));
	}

	// the interaction again, allocated now (with its geometry and physics right after it)
	shared_ptr<Interaction> relocated(const shared_ptr<Interaction>& I)
	{
		// held by the container, both bodies' maps and the sorted list of orderInteractionsInMemory
		if (!ownedOnly(I, 3)) return I;
		auto J          = shared_ptr<Interaction>(new Interaction(I->id1, I->id2));
		J->isActive     = I->isActive;
		J->functorCache = I->functorCache;
		J->iterMadeReal = I->iterMadeReal;
		J->iterLastSeen = I->iterLastSeen;
		J->geom         = nextToIt<RbsmGeom>(I->geom);
		J->phys         = nextToIt<RbsmPhys>(I->phys);
		J->cellDist     = I->cellDist;
		J->iterBorn     = I->iterBorn;
		return J;
	}
} // namespace

long orderInteractionsInMemory(Scene& scene)
{
	InteractionContainer& intrs = *scene.interactions;
	if (intrs.size() == 0) return 0;
	if (hasSubdomains(scene)) return -1;
	std::vector<shared_ptr<Interaction>> sorted;
	sorted.reserve(intrs.size());
	for (const auto& I : intrs)
		if (I) sorted.push_back(I);
	std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return idsBefore(*a, *b); });
	// all new objects first, while the old ones still hold their memory: the new ones then come
	// from fresh, consecutive memory instead of the holes the old ones leave
	std::vector<shared_ptr<Interaction>> moved;
	moved.reserve(sorted.size());
	for (const auto& I : sorted)
		moved.push_back(relocated(I));
	sorted.clear();
	// the same set again: the collider's view stays valid, so the flag that clear() raises (a full
	// re-initialisation of the collider at the next step) is put back
	const bool dirty = intrs.dirty;
	intrs.clear(); // also the bodies' maps (their nodes are made anew, in order, by insert)
	for (const auto& J : moved) {
		const long born = J->iterBorn; // insert() sets it to this step
		intrs.insert(J);
		J->iterBorn = born;
	}
	intrs.dirty = dirty;
	return static_cast<long>(moved.size());
}
} // namespace yade
