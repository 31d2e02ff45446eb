"""Scene S1 of doc/scenes.md, the shaken gravitational packing of Smeets et al., CMAME 277 (2014) 219-238,
Section 3.4 (Figs. 10-12), run whole with rounded bodies: `--count` bodies of one shape fall from S1's lattice
into a 0.40 m x 0.40 m box of five YADE Walls, the box moves vertically as z_box(t) = A sin(2 pi t / T)
(A = 0.025 m, T = 0.25 s) for three periods (0.75 s), then stands still; 1.35 s in all, 13,500 steps of 1e-4 s.

    /usr/bin/python3 scripts/s1_packing.py [--shape gummy_bear] [--count 250] [--seed 1] [--dt 1e-4]
        [--duration 1.35] [--sample 100] [--frames 1] [--threads 1] [--output out/s1/<shape>]

Shapes: gummy_bear and pear (Mesh.reference_shape, ~554 and ~486 nodes asked), icosphere12, icosphere42 and
icosphere162 (Mesh.icosphere with 0, 1, 2 subdivisions, its radius chosen so that the mesh's volume is that of
the sphere of radius 0.025 m). Every body has the volume of that sphere. Materials (S1): particles E = 1e6 Pa,
nu = 0.4, 2000 kg/m^3; box E = 5e6 Pa, nu = 0.4; normal damping constant A = 0.01 s (Eq. 7) on both; no
friction. NewtonIntegrator without numerical damping, gravity (0, 0, -9.81) m/s^2.

The box is moved by YADE's HarmonicMotionEngine on all five walls, which sets each wall's velocity at the start
of every step to v = -A' w sin(w t + phi) (w = 2 pi / T). With A' = A and phi = -pi/2 it would use the velocity
at the start of the step for the whole step, and the box would drift from A sin(w t) by up to A w dt (0.063 mm
at dt = 1e-4 s). With x = w dt / 2, phi = -pi/2 + x and A' = A sin(x) / x its velocity in the step from t to
t + dt is exactly (z_box(t + dt) - z_box(t)) / dt (a sum of cosines), so the box stands at A sin(w t) at every
step to rounding. After 0.75 s the engine is stopped and the walls' velocities set to zero (a stopped
HarmonicMotionEngine leaves the last velocity in place, and the box would keep moving).

Heights are those of the bodies' centres of mass above z = 0, the floor's rest position [m]. Outputs, in
--output:
    height.csv    one row per window of --sample steps (also ending at the end of shaking and of the run), at
                  the window's end: step, time [s], phase of the window, box position [m], mean and max height
                  [m], mean speed [m/s], bodies in the scene and bodies whose centre left the box, the last
                  step's counts of rm.statistics() (body_pairs, touching_pairs, candidates, contacts =
                  quadrature_contacts + direct_contacts, candidate_rebuilds, near_rebuilds) and its stage times
                  (pairs_ms, read_ms, write_ms [ms]), and the window's steps, wall time and CPU time per step
                  [ms] (CPU of all the process's threads: on a shared machine, how much of the wall time it got)
    packing.csv   at the end, Eq. 28: P(h) = N_h V_p / (A_b h) * 100 [%] for h = 0.01 ... 0.30 m, N_h the bodies
                  whose centre is less than h above the floor, V_p a body's volume [m^3], A_b = 0.16 m^2
    timing.csv    OpenMP threads, wall time of building and of running [s], CPU time of the run [s] (all
                  threads), median wall and CPU ms/step over the windows of shaking and of settling, machine,
                  command
    height.png    mean and max height and the box's position vs time (the paper's Fig. 11a)
    vtk/          ParaView series <shape>.pvd of --frames frames (roundedmesh.export.VtkSeries), evenly spaced,
                  the last at the end of the run
A window's time excludes sampling and frame writing. The recorder runs in a PyRunner at the start of every
step (about 0.015 ms per step), inside one O.run, so that no window includes the up to 40 ms by which
O.run(n, True) notices the end of a run.

The touching pairs of the first step, before anything has moved, are printed: S1's lattice does not keep every
body off the side walls (the outer nodes are 0.05 m +- 0.003 m from them, and the gummy bear reaches 0.0485 m
from its centre), so a few bodies may start pressed against a wall.

--threads sets OMP_NUM_THREADS for the roundedmesh engine: the script restarts itself with it set before YADE
loads OpenMP. Bad input (an unknown shape, a time step above rm.critical_timestep() or one that does not divide
the shaking into whole steps, an output folder that cannot be written) stops the script with a message before
it runs a step.
"""
import argparse
import math
import os
import shlex
import sys
import tempfile
import time

SHAPES = ("gummy_bear", "pear", "icosphere12", "icosphere42", "icosphere162")
ICOSPHERE_SUBDIVISIONS = {"icosphere12": 0, "icosphere42": 1, "icosphere162": 2}
SHAKING = 0.75  # three periods of T = 0.25 s [s]


def parse(argv):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="Perfect spheres, S1's first shape, are left out for now: how a YADE Sphere takes part in the "
               "same contact law is still being decided.")
    parser.add_argument("--shape", default="gummy_bear", help=f"one of {', '.join(SHAPES)} (default gummy_bear)")
    parser.add_argument("--count", type=int, default=250, help="bodies (default 250)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the jitter and the orientations (default 1)")
    parser.add_argument("--dt", type=float, default=1e-4, help="time step [s] (default 1e-4)")
    parser.add_argument("--duration", type=float, default=1.35, help="simulated time [s] (default 1.35)")
    parser.add_argument("--sample", type=int, default=100, help="steps per window of height.csv (default 100)")
    parser.add_argument("--frames", type=int, default=1, help="ParaView frames over the run (default 1: the end)")
    parser.add_argument("--threads", type=int, default=1, help="OpenMP threads (default 1)")
    parser.add_argument("--output", help="output folder (default out/s1/<shape>)")
    args = parser.parse_args(argv)
    if args.shape == "sphere":
        parser.error("--shape sphere: perfect spheres are left out for now (see --help); use one of "
                     + ", ".join(SHAPES))
    if args.shape not in SHAPES:
        parser.error(f"--shape {args.shape}: unknown shape; use one of {', '.join(SHAPES)}")
    for name in ("count", "sample", "frames", "threads"):
        if getattr(args, name) < 1:
            parser.error(f"--{name} must be at least 1")
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
    args.output = args.output or os.path.join("out", "s1", args.shape)
    try:
        os.makedirs(args.output, exist_ok=True)
        with tempfile.TemporaryFile(dir=args.output):
            pass
    except OSError as error:
        parser.error(f"--output {args.output}: cannot write there ({error.strerror or error})")
    return args


ARGS = parse(sys.argv[1:])
if os.environ.get("OMP_NUM_THREADS") != str(ARGS.threads):  # before YADE loads OpenMP
    os.environ["OMP_NUM_THREADS"] = str(ARGS.threads)
    os.execv(sys.executable, [sys.executable] + sys.argv)

import csv  # noqa: E402
import ctypes  # noqa: E402
import statistics  # noqa: E402

import numpy as np  # noqa: E402
from yade import ForceResetter, HarmonicMotionEngine, NewtonIntegrator, O, PyRunner, utils  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.benchmarking import machine  # noqa: E402
from roundedmesh.export import VtkSeries  # noqa: E402
from roundedmesh.progress import Progress  # noqa: E402

# Scene S1 (doc/scenes.md)
RADIUS = 0.025                       # volume-equivalent radius r [m]
HALF_BASE = 0.20                     # the box's inner base is 0.40 m x 0.40 m, centred on the z axis [m]
LATTICE = (-0.15, -0.05, 0.05, 0.15)  # x and y of a layer's 4 x 4 nodes [m]
LAYER_SPACING, LOWEST_LAYER, JITTER = 0.10, 0.06, 0.003  # [m]
AMPLITUDE, PERIOD = 0.025, 0.25      # the box's shaking [m], [s]
GRAVITY = 9.81                       # [m/s^2]
PARTICLE = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01)
BOX = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0.01)  # density unused: walls are kinematic
PACKING_HEIGHTS = np.round(np.arange(1, 31) * 0.01, 2)  # h of Eq. 28 [m]
FIELDS = ["step", "time_s", "phase", "box_z_m", "mean_height_m", "max_height_m", "mean_speed_m_s", "bodies",
          "outside", "body_pairs", "touching_pairs", "candidates", "contacts", "candidate_rebuilds",
          "near_rebuilds", "pairs_ms", "read_ms", "write_ms", "window_steps", "ms_per_step", "cpu_ms_per_step"]


def make_mesh(shape):
    if shape in ICOSPHERE_SUBDIVISIONS:
        k = ICOSPHERE_SUBDIVISIONS[shape]
        # an inscribed polyhedron has less volume than its sphere; volume scales as radius cubed
        scale = (4 / 3 * math.pi * RADIUS ** 3 / rm.Mesh.icosphere(RADIUS, k).volume) ** (1 / 3)
        return rm.Mesh.icosphere(RADIUS * scale, k)
    return rm.Mesh.reference_shape(shape)


def build(args):
    """Resets YADE and builds S1: the bodies on the lattice, the box, the engines. Returns (body ids, wall ids,
    the box's HarmonicMotionEngine, mesh)."""
    O.reset()
    mesh = make_mesh(args.shape)
    rng = np.random.default_rng(args.seed)
    bodies = []
    for i in range(args.count):
        layer, node = divmod(i, 16)
        row, column = divmod(node, 4)  # bottom layer first, x fastest
        pos = np.array([LATTICE[column], LATTICE[row], LOWEST_LAYER + LAYER_SPACING * layer])
        pos += rng.uniform(-JITTER, JITTER, 3)
        ori = Quaternion(*rng.normal(size=4))  # a normalised 4D Gaussian is a uniformly random rotation
        ori.normalize()
        bodies.append(rm.add_body(mesh, tuple(pos), ori, PARTICLE))
    walls = [O.bodies.append(wall) for wall in
             (utils.wall(0, axis=2, sense=1),
              utils.wall(-HALF_BASE, axis=0, sense=1), utils.wall(HALF_BASE, axis=0, sense=-1),
              utils.wall(-HALF_BASE, axis=1, sense=1), utils.wall(HALF_BASE, axis=1, sense=-1))]
    for wall in walls:
        rm.assign_material(wall, BOX)
    omega = 2 * math.pi / PERIOD
    x = omega * args.dt / 2  # see the module docstring: the step's mean velocity, not its first
    box = HarmonicMotionEngine(A=(0, 0, AMPLITUDE * math.sin(x) / x), f=(0, 0, 1 / PERIOD),
                               fi=(0, 0, -math.pi / 2 + x), ids=walls, label="box")
    # The recorder runs first in every step, while O.iter and O.time still describe the state the previous steps
    # left; the clock also runs last in the final step alone (iterLast starts at 0), so that the last window
    # ends there and not when O.run notices the end of the run.
    O.engines = [PyRunner(command="s1_record()", iterPeriod=1), ForceResetter(), box, rm.engine(),
                 NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0),
                 PyRunner(command="s1_last_step_ends()", iterPeriod=max(args.steps - 1, 1), initRun=args.steps == 1)]
    return bodies, walls, box, mesh


class Recorder:
    """Called at the start of every step and once after the run, with the state that `O.iter` steps left: stops
    the box, samples the windows into height.csv and writes the frames."""

    def __init__(self, args, bodies, walls, box, series):
        self.args, self.bodies, self.walls, self.box, self.series = args, bodies, walls, box, series
        ends = set(range(args.sample, args.steps + 1, args.sample)) | {args.steps}
        if args.shaking_steps < args.steps:
            ends.add(args.shaking_steps)
        self.window_ends = ends
        self.frame_steps = {round(k * args.steps / args.frames) for k in range(1, args.frames + 1)}
        self.rows = []
        self.window_start_step, self.window_start_clock = 0, None
        self.excluded = np.zeros(2)  # wall and CPU seconds of the current window spent writing frames
        self.last_step_end = None
        self.failure = None
        self.reporter = Progress(args.steps, f"S1 {args.shape}", interval=10.0)
        self.file = open(os.path.join(args.output, "height.csv"), "w", newline="")
        self.writer = csv.writer(self.file)
        self.writer.writerow(FIELDS)

    def start(self):
        self.window_start_clock = clocks()

    def last_step_ends(self):
        self.last_step_end = clocks()

    def record(self, clock=None):
        done = O.iter
        if clock is None and done in self.window_ends:
            clock = clocks()
        if done == 1:  # the bodies have not moved yet: a contact now is an overlap in the start
            touching = rm.statistics()["touching_pairs"]
            print(f"touching pairs in the first step: {touching}"
                  + ("" if touching == 0 else " (bodies overlapping each other or a wall at the start)"), flush=True)
        if done == self.args.shaking_steps and done < self.args.steps:
            self.box.dead = True
            for wall in self.walls:
                O.bodies[wall].state.vel = Vector3.Zero
        if done in self.window_ends:
            self.sample(done, clock)
        if done in self.frame_steps:
            begin = clocks()
            self.series.write()
            self.excluded += clocks() - begin
        if done in self.window_ends:  # the next window starts after this step's sampling and frame
            self.window_start_step, self.window_start_clock, self.excluded = done, clocks(), np.zeros(2)

    def sample(self, done, clock):
        positions, speeds = kinematics(self.bodies)
        stats = rm.statistics()
        steps = done - self.window_start_step
        row = [done, O.time, "shaking" if done <= self.args.shaking_steps else "settling", self.box_z(),
               positions[:, 2].mean(), positions[:, 2].max(), speeds.mean(), len(rm.rounded_bodies()),
               outside(positions, self.box_z()), stats["body_pairs"], stats["touching_pairs"], stats["candidates"],
               stats["quadrature_contacts"] + stats["direct_contacts"], stats["candidate_rebuilds"],
               stats["near_rebuilds"], stats["pairs_ms"], stats["read_ms"], stats["write_ms"], steps,
               *(clock - self.window_start_clock - self.excluded) / steps * 1e3]
        self.rows.append(row)
        self.writer.writerow(row)
        self.file.flush()  # a run stopped early leaves every window so far
        self.reporter.update(done)
        if len(self.rows) % 10 == 0 or done == self.args.steps:
            print(f"  t = {row[1]:.3f} s: box at {row[3] * 1e3:+.2f} mm, mean height {row[4]:.4f} m, max "
                  f"{row[5]:.4f} m, mean speed {row[6]:.3g} m/s, {row[10]} touching pairs, {row[12]} triangle "
                  f"contacts, {row[-2]:.2f} ms/step ({row[-1]:.2f} CPU)", flush=True)
        if not (np.isfinite(positions).all() and np.isfinite(speeds).all()):
            self.fail(f"non-finite positions or speeds at t = {row[1]:.4f} s")
        elif row[8] or row[7] != self.args.count:
            self.fail(f"at t = {row[1]:.4f} s, {row[8]} bodies have left the box and {row[7]} of "
                      f"{self.args.count} are in the scene")

    def fail(self, message):
        self.failure = message
        O.pause()  # the run stops after this step

    def box_z(self):
        return O.bodies[self.walls[0]].state.pos[2]


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


def packing_factor(heights, volume, h):
    """Eq. 28 [%]: P(h) = N_h V_p / (A_b h) * 100, N_h the bodies with their centre below h."""
    return (heights < h).sum() * volume / ((2 * HALF_BASE) ** 2 * h) * 100


def plot(path, rows, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = np.array([r[1] for r in rows])
    column = {name: np.array([r[k] for r in rows], dtype=float) for k, name in enumerate(FIELDS) if name != "phase"}
    figure, axes = plt.subplots(figsize=(7, 4.5))
    axes.plot(t, column["mean_height_m"] * 1e3, "k-", label="mean height")
    axes.plot(t, column["max_height_m"] * 1e3, "k:", label="max height")
    axes.plot(t, column["box_z_m"] * 1e3, "C0-", lw=0.8, label="box floor")
    axes.axvspan(0, min(SHAKING, t[-1]), color="C0", alpha=0.08, label="shaking")
    axes.set(xlabel="time [s]", ylabel="height of the centres [mm]", xlim=(0, t[-1]),
             title=f"S1, {args.count} x {args.shape}, dt = {args.dt:g} s")
    axes.grid(alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def medians(windows):
    """(median wall, median CPU) ms per step over `windows` [(wall, CPU)], NaN for none."""
    return tuple(statistics.median(column) for column in zip(*windows)) if windows else (math.nan, math.nan)


def main(args):
    started = time.perf_counter()
    command = shlex.join([sys.executable] + sys.argv)
    threads = ctypes.CDLL("libgomp.so.1").omp_get_max_threads()
    print(f"machine: {machine()}\ncommand: {command}\nOpenMP threads: {threads}", flush=True)
    bodies, walls, box, mesh = build(args)
    limit = rm.critical_timestep()
    if args.dt > limit:
        raise SystemExit(f"--dt {args.dt:g} s is above the stability limit rm.critical_timestep() = {limit:g} s of "
                         f"this scene; S1 uses 1e-4 s")
    O.dt = args.dt
    build_seconds = time.perf_counter() - started
    print(f"S1: {args.count} x {args.shape} ({len(mesh.vertices)} nodes, {len(mesh.triangles)} triangles, volume "
          f"{mesh.volume:.6g} m^3), seed {args.seed}; dt = {args.dt:g} s ({args.dt / limit:.3f} of the limit "
          f"{limit:.3g} s), {args.steps} steps: shaking {args.shaking_steps}, settling "
          f"{args.steps - args.shaking_steps}; built in {build_seconds:.1f} s", flush=True)

    recorder = Recorder(args, bodies, walls, box, VtkSeries(os.path.join(args.output, "vtk"), args.shape))
    sys.modules["__main__"].s1_record = recorder.record  # PyRunner commands run in __main__
    sys.modules["__main__"].s1_last_step_ends = recorder.last_step_ends
    start, start_cpu = time.perf_counter(), time.process_time()
    recorder.start()
    try:
        O.run(args.steps, True)
    except RuntimeError as error:  # the roundedmesh engine stopped the run; its message names the cause
        recorder.failure = str(error)
    if O.iter == args.steps:  # not stopped early: the state after the last step
        recorder.record(recorder.last_step_end)
    run_seconds, run_cpu = time.perf_counter() - start, time.process_time() - start_cpu
    recorder.file.close()
    if recorder.rows:
        plot(os.path.join(args.output, "height.png"), recorder.rows, args)
    if recorder.failure:
        raise SystemExit(f"S1 stopped: {recorder.failure} (windows so far in {args.output}/height.csv)")

    positions, _ = kinematics(bodies)
    heights = positions[:, 2] - recorder.box_z()
    packing = [packing_factor(heights, mesh.volume, h) for h in PACKING_HEIGHTS]
    with open(os.path.join(args.output, "packing.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["h_m", "bodies_below", "packing_factor_percent"])
        writer.writerows([h, int((heights < h).sum()), p] for h, p in zip(PACKING_HEIGHTS, packing))

    shaking = [r[-2:] for r in recorder.rows if r[2] == "shaking"]
    settling = [r[-2:] for r in recorder.rows if r[2] == "settling"]
    total_seconds = time.perf_counter() - started
    with open(os.path.join(args.output, "timing.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["threads", "omp_max_threads", "shape", "nodes", "count", "dt_s", "steps", "build_wall_s",
                         "run_wall_s", "run_cpu_s", "total_wall_s", "shaking_windows", "median_ms_per_step_shaking",
                         "median_cpu_ms_per_step_shaking", "settling_windows", "median_ms_per_step_settling",
                         "median_cpu_ms_per_step_settling", "machine", "command"])
        writer.writerow([args.threads, threads, args.shape, len(mesh.vertices), args.count, args.dt, args.steps,
                         build_seconds, run_seconds, run_cpu, total_seconds, len(shaking), *medians(shaking),
                         len(settling), *medians(settling), machine(), command])

    at_10_cm = packing[list(PACKING_HEIGHTS).index(0.10)]
    print(f"\nS1, {args.count} x {args.shape}, {threads} thread(s): run {run_seconds:.1f} s wall, {run_cpu:.1f} s CPU "
          f"for {args.steps} steps (build {build_seconds:.1f} s, total {total_seconds:.1f} s); median ms/step, wall "
          "(CPU): shaking {:.2f} ({:.2f}), settling {:.2f} ({:.2f})".format(*medians(shaking), *medians(settling)))
    print(f"final: mean height {heights.mean():.4f} m, max {heights.max():.4f} m above the floor; "
          f"P(0.10 m) = {at_10_cm:.1f} %")
    print(f"wrote height.csv, packing.csv, timing.csv, height.png and vtk/{args.shape}.pvd to {args.output}")
    print(f"machine: {machine()}\ncommand: {command}")


main(ARGS)
