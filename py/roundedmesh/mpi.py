"""Rounded bodies under YADE's own MPI decomposition, yade.mpy: a scene split into subdomains, one process each.

    mpiexec -n 3 yade -n -x my_scene.py          # my_scene.py builds the scene, then:
    import roundedmesh as rm
    rm.mpi.mpirun(20000)                          # in place of yade.mpy.mpirun(20000)

How it works (doc/architecture.md, "Many processes"):
  - mpy ships a body to the processes whose subdomain its bound overlaps, and erases it elsewhere. A rounded body
    is bound-less in one process (bodies.py); for mpy it becomes a Tetra (a YADE shape for which the collider has no
    bound functor, so YADE never computes a bound, an interaction or a contact of it), bounded, with an Aabb of its
    whole rounded surface grown by a margin (BOUND_MARGIN of its bound radius), set here before each of mpy's
    collisions (an Aabb is not saved: it comes as NaN with every transfer), and a group mask that lets YADE's
    collider pair it with subdomain bodies only. The collider is labelled "collider", the name mpy calls it by.
  - A worker's copies of the master's bodies are moved as the master moves them (mpy does not update them).
  - Its YADE material goes into O.materials (mpy's merge needs it there), one per density.
  - Its mesh and HertzMaterial travel with the scene mpy sends from the master to every worker at the split
    (O.tags): every process knows every rounded body, whether it holds it or not.
  - On each process the engine computes the pairs with one side it owns (the master's walls, boxes and facets'
    with the workers' bodies on the workers), and applies the forces of its own bodies and of the master's (which
    mpy sends to the master): stepping.py, ContactData::residences.
  - A stop (a pair past stop_overlap, a centre through a wall) on one process ends every process with its message
    (MPI_Abort), since the others would wait for it forever.
Not supported: sphere bodies (rm.add_sphere), adding or erasing bodies after the split, mpy's reallocation of bodies
between workers (REALLOCATE_FREQUENCY), periodic cells. A body's tangential springs live on the processes that
compute its pairs; they are not merged into the master's scene by withMerge.
"""
import json
import sys
import time

import numpy as np
from yade import Aabb, InsertionSortCollider, Material, NewtonIntegrator, O, PyRunner, Shape, Tetra
from yade.minieigenHP import Quaternion, Vector3

from . import readout, stepping
from ._records import _load_mesh, _tag, _tags_named
from .bodies import _YADE_LABEL, _body_or_none

# Group masks (YADE's Collider::mayCollide): two bodies are paired when their masks share a bit, unless the masks are
# equal and share a bit with avoidSelfInteractionMask. Rounded bodies (6) are never paired with each other (equal,
# with the avoided bit 4) nor with YADE's bodies of the default mask 1 (no common bit); subdomain bodies, which mpy
# creates with mask 1, get 3: paired with the rounded bodies (bit 2), the master's walls (bit 1) and each other.
ROUNDED_MASK, SUBDOMAIN_MASK, AVOIDED_MASK = 6, 3, 4
BOUND_MARGIN = 0.2  # of a rounded body's bound radius: how far it moves before mpy collides again


def _mpy():
    from yade import mpy  # imported here: importing it starts MPI
    if mpy.comm is None:
        mpy.configure()
    return mpy


def _rounded_ids():
    return sorted(int(i) for i in _tags_named("body"))


def _collider():
    colliders = [e for e in O.engines if isinstance(e, InsertionSortCollider)]
    if len(colliders) != 1:
        raise ValueError(f"O.engines holds {len(colliders)} InsertionSortColliders; yade.mpy needs exactly one "
                         "(before the roundedmesh engine, with the bound functors of the scene's Walls, Boxes and Facets)")
    collider = colliders[0]
    if any(type(f).__name__ == "Bo1_Tetra_Aabb" for f in collider.boundDispatcher.functors):
        raise ValueError("InsertionSortCollider: a Bo1_Tetra_Aabb functor would bound the rounded bodies, which are "
                         "Tetra under yade.mpy (roundedmesh.mpi); remove it")
    if collider.avoidSelfInteractionMask not in (0, AVOIDED_MASK):
        raise ValueError(f"InsertionSortCollider.avoidSelfInteractionMask is {collider.avoidSelfInteractionMask}; "
                         f"roundedmesh.mpi needs {AVOIDED_MASK} (rounded bodies share that group-mask bit)")
    return collider


def _shared_material(density):
    """The YADE material of rounded bodies of this density, in O.materials."""
    for material in O.materials:
        if type(material) is Material and material.label == _YADE_LABEL and material.density == density:
            return material
    material = Material(density=density, label=_YADE_LABEL)
    O.materials.append(material)
    return material


def _bound(body, radius):
    p = body.state.pos
    half = (1 + BOUND_MARGIN) * radius
    d = Vector3(half, half, half)
    return Aabb(min=p - d, max=p + d, refPos=p, sweepLength=BOUND_MARGIN * radius)


_radii = {}  # body id -> the bound radius of its mesh [m]
_collisions = 0  # of mpy's parallel collisions in this process


def _refresh_bounds():
    """Bounds of the rounded bodies this process holds, and the masks of the subdomain bodies: before each of mpy's
    collisions."""
    for subdomain in O.subD.subdomains if getattr(O, "subD", None) is not None else ():
        if O.bodies[subdomain] is not None:
            O.bodies[subdomain].groupMask = SUBDOMAIN_MASK
    for body_id, radius in _radii.items():
        body = _body_or_none(body_id)
        if body is not None and body.bounded:
            body.bound = _bound(body, radius)


def _wrap_parallel_collide(mpy):
    # mpy's splitScene and checkAndCollide call parallelCollide through its module globals.
    if getattr(mpy.parallelCollide, "roundedmesh", False):
        return
    original = mpy.parallelCollide

    def parallel_collide():
        global _collisions
        _collisions += 1
        _refresh_bounds()
        original()
    parallel_collide.roundedmesh = True
    mpy.parallelCollide = parallel_collide


_FOLLOWER = "__import__('roundedmesh').mpi._move_master_copies()"


def _follow_master_bodies():
    """A worker holds copies of the master's partners (a Wall, a Box, a Facet) that mpy never updates (its
    MASTER_UPDATE_STATES path hangs in YADE 2023.02a) and its NewtonIntegrator does not move: a PyRunner after
    NewtonIntegrator moves them as the master's NewtonIntegrator moves the originals, by the velocities the scene's
    motion engines, which run on every process, gave them."""
    engines = [e for e in O.engines if not (isinstance(e, PyRunner) and e.command == _FOLLOWER)]
    newton = next(i for i, e in enumerate(engines) if isinstance(e, NewtonIntegrator))
    O.engines = engines[:newton + 1] + [PyRunner(command=_FOLLOWER, iterPeriod=1, initRun=True)] + engines[newton + 1:]


def _move_master_copies():
    if not getattr(O, "splitted", False) or _mpy().rank == 0:
        return
    for body_id in map(int, _tags_named("partner")):
        body = _body_or_none(body_id)
        if body is None or body.subdomain != 0 or body.dynamic:
            continue
        state = body.state
        state.pos = state.pos + state.vel * O.dt  # NewtonIntegrator's operations: the master's position, bitwise
        if state.angVel.squaredNorm() > 0:  # the same rotation, not necessarily to the last bit
            state.ori = Quaternion(state.angVel.normalized(), state.angVel.norm() * O.dt) * state.ori
            state.ori.normalize()


def assign_subdomains(workers=None, axis=None):
    """Gives the rounded bodies to the workers 1..workers (default: every worker process of this run) in slabs of
    equal counts along `axis` (0, 1, 2; default: the axis on which they spread most); every other body stays the
    master's (subdomain 0). Slabs across the bodies' fall keep the workers' loads even in a packing that settles
    (a gravitational packing: a horizontal axis). A script may set body.subdomain itself instead."""
    if workers is None:
        workers = _mpy().numThreads - 1
    ids = _rounded_ids()
    if workers < 1 or not ids:
        return
    positions = np.array([list(O.bodies[i].state.pos) for i in ids])
    if axis is None:
        axis = int(np.argmax(positions.var(axis=0)))
    elif axis not in (0, 1, 2):
        raise ValueError(f"axis: expected 0, 1 or 2, got {axis!r}")
    order = np.argsort(positions[:, axis], kind="stable")
    for rank, chunk in enumerate(np.array_split(order, workers), start=1):
        for k in chunk:
            O.bodies[ids[k]].subdomain = rank


def prepare(mpy=None):
    """Makes the rounded bodies of the current scene ready for mpy's split (the module's docstring), on every
    process, before mpy.mpirun; assigns them to the workers (assign_subdomains) unless the script did. Raises
    ValueError, changing nothing, for a scene mpy cannot run (sphere bodies, no or two colliders)."""
    mpy = mpy or _mpy()
    if _tags_named("sphere"):
        raise ValueError(f"sphere bodies {sorted(map(int, _tags_named('sphere')))}: not supported under yade.mpy "
                         "(roundedmesh.mpi); use rounded bodies of an icosphere mesh")
    collider = _collider()
    ids = _rounded_ids()
    if mpy.numThreads > 1 and not any(O.bodies[i].subdomain > 0 for i in ids):
        assign_subdomains(mpy.numThreads - 1)
    collider.avoidSelfInteractionMask = AVOIDED_MASK
    # mpy's parallel collision calls the collider by its label: without it, the workers' bodies are never paired
    # with the other subdomains and never shipped.
    collider.label = "collider"
    _follow_master_bodies()  # assigns O.engines anew, which makes YADE publish the label
    for body_id in ids:
        body = O.bodies[body_id]
        mesh = _load_mesh(json.loads(_tag(f"body.{body_id}"))["mesh"])
        _radii[body_id] = mesh.bound_radius
        body.shape = Tetra()
        body.bounded = True
        body.groupMask = ROUNDED_MASK
        body.material = _shared_material(body.material.density)
        body.bound = _bound(body, _radii[body_id])
    _wrap_parallel_collide(mpy)


def restore():
    """After a merge (mpirun(..., withMerge=True)), on the master: the rounded bodies as one process has them
    (bodies.py), so that the scene runs on with O.run."""
    for body_id in _rounded_ids():
        body = _body_or_none(body_id)
        if body is not None:
            body.shape = Shape()
            body.bounded = False
            body.groupMask = 1


def mpirun(nSteps, withMerge=False):
    """yade.mpy.mpirun(nSteps, withMerge=withMerge) for a scene with rounded bodies: prepare() on the first call,
    then the run; a stop on any process ends every process (MPI_Abort) after printing its message. Returns, on the
    master, the merged summary of the run (summary()); None on the workers."""
    mpy = _mpy()
    if mpy.numThreads == 1:  # one process: the scene as it is
        start, first = time.time(), O.iter
        O.run(nSteps, True)
        return summary(mpy, O.iter - first, time.time() - start, 0)
    if not O.splitted:
        prepare(mpy)
    start, first, collisions = time.time(), O.iter, _collisions
    try:
        mpy.mpirun(nSteps, withMerge=False)
    except Exception as error:  # the other processes would wait for this one forever
        # One write per line: print's separate write of the newline lets another process's output in between.
        sys.__stderr__.write(f"roundedmesh.mpi: rank {mpy.rank}: {_cause(error)}\n")
        sys.__stderr__.flush()
        mpy.comm.Abort(1)
    parts = summary(mpy, O.iter - first, time.time() - start, _collisions - collisions)
    if withMerge:
        mpy.mergeScene()
        if mpy.rank == 0:
            restore()
    return parts


def _cause(error):
    """The line of YADE's "PyRunner error ... STACK TRACE" that says why the run stopped."""
    lines = str(error).splitlines()
    return next((line for line in lines if line.startswith("roundedmesh stopped the run")), lines[0] if lines else "")


def _own_summary(mpy, steps, seconds, collisions):
    state = stepping._current_state()
    own = [i for i in _rounded_ids() if (b := _body_or_none(i)) is not None and b.subdomain == mpy.rank]
    s = readout.statistics() if state is not None and state.stepped_iteration is not None else {}
    return {"rank": mpy.rank, "bodies": len(own), "steps": steps, "seconds": seconds, "collisions": collisions,
            "touching_pairs": s.get("touching_pairs", 0),
            "triangle_contacts": s.get("quadrature_contacts", 0) + s.get("direct_contacts", 0) + s.get("exact_contacts", 0),
            "deepest_pair_fraction": s.get("deepest_pair_fraction", 0.0)}


def summary(mpy=None, steps=0, seconds=0.0, collisions=0):
    """Every process's part of a run and of its last step, gathered on the master: a list of dicts (rank, bodies
    owned, steps, seconds, mpy's collisions, touching_pairs, triangle_contacts, deepest_pair_fraction of the last
    step), printed there; None on the workers. A pair of two workers' bodies counts on both."""
    mpy = mpy or _mpy()
    own = _own_summary(mpy, steps, seconds, collisions)
    parts = mpy.comm.gather(own, root=0) if mpy.numThreads > 1 else [own]
    if mpy.rank != 0:
        return None
    print("roundedmesh.mpi: rank  bodies  steps  ms/step  collisions  touching pairs  triangle contacts  deepest [r_eq]")
    for p in parts:
        per_step = 1e3 * p["seconds"] / p["steps"] if p["steps"] else float("nan")
        print(f"roundedmesh.mpi: {p['rank']:4d}  {p['bodies']:6d}  {p['steps']:5d}  {per_step:7.3f}  {p['collisions']:10d}  "
              f"{p['touching_pairs']:14d}  {p['triangle_contacts']:17d}  {p['deepest_pair_fraction']:.3g}", flush=True)
    return parts
