"""One home for what the helpers read from YADE's Omega (``O``): the real RBSM joints, the free
blocks, and the engines of the loop by their labels.

:func:`yade_rbsm.engines` and :func:`yade_rbsm.mixed_engines` label their engines and functors
(collider, ig2, ip2, law, timeStepper, newton, pairCheck); a list built by hand may have no labels,
so :func:`engine` falls back to the class name of each label (:data:`LABEL_TYPES`).

Every function takes an optional *O* (default: ``yade.O``, imported when called, so this module
imports without YADE); classes are recognised by their names, so a stand-in O works too.
"""

__all__ = ["LABEL_TYPES", "is_joint", "joints", "is_fixed", "free_bodies", "engine", "engines_of_type", "newton", "before_newton", "ip2",
           "switch_off_pyrunners"]

#: the class each label of engines() / mixed_engines() names, for lists built without labels
LABEL_TYPES = {
    "collider": "InsertionSortCollider",
    "ig2": "Ig2_Polygon2D_Polygon2D_RbsmGeom",
    "ip2": "Ip2_RbsmMat_RbsmMat_RbsmPhys",
    "law": "Law2_RbsmGeom_RbsmPhys_MohrCoulomb",
    "timeStepper": "RbsmTimeStepper",
    "newton": "NewtonIntegrator",
    "pairCheck": "RbsmPairCheck",
}


def _omega(O):
    if O is None:
        from yade import O
    return O


# ---- joints and bodies ------------------------------------------------------------------------
def is_joint(I):
    """A real interaction with RBSM joint physics (RbsmPhys)."""
    return I.isReal and type(I.phys).__name__ == "RbsmPhys"


def joints(O=None):
    """The real RBSM joints (interactions with RbsmPhys), in O.interactions' order (a generator)."""
    return (I for I in _omega(O).interactions if is_joint(I))


def is_fixed(b):
    """A fixed block (all degrees of freedom blocked: foundation, wall)."""
    return b.state.blockedDOFs == "xyzXYZ"


def free_bodies(O=None):
    """The bodies that are not fixed (in O.bodies' order, erased ones skipped), a list."""
    return [b for b in _omega(O).bodies if b is not None and not is_fixed(b)]


# ---- engines ----------------------------------------------------------------------------------
def _functors(e):
    for d in ("geomDispatcher", "physDispatcher", "lawDispatcher"):
        disp = getattr(e, d, None)
        if disp is not None:
            yield from disp.functors


def _everything(O):
    """The engines and, inside each InteractionLoop, its functors, in loop order."""
    for e in O.engines:
        yield e
        yield from _functors(e)


def engines_of_type(name, O=None):
    """The engines and functors of class *name* (e.g. "PyRunner"), in loop order."""
    return [e for e in _everything(_omega(O)) if type(e).__name__ == name]


def engine(label, O=None):
    """The engine or functor labelled *label*; without one, the first of the class
    :data:`LABEL_TYPES` gives for the label. LookupError if there is neither."""
    O = _omega(O)
    for e in _everything(O):
        if getattr(e, "label", "") == label:
            return e
    name = LABEL_TYPES.get(label)
    found = engines_of_type(name, O) if name else []
    if not found:
        raise LookupError("no engine labelled %r%s in O.engines" % (label, " nor any %s" % name if name else ""))
    return found[0]


def newton(O=None):
    """The NewtonIntegrator (label "newton")."""
    return engine("newton", O)


def before_newton(engines, engine):
    """*engines* (a list) with *engine* inserted right before NewtonIntegrator (by label or class), else at the
    end: an engine that reads the step's forces, with NewtonIntegrator staying last."""
    at = [j for j, e in enumerate(engines) if getattr(e, "label", "") == "newton" or type(e).__name__ == LABEL_TYPES["newton"]]
    engines.insert(at[0] if at else len(engines), engine)
    return engines


def ip2(O=None):
    """The IPhys functor of the blocks' joints, Ip2_RbsmMat_RbsmMat_RbsmPhys (label "ip2")."""
    return engine("ip2", O)


def switch_off_pyrunners(O=None):
    """Sets ``dead`` on every PyRunner (monitors, output) for a run that is not to be recorded."""
    for e in engines_of_type("PyRunner", O):
        e.dead = True
