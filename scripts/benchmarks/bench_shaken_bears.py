"""Whole-step cost of scene S1 (doc/scenes.md) with 250 gummy bears, on the settled packing: the bears
fall from S1's lattice into the box (standing still: no shaking), settle, and the settled scene is saved;
then the median wall time per complete YADE step is measured with 1 and 2 OpenMP threads, each in a fresh
process started from the saved scene, with the share of every engine (ForceResetter, the roundedmesh
engine split into its C++ step, its Python wrapper and the PyRunner that calls it, NewtonIntegrator).

    /usr/bin/python3 scripts/benchmarks/bench_shaken_bears.py [--rebuild] [--output out/bench_shaken_bears]
        [--shape gummy_bear] [--settle-only]
        [--count 250] [--dt 1e-4] [--max-time 1.5] [--settled-speed 1e-2]
        [--settle-dt 5e-4] [--settle-damping 0.3]
        [--threads 1 2] [--blocks 5] [--block-steps 200] [--warmup 100]

--shape: the bodies, 'gummy_bear' (Mesh.reference_shape("gummy_bear", 554)), a study grain of the
speed-against-error study (roundedmesh_study.grains.NAMES: 'spheroid', 'pill', 'tetra_grain'), whose mesh is
grains.grain(name).mesh(grains.REFERENCE_NODES = 600), curvature computed, or another shape of S1: 'pear'
(Mesh.reference_shape("pear"), 486 nodes), 'icosphere162' (Mesh.icosphere(0.025, 2), its mesh's own mass) or
'sphere' (sphere bodies of 0.025 m, rm.add_sphere): the same lattice, jitter, random orientations (--seed),
materials, box and gravity, so that every shape's packing is S1's. The default output
folder is out/bench_shaken_bears for the bear and out/bench_shaken_bears_<shape> for any other shape.
--settle-only: settle (or reuse the saved scene) and describe it, without the measurements: what
scripts/benchmarks/record_s1_scene.py needs to write the packing (bench/data/s1_settled_<shape>.csv).

Settling follows S1 (dt, no numerical damping) unless --settle-dt / --settle-damping say otherwise. With 250
bears a step of the packing costs a few hundred ms (0.43 s on one thread, 0.26 s on two, 2-core Xeon at
2.0 GHz, 2026-11-22), so S1's 15,000 settling steps take hours; a larger step and NewtonIntegrator damping
while settling only (--settle-dt 5e-4 --settle-damping 0.3: 3,000 steps, about 8 minutes) make it
affordable. The saved scene has S1's dt and no damping either way, and the measurement runs with them.

Writes to the output folder:
    settled.yade.gz     the settled scene (O.save); reused unless --rebuild is given
    settling.csv        every 100 steps of settling: wall time, mean / max height and speed, contact counts
    settling.png        mean height vs time, and wall time per step and contacts vs time
    timing.csv          per thread count: median ms/step over the blocks, and the split between engines
The thread count of the roundedmesh engine follows OMP_NUM_THREADS, as YADE's own engines do:
each measurement runs this script again with --measure and OMP_NUM_THREADS set.
"""
import argparse
import ctypes
import csv
import json
import math
import os
import shlex
import subprocess
import sys
import time

import numpy as np
from yade import ForceResetter, NewtonIntegrator, O, PyRunner, utils
from yade.minieigenHP import Quaternion

import roundedmesh as rm
import roundedmesh.scene  # noqa: F401  (the engine's step, wrapped for timing in --measure)
from roundedmesh.progress import Progress
from roundedmesh_study import benchmarking, grains, peers
from roundedmesh_study.benchmarking import machine

# Scene S1 (doc/scenes.md); the box stands still here.
RADIUS = 0.025                      # volume-equivalent radius [m]
HALF_BASE = 0.20                    # the box's inner base is 0.40 m x 0.40 m, centred on the z axis
LATTICE = (-0.15, -0.05, 0.05, 0.15)
LAYER_SPACING, LOWEST_LAYER, JITTER = 0.10, 0.06, 0.003
GRAVITY = 9.81
PARTICLE = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01)
BOX = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0.01)   # density unused: walls are fixed
SAMPLE = 100                        # steps between samples while settling
RESULT = "RESULT "                  # prefix of the --measure process's result line
SHAPES = ("gummy_bear",) + grains.NAMES + ("pear", "icosphere162", "sphere")
TAG = "bench_shaken_bears.settled"  # O.tags key of the saved scene's settling record (JSON)


def shape_mesh(shape):
    """The mesh every body of `shape` shares (module docstring), in its principal frame, which the bodies' states
    are of; None for spheres."""
    return None if shape == "sphere" else peers.body_frame(shape)[0]


def build(count, dt, seed, shape="gummy_bear"):
    """Resets YADE and builds S1 with `count` bodies of `shape` (SHAPES) and a standing box. Returns the bodies'
    ids."""
    O.reset()
    mesh = shape_mesh(shape)
    rng = np.random.default_rng(seed)
    bears = []
    for i in range(count):
        layer, node = divmod(i, 16)
        row, column = divmod(node, 4)  # bottom layer first, x fastest
        pos = np.array([LATTICE[column], LATTICE[row], LOWEST_LAYER + LAYER_SPACING * layer])
        pos += rng.uniform(-JITTER, JITTER, 3)
        ori = Quaternion(*rng.normal(size=4))  # uniformly random rotation
        ori.normalize()
        bears.append(rm.add_sphere(tuple(pos), RADIUS, PARTICLE, ori=ori) if mesh is None else
                     rm.add_body(mesh, tuple(pos), ori, PARTICLE))
    walls = [utils.wall(0, axis=2, sense=1),                    # bottom, facing +z
             utils.wall(-HALF_BASE, axis=0, sense=1), utils.wall(HALF_BASE, axis=0, sense=-1),
             utils.wall(-HALF_BASE, axis=1, sense=1), utils.wall(HALF_BASE, axis=1, sense=-1)]
    for wall in walls:
        rm.assign_material(O.bodies.append(wall), BOX)
    O.engines = [ForceResetter(), rm.engine(),
                 NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]
    limit = rm.critical_timestep()
    if dt < limit:
        print(f"dt = {dt:g} s, below rm.critical_timestep() = {limit:g} s ({dt / limit:.2f} of it)")
    else:
        print(f"dt = {dt:g} s is NOT below rm.critical_timestep() = {limit:g} s: using 0.5 of the limit, "
              f"{0.5 * limit:g} s")
        dt = 0.5 * limit
    O.dt = dt
    return bears


def bear_ids():
    return sorted([*rm.rounded_bodies(), *rm.sphere_bodies()])


def kinematics(ids):
    """(positions (n, 3), speeds (n,)) of the bodies."""
    states = [O.bodies[i].state for i in ids]
    positions = np.array([tuple(s.pos) for s in states])
    speeds = np.array([s.vel.norm() for s in states])
    return positions, speeds


def escaped(positions, margin=0.01):
    """Bodies whose centre is outside the box (a wall was passed) or below its floor."""
    outside = (np.abs(positions[:, :2]) > HALF_BASE + margin).any(axis=1) | (positions[:, 2] < -margin)
    return int(outside.sum())


def packing_factor(heights, volume, h):
    """Eq. 28: P(h) = N_h V_p / (A_b h) * 100, N_h the bodies with their centre below h."""
    return (heights < h).sum() * volume / ((2 * HALF_BASE) ** 2 * h) * 100


SETTLING_FIELDS = ["step", "time_s", "wall_s", "ms_per_step", "mean_height_m", "max_height_m", "mean_speed_m_s",
                   "max_speed_m_s", "body_pairs", "quadrature_contacts", "direct_contacts", "sliding_contacts",
                   "escaped"]


def settle(args, path):
    bears = build(args.count, args.dt, args.seed, args.shape)
    dt, newton = O.dt, O.engines[-1]
    if args.settle_dt:
        limit = rm.critical_timestep()
        if not args.settle_dt < limit:
            raise SystemExit(f"--settle-dt {args.settle_dt:g} s is not below rm.critical_timestep() = {limit:g} s")
        O.dt = args.settle_dt
    newton.damping = args.settle_damping
    max_steps = int(round(args.max_time / O.dt))
    mesh = shape_mesh(args.shape)
    nodes = "sphere bodies" if mesh is None else f"{len(mesh.vertices)} nodes each"
    print(f"settling {len(bears)} {args.shape} bodies ({nodes}): until the mean speed is below {args.settled_speed:g} m/s (after {args.min_time:g} s), "
          f"at most {args.max_time:g} s = {max_steps} steps of {O.dt:g} s, NewtonIntegrator damping "
          f"{newton.damping:g}", flush=True)
    rows = []
    reporter = Progress(max_steps, "settling", interval=10.0)
    done, settled, start = 0, False, time.perf_counter()
    while done < max_steps:
        steps = min(SAMPLE, max_steps - done)
        begin = time.perf_counter()
        O.run(steps, True)
        wall = time.perf_counter() - begin
        done += steps
        positions, speeds = kinematics(bears)
        stats = rm.statistics()
        rows.append([O.iter, O.time, wall, wall / steps * 1e3, positions[:, 2].mean(), positions[:, 2].max(),
                     speeds.mean(), speeds.max(), stats["body_pairs"], stats["quadrature_contacts"],
                     stats["direct_contacts"], stats["sliding_contacts"], escaped(positions)])
        write_csv(args.output, rows)  # rewritten every sample, so that a long settling can be followed
        reporter.update(done)
        if done % (10 * SAMPLE) == 0:
            print(f"  t = {O.time:.3f} s: mean height {positions[:, 2].mean():.4f} m, mean speed {speeds.mean():.3g} "
                  f"m/s, max {speeds.max():.3g} m/s, {stats['body_pairs']} body pairs, "
                  f"{stats['quadrature_contacts'] + stats['direct_contacts']} triangle contacts, "
                  f"{wall / steps * 1e3:.1f} ms/step", flush=True)
        if not np.isfinite(positions).all() or not np.isfinite(speeds).all():
            plot_settling(args.output, rows, len(bears), args.shape)
            raise SystemExit(f"settling: non-finite positions or speeds at t = {O.time:g} s; stopped "
                             f"(rows so far in {args.output}/settling.csv)")
        if O.time >= args.min_time and speeds.mean() < args.settled_speed:
            settled = True
            break
    print(f"settling: {'settled' if settled else 'NOT settled (max time reached)'} at t = {O.time:.4f} s "
          f"({O.iter} steps) after {time.perf_counter() - start:.1f} s of wall time; mean speed "
          f"{rows[-1][6]:.3g} m/s, max {rows[-1][7]:.3g} m/s")
    O.tags[TAG] = json.dumps({"settled": settled, "time": O.time, "steps": O.iter, "seed": args.seed,
                              "count": len(bears), "dt": O.dt, "damping": newton.damping, "shape": args.shape,
                              "wall_s": time.perf_counter() - start, "command": args.command})
    O.dt, newton.damping = dt, 0.0  # the benchmark runs S1's step without numerical damping
    O.save(path)
    plot_settling(args.output, rows, len(bears), args.shape)
    print(f"wrote {path}, {args.output}/settling.csv, {args.output}/settling.png")


def write_csv(folder, rows):
    with open(os.path.join(folder, "settling.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(SETTLING_FIELDS)
        writer.writerows(rows)


def plot_settling(folder, rows, count, shape="gummy_bear"):
    if not rows:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    data = np.array(rows, dtype=float)
    column = {name: data[:, k] for k, name in enumerate(SETTLING_FIELDS)}
    t = column["time_s"]
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    top.plot(t, column["mean_height_m"] * 1e3, "k-", label="mean height")
    top.set(ylabel="mean height of the centres [mm]",
            title=f"S1, {count} {'gummy bears' if shape == 'gummy_bear' else shape + ' bodies'} falling into "
                  "a standing box")
    top.grid(alpha=0.3)
    bottom.plot(t, column["ms_per_step"], "C0-", label="wall ms/step")
    bottom.set(xlabel="time [s]", ylabel="wall time per step [ms]")
    other = bottom.twinx()
    other.plot(t, column["quadrature_contacts"] + column["direct_contacts"], "C1-", label="triangle contacts")
    other.plot(t, column["body_pairs"], "C2-", label="body pairs")
    other.set(ylabel="count")
    lines = bottom.get_lines() + other.get_lines()
    bottom.legend(lines, [line.get_label() for line in lines], loc="upper left")
    figure.tight_layout()
    figure.savefig(os.path.join(folder, "settling.png"), dpi=120)
    plt.close(figure)


class TimedContacts:
    """Stands in for the scene state's C++ contacts (_core.SceneContacts), timing its step()."""

    def __init__(self, contacts):
        self.contacts = contacts
        self.seconds = 0.0

    def step(self, omega):
        start = time.perf_counter()
        result = self.contacts.step(omega)
        self.seconds += time.perf_counter() - start
        return result

    def __getattr__(self, name):
        return getattr(self.contacts, name)


def measure(args, path):
    """In this process (its OMP_NUM_THREADS fixed by the caller): block timings on the saved scene, then one
    block with YADE's engine timing and the roundedmesh step wrapped. Prints one RESULT line of JSON."""
    O.load(path)
    threads = ctypes.CDLL("libgomp.so.1").omp_get_max_threads()
    if args.warmup > 0:  # O.run(0) would run for ever
        O.run(args.warmup, True)
    wall, cpu = benchmarking.step_times_ms(args.block_steps, args.blocks)
    stats = rm.statistics()

    # One more block with YADE's per-engine timing, and the Python step and the C++ SceneContacts.step timed.
    state = rm.scene._current_state()
    cxx = TimedContacts(state.contacts)
    state.contacts = cxx
    original_step = rm.scene.step
    python = {"seconds": 0.0}

    def timed_step(**options):
        begin = time.perf_counter()
        original_step(**options)
        python["seconds"] += time.perf_counter() - begin

    rm.scene.step = timed_step
    O.timingEnabled = True
    for e in O.engines:
        e.execTime, e.execCount = 0, 0
    start = time.perf_counter()
    O.run(args.block_steps, True)
    timed_wall = time.perf_counter() - start
    O.timingEnabled = False
    rm.scene.step = original_step
    state.contacts = cxx.contacts
    n = args.block_steps
    split = {}
    for e in O.engines:
        name = "roundedmesh PyRunner" if isinstance(e, PyRunner) else type(e).__name__
        split[name] = e.execTime * 1e-6 / n
    runner = split.get("roundedmesh PyRunner", 0.0)
    split["  C++ SceneContacts.step (read states, contacts, write forces)"] = cxx.seconds * 1e3 / n
    split["  Python scene.step around it"] = (python["seconds"] - cxx.seconds) * 1e3 / n
    split["  PyRunner's own cost"] = runner - python["seconds"] * 1e3 / n
    split["YADE loop, rest"] = timed_wall * 1e3 / n - sum(e.execTime for e in O.engines) * 1e-6 / n
    split["whole step (timed block)"] = timed_wall * 1e3 / n
    positions, speeds = kinematics(bear_ids())
    print(RESULT + json.dumps({"omp_max_threads": threads, "wall_ms": wall, "cpu_ms": cpu, "statistics": stats,
                               "split_ms": split, "mean_height": positions[:, 2].mean(),
                               "mean_speed": speeds.mean(), "max_speed": speeds.max(),
                               "escaped": escaped(positions), "time": O.time}), flush=True)


def describe_settled(path):
    O.load(path)
    ids = bear_ids()
    positions, speeds = kinematics(ids)
    z = positions[:, 2]
    meshes = rm.rounded_bodies()
    volume = meshes[ids[0]].volume if ids[0] in meshes else 4 / 3 * math.pi * RADIUS ** 3
    info = json.loads(O.tags[TAG]) if O.tags.has_key(TAG) else {}
    print(f"\nsettled scene {path}: {len(ids)} {info.get('shape', 'gummy_bear')} bodies, t = {O.time:.4f} s "
          f"({O.iter} steps of "
          f"{info.get('dt', math.nan):g} s, NewtonIntegrator damping {info.get('damping', math.nan):g}; "
          f"{'settled' if info.get('settled') else 'max time reached, not settled'}); benchmark dt = {O.dt:g} s")
    print(f"  mean height {z.mean():.4f} m, median {np.median(z):.4f} m, lowest {z.min():.4f} m, highest "
          f"{z.max():.4f} m; mean speed {speeds.mean():.3g} m/s, max {speeds.max():.3g} m/s; "
          f"{escaped(positions)} outside the box")
    heights = [0.05, 0.10, 0.15, 0.20, 0.25, 0.30]
    print("  packing factor (Eq. 28) P(h) [%]: " +
          ", ".join(f"h={h:.2f} m: {packing_factor(z, volume, h):.1f}" for h in heights))
    print(f"  solid volume {len(ids) * volume * 1e3:.3f} L, a solid layer {len(ids) * volume / (2 * HALF_BASE) ** 2:.4f} m "
          f"thick over the base")
    if ids[0] in meshes:  # the meshes' pairs, one at a time
        pair_analysis(ids)
    return len(ids)


def pair_analysis(ids):
    """Every pair of bears whose bounding spheres overlap, and every bear near a wall, evaluated alone through
    the engine's pipeline (rm.body_contact, rm.plane_contact; one thread): triangle contacts, overlaps and
    the time each pair costs."""
    meshes = rm.rounded_bodies()
    states = [O.bodies[i].state for i in ids]
    positions = np.array([tuple(s.pos) for s in states])
    bounds = np.array([np.linalg.norm(meshes[i].vertices, axis=1).max() for i in ids]) + 0.002  # caps
    pairs, seconds, counts, overlaps = [], [], [], []
    for a in range(len(ids)):
        near = np.nonzero(np.linalg.norm(positions[a + 1:] - positions[a], axis=1) < bounds[a] + bounds[a + 1:])[0]
        for b in near + a + 1:
            s1, s2 = states[a], states[b]
            arguments = (meshes[ids[a]], s1.pos, s1.ori, meshes[ids[b]], s2.pos, s2.ori, PARTICLE, PARTICLE,
                         s1.vel, s1.angVel, s2.vel, s2.angVel)
            start = time.perf_counter()
            rm.body_contact(*arguments)
            seconds.append(time.perf_counter() - start)
            listed = rm.triangle_contacts(*arguments)
            pairs.append((ids[a], ids[b]))
            counts.append(len(listed["triangle1"]))
            overlaps.append(listed["effective_overlap"].max() if counts[-1] else 0.0)
    walls = [(i, w) for w in range(len(ids), len(O.bodies)) for i in ids
             if O.bodies[w] is not None and type(O.bodies[w].shape).__name__ == "Wall"]
    wall_seconds = []
    for i, w in walls:
        shape, state, wall = O.bodies[w].shape, O.bodies[i].state, O.bodies[w].state
        gap = (state.pos[shape.axis] - wall.pos[shape.axis]) * shape.sense
        if gap > bounds[ids.index(i)]:
            continue
        normal = [0.0, 0.0, 0.0]
        normal[shape.axis] = float(shape.sense)
        start = time.perf_counter()
        rm.plane_contact(meshes[i], state.pos, state.ori, wall.pos, tuple(normal), PARTICLE, BOX, state.vel,
                         state.angVel)
        wall_seconds.append(time.perf_counter() - start)
    counts, seconds, overlaps = np.array(counts), np.array(seconds) * 1e3, np.array(overlaps) * 1e3
    touching = counts > 0
    print(f"  bear-bear pairs with overlapping bounding spheres: {len(pairs)}, of which {touching.sum()} in contact "
          f"({touching.sum() * 2 / len(ids):.2f} contacts per bear); {counts.sum()} triangle contacts, "
          f"{counts[touching].mean() if touching.any() else 0:.1f} per touching pair (max {counts.max(initial=0)})")
    if touching.any():
        print(f"  deepest effective overlap per touching pair: median {np.median(overlaps[touching]):.3f} mm, "
              f"max {overlaps.max():.3f} mm ({overlaps.max() / RADIUS / 10:.1f} % of r)")
    print(f"  one call of rm.body_contact per pair: median {np.median(seconds) if len(pairs) else 0:.3f} ms, "
          f"sum over pairs {seconds.sum():.1f} ms (touching {seconds[touching].sum():.1f} ms, not touching "
          f"{seconds[~touching].sum():.1f} ms); bear-wall pairs: {len(wall_seconds)}, sum "
          f"{1e3 * sum(wall_seconds):.1f} ms")
    if len(pairs):
        order = np.argsort(seconds)[::-1][:5]
        print("  costliest bear-bear pairs: " + "; ".join(
            f"{pairs[k][0]}-{pairs[k][1]}: {seconds[k]:.2f} ms, {counts[k]} triangle contacts" for k in order))


def run_measurement(args, path, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    command = [sys.executable, os.path.abspath(__file__), "--measure", "--output", args.output,
               "--blocks", str(args.blocks), "--block-steps", str(args.block_steps), "--warmup", str(args.warmup)]
    print(f"\nmeasuring with OMP_NUM_THREADS={threads}: {args.warmup} steps warm-up, {args.blocks} blocks of "
          f"{args.block_steps} steps, one timed block", flush=True)
    result = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    lines = result.stdout.splitlines()
    found = [line for line in lines if line.startswith(RESULT)]
    if result.returncode != 0 or not found:
        print("\n".join(lines[-30:]))
        raise SystemExit(f"measurement with {threads} thread(s) failed (exit code {result.returncode})")
    return json.loads(found[-1][len(RESULT):])


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default=None,
                        help="folder (default out/bench_shaken_bears, or out/bench_shaken_bears_<shape> for a grain)")
    parser.add_argument("--shape", default="gummy_bear", choices=SHAPES, help="the bodies (module docstring)")
    parser.add_argument("--settle-only", action="store_true",
                        help="settle (or reuse) and describe the packing; no measurement")
    parser.add_argument("--rebuild", action="store_true", help="settle afresh even if settled.yade.gz exists")
    parser.add_argument("--count", type=int, default=250)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--dt", type=float, default=1e-4, help="time step of S1 and of the measurement [s]")
    parser.add_argument("--settle-dt", type=float, default=None,
                        help="a larger time step for settling only (default: --dt) [s]")
    parser.add_argument("--settle-damping", type=float, default=0.0,
                        help="NewtonIntegrator's numerical damping while settling only (default 0, as in S1)")
    parser.add_argument("--max-time", type=float, default=1.5, help="longest settling [s of simulated time]")
    parser.add_argument("--min-time", type=float, default=0.1, help="shortest settling [s]")
    parser.add_argument("--settled-speed", type=float, default=1e-2, help="mean speed of a settled packing [m/s]")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--blocks", type=int, default=5)
    parser.add_argument("--block-steps", type=int, default=200)
    parser.add_argument("--warmup", type=int, default=100)
    parser.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if not 0 < args.count <= 16 * 20:
        parser.error(f"--count must be in 1..320, got {args.count}")
    for name in ("blocks", "block_steps"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')} must be positive")
    if args.warmup < 0 or any(n < 1 for n in args.threads):
        parser.error("--warmup must be >= 0 and --threads positive")
    if args.output is None:
        args.output = os.path.join("out", "bench_shaken_bears" + ("" if args.shape == "gummy_bear" else
                                                                  f"_{args.shape}"))
    os.makedirs(args.output, exist_ok=True)
    path = os.path.join(args.output, "settled.yade.gz")
    if args.measure:
        measure(args, path)
        return

    command = " ".join(shlex.quote(a) for a in [sys.executable] + sys.argv)
    # kept in the saved scene's settling record, for the packing's provenance; the settling's threads with it
    args.command = f"OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS', '')} {command}"
    print(f"machine: {machine()}")
    print(f"command: {command}")
    if args.rebuild or not os.path.exists(path):
        settle(args, path)
    else:
        print(f"reusing {path} (--rebuild to settle afresh)")
    count = describe_settled(path)
    if count != args.count:
        raise SystemExit(f"{path} holds {count} bears, not --count {args.count}: give --rebuild")
    settled_shape = json.loads(O.tags[TAG]).get("shape", "gummy_bear") if O.tags.has_key(TAG) else "gummy_bear"
    if settled_shape != args.shape:
        raise SystemExit(f"{path} holds {settled_shape} bodies, not --shape {args.shape}: give --rebuild")
    if args.settle_only:
        return

    results = {n: run_measurement(args, path, n) for n in args.threads}

    print(f"\nmachine: {machine()}")
    print(f"command: {command}")
    first = results[args.threads[0]]
    s = first["statistics"]
    print(f"settled packing, {count} gummy bears: {s['body_pairs']} body pairs (bounds overlapping, walls "
          f"included), {s['quadrature_contacts'] + s['direct_contacts']} triangle contacts "
          f"({s['quadrature_contacts']} quadrature, {s['direct_contacts']} direct, {s['sliding_contacts']} sliding)")
    print(f"\n{'threads':>7} {'omp':>4} {'wall ms/step':>13} {'min':>8} {'max':>8} {'CPU ms/step':>12}   blocks (wall ms/step)")
    for n, r in results.items():
        print(f"{n:7d} {r['omp_max_threads']:4d} {np.median(r['wall_ms']):13.3f} {min(r['wall_ms']):8.3f} "
              f"{max(r['wall_ms']):8.3f} {np.median(r['cpu_ms']):12.3f}   "
              + " ".join(f"{w:.2f}" for w in r["wall_ms"]))
    names = list(first["split_ms"])
    print(f"\nsplit of one timed block of {args.block_steps} steps [ms/step] (O.timingEnabled; the roundedmesh "
          "PyRunner's time split by timing scene.step and the C++ SceneContacts.step inside it)")
    print(f"{'':58}" + "".join(f"{f'{n} thread(s)':>13}" for n in results))
    for name in names:
        print(f"{name:58}" + "".join(f"{r['split_ms'].get(name, math.nan):13.3f}" for r in results.values()))
    engine_key = "  C++ SceneContacts.step (read states, contacts, write forces)"
    for n, r in results.items():
        split = r["split_ms"]
        print(f"  {n} thread(s): the roundedmesh engine (PyRunner) takes "
              f"{100 * split['roundedmesh PyRunner'] / split['whole step (timed block)']:.1f} % of the step, its C++ "
              f"step {100 * split[engine_key] / split['whole step (timed block)']:.1f} %")

    with open(os.path.join(args.output, "timing.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["threads", "omp_max_threads", "blocks", "block_steps", "median_wall_ms_per_step",
                         "min_wall_ms_per_step", "max_wall_ms_per_step", "median_cpu_ms_per_step", "body_pairs",
                         "quadrature_contacts", "direct_contacts", "sliding_contacts"]
                        + [name.strip() + " [ms/step]" for name in names] + ["machine", "command"])
        for n, r in results.items():
            s = r["statistics"]
            writer.writerow([n, r["omp_max_threads"], args.blocks, args.block_steps, np.median(r["wall_ms"]),
                             min(r["wall_ms"]), max(r["wall_ms"]), np.median(r["cpu_ms"]), s["body_pairs"],
                             s["quadrature_contacts"], s["direct_contacts"], s["sliding_contacts"]]
                            + [r["split_ms"].get(name, math.nan) for name in names] + [machine(), command])
    print(f"\nwrote {args.output}/timing.csv")


if __name__ == "__main__":
    main(sys.argv[1:])
