"""Speed against error, the cost axis (issue 14; doc/speed-vs-error.md): milliseconds per step of scene S1's settled
packing of 250 gummy bears (bench/data/s1_settled.csv, doc/scenes.md) for each configuration of the error study
that scripts/studies/speed_vs_error.py measures for the gummy bear, timed by one harness,
scripts/benchmarks/bench_s1_peers.py, one configuration after the other, each in its own process on one thread.

    /usr/bin/python3 scripts/studies/speed_vs_error_costs.py [--quick] [--output out/speed_vs_error]

Configurations: roundedmesh meshes of 300 to 2200 nodes in the 'auto', 'quadrature' and 'direct' regimes (the
150-node mesh is left out: at the packing's poses 134 of its pairs start overlapped past a tenth of r_eq, its
scaled-up coarse triangles bulging into the neighbours, so it would time an explosion, not a packing); YADE's
clumps of 10, 20, 40 and 80 spheres; level-set bodies at the study's grid spacings and node counts. Curvature
prescribed or computed does not change the work of a step (the same triangle pairs are tested), so the computed
meshes' cost stands for both.

Writes costs.csv (configuration as errors.csv names it, size, median wall and CPU ms per step, contacts after the
warm-up, machine) and prints it. CPU time is the figure to compare on a shared machine (bench_s1_peers.py).
--quick: one configuration per family, a short warm-up and one block (a smoke test, not a measurement).
"""
import argparse
import csv
import importlib.util
import os
import subprocess
import sys

from roundedmesh.export import write_csv

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, os.pardir)
_spec = importlib.util.spec_from_file_location("speed_vs_error", os.path.join(HERE, "speed_vs_error.py"))
_errors = importlib.util.module_from_spec(_spec)   # the error axis's script, for its level sets
_spec.loader.exec_module(_errors)
LEVEL_SETS = _errors.LEVEL_SETS

POSES = os.path.join(SCRIPTS, os.pardir, "bench", "data", "s1_settled.csv")   # from any working folder
NODES = (300, 554, 1100, 2200)
REGIMES = ("auto", "quadrature", "direct")
CLUMPS = (10, 20, 40, 80)


def configurations(quick):
    """[(configuration, size, bench_s1_peers arguments)], named as errors.csv names them."""
    result = []
    for regime in REGIMES[:1] if quick else REGIMES:
        for nodes in NODES[:1] if quick else NODES:
            result.append((f"curvature computed, {regime}", nodes,
                           ["--peers", "roundedmesh", "--nodes", str(nodes), "--regime", regime]))
    for count in CLUMPS[:1] if quick else CLUMPS:
        result.append(("clump", count, ["--peers", "clumps", "--count", str(count)]))
    for spacing, nodes in LEVEL_SETS[:1] if quick else LEVEL_SETS:
        result.append((f"level set, grid {spacing * 1e3:g} mm", nodes,
                       ["--peers", "levelset", "--spacing", repr(spacing), "--surface-nodes", str(nodes)]))
    return result


def measure(arguments, output, quick):
    """The row bench_s1_peers.py writes for one configuration."""
    timing = ["--warmup", "5", "--blocks", "1", "--block-steps", "5", "--min-block-seconds", "0"] if quick else []
    path = os.path.join(output, "bench.csv")
    subprocess.run([sys.executable, os.path.join(SCRIPTS, "benchmarks", "bench_s1_peers.py"), *arguments, *timing,
                    "--poses", POSES, "--output", path], check=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
    with open(path, newline="") as f:
        return next(csv.DictReader(f))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="one configuration per family, one short block")
    parser.add_argument("--output", default=os.path.join("out", "speed_vs_error"))
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    header = ["configuration", "size", "median_wall_ms", "median_cpu_ms", "contacts", "machine"]
    rows = []
    for configuration, size, arguments in configurations(args.quick):
        row = measure(arguments, args.output, args.quick)
        rows.append([configuration, size, row["median_wall_ms"], row["median_cpu_ms"],
                     row["real_interactions_after_warmup"], row["machine"]])
        print(f"cost: {configuration}, {size}: {float(row['median_cpu_ms']):.2f} CPU ms/step", flush=True)
    write_csv(os.path.join(args.output, "costs.csv"), header, rows)


if __name__ == "__main__":
    main()
