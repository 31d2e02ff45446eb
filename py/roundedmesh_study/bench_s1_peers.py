"""Whole-step cost of the gummy bear in scene S1 (doc/scenes.md) at the poses of a settled packing, timed in one
process: as roundedmesh's rounded bodies, and as YADE's own representations, clumps of spheres, level-set bodies
and plain spheres of the volume-equivalent radius, each with YADE's Hertz-Mindlin law (roundedmesh_study.peers). The
figures our engine's speed is stated against.

    scripts/benchmarks/bench_s1_peers.py runs it (its docstring has the options).

One process, one thread (the script restarts itself with OMP_NUM_THREADS=1 if that is not set), one
representation after the other: build at the poses (O is reset), run --warmup steps, then time --blocks blocks
(roundedmesh_study.benchmarking.step_times_ms) and one more block with YADE's per-engine timing (O.timingEnabled).
Level sets are opt-in (--peers ... levelset): they cost tens of ms per step. roundedmesh-principal is roundedmesh
with rm.engine(curvature='principal'), the elliptical contact (issue 13).

Blocks last at least --min-block-seconds of CPU time (more steps than --block-steps if need be): O.run(n, True)
returns on YADE's 40 ms polling of the running loop, so a short block's wall time is rounded up by as much
as 40 ms (2 % of a 2 s block). CPU time is not affected, and is the steadier figure on a shared machine.
Clumps and level sets keep the packing of the poses (their contacts at the end are within 10 % of those after
the warm-up); spheres at the bears' centres are no packing and rearrange within a few hundredths of a second,
so theirs is the cost of 250 spheres settling in the box (the contact counts before and after are printed).

--shape: the gummy bear (default) or a study grain of the speed-against-error study (roundedmesh_study.grains.NAMES:
'spheroid', 'pill', 'tetra_grain'), at the poses of its own settled packing, bench/data/s1_settled_<shape>.csv by
default (bench_shaken_bears.py --shape, then record_s1_scene.py). A grain's roundedmesh bodies are
grains.grain(shape).mesh(--nodes), default its reference mesh of grains.REFERENCE_NODES = 600 nodes, the mesh
the packing was settled with; its clumps and level sets are those of roundedmesh_study.peers (an inscribed-sphere
fill and the level set of its 2200-node mesh). Spheres are the volume-equivalent ones, whatever the shape. A
grain's coarse clumps are much smaller than its mesh and start nearly out of touch (the pill's 10-sphere clumps:
27 touching pairs after the warm-up, 839 at the end, against the rounded bodies' 1010), so their cost is that of
the clumps settling again into their own packing; the spheroid's 160-sphere clumps start with up to 286 member
contacts in a pair and blow up within 20 steps (out/sve27_costs, 2026-11-26).

--poses: CSV as scripts/benchmarks/record_s1_scene.py writes it: '#' lines are comments, a header, one row per body: id,
shape (rows whose shape starts with "wall" are the box's and are skipped: the builders make S1's box), and
x,y,z [m], qw,qx,qy,qz (unit quaternion body -> global, principal frame of the shape's reference mesh,
peers.body_frame), vx,vy,vz [m/s], wx,wy,wz [rad/s].

Prints and writes to --output (CSV), per representation: the median wall and CPU ms per step, the real
interactions (YADE's, and the touching body pairs and body-wall pairs they make), the per-engine split, and
the machine and command.
"""
import argparse
import csv
import ctypes
import math
import os
import shlex
import sys
import time

import numpy as np
import roundedmesh as rm
from roundedmesh.progress import Progress
from yade import O

from . import grains, peers
from .benchmarking import machine, step_times_ms

STATE_COLUMNS = ["x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"]
ENGINES = ["ForceResetter", "InsertionSortCollider", "InteractionLoop", "roundedmesh PyRunner", "NewtonIntegrator"]
# rm.statistics()'s stage times: states read from YADE, broad phase, pairs (lists, narrow phase, law), sums,
# forces written to YADE; inside the pairs, with timing='stages', the CPU time of the lists (near searches
# included, and given alone), the narrow phase, the law and the core.
ROUNDEDMESH_STAGES = ["read_ms", "broad_phase_ms", "pairs_ms", "reduction_ms", "write_ms", "lists_cpu_ms",
                      "near_search_cpu_ms", "narrow_phase_cpu_ms", "law_cpu_ms", "core_cpu_ms"]
# What those stages work through per step.
ROUNDEDMESH_COUNTS = ["body_pairs", "touching_pairs", "near_rebuilds", "candidate_rebuilds", "near_pairs_scanned", "candidates",
                      "contacts"]
DATA = os.path.join("bench", "data")  # the settled packings, relative to the repository's root


def default_poses(shape):
    """The settled packing of `shape`: S1's of the bear, s1_settled_<shape>.csv of anything else."""
    return os.path.join(DATA, "s1_settled.csv" if shape == "gummy_bear" else f"s1_settled_{shape}.csv")


def read_poses(path, shape):
    """[(position, quaternion (w, x, y, z), velocity, angular velocity)] of the bodies in the CSV at `path`, in
    the order of their ids."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    id_column = "id"
    missing = [c for c in [id_column] + STATE_COLUMNS if c not in rows[0]]
    if missing:
        raise SystemExit(f"{path}: missing columns {', '.join(missing)}")
    bodies = [r for r in rows if not r.get("shape", shape).startswith("wall")]
    others = {r["shape"] for r in bodies if r.get("shape", shape) != shape}
    if others:
        raise SystemExit(f"{path}: bodies of shape {', '.join(sorted(others))}; this benchmark builds {shape}")
    poses = []
    for row in sorted(bodies, key=lambda r: int(r[id_column])):
        x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz = (float(row[c]) for c in STATE_COLUMNS)
        if abs(math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz) - 1) > 1e-6:
            raise SystemExit(f"{path}: body {row[id_column]} has a quaternion of norm other than 1")
        poses.append(((x, y, z), (qw, qx, qy, qz), (vx, vy, vz), (wx, wy, wz)))
    return poses


def contact_counts(ids):
    """(real interactions, touching body pairs, body-wall pairs): YADE's real interactions, and the distinct
    pairs of bodies (clumps counted once, whatever members touch) and of body and wall that they make. For
    rounded bodies, whose contacts are roundedmesh's: (triangle contacts, touching pairs, -1: walls included)."""
    if rm.rounded_bodies():
        s = rm.statistics()
        return s["quadrature_contacts"] + s["direct_contacts"] + s["exact_contacts"], s["touching_pairs"], -1
    owner = {}
    for body in O.bodies:
        owner[body.id] = body.clumpId if body.isClumpMember else body.id
    particles = set(ids)
    body_pairs, wall_pairs, real = set(), set(), 0
    for interaction in O.interactions:
        if not interaction.isReal:
            continue
        real += 1
        a, b = sorted((owner[interaction.id1], owner[interaction.id2]))
        (body_pairs if a in particles and b in particles else wall_pairs).add((a, b))
    return real, len(body_pairs), len(wall_pairs)


def largest_speed(ids):
    return max(O.bodies[i].state.vel.norm() for i in ids)


def engine_split(steps):
    """Runs `steps` steps with YADE's engine timing on; returns {engine or part: ms per step}. With rounded bodies,
    also the roundedmesh engine's own stages (rm.statistics()) over as many further steps, run one by one."""
    O.timingEnabled = True
    for engine in O.engines:
        engine.execTime, engine.execCount = 0, 0
    start = time.perf_counter()
    O.run(steps, True)
    wall = time.perf_counter() - start
    O.timingEnabled = False
    split = {("roundedmesh PyRunner" if type(engine).__name__ == "PyRunner" else type(engine).__name__):
             engine.execTime * 1e-6 / steps for engine in O.engines}
    split["YADE loop, rest"] = wall * 1e3 / steps - sum(split.values())
    split["whole step (timed block)"] = wall * 1e3 / steps
    if rm.rounded_bodies():
        stages = dict.fromkeys(ROUNDEDMESH_STAGES + ROUNDEDMESH_COUNTS, 0.0)
        runner = next(e for e in O.engines if type(e).__name__ == "PyRunner")
        untimed = runner.command
        runner.command = rm.engine(**{**options_of_scene(), "timing": "stages"}).command
        for _ in range(steps):
            O.step()
            statistics = rm.statistics()
            statistics["contacts"] = sum(statistics[k] for k in ("quadrature_contacts", "direct_contacts",
                                                                 "exact_contacts"))
            for stage in stages:
                stages[stage] += statistics[stage] / steps
        runner.command = untimed
        split.update({f"  roundedmesh {stage}": value for stage, value in stages.items()})
    return split


def options_of_scene():
    """The options of the scene's roundedmesh engine, by name."""
    from roundedmesh._records import _engine_options
    return _engine_options().record()


def measure(name, build, args):
    print(f"\n{name}: building {args.bodies} bodies", flush=True)
    start = time.perf_counter()
    ids = build()
    print(f"{name}: built in {time.perf_counter() - start:.1f} s, {len(O.bodies)} YADE bodies (walls and clump "
          f"members included); {args.warmup} steps warm-up", flush=True)
    start_cpu = time.process_time()
    if args.warmup > 0:  # O.run(0) would run for ever
        O.run(args.warmup, True)
    warmup_ms = (time.process_time() - start_cpu) * 1e3 / max(args.warmup, 1)
    at_start, time_at_start = contact_counts(ids), O.time
    steps = args.block_steps
    if args.warmup > 0:
        steps = max(steps, math.ceil(args.min_block_seconds * 1e3 / warmup_ms))
    print(f"{name}: {warmup_ms:.3f} CPU ms/step in the warm-up; {args.blocks} blocks of {steps} steps and one "
          f"timed block", flush=True)
    reporter = Progress(args.blocks * steps, name, interval=10.0)
    wall, cpu = [], []
    for block in range(args.blocks):
        block_wall, block_cpu = step_times_ms(steps, 1)
        wall += block_wall
        cpu += block_cpu
        reporter.update((block + 1) * steps)
    at_end, simulated = contact_counts(ids), O.time - time_at_start
    split = engine_split(steps)
    result = {"representation": name, "bodies": len(ids), "yade_bodies": len(O.bodies), "steps_per_block": steps,
              "median_wall_ms": float(np.median(wall)), "min_wall_ms": min(wall), "max_wall_ms": max(wall),
              "median_cpu_ms": float(np.median(cpu)),
              "real_interactions": at_end[0], "touching_body_pairs": at_end[1], "body_wall_pairs": at_end[2],
              "real_interactions_after_warmup": at_start[0], "touching_body_pairs_after_warmup": at_start[1],
              "all_interactions": len(O.interactions), "largest_speed": largest_speed(ids),
              "simulated_s": simulated, "split": split}
    print(f"{name}: median {result['median_wall_ms']:.3f} wall ms/step, {result['median_cpu_ms']:.3f} CPU ms/step "
          f"(blocks: {' '.join(f'{w:.3f}' for w in wall)}); {at_end[0]} real interactions ({at_start[0]} after "
          f"the warm-up): {at_end[1]} touching body pairs ({at_start[1]}), {at_end[2]} body-wall pairs; "
          f"{simulated:.3f} s simulated in the blocks; largest speed {result['largest_speed']:.3g} m/s", flush=True)
    return result


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", default=None,
                        help="settled packing (CSV; default bench/data/s1_settled.csv, s1_settled_<shape>.csv for a "
                             "grain)")
    parser.add_argument("--shape", default="gummy_bear",
                        help=f"gummy_bear or a study grain ({', '.join(grains.NAMES)})")
    parser.add_argument("--peers", nargs="+", default=["roundedmesh", "clumps", "spheres"],
                        choices=["roundedmesh", "clumps", "levelset", "spheres", "roundedmesh-principal"])
    parser.add_argument("--nodes", type=int, default=None,
                        help="nodes of the roundedmesh meshes (Mesh.reference_shape or Grain.mesh; default the "
                             "shape's reference mesh)")
    parser.add_argument("--regime", default="auto", choices=("auto", "quadrature", "direct", "exact"),
                        help="roundedmesh's pressure integration (roundedmesh.engine)")
    parser.add_argument("--normal", default="pressure", choices=("pressure", "energy"),
                        help="roundedmesh's normal law (roundedmesh.engine)")
    parser.add_argument("--count", type=int, default=40, help="spheres per clump")
    parser.add_argument("--clump-method", default=None, choices=peers.CLUMP_METHODS,
                        help="how a clump is built (peers.clump_spheres): the shape's primitives or the fill of its "
                             "mesh; default the shape's own (primitives for the bear, the fill for a grain)")
    parser.add_argument("--spacing", type=float, default=1e-3, help="level-set grid spacing [m]")
    parser.add_argument("--surface-nodes", type=int, default=511, help="level-set boundary nodes asked for")
    parser.add_argument("--level-set-verlet", type=float, default=None,
                        help="InsertionSortCollider.verletDist for level sets [m] (default: build_level_sets')")
    parser.add_argument("--warmup", type=int, default=100)
    parser.add_argument("--blocks", type=int, default=5)
    parser.add_argument("--block-steps", type=int, default=200)
    parser.add_argument("--min-block-seconds", type=float, default=2.0,
                        help="least CPU time of a block, from the warm-up's rate [s]")
    parser.add_argument("--output", default="out/bench_s1_peers/peers.csv")
    args = parser.parse_args(argv)
    if args.blocks < 1 or args.block_steps < 1 or args.warmup < 0:
        parser.error("--blocks and --block-steps must be positive, --warmup >= 0")
    if args.poses is None:
        args.poses = default_poses(args.shape)
    default_nodes = grains.REFERENCE_NODES if args.shape in grains.NAMES else "the default"

    command = " ".join(shlex.quote(a) for a in ["OMP_NUM_THREADS=1", sys.executable] + sys.argv)
    threads = ctypes.CDLL("libgomp.so.1").omp_get_max_threads()
    print(f"machine: {machine()}")
    print(f"command: {command}")
    poses = read_poses(args.poses, args.shape)
    args.bodies = len(poses)
    betan = peers.mindlin_betan()
    print(f"{len(poses)} {args.shape} poses from {args.poses}; OpenMP threads {threads}; dt = {peers.TIME_STEP:g} s; "
          f"Hertz-Mindlin betan {betan['bear-bear']:.3f} bear-bear, {betan['bear-wall']:.3f} bear-wall (Eq. 7's "
          f"damping ratio at {betan['bear-bear overlap'] * 1e3:.3f} / {betan['bear-wall overlap'] * 1e3:.3f} mm)")
    level_set_options = {} if args.level_set_verlet is None else {"verlet_distance": args.level_set_verlet}
    builders = {
        "roundedmesh": (f"roundedmesh, {args.shape} meshes of {args.nodes or default_nodes} nodes, "
                        f"regime {args.regime}, normal {args.normal}",
                        lambda: peers.build_rounded(poses, args.shape, args.nodes, regime=args.regime,
                                                    normal=args.normal)),
        "roundedmesh-principal": (f"roundedmesh, principal curvatures, regime {args.regime}",
                                  lambda: peers.build_rounded(poses, args.shape, args.nodes, regime=args.regime,
                                                              curvature="principal")),
        "clumps": (f"clumps of {args.count} spheres", lambda: peers.build_clumps(poses, args.count, args.shape,
                                                                                 method=args.clump_method)),
        "levelset": (f"level sets ({args.surface_nodes} rays, grid {args.spacing * 1e3:g} mm)",
                     lambda: peers.build_level_sets(poses, args.shape, args.spacing, args.surface_nodes,
                                                    **level_set_options)),
        "spheres": ("spheres of radius r", lambda: peers.build_spheres(poses)),
    }
    results = []
    for key in args.peers:
        results.append(measure(*builders[key], args))
        results[-1]["key"] = key

    print(f"\nmachine: {machine()}")
    print(f"command: {command}")
    print(f"\n{'representation':44} {'wall ms/step':>13} {'CPU ms/step':>12} {'real inter.':>12} "
          f"{'body pairs':>11} {'body-wall':>10}")
    for r in results:
        print(f"{r['representation']:44} {r['median_wall_ms']:13.3f} {r['median_cpu_ms']:12.3f} "
              f"{r['real_interactions']:12d} {r['touching_body_pairs']:11d} {r['body_wall_pairs']:10d}")
    parts = ENGINES + ["YADE loop, rest", "whole step (timed block)"] + [f"  roundedmesh {stage}" for stage in
                                                                        ROUNDEDMESH_STAGES + ROUNDEDMESH_COUNTS]
    print("\nsplit of one timed block [ms/step] (O.timingEnabled; the roundedmesh counts per step)")
    print(f"{'':32}" + "".join(f"{r['key']:>12}" for r in results))
    for part in parts:
        print(f"{part:32}" + "".join(f"{r['split'].get(part, math.nan):12.3f}" for r in results))

    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    fields = [k for k in results[0] if k not in ("split", "key")]
    with open(args.output, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(fields + [f"{part} [ms/step]" for part in parts] + ["threads", "poses", "machine", "command"])
        for r in results:
            writer.writerow([r[k] for k in fields] + [r["split"].get(part, math.nan) for part in parts]
                            + [threads, args.poses, machine(), command])
    print(f"\nwrote {args.output}")
