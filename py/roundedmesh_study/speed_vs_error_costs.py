"""Speed against error, the cost axis (issue 14; doc/speed-vs-error.md): milliseconds per step of scene S1's settled
packing of 250 gummy bears (bench/data/s1_settled.csv, doc/scenes.md) for each configuration of the error study
that scripts/studies/speed_vs_error.py measures for the gummy bear, timed by one harness,
scripts/benchmarks/bench_s1_peers.py, one configuration after the other, each in its own process on one thread.

    /usr/bin/python3 scripts/studies/speed_vs_error_costs.py [--quick] [--output out/speed_vs_error]
        [--shapes gummy_bear [spheroid pill tetra_grain]] [--poses-folder bench/data]

Configurations of the gummy bear: roundedmesh meshes of 300 to 2200 nodes in the 'auto', 'quadrature' and 'direct'
regimes (the 150-node mesh is left out: at the packing's poses 134 of its pairs start overlapped past a tenth of
r_eq, its scaled-up coarse triangles bulging into the neighbours, so it would time an explosion, not a packing);
YADE's clumps of 10, 20, 40 and 80 spheres; level-set bodies at the study's grid spacings and node counts.
Curvature prescribed or computed does not change the work of a step (the same triangle pairs are tested), so the
computed meshes' cost stands for both.

--shapes: the shapes to time, the gummy bear (default) and the study grains (roundedmesh_study.grains.NAMES), each
at its own settled packing of 250 bodies, <poses folder>/s1_settled.csv for the bear and s1_settled_<shape>.csv for
a grain (scripts/benchmarks/record_s1_scene.py). A grain has roundedmesh meshes of 300, 600, 1100 and 2200 nodes in
the 'auto' regime only (the bear's regimes differ in cost by less than one run's noise), clumps of 10 to 160
spheres and the bear's level sets.

Writes costs.csv (shape, configuration as errors.csv names it, size, median wall and CPU ms per step, contacts
after the warm-up, machine), rewritten after every configuration so that a long run can be followed, and prints
it. CPU time is the figure to compare on a shared machine (bench_s1_peers.py). A configuration that blows up
(blown_up: the packing's bodies fly apart, and the blocks time a few bodies in flight, not a packing) is left out
of costs.csv and written with its reason to left_out.csv; one whose run fails is left out too, named at the end,
and makes the exit status 1.
--quick: one configuration per family, a short warm-up and one block (a smoke test, not a measurement).
"""
import argparse
import csv
import os
import subprocess
import sys

from roundedmesh.export import write_csv

from . import SCRIPTS, grains
from .speed_vs_error import LEVEL_SETS

POSES_FOLDER = os.path.join(SCRIPTS, os.pardir, "bench", "data")   # the settled packings, from any working folder
SHAPES = ("gummy_bear",) + grains.NAMES
# Per shape: roundedmesh node counts (the error study's, MESH_NODES of speed_vs_error.py, less 150), regimes and
# clump sphere counts (its CLUMP_COUNTS).
NODES = {"gummy_bear": (300, 554, 1100, 2200), **{g: (300, grains.REFERENCE_NODES, 1100, 2200) for g in grains.NAMES}}
REGIMES = {"gummy_bear": ("auto", "quadrature", "direct", "exact"), **{g: ("auto",) for g in grains.NAMES}}
# The law's other options, timed on the bear in regime 'auto': (label suffix, bench_s1_peers arguments).
LAW_OPTIONS = {"gummy_bear": ((", principal", ["--peers", "roundedmesh-principal"]),
                              (", energy", ["--peers", "roundedmesh", "--normal", "energy"])),
               **{g: () for g in grains.NAMES}}
CLUMPS = {"gummy_bear": (10, 20, 40, 80), **{g: (10, 20, 40, 80, 160) for g in grains.NAMES}}
# The bear's clumps of its primitives, and the fill of its mesh a user would make (a grain's only clump).
FILLED_CLUMPS = {"gummy_bear": (10, 20, 40, 80, 160), **{g: () for g in grains.NAMES}}
# A settled packing's fastest body moves at about 0.1 m/s (bodies rattling, bench_shaken_bears.py's settling log);
# ten times that at the end of the blocks is no packing any more: the grains' 160-sphere clumps reached 2e25 m/s.
BLOWN_UP_SPEED = 1.0   # [m/s]


def blown_up(row):
    """Why the configuration of bench_s1_peers.py's `row` (its CSV row, strings) timed no packing, or None: a body
    faster than BLOWN_UP_SPEED at the end of the blocks (or not finite), or fewer than half the touching body pairs
    of the end of the warm-up left at the end."""
    speed = float(row["largest_speed"])
    before, after = int(row["touching_body_pairs_after_warmup"]), int(row["touching_body_pairs"])
    if not speed <= BLOWN_UP_SPEED:
        return (f"blew up: largest speed {speed:.3g} m/s at the end, touching body pairs {before} after the warm-up, "
                f"{after} at the end")
    if after < before / 2:
        return f"blew up: touching body pairs {before} after the warm-up, {after} at the end"
    return None


def poses_path(shape, folder=POSES_FOLDER):
    """The settled packing of `shape` in `folder`: s1_settled.csv for the bear, s1_settled_<shape>.csv else."""
    return os.path.join(folder, "s1_settled.csv" if shape == "gummy_bear" else f"s1_settled_{shape}.csv")


def configurations(quick, shape="gummy_bear"):
    """[(configuration, size, bench_s1_peers arguments)] of `shape`, named as errors.csv names them."""
    result = []
    nodes_list, regimes, clumps = NODES[shape], REGIMES[shape], CLUMPS[shape]
    for regime in regimes[:1] if quick else regimes:
        for nodes in nodes_list[:1] if quick else nodes_list:
            result.append((f"curvature computed, {regime}", nodes,
                           ["--peers", "roundedmesh", "--nodes", str(nodes), "--regime", regime]))
    for suffix, arguments in () if quick else LAW_OPTIONS[shape]:
        for nodes in nodes_list:
            result.append((f"curvature computed, auto{suffix}", nodes, [*arguments, "--nodes", str(nodes)]))
    for count in clumps[:1] if quick else clumps:
        result.append(("clump", count, ["--peers", "clumps", "--count", str(count)]))
    for count in () if quick else FILLED_CLUMPS[shape]:
        result.append(("clump, sphere fill", count, ["--peers", "clumps", "--count", str(count),
                                                     "--clump-method", "fill"]))
    for spacing, nodes in LEVEL_SETS[:1] if quick else LEVEL_SETS:
        result.append((f"level set, grid {spacing * 1e3:g} mm", nodes,
                       ["--peers", "levelset", "--spacing", repr(spacing), "--surface-nodes", str(nodes)]))
    return [(configuration, size, ["--shape", shape, *arguments]) for configuration, size, arguments in result]


# bench_s1_peers.py's timing: --quick a smoke test; --short 350 steps a configuration (a third of the default's),
# what the whole study's 37 bear and 39 grain configurations take in an hour.
TIMINGS = {"quick": ["--warmup", "5", "--blocks", "1", "--block-steps", "5", "--min-block-seconds", "0"],
           "short": ["--warmup", "50", "--blocks", "3", "--block-steps", "100", "--min-block-seconds", "0"],
           "default": []}


def measure(arguments, output, timing, poses):
    """The row bench_s1_peers.py writes for one configuration at the packing `poses` (CSV) with `timing` (a key of
    TIMINGS); None if it failed."""
    timing = TIMINGS[timing]
    path = os.path.join(output, "bench.csv")
    if os.path.exists(path):
        os.remove(path)  # a failed run must not leave the previous configuration's row to be read
    run = subprocess.run([sys.executable, os.path.join(SCRIPTS, "benchmarks", "bench_s1_peers.py"), *arguments,
                          *timing, "--poses", poses, "--output", path], env={**os.environ, "OMP_NUM_THREADS": "1"})
    if run.returncode != 0 or not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return next(csv.DictReader(f))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="one configuration per family, one short block")
    parser.add_argument("--short", action="store_true",
                        help="50 steps of warm-up and 3 blocks of 100 (TIMINGS), not bench_s1_peers.py's defaults")
    parser.add_argument("--output", default=os.path.join("out", "speed_vs_error"))
    parser.add_argument("--shapes", nargs="+", default=["gummy_bear"], choices=SHAPES,
                        help="shapes to time, each at its own settled packing (default: the gummy bear)")
    parser.add_argument("--poses-folder", default=POSES_FOLDER,
                        help="folder of the settled packings, s1_settled.csv and s1_settled_<grain>.csv")
    args = parser.parse_args(argv)
    missing = [poses_path(shape, args.poses_folder) for shape in args.shapes
               if not os.path.exists(poses_path(shape, args.poses_folder))]
    if missing:
        parser.error(f"no settled packing {', '.join(missing)}: scripts/benchmarks/record_s1_scene.py writes it")
    os.makedirs(args.output, exist_ok=True)
    if os.path.exists(os.path.join(args.output, "left_out.csv")):
        os.remove(os.path.join(args.output, "left_out.csv"))  # an earlier run's, which this one replaces
    header = ["shape", "configuration", "size", "median_wall_ms", "median_cpu_ms", "contacts", "machine"]
    rows, failed, left_out = [], [], []
    for shape in args.shapes:
        for configuration, size, arguments in configurations(args.quick, shape):
            row = measure(arguments, args.output, "quick" if args.quick else "short" if args.short else "default",
                          poses_path(shape, args.poses_folder))
            if row is None:
                failed.append(f"{shape}, {configuration}, {size}")
                print(f"cost: {shape}, {configuration}, {size}: FAILED, left out", flush=True)
                continue
            reason = blown_up(row)
            if reason:
                left_out.append([shape, configuration, size, row["median_cpu_ms"], reason])
                write_csv(os.path.join(args.output, "left_out.csv"),
                          ["shape", "configuration", "size", "median_cpu_ms", "reason"], left_out)
                print(f"cost: {shape}, {configuration}, {size}: left out, {reason}", flush=True)
                continue
            rows.append([shape, configuration, size, row["median_wall_ms"], row["median_cpu_ms"],
                         row["real_interactions_after_warmup"], row["machine"]])
            write_csv(os.path.join(args.output, "costs.csv"), header, rows)
            print(f"cost: {shape}, {configuration}, {size}: {float(row['median_cpu_ms']):.2f} CPU ms/step", flush=True)
    write_csv(os.path.join(args.output, "costs.csv"), header, rows)
    if failed:
        raise SystemExit(f"{len(failed)} configuration(s) failed and are left out of costs.csv: {'; '.join(failed)}")
