"""Checks of a scene's bodies against the engine lists of yade_rbsm (engines(), mixed_engines()), run when a
list is made: what would otherwise end the process inside YADE's interaction loop becomes a ValueError."""
from yade import wrapper


def check_materials(bodies=None):
    """Raises ValueError naming the bodies if a Polygon2D has no RbsmMat (YADE would find no IPhys functor for
    its contacts and end the process), or if spheres of RbsmMat and of FrictMat are both present next to blocks
    (YADE's IPhys dispatch asserts the order of two material classes, which two spheres meet in either order)."""
    if bodies is None:
        from yade import O
        bodies = O.bodies
    wrong, sphere_mats, blocks = [], set(), False
    for b in bodies:
        if b is None or b.shape is None:
            continue
        if isinstance(b.shape, wrapper.Polygon2D):
            blocks = True
            if not isinstance(b.material, wrapper.RbsmMat):
                wrong.append("#%d (%s)" % (b.id, type(b.material).__name__ if b.material is not None else "no material"))
        elif isinstance(b.shape, wrapper.Sphere) and b.material is not None:
            sphere_mats.add("RbsmMat" if isinstance(b.material, wrapper.RbsmMat) else
                            "FrictMat" if isinstance(b.material, wrapper.FrictMat) else type(b.material).__name__)
    if wrong:
        raise ValueError("Polygon2D bodies need an RbsmMat: body %s%s (make blocks with yade_rbsm.polygon2d(vertices, "
                         "RbsmMat(...)))" % (", ".join(wrong[:10]), " and %d more" % (len(wrong) - 10) if len(wrong) > 10 else ""))
    if blocks and {"RbsmMat", "FrictMat"} <= sphere_mats:
        raise ValueError("spheres of RbsmMat and of FrictMat in one scene with blocks: YADE's IPhys dispatch meets the two "
                         "materials of two spheres in either order and ends the process (Debian's build asserts it); give "
                         "the spheres one material class")


def phys_functor_missing(id1, id2):
    """"" if every InteractionLoop in O.engines has an IPhys functor for the materials of bodies id1 and id2,
    otherwise the two material class names as "A B" (RbsmPairCheck asks this, once per material pair, for the
    pairs with a block that are about to touch: YADE's loop ends the process at a contact without one)."""
    from yade import O
    m1, m2 = O.bodies[id1].material, O.bodies[id2].material
    for e in O.engines:
        if isinstance(e, wrapper.InteractionLoop) and not e.dead and e.physDispatcher.dispFunctor(m1, m2) is None:
            return "%s %s" % (type(m1).__name__, type(m2).__name__)
    return ""
