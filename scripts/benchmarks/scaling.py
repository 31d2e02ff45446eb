"""How the contact step's cost grows with the number of bodies and of contact primitives (the paper's Section 3.4,
Fig. 12), one thread: runs build/bench/roundedmesh_scaling_bench (or reads its JSON) and writes a CSV, the table of
doc/scaling.md and two plots.

    /usr/bin/python3 scripts/benchmarks/scaling.py [--bench build/bench/roundedmesh_scaling_bench]
                                                    [--json out/scaling/scaling.json] [--output out/scaling]

Scenes (bench/scaling.cpp): lattices of perfect spheres and of 12- to 642-node icospheres, 216 to 8,000 bodies, at
rest and rattling; the settled S1 packing of gummy bears tiled 1 to 32 times (250 to 8,000 bears), settled and
shaking. Stages per step: the broad phase (the neighbour sweep), the triangle-pair lists (a moving scene's pairs
stage less the same scene's at rest: the lists rebuilt as bodies move) and the resolution (the pairs stage at rest:
the narrow phase and the law over lists that stay valid).

Writes <output>/scaling.csv (one row per scene: shape, bodies, primitives, motion, ms per step, broad phase and pairs
ms, ns per body-step, contacts, engine bytes per body, mesh bytes), <output>/scaling_primitives.png (Fig. 12's axes:
broad phase, lists and resolution against N_prim) and <output>/scaling_bodies.png (cost per body-step against the
number of bodies), and prints the markdown table with the machine.
"""
import argparse
import csv
import json
import os
import platform
import shlex
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
COLUMNS = ["shape", "bodies", "primitives", "motion", "threads", "ms_per_step", "broad_ms", "pairs_ms", "ns_per_body_step",
           "contacts", "body_pairs", "engine_bytes_per_body", "mesh_bytes"]


def machine():
    model = platform.processor() or "unknown processor"
    try:
        with open("/proc/cpuinfo") as info:
            model = next(line.split(":", 1)[1].strip() for line in info if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{model}, {os.cpu_count()} cores"


def rows_from(report):
    """One row per benchmark (the median when repeated) from Google Benchmark's JSON."""
    rows = {}
    for run in report["benchmarks"]:
        if run.get("run_type") == "aggregate" and run.get("aggregate_name") != "median":
            continue
        name = run["run_name"] if "run_name" in run else run["name"]
        label = run.get("label", "")
        shape, _, motion = label.rpartition(", ")
        rows[name] = {
            "shape": shape, "bodies": int(run["bodies"]), "primitives": int(run["primitives"]), "motion": motion,
            "threads": int(run.get("threads", 1)),
            "ms_per_step": run["real_time"], "broad_ms": run["broad_ms"], "pairs_ms": run["pairs_ms"],
            "ns_per_body_step": run["ns_per_body_step"], "contacts": run["contacts"], "body_pairs": run["body_pairs"],
            "engine_bytes_per_body": run["engine_bytes_per_body"], "mesh_bytes": run["mesh_bytes"]}
    return list(rows.values())


def plot(rows, output):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    shapes = list(dict.fromkeys(row["shape"] for row in rows))
    moving = {"rattling", "shaking"}
    at_rest = {(row["shape"], row["bodies"]): row for row in rows if row["motion"] not in moving}
    figure, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for shape in shapes:
        series = sorted((row for row in rows if row["shape"] == shape and row["motion"] in moving),
                        key=lambda row: row["primitives"])
        x = [row["primitives"] for row in series]
        axes[0].loglog(x, [row["broad_ms"] for row in series], "o-", label=shape)
        if shape != "spheres":  # a sphere body has no triangle-pair lists
            axes[1].loglog(x, [row["pairs_ms"] - at_rest[(shape, row["bodies"])]["pairs_ms"] for row in series],
                           "o-", label=shape)
        axes[2].loglog(x, [at_rest[(shape, row["bodies"])]["pairs_ms"] for row in series], "o-", label=shape)
    for axis, title in zip(axes, ["broad phase (neighbour sweep)", "triangle-pair lists (moving less at rest)",
                                  "resolution (narrow phase and law, at rest)"]):
        axis.set_xlabel("contact primitives N_prim (triangles, or spheres)")
        axis.set_ylabel("ms per step, one thread")
        axis.set_title(title, fontsize=10)
        axis.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(output, "scaling_primitives.png"), dpi=120)
    figure, axis = plt.subplots(figsize=(7, 4.5))
    for shape in shapes:
        for motion, style in (("at rest", "o--"), ("settled", "o--"), ("rattling", "s-"), ("shaking", "s-")):
            series = sorted((row for row in rows if row["shape"] == shape and row["motion"] == motion),
                            key=lambda row: row["bodies"])
            if series:
                base = series[0]["ns_per_body_step"]
                axis.semilogx([row["bodies"] for row in series], [row["ns_per_body_step"] / base for row in series],
                              style, label=f"{shape}, {motion}")
    axis.set_xlabel("bodies")
    axis.set_ylabel("cost per body-step / at the fewest bodies")
    axis.axhline(1.3, color="grey", lw=0.8, ls=":")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=7, ncol=2)
    figure.tight_layout()
    figure.savefig(os.path.join(output, "scaling_bodies.png"), dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "roundedmesh_scaling_bench"))
    parser.add_argument("--json", help="read this output of the benchmark instead of running it")
    parser.add_argument("--output", default=os.path.join("out", "scaling"))
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    if args.json:
        with open(args.json) as source:
            report = json.load(source)
    else:
        if not os.path.isfile(args.bench):
            raise SystemExit(f"scaling.py: {args.bench} is missing: build it with "
                             "cmake --build build --target roundedmesh_scaling_bench")
        result = subprocess.run([args.bench, "--benchmark_format=json"], capture_output=True, text=True,
                                env={**os.environ, "OMP_NUM_THREADS": "1"})
        if result.returncode:
            raise SystemExit(f"scaling.py: the benchmark failed:\n{result.stderr[-2000:]}")
        report = json.loads(result.stdout)
        with open(os.path.join(args.output, "scaling.json"), "w") as copy:
            copy.write(result.stdout)
    rows = rows_from(report)
    one_thread = [row for row in rows if row["threads"] == 1]
    with open(os.path.join(args.output, "scaling.csv"), "w", newline="") as table:
        table.write(f"# {machine()}; {shlex.join([sys.executable] + sys.argv)}\n")
        writer = csv.DictWriter(table, COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    plot(one_thread, args.output)
    print(f"Machine: {machine()}\n")
    print("| shape | motion | threads | bodies | N_prim | ms/step | broad phase ms | pairs ms | ns per body-step | contacts |"
          " engine KB per body |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        print(f"| {row['shape']} | {row['motion']} | {row['threads']} | {row['bodies']:,} | {row['primitives']:,} | "
              f"{row['ms_per_step']:.3g} | {row['broad_ms']:.3g} | {row['pairs_ms']:.3g} | "
              f"{row['ns_per_body_step']:,.0f} | {row['contacts']:,.0f} | {row['engine_bytes_per_body'] / 1e3:.1f} |")
    print(f"\nWrote {os.path.join(args.output, 'scaling.csv')}, scaling_primitives.png and scaling_bodies.png")


if __name__ == "__main__":
    main()
