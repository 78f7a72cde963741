"""The scene part of a block slope (needs YADE, imported inside the functions, so that slope.py,
which re-exports these names, still loads without it): the blocks of a :class:`slope.SlopeBlocks`
into O.bodies, bonding and breaking joints (crack, crack polylines), joint sets with their own
strength, the unbalanced-force ratio and the gravity stage. Import these from ``yade_rbsm.slope``."""
import json
import math
import numbers

__all__ = ["build_scene", "break_crack", "joints_on", "joints_of", "set_water", "set_seismic", "break_joints", "set_joint_strength", "give_joint_sets", "joint_sets",
           "apply_joint_sets", "bond_and_break", "unbalanced_ratio", "settle"]


def build_scene(sb, material=None, thickness=1.0):
    """Append the blocks of *sb* to O.bodies (slope blocks free, foundation and walls fixed); sets
    ``Block.id`` and ``sb.ids`` (``sb.ids[k]`` is the id of ``sb.blocks[k]``) and each body's refPos and refOri (for
    displacements and rotations since it was built). Returns the ids. The ids follow a Z-order curve over the blocks' centroids
    (geometry.z_order), not sb.blocks' order: neighbours get near ids, so that the joints sorted by ids
    (RbsmTimeStepper.orderInteractions) find both blocks near each other in memory (a 14 404-block
    Voronoi slope, whose builder numbers blocks at random: 21 % less time per step).
    With layers (``sb.layers``) each slope block takes its layer's material, the fixed blocks
    *material* (default: the bottom layer's); the joints between layers then take the weaker
    material (Ip2_RbsmMat_RbsmMat_RbsmPhys)."""
    from yade import O
    from . import geometry
    from .blocks import polygon2d
    if material is None and not sb.layers:
        raise ValueError("build_scene: give a material (the blocks have no layers)")

    def mat(b):
        if sb.layers and not b.fixed:
            return sb.layers[b.layer][1]
        return material if material is not None else sb.layers[0][1]
    order = [sb.blocks[k] for k in geometry.z_order([geometry.polygon_centroid(b.vertices) for b in sb.blocks])]
    bodies = [polygon2d(b.vertices, mat(b), thickness=thickness, fixed=b.fixed) for b in order]
    built = _tagged(_BUILT_TAG) or {}
    for b, i in zip(order, O.bodies.append(bodies)):
        b.id = i
        st = O.bodies[i].state
        st.refPos, st.refOri = st.pos, st.ori
        axis, angle = st.ori.toAxisAngle()
        built[str(i)] = [st.pos[0], st.pos[1], angle * (1.0 if axis[2] >= 0 else -1.0)]
    # the pose each block was built in, kept with the scene: joints_on reads its cuts there, whatever
    # State.refPos and refOri become (resetting them is how YADE scripts reset displacements)
    O.tags[_BUILT_TAG] = json.dumps(built)
    sb.ids = [b.id for b in sb.blocks]
    return sb.ids


def break_crack(sb, tol=None, counted=None):
    """Break (RbsmPhys.breakJoint) every joint lying on the crack line x = xc above yc. Returns the
    number of joints broken (of those for which ``counted(I)`` is true, if given)."""
    from yade import O
    if sb.crack is None:
        return 0
    xc, yc = sb.crack
    tol = tol if tol is not None else 1e-6 * max(1.0, abs(xc))
    n = 0
    for I in O.interactions:
        if not I.isReal:
            continue
        p0, p1 = I.geom.p0, I.geom.p1
        if abs(p0[0] - xc) <= tol and abs(p1[0] - xc) <= tol and 0.5 * (p0[1] + p1[1]) > yc:
            I.phys.breakJoint()
            n += 1 if counted is None or counted(I) else 0
    return n


def joints_on(polylines, tol=None):
    """The real joints whose contact segment lies on a segment of one of the *polylines* (both ends
    within *tol*, default 1e-6 x the scene size; length > *tol*: corner contacts at a point of the
    polyline are not on it) with their two blocks on opposite sides of it: the joints a cut along
    the polylines made (builders' ``joints=`` and ``cracks=``). Tested in the pose build_scene put the
    blocks in (kept with the scene in O.tags: resetting State.refPos and refOri, YADE's way to reset
    displacements, changes nothing; for bodies build_scene did not make, their refPos and refOri), so
    that a settled slope's joints are found on the polylines it was cut along. The segment (RbsmGeom.p0, p1) lies on the edge of
    the block that holds the reference edge (RbsmGeom.refBody), and was computed before the last
    step moved the blocks: it is taken back with that block's pose of then (pos - vel dt, ori
    turned back by angVel dt), so that neither the joint's overlap (mm in a settled soft slope) nor
    the last step's motion (a soft slope's first step, in bond_and_break) moves it off the polyline.
    The joints :func:`bond_and_break` found on the builder's cuts are found again by their blocks, wherever
    their segment has gone since (a wedge settled 1.2 cm down its bedding moved a crack joint's segment
    past the crack's end: it kept the rock's 5 MPa and the FS was 2.01 against Hoek & Bray's 1.48)."""
    from yade import O
    segs = _segments(polylines)
    if not segs:
        return []
    tol = _tolerance(segs, tol)
    out = {(I.id1, I.id2): I for I, _, _ in _reference_segments(segs, tol)}
    n = len(O.bodies)
    pose = _built_poses()
    for id1, id2, x0, y0, x1, y1 in _recorded_cuts():
        # a block erased since, or held by another rank under yade.mpy (the records are every rank's):
        # YADE's interactions.has() aborts the process for a body that is not there
        if not all(0 <= i < n and O.bodies[i] is not None for i in (id1, id2)):
            continue
        if (id1, id2) not in out and O.interactions.has(id1, id2) and _on_segments((x0, y0), (x1, y1), segs, tol, id1, id2, pose):
            I = O.interactions[id1, id2]
            if I.isReal:
                out[(id1, id2)] = I
    return list(out.values())


_CUTS_TAG = "yade_rbsm.cut_joints"
_BUILT_TAG = "yade_rbsm.built_pose"


def _built_poses():
    """id -> (pos, ori) of the pose build_scene put each body in (O.tags), State.refPos and refOri for the
    bodies it did not build (a scene saved before the tag: the same, unless the script reset them)."""
    from yade import O, Quaternion, Vector3
    tag = _tagged(_BUILT_TAG) or {}

    def pose(i):
        p = tag.get(str(i))
        if p is None:
            s = O.bodies[i].state
            return s.refPos, s.refOri
        return Vector3(p[0], p[1], 0), Quaternion(Vector3(0, 0, 1), p[2])
    return pose


def _segments(polylines):
    return [(a, b) for l in polylines for a, b in zip(l[:-1], l[1:])]


def _tolerance(segs, tol):
    if tol is not None:
        return tol
    return 1e-6 * max(max(abs(c) for s in segs for p in s for c in p), 1.0)


def _on_segments(p0, p1, segs, tol, id1, id2, pose=None):
    """The reference segment p0-p1 of the joint of bodies id1, id2 lies on one of *segs* with the blocks
    (centroids in the built pose, *pose*: :func:`_built_poses`) on opposite sides of it."""
    from .geometry import point_segment_distance
    if math.hypot(p1[0] - p0[0], p1[1] - p0[1]) <= tol:
        return False
    pose = pose or _built_poses()
    c1, c2 = pose(id1)[0], pose(id2)[0]

    def opposite(a, b):
        dx, dy = b[0] - a[0], b[1] - a[1]
        s1 = dx * (c1[1] - a[1]) - dy * (c1[0] - a[0])
        s2 = dx * (c2[1] - a[1]) - dy * (c2[0] - a[0])
        return s1 * s2 < 0
    return any(point_segment_distance(p0, a, b) <= tol and point_segment_distance(p1, a, b) <= tol and opposite(a, b)
               for a, b in segs)


def _reference_segments(segs, tol):
    """(I, p0, p1) for the real joints whose segment, taken back to the reference pose (see
    :func:`joints_on`), lies on *segs*."""
    from yade import O, Quaternion, Vector3
    from . import omega
    dt = O.dt
    pose = _built_poses()
    for I in omega.joints(O):
        ids = (I.id2, I.id1) if getattr(I.geom, "refBody", 1) == 2 else (I.id1, I.id2)
        if type(O.bodies[ids[0]].shape).__name__ != "Polygon2D":  # a wall's or facet's edge: the block's pose
            ids = ids[::-1]
        s = O.bodies[ids[0]].state
        pos = s.pos - s.vel * dt  # the pose the geometry was computed in (NewtonIntegrator: pos += vel dt)
        ori = Quaternion(Vector3(0, 0, 1), -s.angVel[2] * dt) * s.ori
        ref_pos, ref_ori = pose(ids[0])
        back = ref_ori * ori.conjugate()  # that pose -> the built pose

        def ref(x):
            v = ref_pos + back * (Vector3(x[0], x[1], 0) - pos)
            return v[0], v[1]
        p0, p1 = ref(I.geom.p0), ref(I.geom.p1)
        if _on_segments(p0, p1, segs, tol, I.id1, I.id2, pose):
            yield I, p0, p1


def _tagged(tag):
    """The JSON list kept with the scene under O.tags[*tag*] ([] if none)."""
    from yade import O
    return json.loads(O.tags[tag]) if tag in O.tags.keys() else []


def _recorded_cuts():
    return _tagged(_CUTS_TAG)


def _record_cuts(polylines):
    """Keeps with the scene (O.tags) the joints on the builder's cuts and their reference segments, right
    after the bond step: joints_on finds them again by their blocks."""
    from yade import O
    segs = _segments(polylines)
    if not segs:
        return
    from . import mpi
    rec = [[I.id1, I.id2, p0[0], p0[1], p1[0], p1[1]] for I, p0, p1 in _reference_segments(segs, _tolerance(segs, None))]
    if mpi.is_split():  # each rank sees its own joints: every rank keeps all (migration, to_serial's merge)
        rec = [r for part in mpi.distributed().comm.allgather(rec) for r in part]
    # one entry per pair of blocks, the latest (bond_and_break called again appended them all once more)
    kept = {(r[0], r[1]): r for r in _recorded_cuts() + rec}
    O.tags[_CUTS_TAG] = json.dumps(list(kept.values()))


def break_joints(polylines, tol=None, counted=None):
    """Break (RbsmPhys.breakJoint) every joint on the *polylines* (:func:`joints_on`). Returns the
    number broken (of those for which ``counted(I)`` is true, if given)."""
    n = 0
    for I in joints_on(polylines, tol):
        I.phys.breakJoint()
        n += 1 if counted is None or counted(I) else 0
    return n


def set_joint_strength(polylines, cohesion, friction_angle, tensile_strength=None, ductile=None, tol=None,
                       normal_stiffness=None, shear_stiffness=None, name=None, skip_missing=False):
    """A joint set with its own strength: every joint on the *polylines* (:func:`joints_on`; e.g. a
    bedding plane given to a builder's ``joints=``) gets *cohesion* [Pa], tan(*friction_angle* [rad])
    and *tensile_strength* [Pa] (default: the Mohr-Coulomb apex cohesion / tan(friction_angle); a
    cohesive joint without tensile strength loses its cohesion at the first round-off tension), and
    RbsmPhys.ductile if *ductile* is given. The other joints keep what their blocks' materials gave.
    *normal_stiffness*, *shear_stiffness* [Pa/m] (UDEC's jkn, jks), if given, replace the blocks' Kawai
    springs on the set (RbsmPhys.kn, ks; the time step follows at once; strength reduction does not
    reduce them). Give them before settling: the normal springs are total (traction = kn x overlap), so
    a kn above that of a joint in compression is refused (its force would jump); a softer one is taken
    (the blocks sink onto it). Contacts made later along the set take it too, unless it is stiffer
    than theirs and they carry load by then (:func:`apply_joint_sets`).
    Call it after :func:`bond_and_break` (intact points keep their cohesion, broken ones stay broken);
    strength_reduction then reduces these strengths as any joint's. Contacts made later (a block
    sliding onto a new neighbour along the set) take their blocks' materials when they form: the set is
    kept with the scene (:func:`joint_sets`, in O.tags) and :func:`apply_joint_sets` gives them the
    set's strength; strength_reduction does so between the chunks of its trials (without it a wedge
    on a 30 deg set in 40 deg rock, tan 30 / tan 25 = 1.238, stopped at 1.269).
    *name*: the set's name, kept with it (:func:`joints_of` finds its joints by it for the rest of the run).
    *skip_missing*: leave out a polyline without a joint instead of refusing it (give_joint_sets: a trace
    whose joints are not found; ValueError still if none has any).
    *friction_angle* in radians: degrees (> pi/2) are refused. Returns the number of joints set (over
    all ranks under yade.mpy, where every rank calls it);
    ValueError if a polyline carries no joint (it misses the blocks' cuts) or a value is out of range."""
    from .checks import number
    from .geometry import points
    who = "set_joint_strength"
    polylines = list(polylines)
    first = polylines[0] if polylines else None
    if hasattr(first, "__len__") and len(first) == 2 and all(isinstance(v, numbers.Real) for v in first):
        raise ValueError("%s: polylines is a list of polylines, [[(x0, y0), (x1, y1), ...], ...]; this looks like "
                         "one polyline (its first item is the point %r): give [polyline]" % (who, tuple(polylines[0])))
    polylines = [points("%s: polylines[%d]" % (who, k), l, 2) for k, l in enumerate(polylines)]
    if not polylines:
        raise ValueError("%s: no polylines given" % who)
    cohesion = number(who, "cohesion", cohesion, 0)
    friction_angle = number(who, "friction_angle", friction_angle, 0, 0.5 * math.pi, high_open=True)
    if tensile_strength is None:
        if cohesion > 0 and friction_angle == 0:
            raise ValueError("%s: give tensile_strength for a cohesive joint without friction (the default "
                             "cohesion / tan(friction_angle) is infinite)" % who)
        tensile_strength = cohesion / math.tan(friction_angle) if cohesion > 0 else 0.0
    tensile_strength = number(who, "tensile_strength", tensile_strength, 0)
    if ductile is not None and not isinstance(ductile, bool):  # ("no" was taken as True)
        raise ValueError("%s: ductile must be True, False or None (the blocks' own), got %r" % (who, ductile))
    if tol is not None:
        tol = number(who, "tol", tol, 0, low_open=True)
    stiffness = [None if v is None else number(who, name, v, 0, low_open=True)
                 for name, v in (("normal_stiffness", normal_stiffness), ("shear_stiffness", shear_stiffness))]
    from yade import O
    from . import mpi
    found = [joints_on([l], tol) for l in polylines]
    counts = [float(len(js)) for js in found]
    if mpi.is_split():  # a rank may hold none of a polyline's joints: the check is the whole scene's
        counts = mpi.allreduce_sum(counts)
    if skip_missing and any(counts):
        polylines, found = [l for l, n in zip(polylines, counts) if n], [js for js, n in zip(found, counts) if n]
        counts = [n for n in counts if n]
    for k, n in enumerate(counts):
        if n == 0:
            raise ValueError("%s: no joint lies on polylines[%d] %s (give the polyline the blocks were cut along, "
                             "after build_scene and bond_and_break; the joints are looked for where build_scene put "
                             "the blocks, kept in O.tags, or for other bodies State.refPos and refOri: were these reset since?)" % (who, k, polylines[k]))
    joint_set = dict(name=name, polylines=[[list(p) for p in l] for l in polylines], tol=tol, cohesion=cohesion,
                     tan_phi=math.tan(friction_angle), tensile_strength=tensile_strength, ductile=ductile,
                     kn=stiffness[0], ks=stiffness[1])
    if stiffness[0] is not None:
        loaded = [I for js in found for I in js if _loaded_and_stiffer(I.phys, "kn", stiffness[0])]
        n_loaded = int(mpi.allreduce_sum([float(len(loaded))])[0]) if mpi.is_split() else len(loaded)
        if n_loaded:
            e = ("e.g. bodies #%d and #%d: kn %g Pa/m, normal force %g N" % (loaded[0].id1, loaded[0].id2, loaded[0].phys.kn,
                                                                            loaded[0].phys.normalForce)
                 if loaded else "on other ranks")
            raise ValueError("%s: normal_stiffness %g Pa/m is above the kn of %d joints of the set that carry load (%s): "
                             "the normal springs are total (traction = kn x overlap), so their force would jump and throw "
                             "the blocks apart; give the set's stiffness before settling (after bond_and_break)"
                             % (who, stiffness[0], n_loaded, e))
    done = {(I.id1, I.id2) for js in found for I in js}
    _give(joint_set, [I for js in found for I in js])
    # kept with the scene (saved, and in O.saveTmp), for contacts made later along the set
    O.tags[_SETS_TAG] = json.dumps(joint_sets() + [joint_set])
    if mpi.is_split():  # each joint once over the ranks (mpi.counted_here)
        return int(mpi.allreduce_sum([float(sum(1 for k in done if mpi.counted_here(O.interactions[k])))])[0])
    return len(done)


_SETS_TAG = "yade_rbsm.joint_sets"


def joint_sets():
    """The joint sets set_joint_strength gave the current scene (kept in O.tags, so saved with it):
    [{name, polylines, tol, cohesion, tan_phi, tensile_strength, ductile, kn, ks}], in the order they were
    given (kn, ks None: the blocks' springs; name None if none was given)."""
    return _tagged(_SETS_TAG)


def joints_of(name):
    """The real joints now on the joint set or trace called *name* (its name in jointset_blocks, or
    set_joint_strength's *name*), contacts made since it was given included: a list of interactions.
    ValueError naming the sets the scene has, for a name it has not."""
    sets = [js for js in joint_sets() if js.get("name") == name]
    if not sets:
        raise ValueError("joints_of: no joint set called %r (the scene's: %s)" % (
            name, ", ".join(repr(js.get("name")) for js in joint_sets()) or "none"))
    found = {}
    for js in sets:
        for I in joints_on(js["polylines"], js["tol"]):
            found[(I.id1, I.id2)] = I
    return list(found.values())


def _give(js, joints, F=1.0, reduce_tensile=False):
    """The strength of the joint set *js* (a :func:`joint_sets` entry), divided by *F* (the tensile
    strength only if *reduce_tensile*), to *joints*. Returns how many changed."""
    tan_phi, c = js["tan_phi"] / F, js["cohesion"] / F
    t = js["tensile_strength"] / F if reduce_tensile else js["tensile_strength"]
    # the stiffness is not reduced by F (sets saved before it was part of them have none)
    springs = [(name, js[name]) for name in ("kn", "ks") if js.get(name) is not None]
    n = 0
    for I in joints:
        ph = I.phys
        changed = (ph.tanPhi, ph.cohesion, ph.tensileStrength) != (tan_phi, c, t)
        if changed:
            ph.tanPhi, ph.cohesion, ph.tensileStrength = tan_phi, c, t
        for name, v in springs:  # only where it differs: a new stiffness makes the stepper estimate again
            if getattr(ph, name) != v and not _loaded_and_stiffer(ph, name, v):
                setattr(ph, name, v)
                changed = True
        if js["ductile"] is not None:
            ph.ductile = bool(js["ductile"])
        if js.get("water") and not ph.water:  # a contact made along a wet set takes the water
            ph.water = True
        if ph.welded:  # a joint of the set is a discontinuity, not a cut of a deformable continuum
            ph.welded = False
            changed = True
        n += changed
    return n


def _loaded_and_stiffer(ph, name, v):
    """The normal springs are total (traction = kn x overlap): a stiffer kn on a joint in compression
    would raise its force at once and throw its blocks apart (a 1 m layer settled on the rock's springs
    and given a set's 83 x stiffer kn bounced for 200 000 steps); shear tractions are incremental."""
    return name == "kn" and v > ph.kn and ph.normalForce > 0


def apply_joint_sets(F=1.0, reduce_tensile=False, sets=None):
    """Give the contacts on the joint sets (*sets*, default :func:`joint_sets`) the set's friction,
    divided by *F* (strength reduction's trial factor), and its cohesion and tensile strength (divided
    too, the tensile strength only if *reduce_tensile*), and its springs if it has them: contacts a block
    makes along a set as it slides take their blocks' materials when they form. strength_reduction calls it between the chunks of
    every trial; a dynamic run may call it from a PyRunner. Sets given later win where they overlap.
    Returns the number of contacts changed."""
    from .checks import number
    F = number("apply_joint_sets", "F", F, 0, low_open=True)  # (F = -2 wrote negative strengths)
    return sum(_give(js, joints_on(js["polylines"], js["tol"]), F, reduce_tensile)
               for js in (joint_sets() if sets is None else sets))


def bond_and_break(sb, give_sets=True):
    """Bond every initial joint (ip2.setCohesionNow for the first step), take that step, then break
    the joints of the crack (``sb.crack``) and of the crack polylines (``sb.cracks``), and give the
    joint sets and traces of :func:`slope.jointset_blocks` their strength (:func:`give_joint_sets`;
    with *give_sets* False they keep the rock's through the gravity stage, UDEC's practice of an elastic
    equilibrium first: call give_joint_sets(sb) after :func:`settle`; a wedge held by cohesion slides
    while gravity comes on at once and its normal force builds up). Returns
    (number of joints, number broken). Under yade.mpy call it on every rank after
    yade_rbsm.mpi.distribute() (the step is then distributed, each rank bonds and breaks its joints,
    and the counts are of the whole scene)."""
    from yade import O
    from . import omega, mpi
    omega.ip2(O).setCohesionNow = True
    if mpi.is_split():
        mpi.run(1)
    else:
        O.step()
    counted = mpi.counted_here
    crack = []  # the bricks' crack (x = xc above yc) as a polyline: joints_on finds its joints after the wedge slid
    if sb.crack is not None:
        crack = [[(sb.crack[0], sb.crack[1]), (sb.crack[0], max(y for _, y in sb.surface))]]
    _record_cuts(list(sb.joints) + list(sb.cracks) + crack + [t for t, _ in sb.layers if t is not None])  # (the layers' tops cut too)
    nj = sum(1 for I in O.interactions if I.isReal and counted(I))
    nb = break_crack(sb, counted=counted) + break_joints(sb.cracks, counted=counted)
    if give_sets:
        give_joint_sets(sb)
    if mpi.is_split():
        nj, nb = (int(v) for v in mpi.allreduce_sum([nj, nb]))
    return nj, nb


def give_joint_sets(sb):
    """The strength of the joint sets and traces of :func:`slope.jointset_blocks` to their joints, once
    bonded (:func:`bond_and_break` does it unless told not to): :func:`set_joint_strength` along the
    set's traces that cut a joint (SetCut.traces), with its name, so that the sets are kept with the scene
    as any set_joint_strength's and found by :func:`joints_of`. A set
    without a friction angle takes the rock's: the least tan(phi) its joints got from their blocks'
    materials. Returns the number of joints given a set's strength."""
    n = 0
    from . import mpi
    for sc in getattr(sb, "joint_sets", ()):
        src = sc.source
        if not sc.segments:
            continue
        # the set's traces that kept a joint (its joints' edges for an older SetCut): a few long polylines;
        # one whose joints the scene does not find is left out (far from the origin, a trace with one
        # short edge went unfound), by set_joint_strength's own search
        polylines = [list(t) for t in getattr(sc, "traces", [])] or [list(e) for e in sc.segments]
        if src.friction_angle is not None:
            phi = math.radians(src.friction_angle)
        else:
            tans = [I.phys.tanPhi for I in joints_on(polylines)]
            t = min(tans) if tans else float("inf")
            if mpi.is_split():
                t = min(mpi.distributed().comm.allgather(t))
            phi = math.atan(t)
        n += set_joint_strength(polylines, src.cohesion, phi, tensile_strength=src.tensile_strength, ductile=src.ductile,
                                normal_stiffness=src.kn, shear_stiffness=src.ks, name=sc.name, skip_missing=True)
    return n


def set_water(phreatic, joints="sets", unit_weight=9810.0, open_water=False):
    """Water in the joints (UDEC's hydrostatic joint pressure, seed's landslide trigger): below the phreatic
    surface *phreatic* (a polyline of strictly increasing x [m], continued level beyond its ends) each point
    of a wet joint has the pore pressure u = unit_weight x depth below it, which pushes its blocks apart;
    the joint's strength is then c + (σn - u) tan(phi) (Law2_RbsmGeom_RbsmPhys_MohrCoulomb.phreatic).
    *joints*: "sets" (default) for the joints of the scene's joint sets and traces (set_joint_strength,
    jointset_blocks; contacts made later along them too), a tension crack given as a trace included; "all"
    for every joint, the rock's bonded ones too (UDEC: every contact); or a list of set names. The water
    is kept with the scene (O.engines, O.tags), so strength reduction, fos() and dynamic runs take it; it
    stays as given (no flow): set it again to raise it. None removes it. Returns the number of joints wet.

    *open_water*: the blocks stand in open water below the line (a reservoir, a flooded toe, a submerged block),
    so their free faces take the pressure too (OpenWaterPressure: the water's pressure on every block's whole
    boundary, buoyancy included); a dry contact below the line is then pressed shut by the water around it.
    Without it (the default) only the wet joints take water, as UDEC's joints do: right for a water table inside
    a rock slope, whose face above the seepage point is dry."""
    from yade import O, Vector2
    from . import omega
    from .checks import number
    from .geometry import monotone
    law = omega.engine("law", O)
    if not isinstance(open_water, bool):
        raise ValueError("set_water: open_water must be True or False, got %r" % (open_water,))
    if phreatic is None:
        _open_water(O, law, None, 0)
        law.phreatic = []
        for I in omega.joints(O):
            I.phys.water = False
        O.tags[_SETS_TAG] = json.dumps([dict(js, water=False) for js in joint_sets()])
        return 0
    line = monotone("set_water: phreatic", phreatic)  # (every check before any change: a refusal changes nothing)
    unit_weight = number("set_water", "unit_weight", unit_weight, 0)
    sets = joint_sets()
    if isinstance(joints, str) and joints not in ("sets", "all"):
        joints = [joints]  # one set's name ("bedding" read as its letters named seven sets)
    names = None if joints in ("sets", "all") else list(joints)
    if names is not None:
        known = {js.get("name") for js in sets}
        missing = [n for n in names if n not in known]
        if missing:
            raise ValueError("set_water: no joint set called %s (the scene's: %s)" % (
                ", ".join(map(repr, missing)), ", ".join(repr(n) for n in known) or "none"))
    elif joints == "sets" and not sets:
        raise ValueError("set_water: the scene has no joint sets (set_joint_strength, jointset_blocks): give "
                         "joints='all' for water in every joint")
    law.waterUnitWeight = unit_weight
    law.phreatic = [Vector2(x, y) for x, y in line]
    law.waterAll = joints == "all"
    _open_water(O, law, law.phreatic if open_water else None, unit_weight)
    if joints == "all":
        return sum(1 for _ in omega.joints(O))
    wet = set()
    for js in sets:
        js["water"] = names is None or js.get("name") in names
        for I in joints_on(js["polylines"], js["tol"]):  # (a set not named: dry)
            I.phys.water = js["water"]
            if js["water"]:
                wet.add((I.id1, I.id2))
    O.tags[_SETS_TAG] = json.dumps(sets)
    return len(wet)


def _open_water(O, law, line, unit_weight):
    """The open water's engine (label "openWater", before NewtonIntegrator) with the law's water table, or none."""
    from yade import wrapper
    from . import omega
    O.engines = [e for e in O.engines if getattr(e, "label", "") != "openWater"]
    law.openWater = line is not None
    if line is not None:
        O.engines = omega.before_newton(list(O.engines), wrapper.OpenWaterPressure(
            phreatic=line, waterUnitWeight=unit_weight, label="openWater"))


_STATIC_GRAVITY_TAG = "yade_rbsm.static_gravity"


def static_gravity():
    """The scene's static gravity: NewtonIntegrator's, kept in O.tags the first time a pseudo-static or earthquake
    load changes it (so that both can give it back)."""
    from yade import O
    from . import omega
    if _STATIC_GRAVITY_TAG not in O.tags.keys():
        O.tags[_STATIC_GRAVITY_TAG] = json.dumps(list(omega.newton(O).gravity))
    return json.loads(O.tags[_STATIC_GRAVITY_TAG])


def set_seismic(kh, kv=0.0, towards=1):
    """Pseudo-static earthquake load in the block model: gravity becomes g (towards kh, -(1 - kv)) with g the
    static gravity's magnitude (kept in O.tags the first time, so that set_seismic(0) gives it back): a
    horizontal acceleration kh g towards *towards* (+1: +x, -1: -x; the face's outward side), and kv g
    upwards (kv > 0 lightens the blocks), the convention of limit equilibrium's pseudo-static methods (a
    force kh W at each block's centroid). Strength reduction, fos() and dynamic runs take it (it is the
    NewtonIntegrator's gravity); settle under it only if it is stable. Returns the gravity set."""
    from yade import O
    from . import omega
    from .checks import number
    kh = number("set_seismic", "kh", kh, 0, 1)
    kv = number("set_seismic", "kv", kv, -1, 1, high_open=True)
    if towards not in (1, -1):
        raise ValueError("set_seismic: towards must be +1 (+x) or -1 (-x), the side the face looks to (got %r)" % (towards,))
    newton = omega.newton(O)
    g0 = static_gravity()
    gm = math.sqrt(sum(c * c for c in g0))
    if gm == 0:
        raise ValueError("set_seismic: NewtonIntegrator.gravity is zero: there is no weight to load pseudo-statically")
    if kh == 0 and kv == 0:
        newton.gravity = tuple(g0)
    else:
        newton.gravity = (towards * kh * gm, -(1 - kv) * gm, 0.0)
    return tuple(newton.gravity)


def unbalanced_ratio(ids=None, gravity=None):
    """Unbalanced-force ratio = mean over free blocks of |contact force + m·g| divided by the mean
    of |m·g| (computed from O.forces.f, the masses and NewtonIntegrator's gravity). 0 at static
    equilibrium, about 1 for blocks in free fall. Under density scaling (RbsmTimeStepper.massScale) a
    scaled block's force in O.forces is (F + m g)/s - m g: its residual counts s times that, its own
    (read as it was, 2 cm pebbles in the air scaled 115 x let settle converge at once). Collective
    under yade.mpy (yade_rbsm.mpi): each rank sums over the blocks it integrates."""
    from yade import O
    from . import omega, mpi
    from .scene import time_stepper
    if gravity is None:
        gravity = omega.newton(O).gravity
    gx, gy = gravity[0], gravity[1]
    g = math.hypot(gx, gy)
    stepper = time_stepper()
    scale = list(stepper.massScale) if stepper is not None else []  # of the last step (empty: none)
    num = den = 0.0
    for b in O.bodies:
        if b is None or (ids is not None and b.id not in ids) or omega.is_fixed(b) or not mpi.owned(b):
            continue
        f = O.forces.f(b.id)
        m = b.state.mass
        s = scale[b.id] if b.id < len(scale) else 1.0
        num += s * math.hypot(f[0] + m * gx, f[1] + m * gy)
        den += m * g
    if mpi.is_split():
        num, den = mpi.allreduce_sum([num, den])
    return num / den if den > 0 else 0.0


def settle(tol=1e-3, max_steps=50000, check=100, damping=0.7, progress=None, density_scaling=False):
    """Initial (gravity) stage: run with NewtonIntegrator damping *damping* until the unbalanced-force
    ratio (:func:`unbalanced_ratio`) is below *tol*, checked every *check* steps, or *max_steps*.
    *density_scaling*: RbsmTimeStepper.densityScaling during the stage (the small blocks made heavier
    so that all run at the median block's step: the same equilibrium in fewer steps; the motion on the
    way is not physical). Contacts made along a joint set (:func:`set_joint_strength`) get its
    properties after every *check* steps (:func:`apply_joint_sets`). Restores the previous damping and
    scaling. Returns (converged, steps, ratio). Under yade.mpy every rank calls it (yade_rbsm.mpi.run, and a collective ratio)."""
    from yade import O
    from .checks import count, flag, number
    tol = number("settle", "tol", tol, 0, low_open=True)
    density_scaling = flag("settle", "density_scaling", density_scaling)
    max_steps, check = count("settle", "max_steps", max_steps), count("settle", "check", check)
    damping = number("settle", "damping", damping, 0, 1, high_open=True)
    from . import omega, mpi
    from .scene import time_stepper
    newton = omega.newton(O)
    mpi.check_one_subdomain("settle")
    if not any(newton.gravity):  # the ratio is relative to the weight: without it every state is "settled"
        raise ValueError("settle: NewtonIntegrator.gravity is zero: there is no weight to settle under (the "
                         "unbalanced-force ratio is relative to it); set gravity, e.g. yade_rbsm.engines(gravity=(0, -9.81, 0))")
    old = newton.damping
    newton.damping = damping
    stepper = time_stepper()
    if density_scaling and stepper is None:
        raise ValueError("settle: density_scaling needs RbsmTimeStepper in O.engines (yade_rbsm.engines())")
    old_scaling = stepper.densityScaling if stepper is not None else False
    if stepper is not None:
        stepper.densityScaling = bool(density_scaling)
    steps, ratio = 0, float("inf")
    sets = joint_sets()
    try:
        while steps < max_steps:
            mpi.run(check)
            steps += check
            if sets:  # contacts made along a joint set take their blocks' materials when they form
                apply_joint_sets(sets=sets)
            ratio = unbalanced_ratio()
            if progress:
                progress(steps, ratio)
            if ratio < tol:
                return True, steps, ratio
        return False, steps, ratio
    finally:
        newton.damping = old
        if stepper is not None:
            stepper.densityScaling = old_scaling
