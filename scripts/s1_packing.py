"""Scene S1 of doc/scenes.md, the shaken gravitational packing of Smeets et al., CMAME 277 (2014) 219-238,
doi:10.1016/j.cma.2014.04.017, Section 3.4 (Figs. 10-11), run whole: `--count` bodies of equal volume fall from
S1's lattice into a 0.40 m x 0.40 m box of five YADE Walls, the box moves vertically as
z_box(t) = A sin(2 pi t / T) (A = 0.025 m, T = 0.25 s) for three periods (0.75 s), then stands still; 1.35 s in
all, 13,500 steps of 1e-4 s.

    /usr/bin/python3 scripts/s1_packing.py [--shape gummy_bear|...|all|grains] [--peers clumps level_sets]
        [--peers-only] [--count 250] [--seed 1] [--dt 1e-4] [--duration 1.35] [--sample 100] [--frames 14]
        [--threads 1] [--timing off|stages] [--energy] [--checkpoint-every 1000] [--resume] [--plot-only]
        [--output out/s1]

Runs, each in its own process and folder <output>/<run>:
    sphere        perfect spheres (rm.add_sphere): roundedmesh's analytic sphere, Hertz with Eq. 7 damping, the
                  law a meshed sphere converges to, computed by the same engine (doc/physics.md)
    icosphere12, icosphere42, icosphere162
                  Mesh.icosphere of radius r with 0, 1, 2 subdivisions and exact curvature: every triangle's cap
                  lies on the sphere of radius r, so the rounded body is that sphere and has its volume, mass and
                  inertia (set so; the mesh's own volume is 61, 88 and 97 % of it)
    pear, gummy_bear
                  Mesh.reference_shape (~486 and ~554 nodes asked)
    spheroid, pill, tetra_grain
                  the study grains of doc/speed-vs-error.md (roundedmesh_study.grains: a prolate spheroid, a
                  capsule, a rounded tetrahedron), meshed with ~600 nodes and computed curvature, as their packings
                  in bench/data are; not in the paper, so --shape all leaves them out and --shape grains runs them
    gummy_bear_clumps, gummy_bear_level_sets (--peers clumps level_sets)
                  YADE's own representations of the gummy bear on the same scene (roundedmesh_study.peers): 40-sphere
                  clumps of the shape's primitives and level-set bodies of its distance field (1 mm grid, 511
                  surface nodes), with YADE's Hertz-Mindlin law, its damping ratio matched to Eq. 7 at the
                  overlap under one bear's weight (the mapping: roundedmesh_study.peers and doc/s1-packing.md)
Every body has the volume of the sphere of radius 0.025 m. Materials (S1): particles E = 1e6 Pa, nu = 0.4,
2000 kg/m^3; box E = 5e6 Pa, nu = 0.4; normal damping constant A = 0.01 s (Eq. 7) on both; no friction.
NewtonIntegrator without numerical damping, gravity (0, 0, -9.81) m/s^2. The lattice: layers of 4 x 4 nodes at
x, y in {-0.15, -0.05, 0.05, 0.15} m, 0.10 m apart from z = 0.06 m, each node jittered uniformly by +-3 mm and
each body turned by a uniformly random rotation (seeded); every representation starts from the same poses.

The box is moved by YADE's HarmonicMotionEngine on all five walls, which sets each wall's velocity at the start
of every step to v = -A' w sin(w t + phi) (w = 2 pi / T). With A' = A and phi = -pi/2 it would use the velocity
at the start of the step for the whole step, and the box would drift from A sin(w t) by up to A w dt (0.063 mm
at dt = 1e-4 s). With x = w dt / 2, phi = -pi/2 + x and A' = A sin(x) / x its velocity in the step from t to
t + dt is exactly (z_box(t + dt) - z_box(t)) / dt (a sum of cosines), so the box stands at A sin(w t) at every
step to rounding. After 0.75 s the engine is stopped and the walls' velocities set to zero (a stopped
HarmonicMotionEngine leaves the last velocity in place, and the box would keep moving).

Heights are those of the bodies' centres of mass above z = 0, the floor's rest position [m] (for a clump, the
centre of its spheres' union, within 0.3 mm of the bear's). Outputs of a run, in <output>/<run>:
    height.csv    one row per window of --sample steps (also ending at the end of shaking and of the run), at
                  the window's end: step, time [s], phase, box position [m], mean and max height [m], mean
                  speed [m/s], bodies in the scene and bodies whose centre left the box, the contact counts of
                  the last step (roundedmesh: rm.statistics()'s body_pairs, touching_pairs, candidates, contacts =
                  triangle or sphere contacts; YADE peers: touching body pairs and real interactions, the rest
                  empty), roundedmesh's stage times (pairs_ms, read_ms, write_ms [ms]), deepest_pair_r (the largest
                  overlap of a pair for its size: roundedmesh's over every step of the window, as the stop rule
                  measures it, over the smaller r_eq; the peers' deepest sphere or level-set penetration over r at
                  the window's end), the window's steps, wall time and CPU time per step [ms] (CPU of all the
                  process's threads), and roundedmesh's means over the window: window_pairs_ms (the pairs stage's
                  wall time) and with --timing stages the CPU ms of the stages inside it (window_lists_cpu_ms,
                  window_near_search_cpu_ms, window_narrow_phase_cpu_ms, window_law_cpu_ms, window_core_cpu_ms,
                  summed over threads) and the near pairs scanned, candidates and body pairs per step
    packing.csv   at the end, Eq. 28: P(h) = N_h V_p / (A_b h) * 100 [%] for h = 0.01 ... 0.30 m, N_h the bodies
                  whose centre is less than h above the floor, V_p a body's volume [m^3], A_b = 0.16 m^2
    final_state.csv  every body's id, position [m] and orientation (w, x, y, z) at the end
    timing.csv    threads, wall time of building and of running [s], CPU time [s], the largest deepest_pair_r of the
                  run, median wall and CPU ms per step and median contact counts over the windows of shaking and
                  of settling, machine, command
    height.png    mean and max height and the box's position vs time for this run
    timeline.png  with --timing stages: each window's wall ms per step split into roundedmesh's stages
    energy.csv    with --energy (roundedmesh's runs; YADE's peers are not tracked): the energy balance at each
                  window's end (EnergyBalance below), every term cumulated from the start [J]: kinetic (YADE's
                  NewtonIntegrator), gravity_work (YADE's 'gravWork', minus gravity's work: the change of the
                  bodies' potential energy), elastic (the engine's rmElastPotential: the contacts' elastic energy now),
                  normal_damping and friction (rmNormDamp, rmFrictDissip: dissipated so far), box_work (the work the
                  moving box did on the bodies), balance = kinetic + gravity_work + elastic + normal_damping +
                  friction - box_work, which stays at 0 where every force has a potential and every loss is counted,
                  and balance / (normal_damping + friction)
    energy.png    with --energy: those terms and the balance against time
    vtk/          ParaView series <run>.pvd of --frames frames (roundedmesh.export.VtkSeries; YADE's spheres as
                  part 1 for the sphere and clump runs; none for level sets, which YADE 2023.02a's VTKRecorder
                  cannot write), evenly spaced, the last at the end of the run
    checkpoint.yade.gz  the scene every --checkpoint-every steps (roundedmesh.checkpoint), for --resume
And in <output>, from every run folder found there: fig11a_mean_height.png/.csv (the paper's Fig. 11a),
fig11b_packing.png/.csv (Fig. 11b), fig10_packings.png (Fig. 10: a picture of each final packing) and
summary.csv (one row per run). --plot-only remakes them without running.

A window's time excludes sampling, checkpoints and frames. The recorder runs in a PyRunner at the start of every
step (about 0.015 ms per step), inside one O.run, so that no window includes the up to 40 ms by which
O.run(n, True) notices the end of a run. --resume continues each run from its checkpoint (a run whose timing.csv
exists is complete and skipped); height.csv keeps the rows up to the checkpoint, the run's timing the resumed
part. --threads sets OMP_NUM_THREADS in each run's process: for roundedmesh's engine and for YADE's own OpenMP
loops alike.

Bad input stops the script before any run starts: an unknown shape or peer, a time step above the stability
limit of any run asked for (rm.critical_timestep(); YADE's utils.PWaveTimeStep() for the peers) or one that
does not divide the shaking into whole steps, an output folder that cannot be written, and with --resume a
checkpoint that is damaged or from another scene (another shape, count, seed, time step or duration).
"""
import argparse
import csv
import json
import math
import os
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

PAPER_SHAPES = ("sphere", "icosphere12", "icosphere42", "icosphere162", "pear", "gummy_bear")  # --shape all
# --shape grains: roundedmesh_study.grains.NAMES, named here so that this process, which only starts the runs, does not
# load YADE (grains imports roundedmesh).
GRAIN_SHAPES = ("spheroid", "pill", "tetra_grain")
SHAPES = PAPER_SHAPES + GRAIN_SHAPES
PEERS = ("clumps", "level_sets")
PEER_SHAPE = "gummy_bear"
SHAKING = 0.75  # three periods of T = 0.25 s [s]
RADIUS = 0.025                        # volume-equivalent radius r [m]
VOLUME = 4 / 3 * math.pi * RADIUS ** 3  # every body's volume V_p [m^3]
HALF_BASE = 0.20                      # the box's inner base is 0.40 m x 0.40 m, centred on the z axis [m]
LATTICE = (-0.15, -0.05, 0.05, 0.15)  # x and y of a layer's 4 x 4 nodes [m]
LAYER_SPACING, LOWEST_LAYER, JITTER = 0.10, 0.06, 0.003  # [m]
AMPLITUDE, PERIOD = 0.025, 0.25       # the box's shaking [m], [s]
GRAVITY = 9.81                        # [m/s^2]
PACKING_HEIGHTS = np.round(np.arange(1, 31) * 0.01, 2)  # h of Eq. 28 [m]
SUBMERGED_HEIGHT = 0.10               # h at which the summary quotes P(h): below every packing's top [m]
# With --timing stages, roundedmesh's stages inside the pairs (rm.engine(timing='stages'), CPU ms summed over threads)
# and what they work through, as means over each window of height.csv (with the pairs stage's wall time).
TIMED_STAGES = ("lists_cpu_ms", "near_search_cpu_ms", "narrow_phase_cpu_ms", "law_cpu_ms", "core_cpu_ms",
                "near_pairs_scanned", "candidates", "body_pairs")
FIELDS = ["step", "time_s", "phase", "box_z_m", "mean_height_m", "max_height_m", "mean_speed_m_s", "bodies",
          "outside", "body_pairs", "touching_pairs", "candidates", "contacts", "candidate_rebuilds",
          "near_rebuilds", "pairs_ms", "read_ms", "write_ms", "deepest_pair_r", "window_steps", "ms_per_step",
          "cpu_ms_per_step", *(f"window_{stage}" for stage in ("pairs_ms", *TIMED_STAGES))]
ENERGY_FIELDS = ["step", "time_s", "kinetic_J", "gravity_work_J", "elastic_J", "normal_damping_J", "friction_J",
                 "box_work_J", "balance_J", "balance_over_dissipated"]
CHECKPOINT = "checkpoint.yade.gz"
SCENE_TAG = "s1_packing.scene"  # O.tags key of the scene's parameters, to refuse a checkpoint of another scene
BOX_WORK_TAG = "s1_packing.box_work"  # O.tags key of the work the box has done so far [J], kept in a checkpoint


def run_names(shape, peers, peers_only):
    groups = {"all": list(PAPER_SHAPES), "grains": list(GRAIN_SHAPES)}
    shapes = [] if peers_only else groups.get(shape, [shape])
    return shapes + [f"{PEER_SHAPE}_{peer}" for peer in peers]


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shape", default="gummy_bear",
                        help=f"one of {', '.join(SHAPES)}, all (the paper's) or grains (default gummy_bear)")
    parser.add_argument("--peers", nargs="*", default=[], metavar="PEER",
                        help=f"YADE's own representations of the gummy bear to run too: {', '.join(PEERS)}")
    parser.add_argument("--peers-only", action="store_true", help="run the peers only, not --shape")
    parser.add_argument("--count", type=int, default=250, help="bodies (default 250)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the jitter and the orientations (default 1)")
    parser.add_argument("--dt", type=float, default=1e-4, help="time step [s] (default 1e-4)")
    parser.add_argument("--duration", type=float, default=1.35, help="simulated time [s] (default 1.35)")
    parser.add_argument("--sample", type=int, default=100, help="steps per window of height.csv (default 100)")
    parser.add_argument("--frames", type=int, default=14, help="ParaView frames over a run (default 14)")
    parser.add_argument("--threads", type=int, default=1, help="OpenMP threads (default 1)")
    parser.add_argument("--normal", default="pressure", choices=("pressure", "energy"),
                        help="roundedmesh's normal law, rm.engine(normal=...) (default the paper's pressure)")
    parser.add_argument("--timing", default="off", choices=("off", "stages"),
                        help="roundedmesh's rm.engine(timing=...): 'stages' also records the CPU time of the stages "
                             "inside the pairs per window in height.csv and draws timeline.png (default off)")
    parser.add_argument("--energy", action="store_true",
                        help="track the energy balance of roundedmesh's runs: energy.csv and energy.png (the module's "
                             "documentation)")
    parser.add_argument("--checkpoint-every", type=int, default=1000,
                        help="steps between checkpoints, a multiple of --sample (default 1000)")
    parser.add_argument("--resume", action="store_true", help="continue each run from its checkpoint")
    parser.add_argument("--plot-only", action="store_true", help="only remake the figures of --output")
    parser.add_argument("--output", default=os.path.join("out", "s1"), help="output folder (default out/s1)")
    parser.add_argument("--run", help=argparse.SUPPRESS)    # one run, in this process (how the script calls itself)
    parser.add_argument("--check", action="store_true", help=argparse.SUPPRESS)  # with --run: checks only
    args = parser.parse_args(argv)
    if args.shape not in ("all", "grains") and args.shape not in SHAPES:
        parser.error(f"--shape {args.shape}: unknown shape; use one of {', '.join(SHAPES)}, all or grains")
    for peer in args.peers:
        if peer not in PEERS:
            parser.error(f"--peers {peer}: unknown peer; use {' and/or '.join(PEERS)}")
    if args.peers_only and not args.peers:
        parser.error("--peers-only needs --peers")
    for name in ("count", "sample", "frames", "threads", "checkpoint_every"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')} must be at least 1")
    if args.checkpoint_every % args.sample:
        parser.error(f"--checkpoint-every {args.checkpoint_every}: must be a multiple of --sample {args.sample}, so "
                     "that a resumed run's windows are those of an uninterrupted one")
    if not (args.dt > 0 and math.isfinite(args.dt)):
        parser.error("--dt must be a positive number of seconds")
    if not (args.duration >= args.dt and math.isfinite(args.duration)):
        parser.error("--duration must be at least one time step")
    args.steps = round(args.duration / args.dt)
    shaking_steps = SHAKING / args.dt
    if args.duration > SHAKING and abs(shaking_steps - round(shaking_steps)) > 1e-6 * shaking_steps:
        parser.error(f"--dt {args.dt:g} s: the shaking ({SHAKING} s) must last a whole number of steps, so that "
                     "the box stops where it started")
    args.shaking_steps = min(round(shaking_steps), args.steps)
    if args.frames > args.steps:
        parser.error(f"--frames {args.frames}: more frames than the run's {args.steps} steps")
    args.runs = [args.run] if args.run else run_names(args.shape, args.peers, args.peers_only)
    for folder in [args.output] + ([] if args.plot_only else [os.path.join(args.output, r) for r in args.runs]):
        try:
            os.makedirs(folder, exist_ok=True)
            with tempfile.TemporaryFile(dir=folder):
                pass
        except OSError as error:
            parser.error(f"--output {args.output}: cannot write to {folder} ({error.strerror or error})")
    return args


def scene_parameters(args, run):
    """What makes two runs the same scene: a checkpoint of other parameters is refused."""
    parameters = {"run": run, "count": args.count, "seed": args.seed, "dt": args.dt, "duration": args.duration,
                  "normal": args.normal}
    if args.energy and run in SHAPES:  # the box's work so far is in the checkpoint only if it was tracked
        parameters["energy"] = True
    return parameters


def child_command(args, run, check):
    command = [sys.executable, os.path.abspath(__file__), "--run", run, "--count", str(args.count),
               "--seed", str(args.seed), "--dt", repr(args.dt), "--duration", repr(args.duration),
               "--sample", str(args.sample), "--frames", str(args.frames), "--threads", str(args.threads),
               "--checkpoint-every", str(args.checkpoint_every), "--normal", args.normal, "--timing", args.timing,
               "--output", args.output]
    command += ["--energy"] if args.energy else []
    return command + (["--resume"] if args.resume else []) + (["--check"] if check else [])


def main_process(args):
    """Checks every run asked for, then runs them one after the other, each in a process with its own
    OMP_NUM_THREADS, then makes the figures of every run in --output."""
    if not args.plot_only:
        environment = dict(os.environ, OMP_NUM_THREADS=str(args.threads),
                           S1_PACKING_COMMAND=shlex.join([sys.executable] + sys.argv))
        # All checks first, so that bad input stops the script before any run starts (a single run checks
        # itself before its first step).
        for run in args.runs if len(args.runs) > 1 else []:
            check = subprocess.run(child_command(args, run, check=True), env=environment, capture_output=True, text=True)
            if check.returncode:
                lines = (check.stderr.strip() or check.stdout.strip()).splitlines()
                raise SystemExit(f"s1_packing.py: {run}: {lines[-1] if lines else 'check failed'}")
        for run in args.runs:
            if subprocess.run(child_command(args, run, check=False), env=environment).returncode:
                raise SystemExit(f"s1_packing.py: the run {run} failed (its output so far is in "
                                 f"{os.path.join(args.output, run)})")
    from roundedmesh_study import s1_figures  # matplotlib and YADE only now, after the runs
    s1_figures.make_all(args.output, RADIUS, SUBMERGED_HEIGHT)


if __name__ == "__main__":
    ARGS = parse(sys.argv[1:])
    if not ARGS.run:
        main_process(ARGS)
        raise SystemExit(0)

# --- one run, in this process -------------------------------------------------------------------------------

import ctypes  # noqa: E402
import xml.etree.ElementTree as ElementTree  # noqa: E402

from yade import ForceResetter, HarmonicMotionEngine, NewtonIntegrator, O, PyRunner, Wall, utils  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import VtkSeries  # noqa: E402
from roundedmesh.progress import Progress  # noqa: E402
from roundedmesh_study import grains, peers  # noqa: E402
from roundedmesh_study.benchmarking import machine  # noqa: E402
from roundedmesh_study.standing_still import ENERGY_KEYS  # noqa: E402

PARTICLE = rm.HertzMaterial(young=peers.PARTICLE["young"], poisson=peers.PARTICLE["poisson"],
                            density=peers.PARTICLE["density"], damping=peers.DAMPING_CONSTANT)
BOX = rm.HertzMaterial(young=peers.BOX["young"], poisson=peers.BOX["poisson"], density=peers.BOX["density"],
                       damping=peers.DAMPING_CONSTANT)  # density unused: the walls are kinematic


def lattice_poses(count, seed):
    """S1's start: [(position [m], (w, x, y, z), velocity, angular velocity)], bottom layer first, x fastest."""
    rng = np.random.default_rng(seed)
    poses = []
    for i in range(count):
        layer, node = divmod(i, 16)
        row, column = divmod(node, 4)
        position = np.array([LATTICE[column], LATTICE[row], LOWEST_LAYER + LAYER_SPACING * layer])
        position += rng.uniform(-JITTER, JITTER, 3)
        quaternion = rng.normal(size=4)  # a normalised 4D Gaussian is a uniformly random rotation
        poses.append((tuple(position), tuple(quaternion / np.linalg.norm(quaternion)), (0, 0, 0), (0, 0, 0)))
    return poses


def make_mesh(shape):
    if shape in peers.ICOSPHERES:
        return rm.Mesh.icosphere(RADIUS, peers.ICOSPHERES[shape])
    if shape in GRAIN_SHAPES:
        return grains.grain(shape).mesh(grains.REFERENCE_NODES)
    return rm.Mesh.reference_shape(shape)


def give_sphere_mass(body):
    """An icosphere's rounded body is the sphere of radius r (module docstring): its mass and inertia, not those of
    the inscribed polyhedron. Scaling the mesh to the sphere's volume instead would make its rounded body a sphere
    of 29.5 mm for 12 nodes (measured in S1: a mean height of 137 mm against the perfect spheres' 83 mm)."""
    state = O.bodies[body].state
    state.mass = PARTICLE.density * VOLUME
    state.inertia = Vector3(*[0.4 * state.mass * RADIUS ** 2] * 3)


def box_walls():
    return [utils.wall(0, axis=2, sense=1),
            utils.wall(-HALF_BASE, axis=0, sense=1), utils.wall(HALF_BASE, axis=0, sense=-1),
            utils.wall(-HALF_BASE, axis=1, sense=1), utils.wall(HALF_BASE, axis=1, sense=-1)]


def build_roundedmesh(run, poses, normal="pressure", timing="off"):
    """The bodies of `run` at `poses`, the box as roundedmesh partners and the engines. Returns (body ids, wall
    ids, description)."""
    O.reset()
    mesh = None if run == "sphere" else make_mesh(run)  # one mesh, its tree and distance field, for every body
    bodies = []
    for position, (w, x, y, z), _, _ in poses:
        ori = Quaternion(w, x, y, z)
        if mesh is None:
            bodies.append(rm.add_sphere(position, RADIUS, PARTICLE, ori=ori))
        else:
            bodies.append(rm.add_body(mesh, position, ori, PARTICLE))
            if run in peers.ICOSPHERES:
                give_sphere_mass(bodies[-1])
    walls = [O.bodies.append(wall) for wall in box_walls()]
    for wall in walls:
        rm.assign_material(wall, BOX)
    O.engines = [ForceResetter(), rm.engine(normal=normal, timing=timing), NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]
    if mesh is None:
        return bodies, walls, f"analytic spheres of radius {RADIUS} m"
    volume = (f"the sphere's mass; the mesh's volume {mesh.volume:.6g} m^3" if run in peers.ICOSPHERES
              else f"volume {mesh.volume:.6g} m^3")
    return bodies, walls, f"{len(mesh.vertices)} nodes, {len(mesh.triangles)} triangles, {volume}"


def build_peer(run, poses):
    """YADE's own representation `run` at `poses` (roundedmesh_study.peers; the walls are bodies 0-4)."""
    if run.endswith("_clumps"):
        bodies = peers.build_clumps(poses, count=40, name=PEER_SHAPE)
        description = "40-sphere clumps, YADE's Hertz-Mindlin"
    else:
        bodies = peers.build_level_sets(poses, name=PEER_SHAPE)
        description = "level-set bodies (1 mm grid, 511 surface nodes), YADE's Hertz-Mindlin"
    return bodies, list(range(5)), description


def stability_limit(run):
    """(limit [s], how it was found). YADE's utils.PWaveTimeStep() knows only spheres: for level-set bodies, the
    same estimate r sqrt(rho / E) for the volume-equivalent sphere."""
    if run in SHAPES:
        return rm.critical_timestep(), "rm.critical_timestep()"
    if run.endswith("_clumps"):
        return utils.PWaveTimeStep(), "utils.PWaveTimeStep()"
    return RADIUS * math.sqrt(peers.PARTICLE["density"] / peers.PARTICLE["young"]), "r sqrt(rho / E)"


def build(args, run):
    """Resets YADE and builds S1 for `run`: the bodies on the lattice, the box and its motion, the recorder.
    Returns (body ids, wall ids, the box's HarmonicMotionEngine, description)."""
    poses = lattice_poses(args.count, args.seed)
    bodies, walls, description = (build_roundedmesh(run, poses, args.normal, args.timing) if run in SHAPES
                                  else build_peer(run, poses))
    omega = 2 * math.pi / PERIOD
    x = omega * args.dt / 2  # see the module docstring: the step's mean velocity, not its first
    box = HarmonicMotionEngine(A=(0, 0, AMPLITUDE * math.sin(x) / x), f=(0, 0, 1 / PERIOD),
                               fi=(0, 0, -math.pi / 2 + x), ids=walls, label="box")
    # The recorder runs first in every step, while O.iter and O.time still describe the state the previous steps
    # left; the clock also runs last in the final step alone (iterLast starts at 0), so that the last window
    # ends there and not when O.run notices the end of the run.
    engines = list(O.engines)
    O.engines = ([PyRunner(command="s1_record()", iterPeriod=1), engines[0], box] + engines[1:] +
                 [PyRunner(command="s1_last_step_ends()", iterPeriod=max(args.steps - 1, 1), initRun=args.steps == 1)])
    O.tags[SCENE_TAG] = json.dumps(scene_parameters(args, run), sort_keys=True)
    O.trackEnergy = args.energy and run in SHAPES
    return bodies, walls, box, description


class EnergyBalance:
    """The energy balance of a roundedmesh run (--energy): O.energy's terms (YADE's and the engine's) and the work the
    moving box does on the bodies, which O.energy does not count (the box's walls are moved, not integrated), written
    to energy.csv at each window's end (the module's documentation)."""

    def __init__(self, walls, path, resumed_at):
        self.walls = walls
        self.box_work = float(O.tags[BOX_WORK_TAG]) if resumed_at else 0.0
        kept = [row for row in _csv_rows(path) if int(row[0]) <= resumed_at] if resumed_at else []
        self.rows = [[float(value) if value != "" else "" for value in row] for row in kept]
        self.file = open(path, "w", newline="")
        self.writer = csv.writer(self.file)
        self.writer.writerows([ENERGY_FIELDS] + kept)

    def add_step(self):
        """Adds the box's work in the step just ended: minus the force on each wall (the engine's, still in O.forces)
        dotted with the wall's displacement, its velocity (set at the step's start) times the step."""
        self.box_work -= sum(O.forces.f(w, sync=True).dot(O.bodies[w].state.vel) for w in self.walls) * O.dt

    def sample(self, done):
        terms = dict(O.energy.items())
        values = [terms.get(key, 0.0) for key in ENERGY_KEYS]
        balance = sum(values) - self.box_work
        dissipated = values[ENERGY_KEYS.index("rmNormDamp")] + values[ENERGY_KEYS.index("rmFrictDissip")]
        row = [done, O.time, *values, self.box_work, balance, balance / dissipated if dissipated > 0 else ""]
        self.rows.append(row)
        self.writer.writerow(row)
        self.file.flush()

    def save(self):
        """Before a checkpoint: the box's work so far goes with the scene."""
        O.tags[BOX_WORK_TAG] = repr(self.box_work)

    def close(self):
        self.file.close()


class Recorder:
    """Called at the start of every step and once after the run, with the state that `O.iter` steps left: stops
    the box, samples the windows into height.csv, writes the frames and the checkpoints."""

    def __init__(self, args, run, bodies, walls, box, series, resumed_at=0):
        self.args, self.run, self.bodies, self.walls, self.box, self.series = args, run, bodies, walls, box, series
        self.energy = (EnergyBalance(walls, os.path.join(args.output, run, "energy.csv"), resumed_at)
                       if args.energy and run in SHAPES else None)
        ends = set(range(args.sample, args.steps + 1, args.sample)) | {args.steps}
        if args.shaking_steps < args.steps:
            ends.add(args.shaking_steps)
        self.window_ends = ends
        self.frame_steps = {round(k * args.steps / args.frames) for k in range(1, args.frames + 1)}
        self.checkpoint = rm.checkpoint.Checkpointer(os.path.join(args.output, run, CHECKPOINT), every_steps=1)
        self.resumed_at = resumed_at
        self.window_start_step, self.window_start_clock = resumed_at, None
        self.excluded = np.zeros(2)  # wall and CPU seconds of the current window spent on frames and checkpoints
        self.last_step_end = None
        self.failure = None
        self.deepest = 0.0  # the window's largest pair overlap for its size (roundedmesh: every step)
        self.window_sums = dict.fromkeys(("pairs_ms",) + TIMED_STAGES, 0.0)  # roundedmesh: every step's, summed
        self.reporter = Progress(args.steps - resumed_at, f"S1 {run}", interval=10.0)
        path = os.path.join(args.output, run, "height.csv")
        kept = [row for row in _csv_rows(path) if int(row[0]) <= resumed_at] if resumed_at else []
        self.rows = [_typed(row) for row in kept]
        self.file = open(path, "w", newline="")
        self.writer = csv.writer(self.file)
        self.writer.writerows([FIELDS] + kept)

    def start(self):
        self.window_start_clock = clocks()

    def last_step_ends(self):
        self.last_step_end = clocks()

    def record(self, clock=None):
        done = O.iter
        if done == self.resumed_at and done > 0:  # the checkpoint's own step: sampled before it was saved
            return
        if self.run in SHAPES and done > 0:
            statistics = rm.statistics()
            self.deepest = max(self.deepest, statistics["deepest_pair_fraction"])
            for name in self.window_sums:
                self.window_sums[name] += statistics[name]
        if self.energy is not None and done > 0:  # before the box stops: this step moved it
            self.energy.add_step()
        if clock is None and done in self.window_ends:
            clock = clocks()
        if done == 1:  # the bodies have not moved yet: a contact now is an overlap in the start
            touching = self.counts()[1]
            print(f"touching pairs in the first step: {touching}"
                  + ("" if touching == 0 else " (bodies overlapping each other or a wall at the start)"), flush=True)
        if done == self.args.shaking_steps and done < self.args.steps:
            self.box.dead = True
            for wall in self.walls:
                O.bodies[wall].state.vel = Vector3.Zero
        if done in self.window_ends:
            self.sample(done, clock)
        begin = clocks()
        if done in self.frame_steps:
            self.series.write()
        if done % self.args.checkpoint_every == 0 and done < self.args.steps and self.failure is None:
            if self.energy is not None:
                self.energy.save()
            self.checkpoint()
        self.excluded += clocks() - begin
        if done in self.window_ends:  # the next window starts after this step's sampling, frame and checkpoint
            self.window_start_step, self.window_start_clock, self.excluded = done, clocks(), np.zeros(2)

    def counts(self):
        """(body_pairs, touching_pairs, candidates, contacts, candidate_rebuilds, near_rebuilds, pairs_ms, read_ms,
        write_ms) of the last step."""
        if self.run in SHAPES:
            s = rm.statistics()
            return (s["body_pairs"], s["touching_pairs"], s["candidates"], s["quadrature_contacts"] +
                    s["direct_contacts"] + s["exact_contacts"] + s.get("sphere_contacts", 0), s["candidate_rebuilds"], s["near_rebuilds"],
                    s["pairs_ms"], s["read_ms"], s["write_ms"])
        real = [i for i in O.interactions if i.isReal]
        owner = {}
        for i in real:
            for body in (i.id1, i.id2):
                owner.setdefault(body, O.bodies[body].clumpId if O.bodies[body].isClumpMember else body)
        touching = {tuple(sorted((owner[i.id1], owner[i.id2]))) for i in real}
        empty = ""
        return (len(O.interactions), len(touching), empty, len(real), empty, empty, empty, empty, empty)

    def sample(self, done, clock):
        positions, speeds = kinematics(self.bodies)
        steps = done - self.window_start_step
        present = sum(O.bodies[i] is not None for i in self.bodies)
        row = [done, O.time, "shaking" if done <= self.args.shaking_steps else "settling", self.box_z(),
               positions[:, 2].mean(), positions[:, 2].max(), speeds.mean(), present,
               outside(positions, self.box_z()), *self.counts(), self.deepest_in_window(), steps,
               *(clock - self.window_start_clock - self.excluded) / steps * 1e3, *self.window_means(steps)]
        self.rows.append(row)
        self.writer.writerow(row)
        self.file.flush()  # a run stopped early leaves every window so far
        if self.energy is not None:
            self.energy.sample(done)
        self.reporter.update(done - self.resumed_at)
        if len(self.rows) % 10 == 0 or done == self.args.steps:
            print(f"  t = {row[1]:.3f} s: box at {row[3] * 1e3:+.2f} mm, mean height {row[4]:.4f} m, max "
                  f"{row[5]:.4f} m, mean speed {row[6]:.3g} m/s, {row[10]} touching pairs, {row[12]} contacts, "
                  f"{row[FIELDS.index('ms_per_step')]:.2f} ms/step ({row[FIELDS.index('cpu_ms_per_step')]:.2f} CPU)",
                  flush=True)
        if not (np.isfinite(positions).all() and np.isfinite(speeds).all()):
            self.fail(f"non-finite positions or speeds at t = {row[1]:.4f} s")
        elif row[8] or row[7] != self.args.count:
            self.fail(f"at t = {row[1]:.4f} s, {row[8]} bodies have left the box and {row[7]} of "
                      f"{self.args.count} are in the scene")

    def window_means(self, steps):
        """The window's means of roundedmesh's pairs stage (wall ms) and, with --timing stages, of its stages inside
        (empty without, and for YADE's peers)."""
        sums, self.window_sums = self.window_sums, dict.fromkeys(self.window_sums, 0.0)
        timed = self.run in SHAPES and self.args.timing == "stages"
        return [sums["pairs_ms"] / steps if self.run in SHAPES else ""] + [
            sums[name] / steps if timed else "" for name in TIMED_STAGES]

    def deepest_in_window(self):
        """The largest overlap of a pair for its size: for roundedmesh, over the window's steps, as the stop rule
        measures it (rm.statistics()['deepest_pair_fraction']: the pair's depth over the smaller r_eq); for YADE's
        peers, at the window's end, the deepest penetration of two spheres or level sets of different bodies over
        r (clump members: the deepest sphere pair, not the bodies' overlap)."""
        if self.run in SHAPES:
            deepest, self.deepest = self.deepest, 0.0
            return deepest
        depths = [i.geom.penetrationDepth for i in O.interactions if i.isReal and hasattr(i.geom, "penetrationDepth")
                  and not (O.bodies[i.id1].isClumpMember and O.bodies[i.id2].isClumpMember and
                           O.bodies[i.id1].clumpId == O.bodies[i.id2].clumpId)]
        return max(depths, default=0.0) / RADIUS

    def fail(self, message):
        self.failure = message
        O.pause()  # the run stops after this step

    def box_z(self):
        return O.bodies[self.walls[0]].state.pos[2]


def _csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))[1:]


def _typed(row):
    """A height.csv row read back: numbers as floats, the phase as text, empty cells as they were."""
    return [value if k == 2 or value == "" else float(value) for k, value in enumerate(row)]


def clocks():
    """(wall, CPU of every thread of the process) [s]."""
    return np.array([time.perf_counter(), time.process_time()])


def kinematics(ids):
    """(positions (n, 3) [m], speeds (n,) [m/s]) of the bodies."""
    states = [O.bodies[i].state for i in ids]
    return np.array([tuple(s.pos) for s in states]), np.array([s.vel.norm() for s in states])


def outside(positions, floor):
    """Bodies whose centre is beyond a side wall or below the floor: they passed through the box."""
    return int(((np.abs(positions[:, :2]) > HALF_BASE).any(axis=1) | (positions[:, 2] < floor)).sum())


def packing_factor(heights, h):
    """Eq. 28 [%]: P(h) = N_h V_p / (A_b h) * 100, N_h the bodies with their centre below h."""
    return (heights < h).sum() * VOLUME / ((2 * HALF_BASE) ** 2 * h) * 100


def medians(rows, columns):
    """Medians of height.csv columns over `rows` (NaN for none or for empty cells)."""
    result = []
    for column in columns:
        values = [r[FIELDS.index(column)] for r in rows if r[FIELDS.index(column)] != ""]
        result.append(statistics.median(values) if values else math.nan)
    return result


def frames_until(collection, until):
    """The frames [(time [s], [file of each part])] of a ParaView collection written up to time `until`."""
    frames = {}
    if os.path.exists(collection):
        for dataset in ElementTree.parse(collection).getroot().iter("DataSet"):
            frames.setdefault(float(dataset.get("timestep")), []).append(dataset.get("file"))
    return [(t, files) for t, files in sorted(frames.items()) if t <= until * (1 + 1e-12)]


def load_checkpoint(args, run):
    """Loads the run's checkpoint after checking that it is intact and of this scene; returns its iteration."""
    path = os.path.join(args.output, run, CHECKPOINT)
    if not os.path.exists(path):
        raise SystemExit(f"--resume: {path} does not exist (no checkpoint of {run} in {args.output})")
    try:
        rm.checkpoint.resume(path)
    except rm.checkpoint.CheckpointError as error:
        raise SystemExit(f"--resume: {error}")
    saved = json.loads(O.tags[SCENE_TAG]) if SCENE_TAG in O.tags.keys() else None
    wanted = scene_parameters(args, run)
    if saved != wanted:
        raise SystemExit(f"--resume: {path} is a checkpoint of another scene ({saved}); this one is {wanted}")
    return O.iter


def run_one(args, run):
    command = os.environ.get("S1_PACKING_COMMAND") or shlex.join([sys.executable] + sys.argv)
    folder = os.path.join(args.output, run)
    complete = args.resume and os.path.exists(os.path.join(folder, "timing.csv"))
    resuming = args.resume and not complete
    started = time.perf_counter()
    threads = ctypes.CDLL("libgomp.so.1").omp_get_max_threads()
    if resuming:
        resumed_at = load_checkpoint(args, run)
        walls = [b.id for b in O.bodies if isinstance(b.shape, Wall)]
        bodies = [b.id for b in O.bodies if b.id not in walls and not b.isClumpMember]
        box = O.engines[[getattr(e, "label", "") for e in O.engines].index("box")]
        description = "resumed"
    else:
        resumed_at = 0
        bodies, walls, box, description = build(args, run)
    limit, limit_name = stability_limit(run)
    if args.dt > limit:
        raise SystemExit(f"--dt {args.dt:g} s is above the stability limit {limit_name} = {limit:g} s of this "
                         "scene; S1 uses 1e-4 s")
    if args.check:
        print(f"{run}: ok" + (" (complete)" if complete else f" (resumes at step {resumed_at})" if resuming else ""))
        return
    if complete:
        print(f"{run}: complete in {folder} (timing.csv exists); not run again")
        return
    O.dt = args.dt
    build_seconds = time.perf_counter() - started
    print(f"machine: {machine()}\ncommand: {command}\nOpenMP threads: {threads}", flush=True)
    print(f"S1 {run}: {args.count} bodies ({description}), seed {args.seed}; dt = {args.dt:g} s ({args.dt / limit:.3f} "
          f"of the limit {limit:.3g} s), {args.steps} steps: shaking {args.shaking_steps}, settling "
          f"{args.steps - args.shaking_steps}" + (f"; resumed at step {resumed_at}" if resuming else "") +
          f"; built in {build_seconds:.1f} s", flush=True)

    series = VtkSeries(os.path.join(folder, "vtk"), run, spheres=run == "sphere" or run.endswith("_clumps"))
    if resuming:
        series.frames = frames_until(os.path.join(folder, "vtk", run + ".pvd"), O.time)
    recorder = Recorder(args, run, bodies, walls, box, series, resumed_at)
    sys.modules["__main__"].s1_record = recorder.record  # PyRunner commands run in __main__
    sys.modules["__main__"].s1_last_step_ends = recorder.last_step_ends
    start, start_cpu = time.perf_counter(), time.process_time()
    recorder.start()
    try:
        O.run(args.steps - O.iter, True)
    except RuntimeError as error:  # the roundedmesh engine stopped the run; its message names the cause
        recorder.failure = str(error)
    if O.iter == args.steps and recorder.failure is None:  # not stopped early: the state after the last step
        recorder.record(recorder.last_step_end)
    run_seconds, run_cpu = time.perf_counter() - start, time.process_time() - start_cpu
    recorder.file.close()
    if recorder.energy is not None:
        recorder.energy.close()
        if recorder.energy.rows:
            plot_energy(os.path.join(folder, "energy.png"), recorder.energy.rows, args, run)
    if recorder.rows:
        plot_run(os.path.join(folder, "height.png"), recorder.rows, args, run)
        if run in SHAPES and args.timing == "stages":
            plot_timeline(os.path.join(folder, "timeline.png"), recorder.rows, args, run)
    if recorder.failure:
        raise SystemExit(f"S1 {run} stopped: {recorder.failure} (windows so far in {folder}/height.csv)")

    positions, _ = kinematics(bodies)
    heights = positions[:, 2] - recorder.box_z()
    packing = [packing_factor(heights, h) for h in PACKING_HEIGHTS]
    with open(os.path.join(folder, "packing.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["h_m", "bodies_below", "packing_factor_percent"])
        writer.writerows([h, int((heights < h).sum()), p] for h, p in zip(PACKING_HEIGHTS, packing))
    with open(os.path.join(folder, "final_state.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["id", "x_m", "y_m", "z_m", "qw", "qx", "qy", "qz"])
        for i in bodies:
            state = O.bodies[i].state
            q = state.ori  # minieigen orders a quaternion's coefficients x, y, z, w
            writer.writerow([i, *state.pos, q[3], q[0], q[1], q[2]])

    largest = max((r[FIELDS.index("deepest_pair_r")] for r in recorder.rows), default=0.0)
    timed = [r for r in recorder.rows if r[0] > resumed_at]
    phases = {phase: [r for r in timed if r[2] == phase] for phase in ("shaking", "settling")}
    columns = ["ms_per_step", "cpu_ms_per_step", "touching_pairs", "contacts"]
    total_seconds = time.perf_counter() - started
    with open(os.path.join(folder, "timing.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "threads", "omp_max_threads", "count", "dt_s", "steps", "resumed_at", "build_wall_s",
                         "run_wall_s", "run_cpu_s", "total_wall_s", "largest_pair_overlap_r"] +
                        [f"{phase}_{name}" for phase in phases for name in ["windows"] + ["median_" + c for c in columns]] +
                        ["machine", "command"])
        writer.writerow([run, args.threads, threads, args.count, args.dt, args.steps, resumed_at, build_seconds,
                         run_seconds, run_cpu, total_seconds, largest] +
                        [value for rows in phases.values() for value in [len(rows)] + medians(rows, columns)] +
                        [machine(), command])

    shaking, settling = (medians(phases[p], columns[:2]) for p in ("shaking", "settling"))
    at_submerged = packing[list(PACKING_HEIGHTS).index(SUBMERGED_HEIGHT)]
    print(f"\nS1 {run}, {args.count} bodies, {threads} thread(s): run {run_seconds:.1f} s wall, {run_cpu:.1f} s CPU "
          f"for {args.steps - resumed_at} steps (build {build_seconds:.1f} s, total {total_seconds:.1f} s); median "
          "ms/step, wall (CPU): shaking {:.2f} ({:.2f}), settling {:.2f} ({:.2f})".format(*shaking, *settling))
    print(f"final: mean height {heights.mean():.4f} m, max {heights.max():.4f} m above the floor; "
          f"P({SUBMERGED_HEIGHT:.2f} m) = {at_submerged:.1f} %; largest pair overlap {largest:.3f} r")
    if recorder.energy is not None:
        last = recorder.energy.rows[-1]
        dissipated = last[ENERGY_FIELDS.index("normal_damping_J")] + last[ENERGY_FIELDS.index("friction_J")]
        balance = last[ENERGY_FIELDS.index("balance_J")]
        share = f"{balance / dissipated:+.2%} of the {dissipated:.4g} J" if dissipated > 0 else "nothing"
        print(f"energy balance at the end: {balance:+.4g} J, {share} the damping and friction dissipated; the box did "
              f"{last[ENERGY_FIELDS.index('box_work_J')]:+.4g} J of work (energy.csv, energy.png)")
    print(f"wrote height.csv, packing.csv, final_state.csv, timing.csv, height.png and vtk/{run}.pvd to {folder}")
    print(f"ParaView: open {os.path.join(folder, 'vtk', run + '.pvd')}, the run as a time series of {args.frames} "
          "frames (the bodies' surfaces; the contact force on each triangle is the cell data 'contact_force')")
    print(f"machine: {machine()}\ncommand: {command}")


def plot_run(path, rows, args, run):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = np.array([r[1] for r in rows])
    column = {name: np.array([r[k] for r in rows], dtype=float) for k, name in enumerate(FIELDS)
              if name in ("mean_height_m", "max_height_m", "box_z_m")}
    figure, axes = plt.subplots(figsize=(7, 4.5))
    axes.plot(t, column["mean_height_m"] * 1e3, "k-", label="mean height")
    axes.plot(t, column["max_height_m"] * 1e3, "k:", label="max height")
    axes.plot(t, column["box_z_m"] * 1e3, "C0-", lw=0.8, label="box floor")
    axes.axvspan(0, min(SHAKING, t[-1]), color="C0", alpha=0.08, label="shaking")
    axes.set(xlabel="time [s]", ylabel="height of the centres [mm]", xlim=(0, t[-1]),
             title=f"S1, {args.count} bodies, {run}, dt = {args.dt:g} s")
    axes.grid(alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def plot_energy(path, rows, args, run):
    """The energy balance's terms (left) and the balance itself against what was dissipated (right) over time."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    column = {name: np.array([r[k] if r[k] != "" else np.nan for r in rows], dtype=float)
              for k, name in enumerate(ENERGY_FIELDS)}
    t = column["time_s"]
    figure, (terms, balance) = plt.subplots(1, 2, figsize=(11, 4.5))
    for name, label in (("kinetic_J", "kinetic"), ("gravity_work_J", "potential (gravity_work)"),
                        ("elastic_J", "elastic"), ("normal_damping_J", "dissipated by damping"),
                        ("friction_J", "dissipated by friction"), ("box_work_J", "work of the box")):
        terms.plot(t, column[name], label=label)
    balance.plot(t, column["balance_J"], "k-", label="balance")
    balance.plot(t, column["normal_damping_J"] + column["friction_J"], "C3:", label="dissipated")
    for axes in (terms, balance):
        axes.axvspan(0, min(SHAKING, t[-1]), color="0.5", alpha=0.08)
        axes.set(xlabel="time [s]", ylabel="energy [J]", xlim=(0, t[-1]))
        axes.grid(alpha=0.3)
        axes.legend(fontsize=8)
    terms.set_title(f"S1, {args.count} bodies, {run}, normal law '{args.normal}'")
    balance.set_title(f"balance at the end: {column['balance_over_dissipated'][-1]:+.2%} of the dissipated")
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def plot_timeline(path, rows, args, run):
    """Where each window's wall time per step goes: roundedmesh's stages inside the pairs (CPU ms over the threads,
    so that on a step that keeps every thread busy they stack up to the pairs stage's wall time), the rest of the
    pairs stage (their loop, waits for the slowest thread), and everything outside it (YADE's engines, the states
    read and the forces written, Python)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    column = {name: np.array([r[k] if r[k] != "" else np.nan for r in rows], dtype=float)
              for k, name in enumerate(FIELDS) if name.startswith("window_") or name in ("time_s", "ms_per_step")}
    t = column["time_s"]
    stages = [("lists (near searches)", column["window_near_search_cpu_ms"]),
              ("lists (scans of near lists)", column["window_lists_cpu_ms"] - column["window_near_search_cpu_ms"]),
              ("narrow phase", column["window_narrow_phase_cpu_ms"]), ("law", column["window_law_cpu_ms"]),
              ("core", column["window_core_cpu_ms"])]
    stacked = [values / args.threads for _, values in stages]
    inside = sum(stacked)
    stacked.append(np.maximum(column["window_pairs_ms"] - inside, 0))
    stacked.append(column["ms_per_step"] - column["window_pairs_ms"])
    labels = [name for name, _ in stages] + ["pairs stage, rest", "outside the pairs stage"]
    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.stackplot(t, *stacked, labels=labels, alpha=0.85)
    axes.plot(t, column["ms_per_step"], "k-", lw=0.8, label="wall ms per step")
    axes.axvspan(0, min(SHAKING, t[-1]), color="0.5", alpha=0.08)
    axes.set(xlabel="time [s]", ylabel=f"ms per step (CPU stages / {args.threads} threads)", xlim=(0, t[-1]),
             title=f"S1, {args.count} bodies, {run}, {args.threads} thread(s): where a step's time goes")
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8, loc="upper right")
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


if __name__ == "__main__":
    run_one(ARGS, ARGS.run)
