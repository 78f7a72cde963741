// Ig2_Polygon2D_Polygon2D_RbsmGeom: builds and updates RbsmGeom for two Polygon2D blocks.
#pragma once
#include <core/Dispatching.hpp>
#include <pkg/rbsm/Polygon2D.hpp>
#include <pkg/rbsm/RbsmGeom.hpp>

namespace yade {

class Ig2_Polygon2D_Polygon2D_RbsmGeom : public IGeomFunctor {
public:
	bool go(const shared_ptr<Shape>& s1,
	        const shared_ptr<Shape>& s2,
	        const State&             state1,
	        const State&             state2,
	        const Vector3r&          shift2,
	        const bool&              force,
	        const shared_ptr<Interaction>& I) override;
	bool goReverse(const shared_ptr<Shape>&, const shared_ptr<Shape>&, const State&, const State&, const Vector3r&, const bool&, const shared_ptr<Interaction>&) override
	{
		throw std::logic_error("Ig2_Polygon2D_Polygon2D_RbsmGeom::goReverse called: the functor is symmetric and must not be reversed");
	}
	//! Checks the attributes when they are set (raises ValueError in Python, before any step).
	void postLoad(Ig2_Polygon2D_Polygon2D_RbsmGeom&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ig2_Polygon2D_Polygon2D_RbsmGeom, IGeomFunctor,
		"Edge-to-edge contact of two :yref:`Polygon2D` blocks (RBSM, seed paper Fig. 3 and eq. 8-9): separating-axis search "
		"for the reference edge, clipping of the facing edge, integration points along the contact segment. A new contact "
		"is made when the blocks overlap or are closer than :yref:`interactionDistance<Ig2_Polygon2D_Polygon2D_RbsmGeom.interactionDistance>`; "
		"an existing one is kept (also open, in tension) until the law removes it; a wet one (:yref:`RbsmPhys.waterForce` > 0) "
		"while it opens up to the smaller block's size, so that an opening crack keeps its water.",
		((int, nIP, 2, Attr::triggerPostLoad, "Integration points per contact (1-8, Gauss-Legendre). 2 integrates the force and moment of the linear traction of two rigid blocks exactly; more points resolve partial slip and partial opening along a joint."))
		((Real, interactionDistance, 0, Attr::triggerPostLoad, "Largest gap [m] at which a new contact is made (0: touching or overlapping)."))
		((Real, hysteresis, 1e-6, Attr::triggerPostLoad, "Relative margin (fraction of the smaller block size) by which another edge must be better before the reference edge of a contact changes; avoids flip-flopping between the two sides of a shared edge. It must stay well below overlap/size, or a contact keeps an edge that no longer faces the other block."))
		((Real, updateTolerance, 0, Attr::triggerPostLoad, "Trade of accuracy for speed (dimensionless, fraction of the smaller block's diameter). 0 (default): the exact contact geometry (search and clipping) at every step. > 0: while the two blocks of a joint have moved relative to each other by less than updateTolerance × diameter since its last exact update, the joint follows its contact segment as material points of the two blocks (Kawai's small-displacement kinematics, pkg/rbsm/kernel/FrozenContact.hpp): overlap errors O(tol²·size), contact length within tol·size of the exact one; a joint opening beyond its reach (a gap at an end larger than interactionDistance, plus 2σt/kn while intact) and larger motions get the exact geometry, as do new contacts. At most 1e-3, the range in which the verification scenes keep their answers (a runout within 0.1 %; 1e-2 moved it by -5 %). Measured trade in docs/benchmarks.md.")),
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(Polygon2D, Polygon2D);
	DEFINE_FUNCTOR_ORDER_2D(Polygon2D, Polygon2D);

private:
	// The steps of go (Ig2_Polygon2D_Polygon2D_RbsmGeom.cpp): the two blocks and block 2's pose in
	// block 1's frame; the exact update's outcome.
	struct Pair;
	enum class Outcome { Touching, Apart, Lost };
	static void forgetOldShapes(Interaction& I, const Polygon2D& A, const Polygon2D& B);
	Real        reach(const Interaction& I, bool existing, Real minSize) const;
	void        passThrough(const Interaction& I, Real depth, Real halfWidth, bool impact) const;
	bool        followFrozen(const Pair& pair, const Interaction& I, const RbsmGeom& g, rbsm::EdgeContact& c) const;
	Outcome     exactContact(const Pair& pair, const State& state1, const State& state2, const shared_ptr<Interaction>& I, RbsmGeom*& g, rbsm::EdgeContact& c);
	RbsmGeom*   newGeom(const Pair& pair, const State& state1, const State& state2, Interaction& I, const rbsm::SearchMemory& memory);
};
REGISTER_SERIALIZABLE(Ig2_Polygon2D_Polygon2D_RbsmGeom);

} // namespace yade
