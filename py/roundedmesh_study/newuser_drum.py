"""The new user's drum of scene S8 (doc/scenes.md): a drum as a DEM user builds it with YADE's own tools, filled with
soft bodies dropped in from a lattice, and run with the defaults. It is the hard case issue 38 was filed on: thin
plates, soft bodies and a real mesh, where the contact must keep repelling however deep an impact drives a body.

    /usr/bin/python3 scripts/validation/newuser_drum.py [--contents mixed|bears] [--run roundedmesh|clumps]
        [--duration 0.63 (mixed) | 1.67 (bears)] [--seed 1] [--threads 1] [--checkpoint-every 0] [--output out/newuser_drum]

The drum: `geom.facetCylinder` of radius 0.27 m (0.54 m across) and length 0.4 m about the y axis, 24 panels, both
ends closed; four lifters, radial plates 6 cm high of two Facets each (`utils.facet`), standing on the mantle's panel
edges at 0, 90, 180 and 270 degrees (example_containers.py's lifter_plates); `RotationEngine` at 3 rad/s from t = 0 (the rim moves at 0.81 m/s); gravity
(0, 0, -9.81) m/s^2. Facets: E = 100 MPa, nu = 0.3, mu = 0.4.
The contents, E = 1 MPa, nu = 0.4, 1200 kg/m^3, A = 0.05 s, mu = 0.5 (roundedmesh.HertzMaterial): `mixed`, 20 of
YADE's GTS horses (examples/gts-horse/horse.coarse.gts, Debian's yade package, scaled to 5 cm and prepared by
Mesh.load) and 20 gummy bears (Mesh.reference_shape, r_eq 25 mm); or `bears`, 40 gummy bears. Placed on a lattice
0.1 m apart inside the drum (48 nodes, the first 40 taken), horses and bears alternating, in seeded random orientations, at rest.
Time step: the largest the user guide allows for impacts up to 3 m/s, O.dt = rm.critical_timestep(impact_speed=3)
(mixed 2.07e-6 s: a push on a horse's limb turns it, doc/physics.md "Time step"; bears 4.43e-5 s); default engine
options. Each runs for the simulated time its 20,000 steps covered before the limit counted the bodies' turn: mixed
0.63 s (304,000 steps now), bears 1.67 s (37,700).

--run clumps fills the same drum from the same poses with YADE's own bodies: each body a clump of 40 inscribed spheres
(sphere_fill.inscribed_spheres of its mesh), the shape's mass and the union's inertia scaled to it
(peers.add_clump), Hertz-Mindlin (Law2_ScGeom_MindlinPhys_Mindlin, betan 0.2, friction angle atan 0.5; the facets
E = 100 MPa), Facets met by Ig2_Facet_Sphere_ScGeom, O.dt = 0.3 utils.PWaveTimeStep() (YADE's usual choice), run for
the same simulated time.

Every 10 steps it samples the deepest pair for its size (roundedmesh: rm.statistics()["deepest_pair_fraction"], the
stop rule's measure; clumps: the deepest member contact, ScGeom.penetrationDepth, over the smaller body's r_eq, a
facet counting as no size) and the fastest body [m/s]. Writes <output>/<contents>_<run>.csv (step, time [s],
deepest [r_eq], fastest [m/s], wall ms per step over the sample) and, beside it, newuser_drum_<contents>.png of every run found there; prints whether
the run completed, its deepest pair, fastest body and ms per step (the sampling left out). With --checkpoint-every N (roundedmesh only), the
scene is saved every N steps to <output>/<contents>_<run>.yade.gz (rm.checkpoint), to resume a long run or study
a moment of it.
"""
import argparse
import csv
import importlib.util
import math
import os
import sys
import time
import warnings

import numpy as np

from . import SCRIPTS

RADIUS, LENGTH, SEGMENTS = 0.27, 0.4, 24   # [m], [m], panels
LIFTER_HEIGHT = 0.06                        # [m]
ANGULAR_VELOCITY = 3.0                      # [rad/s]
SPACING = 0.1                               # lattice [m]: a bear reaches 48.5 mm from its centre, a horse 28 mm
HORSE_FILE = "/usr/share/doc/yade/examples/gts-horse/horse.coarse.gts"
HORSE_LENGTH = 0.05                         # [m]
BODY = dict(young=1e6, poisson=0.4, density=1200.0)
WALL = dict(young=1e8, poisson=0.3, density=7800.0)
FRICTION, WALL_FRICTION = 0.5, 0.4
IMPACT_SPEED = 3.0                          # [m/s] the time step resolves impacts up to this speed
SAMPLE = 10                                 # steps between samples
CONTENTS = {"mixed": ("horse", "bear") * 20, "bears": ("bear",) * 40}
DURATION = {"mixed": 0.63, "bears": 1.67}   # [s] simulated


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--contents", choices=sorted(CONTENTS), default="mixed")
    parser.add_argument("--run", choices=["roundedmesh", "clumps"], default="roundedmesh")
    parser.add_argument("--duration", type=float, default=None,
                        help="simulated time [s] (default: mixed 0.63, bears 1.67)")
    parser.add_argument("--seed", type=int, default=1, help="of the orientations")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--checkpoint-every", type=int, default=0, help="steps between checkpoints (0: none)")
    parser.add_argument("--output", default=os.path.join("out", "newuser_drum"))
    args = parser.parse_args(argv)
    if args.duration is None:
        args.duration = DURATION[args.contents]
    if not args.duration > 0 or args.threads < 1 or args.checkpoint_every < 0:
        parser.error("--duration and --threads must be positive, --checkpoint-every not negative")
    return args


def horse_mesh():
    """YADE's GTS horse scaled to HORSE_LENGTH, prepared by Mesh.load."""
    import roundedmesh as rm
    with warnings.catch_warnings():  # the file as it is, only for its size
        warnings.simplefilter("ignore", RuntimeWarning)
        extent = np.ptp(np.asarray(rm.Mesh.load(HORSE_FILE, tolerance=None).vertices), axis=0).max()
    return rm.Mesh.load(HORSE_FILE, scale=HORSE_LENGTH / extent)


def lattice():
    """The lattice's nodes [m], bottom layer first: x and z at +-0.05 and +-0.15 m (the nodes nearest a lifter 78 mm
    from it, the farthest 0.21 m from the axis: a bear's reach, 48.5 mm, keeps clear of the plates and the mantle),
    y at 0 and +-0.1 m."""
    across = (-0.15, -0.05, 0.05, 0.15)
    return [(x, y, z) for z in across for y in (-SPACING, 0.0, SPACING) for x in across]


def poses(contents, seed):
    """[(kind, position (3,) [m], quaternion (w, x, y, z))] of the contents."""
    nodes = lattice()
    kinds = CONTENTS[contents]
    if len(nodes) < len(kinds):
        raise RuntimeError(f"the lattice has {len(nodes)} nodes for {len(kinds)} bodies")
    rng = np.random.default_rng(seed)
    quaternions = rng.normal(size=(len(kinds), 4))
    quaternions /= np.linalg.norm(quaternions, axis=1)[:, None]
    return list(zip(kinds, nodes, quaternions))


def example_containers():
    """scripts/examples/example_containers.py as a module: its lifter plates are the ones users are shown."""
    spec = importlib.util.spec_from_file_location("example_containers",
                                                  os.path.join(SCRIPTS, "examples", "example_containers.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def add_drum():
    """The drum's Facets (fixed) and the RotationEngine turning them."""
    from yade import O, RotationEngine, geom, utils
    from yade.minieigenHP import Quaternion, Vector3
    axis_to_y = Quaternion(Vector3(1, 0, 0), math.pi / 2)
    ids = list(O.bodies.append(geom.facetCylinder((0, 0, 0), RADIUS, LENGTH, orientation=axis_to_y,
                                                   segmentsNumber=SEGMENTS, wallMask=7, fixed=True)))
    ids += list(O.bodies.append(example_containers().lifter_plates(utils, Vector3, RADIUS, LENGTH, LIFTER_HEIGHT)))
    rotation = RotationEngine(ids=ids, rotationAxis=(0, 1, 0), rotateAroundZero=True, zeroPoint=(0, 0, 0),
                              angularVelocity=ANGULAR_VELOCITY)
    return ids, rotation


def build_roundedmesh(placed, meshes):
    """Resets O; the drum and the rounded bodies. Returns ({body id: r_eq}, sampler of the deepest pair)."""
    import roundedmesh as rm
    from yade import ForceResetter, NewtonIntegrator, O
    from yade.minieigenHP import Quaternion
    O.reset()
    facets, rotation = add_drum()
    wall = rm.HertzMaterial(damping=0.05, friction=WALL_FRICTION, tangential_damping=0.1, **WALL)
    for facet in facets:
        rm.assign_material(facet, wall)
    body = rm.HertzMaterial(damping=0.05, friction=FRICTION, tangential_damping=0.1, **BODY)
    sizes = {}
    for kind, node, q in placed:
        mesh = meshes[kind]
        sizes[rm.add_body(mesh, pos=node, ori=Quaternion(*q), material=body)] = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    O.engines = [ForceResetter(), rotation, rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = rm.critical_timestep(impact_speed=IMPACT_SPEED)
    return sizes, lambda: rm.statistics()["deepest_pair_fraction"]


def build_clumps(placed, meshes):
    """Resets O; the drum and a 40-sphere clump per body. Returns ({clump id: r_eq}, sampler of the deepest pair)."""
    from yade import (Bo1_Facet_Aabb, Bo1_Sphere_Aabb, ForceResetter, FrictMat, Ig2_Facet_Sphere_ScGeom,
                      Ig2_Sphere_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                      Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator, O, utils)
    from yade.minieigenHP import Quaternion
    from .peers import add_clump
    from .sphere_fill import inscribed_spheres
    O.reset()
    particle = O.materials.append(FrictMat(frictionAngle=math.atan(FRICTION), **BODY))
    wall = O.materials.append(FrictMat(frictionAngle=math.atan(WALL_FRICTION), **WALL))
    facets, rotation = add_drum()
    for facet in facets:
        O.bodies[facet].material = O.materials[wall]
    spheres = {kind: inscribed_spheres(np.asarray(mesh.vertices), np.asarray(mesh.triangles), 40)
               for kind, mesh in meshes.items()}
    sizes, owner = {}, {}
    for kind, node, q in placed:
        mesh = meshes[kind]
        centres, radii = spheres[kind]
        clump, members = add_clump(centres, radii, node, Quaternion(*q), particle, BODY["density"] * mesh.volume)
        sizes[clump] = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
        owner.update({m: clump for m in members})
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                                 [Ip2_FrictMat_FrictMat_MindlinPhys(betan=0.2)], [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 rotation, NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = 0.3 * utils.PWaveTimeStep()

    def deepest():
        worst = 0.0
        for i in O.interactions:
            if not i.isReal:
                continue
            size = min(sizes.get(owner.get(i.id1), math.inf), sizes.get(owner.get(i.id2), math.inf))
            worst = max(worst, i.geom.penetrationDepth / size)
        return worst
    return sizes, deepest


def run(args):
    from yade import O, PyRunner
    from roundedmesh.progress import Progress
    from .benchmarking import machine
    kinds = set(CONTENTS[args.contents])
    import roundedmesh as rm
    meshes = {kind: horse_mesh() if kind == "horse" else rm.Mesh.reference_shape("gummy_bear") for kind in kinds}
    placed = poses(args.contents, args.seed)
    build = build_roundedmesh if args.run == "roundedmesh" else build_clumps
    sizes, deepest = build(placed, meshes)
    steps = math.ceil(args.duration / O.dt - 1e-9)
    os.makedirs(args.output, exist_ok=True)
    print(f"machine: {machine()}\nnew user's drum, {args.contents}, {args.run}: {len(sizes)} bodies, "
          f"O.dt = {O.dt:.3g} s, {steps} steps", flush=True)
    rows, failure = [], ""
    progress = Progress(steps, f"{args.contents} {args.run}")
    sample = {"at": time.perf_counter(), "spent": 0.0}

    def record():
        """Samples the run at the end of every SAMPLE-th step (a PyRunner inside one O.run: O.run(n, True) in a loop
        would add up to 40 ms per call while YADE notices the end of each run). The time per step leaves out the
        sampling (the clumps' deepest contact is a Python loop over every interaction)."""
        now, done = time.perf_counter(), O.iter + 1
        fastest = max(O.bodies[b].state.vel.norm() for b in sizes)
        rows.append((done, O.time + O.dt, deepest(), fastest, 1e3 * (now - sample["at"]) / SAMPLE))
        progress.update(done)
        sample["at"] = time.perf_counter()
        sample["spent"] += sample["at"] - now
    sys.modules["__main__"].newuser_drum_record = record  # PyRunner commands run in __main__
    O.engines = O.engines + [PyRunner(command="newuser_drum_record()", iterPeriod=SAMPLE,
                                       firstIterRun=SAMPLE - 1)]
    if args.checkpoint_every and args.run == "roundedmesh":
        path = os.path.join(args.output, f"{args.contents}_{args.run}.yade.gz")
        O.engines = [rm.checkpoint.Checkpointer(path, every_steps=args.checkpoint_every).engine()] + O.engines
    start = time.perf_counter()
    try:
        O.run(steps - O.iter, True)
    except RuntimeError as error:
        # YADE puts "PyRunner error." first and the engine's reason after it: keep them all.
        failure = " ".join(str(error).split())[:600]
    seconds = time.perf_counter() - start - sample["spent"]
    path = os.path.join(args.output, f"{args.contents}_{args.run}.csv")
    with open(path, "w", newline="") as f:
        f.write(f"# {machine()}\n# {' '.join([sys.executable] + sys.argv)}\n")
        if failure:
            f.write(f"# stopped: {failure}\n")
        writer = csv.writer(f)
        writer.writerow(["step", "time_s", "deepest_r_eq", "fastest_m_s", "ms_per_step"])
        writer.writerows(rows)
    deepest_all = max((r[2] for r in rows), default=0.0)
    fastest_all = max((r[3] for r in rows), default=0.0)
    print(f"{args.contents} {args.run}: {'stopped: ' + failure if failure else 'completed'} after {O.iter} steps "
          f"({O.time:.3g} s) in {seconds:.0f} s, {1e3 * seconds / max(O.iter, 1):.2f} ms per step; deepest pair "
          f"{deepest_all:.3f} r_eq, fastest body {fastest_all:.3g} m/s; wrote {path}", flush=True)
    plot(args.output, args.contents)
    return {"completed": not failure, "steps": O.iter, "deepest": deepest_all, "fastest": fastest_all,
            "ms_per_step": 1e3 * seconds / max(O.iter, 1), "failure": failure}


def plot(output, contents):
    """newuser_drum_<contents>.png: the deepest pair and the fastest body over time, of each run written there."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for name in ("roundedmesh", "clumps"):
        path = os.path.join(output, f"{contents}_{name}.csv")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            data = np.array([[float(x) for x in row] for row in csv.reader(l for l in f if not l.startswith("#"))
                             if row[0] != "step"])
        if len(data):
            top.plot(data[:, 1], data[:, 2], label=name, lw=0.8)
            bottom.plot(data[:, 1], data[:, 3], label=name, lw=0.8)
    top.set_ylabel("deepest pair [r_eq]")
    bottom.set_ylabel("fastest body [m/s]")
    bottom.set_xlabel("time [s]")
    top.legend()
    top.set_title(f"The new user's drum ({contents}), sampled every {SAMPLE} steps")
    figure.tight_layout()
    figure.savefig(os.path.join(output, f"newuser_drum_{contents}.png"), dpi=120)
    plt.close(figure)


def main(argv):
    args = parse(argv)
    # Before YADE is imported: OpenMP reads it when it starts, for YADE's own loops (the clumps) as for roundedmesh.
    os.environ["OMP_NUM_THREADS"] = str(args.threads)
    result = run(args)
    return 0 if result["completed"] else 1
