"""Placing bodies in a container without overlap, in the current scene (scene S7's drum is filled so:
roundedmesh_study.drum).

    lattice_poses(nodes, count, rng, jitter)   a seeded choice of lattice nodes, jittered, each with a random
                                               orientation: where bodies start, apart, before they are grown or
                                               relaxed to their size
    push_apart(max_depth, max_steps)           runs the scene until no two bodies overlap deeper than max_depth
    touching(allowed)                          one step of the engine: the pairs that touch, refused if deeper

A container full to a random packing's density holds no lattice of its bodies at their size; they start on a lattice
smaller (or as something smaller: clumps that grow) and are pushed apart at their size, without gravity or friction,
by the contact engine itself (push_apart), until touching() finds them apart.
"""
import math

import numpy as np
from yade import O

from .readout import contacts


def random_orientation(rng):
    """A uniformly random rotation as a unit quaternion (w, x, y, z): a normalised 4D Gaussian. `rng` is a
    numpy Generator."""
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def lattice_poses(nodes, count, rng, jitter=0.0):
    """[(position (3,) [m], quaternion (w, x, y, z))] of `count` bodies at a random choice of `nodes` (n, 3) [m]
    (the nodes of a lattice inside the container, each far enough from its walls and the others for the body put
    there), each moved by up to `jitter` [m] along each axis and turned at random (random_orientation). `rng` (a numpy
    Generator) draws the choice, then each body's jitter and orientation in turn: a seed gives the same poses.
    Raises ValueError when there are fewer nodes than bodies."""
    nodes = np.asarray(nodes, dtype=float)
    if len(nodes) < count:
        raise ValueError(f"placement: the lattice has {len(nodes)} nodes for {count} bodies")
    chosen = nodes[rng.permutation(len(nodes))[:count]]
    return [(node + rng.uniform(-jitter, jitter, 3), random_orientation(rng)) for node in chosen]


def push_apart(max_depth, max_steps, chunk=100, log=None):
    """Runs the current scene (its O.engines and O.dt; gravity and friction are the caller's to leave out) `chunk`
    steps at a time until no pair that roundedmesh computes overlaps deeper than `max_depth` [m] (rm.contacts()),
    for at most `max_steps` steps of O.iter. `log` (a function of a line), if given, hears every 1000 steps and at
    the end. Returns the deepest overlap left [m]; raises RuntimeError naming it when the steps run out."""
    deepest = math.inf
    while O.iter < max_steps:
        O.run(chunk, True)
        depths = contacts()["depth"]
        deepest = depths.max() if len(depths) else 0.0
        if log is not None and (O.iter % 1000 == 0 or deepest < max_depth):
            log(f"  relaxing: step {O.iter}, {len(depths)} touching pairs, deepest {deepest * 1e3:.4f} mm")
        if deepest < max_depth:
            return deepest
    raise RuntimeError(f"placement: the bodies still overlap by {deepest * 1e3:.3f} mm after {max_steps} steps "
                       f"(wanted: {max_depth * 1e3:g} mm)")


def touching(allowed=0.0):
    """One step of the current scene's engines: the number of pairs roundedmesh finds touching. Raises RuntimeError
    when any touches (with `allowed` [m] > 0: when any overlaps deeper than that), naming the count and the deepest."""
    O.step()
    depths = contacts()["depth"]
    if len(depths) and (not allowed or depths.max() > allowed):
        raise RuntimeError(f"placement: {len(depths)} pairs touch at the start, the deepest by "
                           f"{depths.max() * 1e3:.4f} mm" + (f" (allowed: {allowed * 1e3:g} mm)" if allowed else ""))
    return len(depths)
