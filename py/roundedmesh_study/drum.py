"""Scene S7 of doc/scenes.md, the rotating drum: a drum of YADE Facets made here in the manner of YADE's
examples/baraban (a mantle of 24 flat panels, two end caps and 4 lifter ridges, all Facets), turning about the
horizontal y axis at 3 rad/s with YADE's RotationEngine, filled with 30 gummy bears, 30 pears (rounded bodies) and
40 YADE spheres of radius 0.01 m (rm.add_sphere), with friction mu = 0.5. O.dt = 1e-4 s, 20,000 steps (2 s).

    yade -n -x scripts/examples/example_drum.py [--steps 20000] [--out out/drum] [--seed 1] [--sample 100]
        [--vtk-every 1000] [--threads 1] [--peers clumps] [--start-overlap 0.3] [--place-only] [--contents horses]
    /usr/bin/python3 scripts/examples/example_drum.py [the same options]

--contents horses fills the same drum with 30 of YADE's own GTS horses instead (examples/gts-horse/horse.coarse.gts,
336 nodes, scaled to 56 mm long; Debian's yade package ships it), loaded as a user would, with Mesh.load's defaults
(the coarse mesh is remeshed where too coarse for its curvature: 4,709 nodes), same materials, placed apart on a
lattice of their boxes (horse_poses) and run the same way: the test of a coarse real mesh in a Facet drum (issue 24).

The drum (ours, S7): the mantle is a regular 24-gon prism whose panels lie at the inner radius 0.15 m from the axis
(panel k centred at the angle 15 k degrees in the x-z plane, its corners at 0.15 / cos(7.5 deg) = 0.1513 m), from
y = -0.06 m to 0.06 m, each panel two Facets; each end cap is a fan of 24 Facets from the axis to the mantle's
corners; the 4 lifters stand on the panels at 0, 90, 180 and 270 degrees, each a triangular prism along the whole
length (10 mm wide where it meets the panel, its ridge 15 mm inside it) of which the two sloping faces are Facets
(two each); 112 Facets in all. RotationEngine(ids = the Facets, rotationAxis (0, 1, 0), angularVelocity 3,
rotateAroundZero, zeroPoint (0, 0, 0)) turns them from the first step; gravity (0, 0, -9.81) m/s^2.

Materials (S7): bodies and spheres E = 1e6 Pa, nu = 0.4, 2000 kg/m^3, A = 0.01 s, mu = 0.5; Facets E = 5e6 Pa,
nu = 0.4, mu = 0.5, and A = 0.01 s too (a pair takes the mean of its two A, so that a body's contact with the drum
has A = 0.01 s as with another body; S1 gives its box the same A); no tangential damping (S7 gives none).

Placement. S7's contents fill 48 % of the drum's volume (60 bodies of r_eq = 25 mm: 3.93 l, 40 spheres: 0.17 l,
the drum 8.48 l), more than the bounding boxes of random orientations leave room for (the bears' 92 x 66 x 31 mm
and the pears' 64 x 47 x 47 mm boxes add up to 9.9 l), and a gummy bear reaches 48.5 mm from its centre, so its
bounding sphere spans 81 % of the drum's length: no lattice inside the drum, nor any random sequential placement,
holds them at their size with seeded orientations, and they are near the densest random packing the drum holds.
They are placed as such drums are filled, by growing them from the lattice (initial_poses):
  1. the lattice: nodes 34 mm apart inside the drum (clear of the lifters), 100 of them chosen and jittered by up
     to 0.5 mm, seeded, each with a seeded uniformly random orientation; at 0.34 of their size no two bodies'
     bounding spheres overlap, nor one and the drum;
  2. YADE's own bodies, fast: each body as a clump of spheres inside it (the 40 spheres of
     roundedmesh_study.peers.clump_spheres for a bear; 15 spheres on the pear's axis, each reaching the mesh's nearest
     node), each YADE sphere as itself, at 0.34 of their size on the lattice, grow to their size in the drum
     (utils.growParticles, 40 equal factors, 250 steps after each) without gravity or friction, then relax until
     no two overlap by more than 0.1 mm. Fixed spheres of 3 mm along the lifters' ridges keep the ridges from
     slipping between two spheres of a clump. The clumps leave out the bodies' blends (the meshes' nodes stand up
     to 0.7 mm out of them): clumps 0.7 mm larger, which would hold the bodies whole, jam in the drum;
  3. the rounded bodies, the exact surfaces: each body's mesh and each sphere enlarged by 0.4 %, at the poses the
     clumps reached, in the drum, without gravity or friction, with NewtonIntegrator's damping 0.3, until no pair
     overlaps by more than 0.02 mm (at most 40,000 steps);
  4. the check: the bodies at their own size at those poses (every point of a body at least 0.04 mm inside its
     enlarged self, as no node of a mesh is nearer than 10 mm to its centre) touch nothing in a step of the
     roundedmesh engine.
The poses are kept in <out>/placement_seed<seed>.csv; a later run with the same seed and --out reads them (the
roundedmesh run and the clumps run start from the same poses), and
scripts/examples/drum_placements/placement_seed<seed>.csv is read too if it is there (write it with --place-only --out
scripts/examples/drum_placements). Either is checked (4.) before it is used. The drum starts full, end cap to end cap:
the bodies at rest, touching nothing.
S7 asks for no overlap, and its contents do not come apart that far: the meshes enlarged by 0.4 % still overlap by
0.18 mm after the 40,000 steps of step 3 (measured: jammed). So the script lets the bodies start overlapping by up to
--start-overlap MM millimetres, 0.3 by default (START_OVERLAP: 1.2 % of r_eq, an eighth of the Hertz range
0.1 r_eq, so the first steps push such pairs apart gently): step 3 relaxes them at their own size until no pair overlaps deeper, the check allows it, and the placement is a file of its own,
<out>/placement_seed<seed>_overlap<MM>mm.csv (seed 1's is shipped in scripts/examples/drum_placements/).
--start-overlap 0 asks for S7's clean start and fails with the measured overlap.

Outputs, in <out>/<run> (run: roundedmesh, or clumps with --peers clumps):
    drum.csv      every --sample steps: step, time [s], mean height of the centres [m] (z; the drum's axis is at
                  z = 0), kinetic energy of the bodies [J] (translation and rotation), max speed [m/s], bodies whose
                  centre is outside the drum, the drum's angle [rad], touching pairs and contacts (roundedmesh:
                  rm.statistics(); clumps: touching body pairs and real interactions) and wall ms per step
    drum.png      mean height, kinetic energy and max speed vs time
    initial_state.csv  every body's kind, id, position [m] and orientation (w, x, y, z) at the start
    timing.csv    steps asked and done, wall time of building and running [s], median wall ms per step, threads,
                  whether the run completed and why it stopped if not, machine, command
    vtk/drum.pvd  ParaView series every --vtk-every steps (roundedmesh.export.VtkSeries): rounded bodies (part 0),
                  YADE's spheres and clump members (part 1), the drum's Facets (part 2, with the force on each)
At the end the time per step is printed, beside that of the other run when <out> has one.

--peers clumps runs the same drum from the same poses filled with YADE's own bodies instead: each gummy bear a
40-sphere clump (roundedmesh_study.peers.clump_spheres, add_clump: the shape's mass), each pear the clump of its two
primitive spheres, the spheres YADE spheres, under YADE's Hertz-Mindlin (Ip2_FrictMat_FrictMat_MindlinPhys with
the friction angle atan(0.5) and roundedmesh_study.peers' damping ratios) with InsertionSortCollider and
Ig2_Facet_Sphere_ScGeom for the drum. --threads sets the OpenMP threads of the roundedmesh engine and of YADE's
loops: the script starts again in a new process with OMP_NUM_THREADS set (run() uses the process's own).

The run stops early, with the message, when the roundedmesh engine stops it (its stop rule) or when a body's
centre leaves the drum; the outputs so far are written and the script exits with status 1.
"""
import argparse
import csv
import ctypes
import json
import math
import os
import shlex
import statistics as stats
import sys
import time
import warnings

import numpy as np

import roundedmesh as rm  # imports YADE
from roundedmesh import placement
from roundedmesh.export import VtkSeries
from roundedmesh.progress import Progress

from yade import (Bo1_Facet_Aabb, Bo1_Sphere_Aabb, ForceResetter, FrictMat, Ig2_Facet_Sphere_ScGeom,
                  Ig2_Sphere_Sphere_ScGeom, InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_MindlinPhys,
                  Law2_ScGeom_MindlinPhys_Mindlin, MatchMaker, NewtonIntegrator, O, RotationEngine, utils)
from yade.minieigenHP import Quaternion, Vector3

from . import SCRIPTS, peers
from .benchmarking import machine

# --- scene S7 (doc/scenes.md) ---------------------------------------------------------------------------
DRUM_RADIUS = 0.15        # inner radius: the panels' distance from the axis [m]
DRUM_LENGTH = 0.12        # between the end caps [m]
PANELS = 24               # flat panels of the mantle, two Facets each
LIFTERS = 4               # ridges along the mantle, every 90 degrees
LIFTER_HEIGHT = 0.015     # [m]
LIFTER_BASE = 0.010       # width on the panel [m]
ANGULAR_VELOCITY = 3.0    # [rad/s] about +y
GRAVITY = 9.81            # [m/s^2], along -z
COUNTS = {"gummy_bear": 30, "pear": 30}
SPHERES = 40
SPHERE_RADIUS = 0.01      # [m]
FRICTION = 0.5
BODY = dict(young=1e6, poisson=0.4, density=2000.0, damping=0.01)
DRUM = dict(young=5e6, poisson=0.4, density=2000.0, damping=0.01)  # density unused: the drum is kinematic
TIME_STEP = 1e-4          # [s]
STEPS = 20000
START_OVERLAP = 0.3e-3    # [m] the deepest overlap the bodies may start with (S7's contents jam apart: docstring)
CORNER_RADIUS = DRUM_RADIUS / math.cos(math.pi / PANELS)  # the mantle's corners [m]
RUNS = ("roundedmesh", "clumps")
FIELDS = ["step", "time_s", "mean_height_m", "kinetic_energy_J", "max_speed_m_s", "outside", "drum_angle_rad",
          "touching_pairs", "contacts", "ms_per_step"]

# --- placement (module docstring) ------------------------------------------------------------------------
START_SCALE = 0.34        # the bodies' size on the lattice, a fraction of their own
LATTICE_SPACING = 0.034   # [m]: more than START_SCALE times a gummy bear's reach from its centre, twice
JITTER = 0.0005           # [m]
GROWTH_STAGES = 40        # the clumps grow to their own size in this many equal factors ...
GROWTH_STEPS = 250        # ... each followed by this many steps
GROWN_RELAX_STEPS = 10000  # then at most this many steps ...
GROWN_DEPTH = 1e-4        # ... until no clumps overlap deeper than this [m]
PEAR_PROXY_SPHERES = 15
PROXY_MARGIN = 0.0        # the clumps' spheres are this much larger than the proxy spheres [m]
RIDGE_GUARD = 0.003       # radius of the spheres along the lifters' ridges while the clumps grow [m]
ENLARGE = 0.004           # the rounded bodies' enlargement while their overlaps relax (fraction)
RELAXED_DEPTH = 2e-5      # the deepest overlap left after relaxing [m]
RELAX_DAMPING = 0.3       # NewtonIntegrator's damping while they relax ...
RELAX_MAX_STEPS = 40000   # ... for at most this many steps
MIN_CENTRE_DISTANCE = 0.01  # no body's surface comes nearer its centre than this [m] (checked)
PLACEMENT_VERSION = 1
HORSE_FILE = "/usr/share/doc/yade/examples/gts-horse/horse.coarse.gts"  # Debian's yade package ships it
HORSE_LENGTH = 0.056      # [m]
HORSES = 30


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--steps", type=int, default=STEPS, help=f"time steps (default {STEPS}: 2 s)")
    parser.add_argument("--out", default=os.path.join("out", "drum"), help="output folder (default out/drum)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the lattice's jitter and the orientations")
    parser.add_argument("--sample", type=int, default=100, help="steps per row of drum.csv (default 100)")
    parser.add_argument("--vtk-every", type=int, default=1000,
                        help="steps between ParaView frames (default 1000); 0: none")
    parser.add_argument("--threads", type=int, default=None, help="OpenMP threads (default: OpenMP's own)")
    parser.add_argument("--peers", choices=["clumps"], help="run the drum with YADE's 40-sphere clumps instead")
    parser.add_argument("--start-overlap", type=float, default=START_OVERLAP * 1e3, metavar="MM",
                        help=f"let the bodies start overlapping by up to MM millimetres (default {START_OVERLAP * 1e3:g}; "
                             "0: S7's clean start, which its contents do not reach)")
    parser.add_argument("--contents", choices=["s7", "horses"], default="s7",
                        help="s7 (default): S7's bears, pears and spheres; horses: 30 of YADE's GTS horses (56 mm)")
    parser.add_argument("--place-only", action="store_true",
                        help="only place the bodies (written to <out>/placement_seed<seed>.csv)")
    args = parser.parse_args(argv)
    for name in ("steps", "sample"):
        if getattr(args, name) < 1:
            parser.error(f"--{name} must be at least 1")
    if args.vtk_every < 0:
        parser.error("--vtk-every must be 0 (no frames) or positive")
    if not (args.start_overlap >= 0 and math.isfinite(args.start_overlap)):
        parser.error("--start-overlap must be 0 or a positive number of millimetres")
    args.start_overlap *= 1e-3
    if args.threads is not None and args.threads < 1:
        parser.error("--threads must be at least 1")
    args.run = args.peers or "roundedmesh"
    return args


# --- the drum ---------------------------------------------------------------------------------------------

def _point(angle, radius, y):
    return np.array([radius * math.cos(angle), y, radius * math.sin(angle)])


def drum_triangles():
    """{'mantle', 'cap', 'lifter'}: lists of triangles (3 points (3,) [m]) of the drum (module docstring). Panel k is
    centred at the angle 2 pi k / PANELS in the x-z plane; each triangle is counter-clockwise seen from inside the
    drum, its normal pointing inward."""
    y0, y1 = -DRUM_LENGTH / 2, DRUM_LENGTH / 2
    corners = [(k + 0.5) * 2 * math.pi / PANELS for k in range(PANELS)]  # between panel k and panel k + 1
    parts = {"mantle": [], "cap": [], "lifter": []}
    for k in range(PANELS):
        a0, a1 = corners[k - 1], corners[k]
        p00, p01 = _point(a0, CORNER_RADIUS, y0), _point(a0, CORNER_RADIUS, y1)
        p10, p11 = _point(a1, CORNER_RADIUS, y0), _point(a1, CORNER_RADIUS, y1)
        parts["mantle"] += [(p00, p10, p11), (p00, p11, p01)]
    for y in (y0, y1):
        centre = np.array([0.0, y, 0.0])
        for k in range(PANELS):
            a, b = _point(corners[k - 1], CORNER_RADIUS, y), _point(corners[k], CORNER_RADIUS, y)
            parts["cap"].append((centre, b, a) if y < 0 else (centre, a, b))
    axial = np.array([0.0, 1.0, 0.0])
    for k in range(LIFTERS):
        angle = 2 * math.pi * k / LIFTERS
        radial, tangent = _point(angle, 1.0, 0.0), _point(angle + math.pi / 2, 1.0, 0.0)
        base1 = DRUM_RADIUS * radial - LIFTER_BASE / 2 * tangent
        base2 = DRUM_RADIUS * radial + LIFTER_BASE / 2 * tangent
        ridge = (DRUM_RADIUS - LIFTER_HEIGHT) * radial
        for p, q in ((base1, ridge), (ridge, base2)):
            parts["lifter"] += [(p + y0 * axial, q + y0 * axial, q + y1 * axial),
                                (p + y0 * axial, q + y1 * axial, p + y1 * axial)]
    return parts


def ridges():
    """A point (3,) [m] of each lifter's ridge at y = 0."""
    return [_point(2 * math.pi * k / LIFTERS, DRUM_RADIUS - LIFTER_HEIGHT, 0.0) for k in range(LIFTERS)]


def add_drum(material, partner=None):
    """Appends the drum's Facets (fixed) of YADE material `material` (an id or None); with `partner` (a
    HertzMaterial) makes them contact partners of the rounded bodies. Returns their ids."""
    ids = []
    for triangles in drum_triangles().values():
        for triangle in triangles:
            facet = utils.facet([Vector3(*p) for p in triangle], fixed=True,
                                **({} if material is None else {"material": material}))
            ids.append(O.bodies.append(facet))
    if partner is not None:
        for facet in ids:
            rm.assign_material(facet, partner)
    return ids


def rotation_engine(facets):
    return RotationEngine(ids=facets, rotationAxis=(0, 1, 0), angularVelocity=ANGULAR_VELOCITY,
                          rotateAroundZero=True, zeroPoint=(0, 0, 0), label="drum")


# --- the contents -------------------------------------------------------------------------------------------

def materials():
    """(bodies' HertzMaterial, the drum's HertzMaterial) of S7."""
    return (rm.HertzMaterial(friction=FRICTION, **BODY), rm.HertzMaterial(friction=FRICTION, **DRUM))


def horse_mesh():
    """YADE's GTS horse scaled to HORSE_LENGTH, prepared by Mesh.load (remeshed where too coarse for its curvature)."""
    with warnings.catch_warnings():  # the file as it is, only for its size
        warnings.simplefilter("ignore", RuntimeWarning)
        extent = np.ptp(np.asarray(rm.Mesh.load(HORSE_FILE, tolerance=None).vertices), axis=0).max()
    return rm.Mesh.load(HORSE_FILE, scale=HORSE_LENGTH / extent)


def meshes(names=tuple(COUNTS)):
    return {name: horse_mesh() if name == "horse" else rm.Mesh.reference_shape(name) for name in names}


def _product(a, b):
    """The quaternion product a b, both (w, x, y, z)."""
    return np.array([a[0] * b[0] - a[1:] @ b[1:], *(a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:]))])


def horse_poses(seed):
    """--contents horses: [(kind, position (3,) [m], quaternion (w, x, y, z))] of HORSES horses with their shortest
    principal axis (z) along the drum's axis (y), each also turned by a seeded half turn about one of its axes or not
    at all, on a lattice of their boxes 1 mm apart inside the drum (clear of the lifters and the end caps), a seeded
    choice of its nodes: no two boxes overlap, so the horses start apart, at rest."""
    rng = np.random.default_rng(seed)
    half = np.abs(np.asarray(meshes(["horse"])["horse"].vertices)).max(axis=0)[[0, 2, 1]]  # in the drum's frame
    spacing = 2 * half + 1e-3
    inside = DRUM_RADIUS - LIFTER_HEIGHT - 1e-3
    grid = [spacing[k] * (np.arange(-10, 11) + 0.5 * (k != 1)) for k in range(3)]
    nodes = np.array([(x, y, z) for x in grid[0] for y in grid[1] for z in grid[2]
                      if abs(y) + half[1] <= DRUM_LENGTH / 2 - 1e-3
                      and math.hypot(abs(x) + half[0], abs(z) + half[2]) <= inside])
    if len(nodes) < HORSES:
        raise RuntimeError(f"placement: the lattice has {len(nodes)} nodes for {HORSES} horses")
    chosen = nodes[rng.permutation(len(nodes))[:HORSES]]
    z_along_y = np.array([math.sqrt(0.5), -math.sqrt(0.5), 0, 0])  # a quarter turn about x: z -> y
    turns = np.eye(4)  # none, or a half turn about x, y or z (w, x, y, z)
    return [("horse", node, _product(z_along_y, turns[rng.integers(4)])) for node in chosen]


def kinds(seed):
    """The kind of each body, in the order of the poses: the 60 rounded bodies in a seeded order, then the
    spheres."""
    order = [name for name, count in COUNTS.items() for _ in range(count)]
    np.random.default_rng([seed, 1]).shuffle(order)
    return order + ["sphere"] * SPHERES


def proxy_spheres(name, mesh):
    """(centres (n, 3) [m], radii (n,) [m]) in the body frame of the spheres that stand for the body of `mesh`
    while the drum is filled: a bear's 40 clump spheres (roundedmesh_study.peers.clump_spheres), and for the pear
    spheres on the axis through its two primitive spheres, each reaching the mesh's nearest node. Both lie inside the
    body but for its blends (where its nodes stand up to 0.7 mm out of them)."""
    if name != "pear":
        return peers.clump_spheres(name, 40)
    vertices = np.array(mesh.vertices)
    centres, _ = peers.clump_spheres(name, 2)
    t = np.linspace(-0.4, 1.3, PEAR_PROXY_SPHERES)
    centres = centres[0] + t[:, None] * (centres[1] - centres[0])
    radii = np.linalg.norm(vertices[:, None, :] - centres[None], axis=2).min(axis=0)
    keep = radii > 2e-3
    return centres[keep], radii[keep]


def _yade_quaternion(q):
    w, x, y, z = q
    result = Quaternion(w, x, y, z)
    result.normalize()
    return result


def _wxyz(q):
    x, y, z, w = q  # minieigen iterates a quaternion as x, y, z, w
    return np.array([w, x, y, z])


def reach(kind):
    """How far the body of `kind` reaches from its centre [m]."""
    if kind == "sphere":
        return SPHERE_RADIUS
    return float(np.linalg.norm(np.array(meshes([kind])[kind].vertices), axis=1).max())


def lattice(seed):
    """S7's lattice (module docstring): [(kind, position (3,) [m], quaternion (w, x, y, z))], a seeded choice of
    nodes of a square lattice LATTICE_SPACING apart inside the drum (clear of the lifters), jittered by up to
    JITTER, where every body at START_SCALE of its size is clear of every other and of the drum."""
    rng = np.random.default_rng(seed)
    order = kinds(seed)
    clearance = START_SCALE * reach("gummy_bear") + JITTER + 1e-3
    axis = LATTICE_SPACING * np.arange(-10, 11)
    inside = DRUM_RADIUS - LIFTER_HEIGHT - clearance
    nodes = np.array([(x, y, z) for y in axis for x in axis for z in axis
                      if abs(y) <= DRUM_LENGTH / 2 - clearance and math.hypot(x, z) <= inside])
    poses = placement.lattice_poses(nodes, len(order), rng, JITTER)   # bears, pears and spheres mixed
    return [(kind, position, q) for kind, (position, q) in zip(order, poses)]


def _depths():
    """The overlaps of YADE's real interactions [m]."""
    return [i.geom.penetrationDepth for i in O.interactions if i.isReal]


def _grow(poses, log):
    """Step 2 of the placement: YADE's clumps and spheres, at START_SCALE of the bodies' size at `poses`, grow to it in
    the drum, without gravity or friction. Returns the poses the bodies reached."""
    O.reset()
    grains = O.materials.append(FrictMat(young=1e7, poisson=0.4, density=2000, frictionAngle=0, label="grains"))
    add_drum(grains)
    # Rods of fixed spheres blunt the lifters' ridges, which would slip between two spheres of a clump. YADE pairs
    # two bodies whose masks share a bit: the rods (mask 2) touch the clumps and spheres (3), not the Facets (1).
    for ridge in ridges():
        for y in np.arange(-DRUM_LENGTH / 2, DRUM_LENGTH / 2 + 1e-9, 2 * RIDGE_GUARD):
            O.bodies.append(utils.sphere(Vector3(*(ridge + (0, y, 0))), RIDGE_GUARD, fixed=True, material=grains,
                                         mask=2))
    proxies = {name: proxy_spheres(name, mesh) for name, mesh in meshes().items()}
    masses = {name: BODY["density"] * mesh.volume * START_SCALE ** 3  # grows with the clump (growParticles)
              for name, mesh in meshes().items()}
    tracked = []  # (YADE id, the body's pose relative to the YADE body's own)
    for kind, position, q in poses:
        ori = _yade_quaternion(q)
        if kind == "sphere":
            body = O.bodies.append(utils.sphere(Vector3(*position), START_SCALE * (SPHERE_RADIUS + PROXY_MARGIN),
                                                material=grains))
        else:
            centres, radii = proxies[kind]
            body, _ = peers.add_clump(START_SCALE * centres, START_SCALE * (radii + PROXY_MARGIN), Vector3(*position),
                                      ori, grains, masses[kind])
        state = O.bodies[body].state
        inverse = state.ori.conjugate()
        tracked.append((body, inverse * ori, inverse * (Vector3(*position) - state.pos) / START_SCALE))
        for member in ([body] if kind == "sphere" else O.bodies[body].shape.members.keys()):
            O.bodies[member].mask = 3
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                                 [Ip2_FrictMat_FrictMat_MindlinPhys(betan=0.5)], [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 NewtonIntegrator(damping=0.5, gravity=(0, 0, 0))]
    O.dt = 0.5 * utils.PWaveTimeStep()  # at the smallest size: the stiffest contacts of the growth
    factor = (1 / START_SCALE) ** (1 / GROWTH_STAGES)
    for stage in range(1, GROWTH_STAGES + 1):
        utils.growParticles(factor, updateMass=True, dynamicOnly=True)
        O.run(GROWTH_STEPS, True)
        if stage % 10 == 0:
            depths = _depths()
            log(f"  growing: {START_SCALE * factor ** stage:.3f} of the size, {len(depths)} contacts, deepest "
                f"{max(depths, default=0) * 1e3:.3f} mm")
    for _ in range(GROWN_RELAX_STEPS // 1000):  # the overlaps of the last stages relax
        O.run(1000, True)
        depths = _depths()
        if max(depths, default=0) < GROWN_DEPTH:
            break
    log(f"  grown: {len(depths)} contacts, deepest {max(depths, default=0) * 1e3:.3f} mm after {O.iter} steps")
    result = []
    for (kind, _, _), (body, turn, offset) in zip(poses, tracked):
        state = O.bodies[body].state
        result.append((kind, np.array(state.pos + state.ori * offset), _wxyz(state.ori * turn)))
    return result


def _add_bodies(poses, body_material, scale=1.0):
    """Appends the rounded bodies and sphere bodies at `poses`, their meshes and radii times `scale`; returns
    their ids."""
    shapes = meshes({kind for kind, _, _ in poses if kind != "sphere"})
    if scale != 1.0:
        shapes = {name: rm.Mesh.from_arrays(np.array(m.vertices) * scale, np.array(m.triangles))
                  for name, m in shapes.items()}
    ids = []
    for kind, position, q in poses:
        if kind == "sphere":
            ids.append(rm.add_sphere(tuple(position), SPHERE_RADIUS * scale, body_material, ori=_yade_quaternion(q)))
        else:
            ids.append(rm.add_body(shapes[kind], tuple(position), _yade_quaternion(q), body_material))
    return ids


def _relax(poses, log, allowed=0.0, max_steps=None):
    """Step 3 of the placement: the rounded bodies, enlarged by ENLARGE (at their own size if `allowed` [m] > 0), push
    each other apart in the drum without gravity or friction until no pair overlaps by more than RELAXED_DEPTH
    (`allowed`). Returns their poses."""
    O.reset()
    body, drum = (rm.HertzMaterial(**BODY), rm.HertzMaterial(**DRUM))
    add_drum(None, partner=drum)
    ids = _add_bodies(poses, body, 1 + ENLARGE if not allowed else 1.0)
    # The clumps' poses may leave a lifter's ridge inside a body's blend (not in its clump): such a pair starts deep and
    # is pushed apart here, so no overlap stops this stage (the check, step 4, ensures the run starts clean).
    O.engines = [ForceResetter(), rm.engine(stop_overlap=math.inf),
                 NewtonIntegrator(damping=RELAX_DAMPING, gravity=(0, 0, 0))]
    O.dt = TIME_STEP
    try:
        placement.push_apart(allowed or RELAXED_DEPTH, max_steps or RELAX_MAX_STEPS, log=log)
    except RuntimeError as error:
        size = f"enlarged by {ENLARGE:.1%}" if not allowed else "at their own size"
        raise RuntimeError(f"{error}, {size}: the drum does not hold them apart") from None
    return [(kind, np.array(O.bodies[i].state.pos), _wxyz(O.bodies[i].state.ori))
            for (kind, _, _), i in zip(poses, ids)]


def check_start(poses, allowed=0.0):
    """Step 4: the bodies at their own size at `poses`, in a step of the roundedmesh engine, touch nothing (with
    `allowed` [m] > 0: overlap by at most that). A body enlarged by ENLARGE about its centre holds itself with every
    surface point at least ENLARGE times its distance from the centre inside, which is MIN_CENTRE_DISTANCE or more
    (checked here). Returns the pairs touching."""
    for name, mesh in meshes().items():
        nearest = np.linalg.norm(np.array(mesh.vertices), axis=1).min()
        if nearest < MIN_CENTRE_DISTANCE:
            raise RuntimeError(f"placement: the {name}'s surface comes {nearest * 1e3:.1f} mm from its centre")
    O.reset()
    body, drum = materials()
    add_drum(None, partner=drum)
    _add_bodies(poses, body)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
    O.dt = TIME_STEP
    return placement.touching(allowed)


SHIPPED_PLACEMENTS = os.path.join(SCRIPTS, "examples", "drum_placements")


def placement_path(out, seed, start_overlap=0.0):
    suffix = f"_overlap{start_overlap * 1e3:g}mm" if start_overlap else ""
    return os.path.join(out, f"placement_seed{seed}{suffix}.csv")


def _placement_key(seed, start_overlap=0.0):
    return json.dumps({"version": PLACEMENT_VERSION, "seed": seed, "counts": COUNTS, "spheres": SPHERES,
                       "enlarge": ENLARGE, "margin": PROXY_MARGIN, "guard": RIDGE_GUARD, "start": START_SCALE,
                       "stages": [GROWTH_STAGES, GROWTH_STEPS], "start_overlap": start_overlap}, sort_keys=True)


def read_placement(path, seed, start_overlap=0.0):
    """The poses of a placement file written for this seed and these placement parameters, or None."""
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0] != ["# " + _placement_key(seed, start_overlap)]:
        return None
    return [(r[0], np.array(r[1:4], float), np.array(r[4:8], float)) for r in rows[2:]]


def write_placement(path, seed, poses, start_overlap=0.0):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["# " + _placement_key(seed, start_overlap)])
        writer.writerow(["kind", "x_m", "y_m", "z_m", "qw", "qx", "qy", "qz"])
        writer.writerows([kind, *map(repr, map(float, position)), *map(repr, map(float, q))]
                         for kind, position, q in poses)


def initial_poses(seed, out=None, log=print, start_overlap=0.0):
    """S7's start: [(kind, position (3,) [m], quaternion (w, x, y, z))] of every body, the rounded bodies first (in
    a seeded order of bears and pears), then the spheres, touching nothing (start_overlap [m] > 0: overlapping by at
    most that, which S7 does not allow): read from <out>/placement_seed<seed>.csv or
    scripts/examples/drum_placements/placement_seed<seed>.csv if either holds this placement and passes the check,
    else placed as the module docstring says (minutes) and written to the first."""
    for folder in ([out] if out else []) + [SHIPPED_PLACEMENTS]:
        path = placement_path(folder, seed, start_overlap)
        poses = read_placement(path, seed, start_overlap)
        if poses is not None:
            try:
                check_start(poses, start_overlap)
            except RuntimeError as error:
                log(f"placement: {path} fails the check ({error}); placing again")
                continue
            O.reset()
            log(f"placement: read from {path}, checked")
            return poses
    started = time.perf_counter()
    log(f"placement (seed {seed}): growing YADE clumps from the lattice")
    poses = _grow(lattice(seed), log)
    log("placement: relaxing the overlaps of the rounded bodies")
    poses = _relax(poses, log, start_overlap)
    touching = check_start(poses, start_overlap)
    O.reset()
    log(f"placement: done in {time.perf_counter() - started:.1f} s, {touching} pairs touch")
    if out:
        write_placement(placement_path(out, seed, start_overlap), seed, poses, start_overlap)
    return poses


# --- the scene ----------------------------------------------------------------------------------------------

def build_roundedmesh(poses):
    """Resets YADE and builds S7 with rounded bodies and sphere bodies at `poses`. Returns (body ids, facet ids)."""
    O.reset()
    body, drum = materials()
    facets = add_drum(None, partner=drum)
    bodies = _add_bodies(poses, body)
    O.engines = [ForceResetter(), rotation_engine(facets), rm.engine(),
                 NewtonIntegrator(damping=0, gravity=(0, 0, -GRAVITY))]
    O.dt = TIME_STEP
    return bodies, facets


def build_clumps(poses):
    """Resets YADE and builds S7 with YADE's own bodies at `poses` (module docstring). Returns (body ids: the clumps
    and the spheres, facet ids)."""
    O.reset()
    friction = math.atan(FRICTION)
    particle = O.materials.append(FrictMat(young=BODY["young"], poisson=BODY["poisson"], density=BODY["density"],
                                           frictionAngle=friction, label="particle"))
    drum = O.materials.append(FrictMat(young=DRUM["young"], poisson=DRUM["poisson"], density=DRUM["density"],
                                       frictionAngle=friction, label="drum"))
    facets = add_drum(drum)
    clumps = {"gummy_bear": peers.clump_spheres("gummy_bear", 40), "pear": peers.clump_spheres("pear", 2)}
    masses = {name: BODY["density"] * mesh.volume for name, mesh in meshes().items()}
    bodies = []
    for kind, position, q in poses:
        if kind == "sphere":
            bodies.append(O.bodies.append(utils.sphere(Vector3(*position), SPHERE_RADIUS, material=particle)))
        else:
            centres, radii = clumps[kind]
            bodies.append(peers.add_clump(centres, radii, Vector3(*position), _yade_quaternion(q), particle,
                                          masses[kind])[0])
    betan = peers.mindlin_betan()
    physics = Ip2_FrictMat_FrictMat_MindlinPhys(
        betan=MatchMaker(matches=((particle, particle, betan["bear-bear"]), (particle, drum, betan["bear-wall"]))))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [physics],
                                 [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 rotation_engine(facets), NewtonIntegrator(damping=0, gravity=(0, 0, -GRAVITY))]
    O.dt = TIME_STEP
    return bodies, facets


# --- measuring ----------------------------------------------------------------------------------------------

def kinematics(bodies):
    """(positions (n, 3) [m], speeds (n,) [m/s], kinetic energy [J]: translation and rotation) of the bodies."""
    positions, speeds, energy = [], [], 0.0
    for i in bodies:
        state = O.bodies[i].state
        spin = state.ori.conjugate() * state.angVel  # in the body's principal frame
        positions.append(tuple(state.pos))
        speeds.append(state.vel.norm())
        energy += 0.5 * state.mass * state.vel.squaredNorm() + 0.5 * sum(
            state.inertia[k] * spin[k] ** 2 for k in range(3))
    return np.array(positions).reshape(-1, 3), np.array(speeds), energy


def outside(positions):
    """Bodies whose centre is outside the drum: beyond its end caps or its mantle's corners."""
    radial = np.hypot(positions[:, 0], positions[:, 2])
    return int(((np.abs(positions[:, 1]) > DRUM_LENGTH / 2) | (radial > CORNER_RADIUS)).sum())


def contact_counts(run):
    """(touching pairs, contacts) of the last step."""
    if run == "roundedmesh":
        s = rm.statistics()
        return s["touching_pairs"], s["quadrature_contacts"] + s["direct_contacts"] + s["exact_contacts"] + s.get("sphere_contacts", 0)
    real = [i for i in O.interactions if i.isReal]
    owner = lambda body: O.bodies[body].clumpId if O.bodies[body].isClumpMember else body  # noqa: E731
    return len({tuple(sorted((owner(i.id1), owner(i.id2)))) for i in real}), len(real)


def overlaps_at_start(run):
    """Pairs touching in the first step (rounded bodies: the engine's; clumps: YADE's real interactions)."""
    return contact_counts(run)[0]


def drum_angle(facets):
    """The angle the drum has turned by [rad], from its first Facet's orientation."""
    axis, angle = O.bodies[facets[0]].state.ori.toAxisAngle()
    return angle * (1 if axis[1] >= 0 else -1)


# --- the run ------------------------------------------------------------------------------------------------

def plot(path, rows, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    data = np.array([[float(v) for v in r[:6]] for r in rows])
    figure, axes = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    for axis, column, label in zip(axes, (2, 3, 4), ("mean height of the centres [mm]", "kinetic energy [J]",
                                                      "max speed [m/s]")):
        axis.plot(data[:, 1], data[:, column] * (1e3 if column == 2 else 1), "k-")
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    axes[0].set_title(title)
    axes[-1].set_xlabel("time [s]")
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def openmp_threads():
    """The OpenMP threads of this process's parallel loops (the roundedmesh engine's and YADE's)."""
    return ctypes.CDLL("libgomp.so.1").omp_get_max_threads()


def run_with_threads(threads, argv):
    """Runs this script again in a new process with OMP_NUM_THREADS = `threads`, which OpenMP reads when it starts:
    setting it later (omp_set_num_threads) leaves YADE's per-thread force buffers, sized when it started, too small
    for the threads it then runs. Returns only if the variable is set so already."""
    if os.environ.get("OMP_NUM_THREADS") == str(threads):
        return
    sys.stdout.flush()
    environment = dict(os.environ, OMP_NUM_THREADS=str(threads))
    os.execve(sys.executable, [sys.executable, os.path.join(SCRIPTS, "examples", "example_drum.py")] + list(argv),
              environment)


def reason(error):
    """The roundedmesh engine's own message in a RuntimeError from O.run (YADE wraps it in the PyRunner's)."""
    text = str(error)
    if "ERROR:" in text:
        text = text.split("ERROR:", 1)[1].split("STACK TRACE:", 1)[0]
    return " ".join(text.split())


def run(args, poses=None, log=print):
    """Builds S7 for args.run at `poses` (default initial_poses(args.seed, args.out)), runs args.steps steps and
    writes the outputs (module docstring) to <out>/<run>. Returns a dict: folder, steps_done, completed, failure,
    ms_per_step (median over the rows), bodies, facets, rows."""
    threads = openmp_threads()
    started = time.perf_counter()
    if poses is None:
        poses = initial_poses(args.seed, args.out, log, args.start_overlap)
    folder = os.path.join(args.out, args.run)
    os.makedirs(folder, exist_ok=True)
    bodies, facets = (build_roundedmesh if args.run == "roundedmesh" else build_clumps)(poses)
    build_seconds = time.perf_counter() - started
    with open(os.path.join(folder, "initial_state.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["kind", "id", "x_m", "y_m", "z_m", "qw", "qx", "qy", "qz"])
        for (kind, _, _), i in zip(poses, bodies):
            state = O.bodies[i].state
            writer.writerow([kind, i, *state.pos, *_wxyz(state.ori)])
    limit = rm.critical_timestep() if args.run == "roundedmesh" else utils.PWaveTimeStep()
    log(f"S7 drum, {args.run}: {sum(k != 'sphere' for k, _, _ in poses)} bodies, "
        f"{sum(k == 'sphere' for k, _, _ in poses)} spheres, {len(facets)} Facets; seed {args.seed}; "
        f"dt = {O.dt:g} s ({O.dt / limit:.2f} of the stability limit {limit:.3g} s), {args.steps} steps; "
        f"OpenMP threads {threads}")

    series = None
    if args.vtk_every:
        series = VtkSeries(os.path.join(folder, "vtk"), "drum", spheres=True, partners=True)
        series.write()
    rows, failure, touching_at_start = [], None, None
    reporter = Progress(args.steps, f"S7 drum ({args.run})", interval=10.0)
    file = open(os.path.join(folder, "drum.csv"), "w", newline="")
    writer = csv.writer(file)
    writer.writerow(FIELDS)
    positions, speeds, energy = kinematics(bodies)  # the start, at rest
    rows.append([0, O.time, positions[:, 2].mean(), energy, speeds.max(), outside(positions), drum_angle(facets),
                 "", "", ""])
    writer.writerow(rows[-1])
    window_start, window_seconds = 0, 0.0
    while O.iter < args.steps and failure is None:
        targets = [args.steps, (O.iter // args.sample + 1) * args.sample]
        if series:
            targets.append((O.iter // args.vtk_every + 1) * args.vtk_every)
        if touching_at_start is None:
            targets.append(1)
        steps = min(targets) - O.iter
        begin = time.perf_counter()
        try:
            O.run(steps, True)
        except RuntimeError as error:  # the roundedmesh engine stopped the run; its message says why
            failure = reason(error)
        window_seconds += time.perf_counter() - begin
        if touching_at_start is None:
            touching_at_start = overlaps_at_start(args.run)
            log(f"touching pairs in the first step: {touching_at_start}")
        positions, speeds, energy = kinematics(bodies)
        if O.iter % args.sample == 0 or O.iter == args.steps or failure:
            done = O.iter - window_start
            row = [O.iter, O.time, positions[:, 2].mean(), energy, speeds.max(), outside(positions),
                   drum_angle(facets), *contact_counts(args.run), window_seconds / max(done, 1) * 1e3]
            rows.append(row)
            writer.writerow(row)
            file.flush()
            window_start, window_seconds = O.iter, 0.0
            reporter.update(O.iter)
            if row[5] and failure is None:
                failure = f"at t = {O.time:.4f} s, {row[5]} bodies have left the drum"
            if not (np.isfinite(positions).all() and np.isfinite(speeds).all()) and failure is None:
                failure = f"non-finite positions or speeds at t = {O.time:.4f} s"
        if series and (O.iter % args.vtk_every == 0 or O.iter == args.steps or failure):
            series.write()
    file.close()
    run_seconds = time.perf_counter() - started - build_seconds
    ms_per_step = stats.median(r[-1] for r in rows if r[0] > 1) if any(r[0] > 1 for r in rows) else math.nan
    if rows:
        plot(os.path.join(folder, "drum.png"), rows, f"S7 rotating drum, {args.run}, seed {args.seed}, "
                                                     f"dt = {O.dt:g} s")
    command = shlex.join([sys.executable] + sys.argv)
    with open(os.path.join(folder, "timing.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "steps", "steps_done", "completed", "failure", "build_wall_s", "run_wall_s",
                         "median_ms_per_step", "threads", "touching_at_start", "machine", "command"])
        writer.writerow([args.run, args.steps, O.iter, failure is None, failure or "", build_seconds, run_seconds,
                         ms_per_step, threads, touching_at_start, machine(), command])
    return {"folder": folder, "steps_done": O.iter, "completed": failure is None, "failure": failure,
            "ms_per_step": ms_per_step, "bodies": bodies, "facets": facets, "rows": rows,
            "touching_at_start": touching_at_start, "series": series}


def main(argv):
    args = parse(argv)
    if args.threads:
        run_with_threads(args.threads, argv)
    try:
        if args.place_only:
            initial_poses(args.seed, args.out, start_overlap=args.start_overlap)
            print(f"wrote {placement_path(args.out, args.seed, args.start_overlap)}")
            return
        result = run(args, horse_poses(args.seed) if args.contents == "horses" else None)
    except RuntimeError as error:  # the placement failed
        raise SystemExit(f"S7 drum: {reason(error)}")
    log = print
    last = result["rows"][-1] if result["rows"] else None
    if last:
        log(f"S7 drum, {args.run}: {result['steps_done']} of {args.steps} steps (t = {last[1]:.3f} s): mean height "
            f"{last[2]:.4f} m, kinetic energy {last[3]:.3g} J, max speed {last[4]:.3g} m/s, {last[5]} outside; "
            f"{result['ms_per_step']:.2f} ms per step (median, wall)")
    for other in RUNS:
        path = os.path.join(args.out, other, "timing.csv")
        if other != args.run and os.path.exists(path):
            with open(path, newline="") as f:
                previous = list(csv.DictReader(f))[0]
            log(f"  beside {other} (from {path}): {float(previous['median_ms_per_step']):.2f} ms per step over "
                f"{previous['steps_done']} steps")
    log("wrote drum.csv, drum.png, initial_state.csv, timing.csv" + (" and vtk/drum.pvd" if args.vtk_every else "")
        + f" to {result['folder']}")
    log(f"machine: {machine()}")
    if result["failure"]:
        raise SystemExit(f"S7 drum ({args.run}) stopped at step {result['steps_done']}: {result['failure']}")
