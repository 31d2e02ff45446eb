"""Speed against error, the report (issue 14; doc/speed-vs-error.md): the error axis (errors.csv of
scripts/studies/speed_vs_error.py) joined with the cost axis (costs.csv of scripts/studies/speed_vs_error_costs.py) for
the gummy bear, the Pareto front of error against cost, and which configuration is the cheapest for a target error.

    /usr/bin/python3 scripts/studies/speed_vs_error_report.py [--input out/speed_vs_error]
                                                              [--output out/speed_vs_error] [--package-data]

Error of a configuration: the NRMSE of its force against Hertz [%], the worse of its two partners (pressed on the
plane, pressed on a copy), taken over the poses as the median (the headline: what a typical contact of a scene
sees, not swayed by the few poses at the edge of a small feature) or as the worst pose (shown beside it: what the
worst contact sees). Cost: CPU ms per step of S1's settled packing of 250 gummy bears, one thread. A roundedmesh
mesh with prescribed curvature costs what the computed one of the same nodes and regime costs (the same triangle
pairs are tested; speed_vs_error_costs.py). Configurations without a cost (the 150-node bear, not timed because it
starts S1 overlapped past a tenth of r_eq) are in the table, not in the plot: a point needs both axes.

Writes to --output:
    pareto.csv          one row per gummy-bear configuration: errors per partner and statistic, cost, on the front
    pareto.md           the same table in markdown
    pareto.png          error [%] against CPU ms per step, log-log, median (left) and worst pose (right), one marker
                        per configuration, the Pareto front as a step line, its points labelled
    guide.md            for 1 %, 5 %, 20 %: the cheapest configuration overall and per family, its cost; the ratio
                        of the cheapest roundedmesh to the cheapest clump and level set at 5 %
    speed_vs_error.json every roundedmesh configuration of every shape with its errors (fractions) and cost: the data
                        of roundedmesh.study.model_choice; --package-data also writes it to
                        py/roundedmesh/study/, where the helper reads it
"""
import argparse
import csv
import json
import os
import shutil
import sys

from roundedmesh.export import write_csv

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)  # the repository
SHAPE = "gummy_bear"                           # the shape S1 packs: the one with costs
FAMILIES = ("roundedmesh", "clumps", "level_sets")
STATISTICS = ("median", "worst")               # over the poses; the headline first
PARTNERS = ("plane", "self")
TARGETS = (1.0, 5.0, 20.0)                     # NRMSE [%] the guide answers for
COMPARED_AT = 5.0                              # the closing note's target [%]
NO_FORCE = 53.1                                # NRMSE [%] of a representation with no force within 0.5 mm
STUDY = ("doc/speed-vs-error.md; scripts/studies/speed_vs_error.py (errors), "
         "scripts/studies/speed_vs_error_costs.py (S1 costs), "
         "scripts/studies/speed_vs_error_report.py (the report and this data)")


def read_errors(path):
    """{(shape, family, configuration, size): {(partner, statistic): NRMSE [%]}} from errors.csv."""
    errors = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = (row["shape"], row["family"], row["configuration"], int(row["nodes or spheres"]))
            for statistic in STATISTICS:
                value = row[f"NRMSE {statistic} [%]"]
                if value:
                    errors.setdefault(key, {})[(row["partner"], statistic)] = float(value)
    return errors


def read_costs(path):
    """{(configuration, size): (CPU ms per step, wall ms per step)} from costs.csv, and the machine it names."""
    costs, machines = {}, set()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            costs[(row["configuration"], int(row["size"]))] = (float(row["median_cpu_ms"]),
                                                              float(row["median_wall_ms"]))
            machines.add(row["machine"])
    return costs, "; ".join(sorted(machines))


def timed_as(configuration):
    """The configuration whose S1 cost stands for `configuration`: prescribed curvature costs as computed."""
    return configuration.replace("curvature prescribed", "curvature computed")


def error_of(partners, statistic):
    """The configuration's error [%] for a pose statistic: the worse of plane and copy (None if one is missing)."""
    values = [partners.get((partner, statistic)) for partner in PARTNERS]
    return None if None in values else max(values)


def table(errors, costs, shape):
    """One dict per configuration of `shape`: family, configuration, size, errors, cost [ms] (None: not timed)."""
    rows = []
    for (name, family, configuration, size), partners in errors.items():
        if name != shape:
            continue
        cpu, wall = costs.get((timed_as(configuration), size), (None, None))
        rows.append({"family": family, "configuration": configuration, "size": size, "partners": partners,
                     "error": {s: error_of(partners, s) for s in STATISTICS}, "cpu_ms": cpu, "wall_ms": wall})
    return rows


def pareto_front(rows, statistic):
    """The rows with a cost that no cheaper (or equally cheap) row matches in error, by increasing cost."""
    front, best = [], float("inf")
    for row in sorted((r for r in rows if r["cpu_ms"] is not None and r["error"][statistic] is not None),
                      key=lambda r: (r["cpu_ms"], r["error"][statistic])):
        if row["error"][statistic] < best:
            front.append(row)
            best = row["error"][statistic]
    return front


def cheapest(rows, target, statistic, family=None):
    """The row with the lowest cost whose error meets `target` [%], of `family` if given; None if no row does.
    Equal costs (prescribed and computed curvature) go to the smaller error."""
    meeting = [r for r in rows if r["cpu_ms"] is not None and r["error"][statistic] is not None
               and r["error"][statistic] <= target and family in (None, r["family"])]
    return min(meeting, key=lambda r: (r["cpu_ms"], r["error"][statistic]), default=None)


def most_accurate(rows, statistic, family):
    """The row of `family` with a cost and the smallest error (the best it reaches)."""
    timed = [r for r in rows if r["cpu_ms"] is not None and r["family"] == family]
    return min(timed, key=lambda r: (r["error"][statistic], r["cpu_ms"]), default=None)


def label(row):
    """'roundedmesh, curvature computed, direct, 1100 nodes'; 'clumps, 40 spheres'; 'level set, grid 1 mm, 2047
    nodes'."""
    if row["family"] == "roundedmesh":
        return f"roundedmesh, {row['configuration']}, {row['size']} nodes"
    if row["family"] == "clumps":
        return f"clump of {row['size']} spheres"
    return f"{row['configuration']}, {row['size']} nodes"


def write_table(rows, fronts, path):
    """pareto.csv, and the same table as markdown beside it (pareto.md)."""
    header = (["family", "configuration", "nodes or spheres"]
              + [f"{p} NRMSE {s} [%]" for s in STATISTICS for p in ("plane", "copy")]
              + [f"NRMSE {s}, worse partner [%]" for s in STATISTICS]
              + ["CPU ms per step", "wall ms per step", "cost"]
              + [f"on the front ({s})" for s in STATISTICS])
    lines = []
    for r in sorted(rows, key=lambda r: (FAMILIES.index(r["family"]), r["configuration"], r["size"])):
        cost = ("no S1 cost" if r["cpu_ms"] is None else
                "measured" if timed_as(r["configuration"]) == r["configuration"] else
                f"as '{timed_as(r['configuration'])}'")
        lines.append([r["family"], r["configuration"], r["size"]]
                     + [r["partners"].get((p, s), "") for s in STATISTICS for p in PARTNERS]
                     + [r["error"][s] for s in STATISTICS]
                     + ["" if r["cpu_ms"] is None else f"{r['cpu_ms']:.3f}",
                        "" if r["wall_ms"] is None else f"{r['wall_ms']:.3f}", cost]
                     + ["yes" if r in fronts[s] else "" for s in STATISTICS])
    write_csv(path, header, lines)
    with open(os.path.splitext(path)[0] + ".md", "w") as f:
        f.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for line in lines:
            f.write("| " + " | ".join(f"{v:.3g}" if isinstance(v, float) else str(v) for v in line) + " |\n")


def style(row):
    """(colour, marker) of a row: colour by family, marker by roundedmesh variant."""
    if row["family"] == "clumps":
        return "tab:orange", "o"
    if row["family"] == "level_sets":
        return "tab:green", "s"
    markers = {"curvature computed, auto": "^", "curvature computed, quadrature": "v",
               "curvature computed, direct": "D", "curvature prescribed, auto": "*"}
    return "tab:blue", markers.get(row["configuration"], "x")


def plot(rows, fronts, path):
    """pareto.png: one panel per pose statistic."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    timed = [r for r in rows if r["cpu_ms"] is not None]
    figure, axes = plt.subplots(1, len(STATISTICS), figsize=(14, 6), sharey=True)
    for axis, statistic in zip(axes, STATISTICS):
        seen = set()
        for r in timed:
            colour, marker = style(r)
            name = "clumps" if r["family"] == "clumps" else "level sets" if r["family"] == "level_sets" else \
                f"roundedmesh, {r['configuration']}"
            axis.plot(r["cpu_ms"], r["error"][statistic], marker, color=colour, markersize=9 if marker == "*" else 7,
                      alpha=0.8, label=None if name in seen else name, linestyle="none")
            seen.add(name)
        front = fronts[statistic]
        xs = [r["cpu_ms"] for r in front] + [max(r["cpu_ms"] for r in timed) * 1.3]
        ys = [r["error"][statistic] for r in front] + [front[-1]["error"][statistic]]
        axis.step(xs, ys, where="post", color="black", linewidth=1, label="Pareto front")
        for r in front:
            axis.annotate(label(r).replace("roundedmesh, curvature ", "").replace(", ", " "),
                          (r["cpu_ms"], r["error"][statistic]), textcoords="offset points", xytext=(6, 4),
                          fontsize=7)
        axis.axhline(NO_FORCE, color="grey", linestyle=":", linewidth=1, label="no force within 0.5 mm (53.1 %)")
        for target in TARGETS:
            axis.axhline(target, color="grey", linestyle="--", linewidth=0.5)
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("CPU ms per step, S1 (250 gummy bears, one thread)")
        axis.set_title(f"gummy bear: NRMSE, {statistic} pose, worse of plane and copy")
        axis.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("NRMSE of the force against Hertz [%]")
    axes[0].legend(fontsize=7, loc="lower left")
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def describe(row, statistic):
    """'clump of 40 spheres: 15.6 % (worst 15.6 %), 11.1 ms'."""
    other = [s for s in STATISTICS if s != statistic][0]
    return (f"{label(row)}: {row['error'][statistic]:.3g} % ({other} {row['error'][other]:.3g} %), "
            f"{row['cpu_ms']:.3g} ms")


def comparison(rows, statistic, target):
    """Sentences: the cheapest roundedmesh at `target` against the cheapest clump and level set, as ratios."""
    ours = cheapest(rows, target, statistic, "roundedmesh")
    if ours is None:
        return [f"No roundedmesh configuration reaches {target:g} % ({statistic} pose)."]
    sentences = [f"Cheapest roundedmesh at {target:g} % ({statistic} pose): {describe(ours, statistic)}."]
    for family, name in (("clumps", "clump"), ("level_sets", "level set")):
        theirs = cheapest(rows, target, statistic, family)
        if theirs is None:
            best = most_accurate(rows, statistic, family)
            reach = "" if best is None else (f"; the best it reaches is {describe(best, statistic)}, and roundedmesh "
                                             f"/ that = {ours['cpu_ms'] / best['cpu_ms']:.2f}")
            sentences.append(f"No {name} reaches {target:g} %{reach}.")
        else:
            ratio = ours["cpu_ms"] / theirs["cpu_ms"]
            sentences.append(f"Cheapest {name}: {describe(theirs, statistic)}; roundedmesh / {name} = {ratio:.2f} "
                             f"({'slower' if ratio > 1 else 'faster'}: {max(ratio, 1 / ratio):.2f} times).")
    return sentences


def guide(rows, machine):
    """guide.md: which model does my scene need."""
    lines = ["# Which model does my scene need (gummy bear, S1)", "",
             "Error: NRMSE of the force against Hertz, the worse of plane and copy; median over the poses "
             "(headline), worst pose beside it. Cost: CPU ms per step of S1's settled packing of 250 gummy bears, "
             f"one thread ({machine}).", ""]
    for statistic in STATISTICS:
        lines += [f"## {statistic.capitalize()} pose", "",
                  "| target | cheapest overall | roundedmesh | clumps | level sets |", "|---|---|---|---|---|"]
        for target in TARGETS:
            cells = [f"{target:g} %"]
            for family in (None,) + FAMILIES:
                row = cheapest(rows, target, statistic, family)
                cells.append("none" if row is None else describe(row, statistic))
            lines.append("| " + " | ".join(cells) + " |")
        lines += ["", *comparison(rows, statistic, COMPARED_AT), ""]
    copy_only = [dict(r, error={s: r["partners"].get(("self", s)) for s in STATISTICS}) for r in rows]
    lines += ["## Bear on bear only (copy partner, median pose)", "",
              "Most contacts of S1 are between bears; against YADE's Wall a clump's sphere gets R* = r/2 where a "
              "plane has r (15.6 % on the plane at every clump size), so clumps are judged here on the copy alone.",
              "",
              *comparison(copy_only, "median", COMPARED_AT), ""]
    return "\n".join(lines)


def package_data(errors, costs, machine):
    """The helper's data: every roundedmesh configuration of every shape, errors as fractions, cost or None."""
    shapes = {}
    for (shape, family, configuration, size), partners in errors.items():
        if family != "roundedmesh":
            continue
        curvature, regime = configuration.replace("curvature ", "").split(", ")
        cost = costs.get((timed_as(configuration), size)) if shape == SHAPE else None   # S1 packs bears only
        entry = {"nodes": size, "curvature": curvature, "regime": regime,
                 "cost_ms_per_step": None if cost is None else round(cost[0], 3)}
        for statistic in STATISTICS:
            error = error_of(partners, statistic)
            entry[f"nrmse_{statistic}"] = None if error is None else float(f"{error / 100:.6g}")
        shapes.setdefault(shape, []).append(entry)
    regimes = sorted({e["regime"] for entries in shapes.values() for e in entries},
                     key=lambda regime: regime_cost(shapes, regime))
    return {"study": STUDY,
            "error": "NRMSE of the force against Hertz over overlaps up to 2 % of r = 25 mm, the worse of plane "
                     "and copy, median or worst over the poses; a fraction",
            "cost": "CPU ms per step of S1's settled packing of 250 gummy bears, one thread; null: not timed",
            "machine": machine, "regimes_by_cost": regimes, "shapes": shapes}


def regime_cost(shapes, regime):
    """A regime's S1 cost summed over the node counts timed in every regime (inf if none): its rank among regimes
    for shapes without costs."""
    timed = [e for entries in shapes.values() for e in entries
             if e["cost_ms_per_step"] is not None and e["curvature"] == "computed"]
    regimes = {e["regime"] for e in timed}
    common = set.intersection(*({e["nodes"] for e in timed if e["regime"] == r} for r in regimes)) if timed else set()
    costs = [e["cost_ms_per_step"] for e in timed if e["regime"] == regime and e["nodes"] in common]
    return sum(costs) if costs else float("inf")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--input", default=os.path.join("out", "speed_vs_error"),
                        help="folder with errors.csv and costs.csv")
    parser.add_argument("--output", default=os.path.join("out", "speed_vs_error"))
    parser.add_argument("--package-data", action="store_true",
                        help="also write py/roundedmesh/study/speed_vs_error.json, the data "
                             "roundedmesh.study.model_choice reads")
    args = parser.parse_args(argv)
    errors = read_errors(os.path.join(args.input, "errors.csv"))
    costs, machine = read_costs(os.path.join(args.input, "costs.csv"))
    rows = table(errors, costs, SHAPE)
    fronts = {s: pareto_front(rows, s) for s in STATISTICS}
    os.makedirs(args.output, exist_ok=True)
    write_table(rows, fronts, os.path.join(args.output, "pareto.csv"))
    plot(rows, fronts, os.path.join(args.output, "pareto.png"))
    text = guide(rows, machine)
    with open(os.path.join(args.output, "guide.md"), "w") as f:
        f.write(text)
    data = os.path.join(args.output, "speed_vs_error.json")
    with open(data, "w") as f:
        json.dump(package_data(errors, costs, machine), f, indent=1)
        f.write("\n")
    if args.package_data:
        shutil.copyfile(data, os.path.join(ROOT, "py", "roundedmesh", "study", "speed_vs_error.json"))
    print(text)


if __name__ == "__main__":
    sys.exit(main())
