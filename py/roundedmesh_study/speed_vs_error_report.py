"""Speed against error, the report (issues 14 and 27; doc/speed-vs-error.md): the error axis (errors.csv of
scripts/studies/speed_vs_error.py) joined with the cost axis (costs.csv of scripts/studies/speed_vs_error_costs.py)
for every shape of the study, the Pareto front of error against cost where a shape has costs, and which
configuration is the cheapest for a target error.

    /usr/bin/python3 scripts/studies/speed_vs_error_report.py [--input out/speed_vs_error]
        [--costs PATH [PATH ...]] [--output out/speed_vs_error] [--package-data]

Error of a configuration: the NRMSE of its force against Hertz [%], the worse of its two partners (pressed on the
plane, pressed on a copy), taken over the poses as the median (the headline: what a typical contact of a scene
sees, not swayed by the few poses at the edge of a small feature) or as the worst pose (shown beside it: what the
worst contact sees). roundedmesh configurations are named as speed_vs_error.py's variant_label names them,
'curvature <computed|prescribed>, <regime>[, principal][, energy]': the mesh's curvature, the law's regime, its
curvature ('mean' unless 'principal', Hertz's ellipse) and its normal ('pressure' unless 'energy').

Cost: CPU ms per step of S1's settled packing of 250 bodies of the shape, one thread, measured for the gummy bear
and, where timed, the grains (costs.csv rows without a 'shape' column are the gummy bear's; --costs merges several
files, a later file's row replacing an earlier one's). roundedmesh costs are timed for 'curvature computed,
<regime>' only; a configuration carries the cost of the one it stands for (timed_as, named in cost_from): prescribed
curvature costs what the computed mesh of the same nodes costs (the same triangle pairs are tested), and a regime or
law option not timed for that shape costs what 'curvature computed, auto' of the same nodes costs (the options
change the work per triangle pair, not which pairs are tested; the approximation is named wherever it is used).
Configurations without a cost (the 150-node bear, which starts S1 overlapped past a tenth of r_eq) are in the table,
not in the plot, and not offered as the cheapest. A shape without any cost is ranked by nodes (or spheres), then by
the regime cheaper on S1 (regimes_by_cost). A missing costs file is named and the report goes on without it.

Writes to --output:
    pareto_<shape>.csv   per shape with costs, one row per configuration: errors per partner and statistic, cost
                         and where it comes from, on the front
    pareto_<shape>.md    the same table in markdown
    pareto_<shape>.png   error [%] against CPU ms per step, log-log, median (left) and worst pose (right), colour by
                         family, marker by roundedmesh variant, the Pareto front as a step line, its points labelled
    guide.md             per shape with costs: for 1 %, 5 %, 20 % the cheapest configuration overall and per family
                         and the ratios of the cheapest roundedmesh to the cheapest clump and level set at 5 %; per
                         shape without: the fewest-node roundedmesh meeting each target and the best clump and level
                         set
    guide_summary.md     one row per shape: the cheapest (without costs the fewest-node) roundedmesh at 1, 5 and 20 %
                         and the cheapest clump and level set at 5 % (median pose)
    speed_vs_error.json  every roundedmesh configuration of every shape with its errors (fractions) and cost, and the
                         resolution of each mesh (roundedmesh.model_choice.mesh_resolution): the study's data;
                         --package-data also writes it to py/roundedmesh_study/ (roundedmesh_study.model_table) and
                         the table rm.cheapest_model reads, made from it, to py/roundedmesh/model_table.json
"""
import argparse
import csv
import json
import os
import shutil
import sys

from roundedmesh.export import write_csv

from . import model_table
from .model_table import variant_label
from .speed_vs_error import FAMILIES, SHAPES


COSTED_BY_DEFAULT = "gummy_bear"               # the shape of costs.csv rows without a 'shape' column
VARIANT = ("curvature", "regime", "law_curvature", "normal")   # a roundedmesh configuration's options
TIMED = variant_label("computed", "auto", "mean", "pressure")  # the roundedmesh configuration timed for every shape
STATISTICS = ("median", "worst")               # over the poses; the headline first
PARTNERS = ("plane", "self")
TARGETS = (1.0, 5.0, 20.0)                     # NRMSE [%] the guide answers for
COMPARED_AT = 5.0                              # the comparison's target [%]
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


def read_costs(paths):
    """{(shape, configuration, size): (CPU ms per step, wall ms per step)} merged from the costs.csv files `paths`
    (a row without a 'shape' column is the gummy bear's; a later file replaces an earlier one's row), and
    {shape: the machines its rows name}. A missing file is named on stderr and skipped: the report then ranks
    that file's shapes by nodes."""
    costs, machines = {}, {}
    for path in paths:
        if not os.path.exists(path):
            print(f"no costs file {path}: its shapes get no S1 cost, no Pareto plot, and are ranked by nodes "
                  "(scripts/studies/speed_vs_error_costs.py writes it)", file=sys.stderr)
            continue
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                shape = row.get("shape") or COSTED_BY_DEFAULT
                costs[(shape, row["configuration"], int(row["size"]))] = (float(row["median_cpu_ms"]),
                                                                         float(row["median_wall_ms"]))
                machines.setdefault(shape, set()).add(row["machine"])
    return costs, machines


def parse_configuration(configuration):
    """(curvature, regime, law_curvature, normal) of a roundedmesh label of speed_vs_error.py's variant_label:
    'curvature prescribed, auto, principal' -> ('prescribed', 'auto', 'principal', 'pressure'). Raises ValueError
    for a label variant_label does not write, rather than filing an unknown variant under a known one."""
    head, *rest = configuration.split(", ")
    variant = (head.removeprefix("curvature "), rest[0] if rest else "",
               "principal" if "principal" in rest[1:] else "mean", "energy" if "energy" in rest[1:] else "pressure")
    if not rest or variant_label(*variant) != configuration:
        raise ValueError(f"configuration {configuration!r} is not a roundedmesh label of speed_vs_error.py "
                         "('curvature <computed|prescribed>, <regime>[, principal][, energy]')")
    return variant


def timed_as(family, configuration, timed):
    """The configuration whose S1 cost stands for `configuration`, of those `timed` (the shape's configurations
    with a cost at its size); None if none. A configuration timed itself is its own; a roundedmesh one not timed
    costs as the computed mesh of the same options (prescribed curvature tests the same triangle pairs), else as
    TIMED, 'curvature computed, auto' (a regime or law option not timed for the shape)."""
    if configuration in timed:
        return configuration
    if family != "roundedmesh":
        return None
    return next((c for c in (computed_twin(parse_configuration(configuration)), TIMED) if c in timed), None)


def computed_twin(variant):
    """The label of a roundedmesh variant with computed curvature and the same regime and law options."""
    return variant_label("computed", *variant[1:])


def error_of(partners, statistic):
    """The configuration's error [%] for a pose statistic: the worse of plane and copy (None if one is missing)."""
    values = [partners.get((partner, statistic)) for partner in PARTNERS]
    return None if None in values else max(values)


def table(errors, costs):
    """One dict per configuration of errors.csv: shape, family, configuration, size, partners, error per statistic
    (worse partner) [%], variant (the roundedmesh options, None for the other families), cost_from (the
    configuration whose cost it carries, None: no cost), cpu_ms and wall_ms [ms per step] (None: no cost), and rank
    (None until ranked, see rank_rows)."""
    rows = []
    for (shape, family, configuration, size), partners in errors.items():
        timed = {c for (s, c, n) in costs if (s, n) == (shape, size)}
        cost_from = timed_as(family, configuration, timed)
        cpu, wall = costs.get((shape, cost_from, size), (None, None))
        rows.append({"shape": shape, "family": family, "configuration": configuration, "size": size,
                     "partners": partners, "error": {s: error_of(partners, s) for s in STATISTICS},
                     "variant": parse_configuration(configuration) if family == "roundedmesh" else None,
                     "cost_from": cost_from, "cpu_ms": cpu, "wall_ms": wall, "rank": None})
    return rows


def by_shape(rows):
    """{shape: its rows}, the shapes in the study's order (speed_vs_error.SHAPES), unknown ones after."""
    shapes = sorted({r["shape"] for r in rows}, key=lambda s: (SHAPES.index(s) if s in SHAPES else len(SHAPES), s))
    return {shape: [r for r in rows if r["shape"] == shape] for shape in shapes}


def has_costs(rows):
    """Whether any of a shape's rows has an S1 cost: then it is ranked by cost, else by size."""
    return any(r["cpu_ms"] is not None for r in rows)


def regimes_by_cost(rows):
    """The regimes of the roundedmesh rows, cheapest on S1 first: each regime's cost measured for itself ('curvature
    computed, <regime>') summed over the (shape, nodes) timed in every measured regime; regimes never measured
    last, by name. The order ranks the regimes of a shape without costs."""
    measured = [r for r in rows if r["variant"] is not None and r["cost_from"] == r["configuration"]
                and r["variant"][0] == "computed"]
    timed = {}
    for r in measured:
        timed.setdefault(r["variant"][1], set()).add((r["shape"], r["size"]))
    common = set.intersection(*timed.values()) if timed else set()

    def cost(regime):
        values = [r["cpu_ms"] for r in measured if r["variant"][1] == regime and (r["shape"], r["size"]) in common]
        return sum(values) if values else float("inf")
    return sorted({r["variant"][1] for r in rows if r["variant"] is not None}, key=lambda g: (cost(g), g))


def rank_rows(rows, regimes):
    """Sets each row's rank, the key 'cheapest' orders by (smaller is cheaper): where the shape has costs its CPU ms
    per step (None, not offered, for a row without a cost); else its size (nodes or spheres), then its regime's
    place in `regimes` (regimes_by_cost)."""
    for shape_rows in by_shape(rows).values():
        costed = has_costs(shape_rows)
        for r in shape_rows:
            if costed:
                r["rank"] = None if r["cpu_ms"] is None else (r["cpu_ms"],)
            else:
                r["rank"] = (r["size"], 0 if r["variant"] is None else regimes.index(r["variant"][1]))


def offered(rows, statistic, family=None):
    """The rows of `family` (all if None) with a rank and an error for `statistic`."""
    return [r for r in rows if r["rank"] is not None and r["error"][statistic] is not None
            and family in (None, r["family"])]


def cheapest(rows, target, statistic, family=None):
    """The offered row of lowest rank whose error meets `target` [%], of `family` if given; None if no row does.
    Equal ranks (prescribed and computed curvature, law options costed as 'auto') go to the smaller error."""
    meeting = [r for r in offered(rows, statistic, family) if r["error"][statistic] <= target]
    return min(meeting, key=lambda r: (r["rank"], r["error"][statistic]), default=None)


def most_accurate(rows, statistic, family):
    """The offered row of `family` with the smallest error (the best it reaches), the cheaper of equals."""
    return min(offered(rows, statistic, family), key=lambda r: (r["error"][statistic], r["rank"]), default=None)


def packing(shape):
    """'gummy bears': the bodies of the shape's S1 packing, for the plots' and guide's text."""
    return shape.replace("_", " ") + "s"


def label(row):
    """'roundedmesh, curvature computed, direct, 1100 nodes'; 'clump of 40 spheres'; 'YADE sphere'; 'level set,
    grid 1 mm, 2047 nodes'."""
    if row["family"] == "roundedmesh":
        return f"roundedmesh, {row['configuration']}, {row['size']} nodes"
    if row["family"] == "clumps":
        return "YADE sphere" if row["configuration"] == "sphere" else f"clump of {row['size']} spheres"
    return f"{row['configuration']}, {row['size']} nodes"


def cost_note(row):
    """Where a row's cost comes from: 'measured', "as 'curvature computed, auto'" or 'no S1 cost'."""
    if row["cost_from"] is None:
        return "no S1 cost"
    return "measured" if row["cost_from"] == row["configuration"] else f"as '{row['cost_from']}'"


def write_table(rows, fronts, path):
    """pareto_<shape>.csv, and the same table as markdown beside it (.md)."""
    header = (["family", "configuration", "nodes or spheres"]
              + [f"{p} NRMSE {s} [%]" for s in STATISTICS for p in ("plane", "copy")]
              + [f"NRMSE {s}, worse partner [%]" for s in STATISTICS]
              + ["CPU ms per step", "wall ms per step", "cost"]
              + [f"on the front ({s})" for s in STATISTICS])
    lines = []
    for r in sorted(rows, key=lambda r: (FAMILIES.index(r["family"]), r["configuration"], r["size"])):
        lines.append([r["family"], r["configuration"], r["size"]]
                     + [r["partners"].get((p, s), "") for s in STATISTICS for p in PARTNERS]
                     + [r["error"][s] for s in STATISTICS]
                     + ["" if r["cpu_ms"] is None else f"{r['cpu_ms']:.3f}",
                        "" if r["wall_ms"] is None else f"{r['wall_ms']:.3f}", cost_note(r)]
                     + ["yes" if r in fronts[s] else "" for s in STATISTICS])
    write_csv(path, header, lines)
    with open(os.path.splitext(path)[0] + ".md", "w") as f:
        f.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for line in lines:
            f.write("| " + " | ".join(f"{v:.3g}" if isinstance(v, float) else str(v) for v in line) + " |\n")


def pareto_front(rows, statistic):
    """The rows with a cost that no cheaper (or equally cheap) row matches in error, by increasing cost."""
    front, best = [], float("inf")
    for row in sorted((r for r in rows if r["cpu_ms"] is not None and r["error"][statistic] is not None),
                      key=lambda r: (r["cpu_ms"], r["error"][statistic])):
        if row["error"][statistic] < best:
            front.append(row)
            best = row["error"][statistic]
    return front


REGIME_MARKERS = {"auto": "^", "quadrature": "v", "direct": "D", "exact": "P"}
LAW_COLOURS = {("mean", "pressure"): "tab:blue", ("principal", "pressure"): "tab:purple",
               ("mean", "energy"): "tab:cyan", ("principal", "energy"): "tab:pink"}


def style(row):
    """(colour, marker, filled) of a row: clumps orange circles, level sets green squares; a roundedmesh variant's
    marker by regime, colour by the law's curvature and normal (blue the defaults), hollow for prescribed
    curvature, so that every variant of VARIANTS reads apart."""
    if row["family"] == "clumps":
        return "tab:orange", "o", True
    if row["family"] == "level_sets":
        return "tab:green", "s", True
    curvature, regime, law_curvature, normal = row["variant"]
    return (LAW_COLOURS.get((law_curvature, normal), "black"), REGIME_MARKERS.get(regime, "x"),
            curvature == "computed")


def legend_name(row):
    """The plot legend's entry of a row: its family, or for roundedmesh its configuration."""
    return {"clumps": "clumps", "level_sets": "level sets"}.get(row["family"], f"roundedmesh, {row['configuration']}")


def plot(shape, rows, fronts, path):
    """pareto_<shape>.png: one panel per pose statistic."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    timed = [r for r in rows if r["cpu_ms"] is not None]
    figure, axes = plt.subplots(1, len(STATISTICS), figsize=(14, 7), sharey=True)
    for axis, statistic in zip(axes, STATISTICS):
        seen = set()
        for r in sorted(timed, key=legend_name):
            if r["error"][statistic] is None:
                continue
            colour, marker, filled = style(r)
            name = legend_name(r)
            axis.plot(r["cpu_ms"], r["error"][statistic], marker, color=colour, markersize=7, alpha=0.8,
                      markerfacecolor=colour if filled else "none", label=None if name in seen else name,
                      linestyle="none")
            seen.add(name)
        front = fronts[statistic]
        if front:
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
        axis.set_xlabel(f"CPU ms per step, S1 packing of 250 {packing(shape)}, one thread")
        axis.set_title(f"{shape.replace('_', ' ')}: NRMSE, {statistic} pose, worse of plane and copy")
        axis.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("NRMSE of the force against the reference (Hertz or half-space) [%]")
    entries = {}                                 # one legend below both panels, off the points
    for axis in axes:
        entries.update(zip(*reversed(axis.get_legend_handles_labels())))
    figure.legend(list(entries.values()), list(entries), fontsize=7, loc="lower center", ncol=4)
    figure.tight_layout(rect=(0, 0.14, 1, 1))
    figure.savefig(path, dpi=120)
    plt.close(figure)


def describe(row, statistic):
    """'clump of 40 spheres: 15.6 % (worst 15.6 %), 11.1 ms'; without a cost the error only."""
    other = [s for s in STATISTICS if s != statistic][0]
    cost = "" if row["cpu_ms"] is None else f", {row['cpu_ms']:.3g} ms"
    other_error = "n/a" if row["error"][other] is None else f"{row['error'][other]:.3g} %"
    return f"{label(row)}: {row['error'][statistic]:.3g} % ({other} {other_error}){cost}"


def answer(rows, target, statistic, family):
    """A guide's cell: the cheapest row of `family` meeting `target`, else 'none (best: X %)', or 'none in the
    study' where the family has no offered row."""
    row = cheapest(rows, target, statistic, family)
    if row is not None:
        return describe(row, statistic)
    best = most_accurate(rows, statistic, family)
    return "none in the study" if best is None else f"none (best: {best['error'][statistic]:.3g} %)"


def comparison(rows, statistic, target):
    """Sentences: the cheapest roundedmesh at `target` against the cheapest clump and level set, as cost ratios."""
    ours = cheapest(rows, target, statistic, "roundedmesh")
    if ours is None:
        return [f"No roundedmesh configuration reaches {target:g} % ({statistic} pose)."]
    sentences = [f"Cheapest roundedmesh at {target:g} % ({statistic} pose): {describe(ours, statistic)}."]
    for family, name in (("clumps", "clump"), ("level_sets", "level set")):
        theirs = cheapest(rows, target, statistic, family)
        if theirs is None:
            best = most_accurate(rows, statistic, family)
            sentences.append(f"No {name} in the study." if best is None else
                             f"No {name} reaches {target:g} %; the best it reaches is {describe(best, statistic)}, "
                             f"and roundedmesh / that = {ours['cpu_ms'] / best['cpu_ms']:.2f}.")
        else:
            ratio = ours["cpu_ms"] / theirs["cpu_ms"]
            sentences.append(f"Cheapest {name}: {describe(theirs, statistic)}; roundedmesh / {name} = {ratio:.2f} "
                             f"({'slower' if ratio > 1 else 'faster'}: {max(ratio, 1 / ratio):.2f} times).")
    return sentences


def markdown_table(header, lines):
    """Markdown lines of a table with `header` and rows `lines` (lists of cells)."""
    return (["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
            + ["| " + " | ".join(cells) + " |" for cells in lines])


def costed_guide(shape, rows, machines):
    """The guide's section of a shape with S1 costs: per pose statistic the cheapest configuration overall and per
    family at each target and the comparison at COMPARED_AT; then the same comparison on the copy alone."""
    untimed = sorted({r["configuration"] for r in rows if r["variant"] is not None
                      and r["cost_from"] not in (None, computed_twin(r["variant"]))})
    lines = [f"## {shape.replace('_', ' ')} (ranked by S1 cost)", "",
             f"Cost: CPU ms per step of S1's settled packing of 250 {packing(shape)}, one thread "
             f"({'; '.join(sorted(machines))}). Prescribed curvature costs as computed"
             + (f"; not timed, costed as '{TIMED}' of their nodes: {'; '.join(untimed)}" if untimed else "") + ".",
             ""]
    for statistic in STATISTICS:
        lines += [f"### {statistic.capitalize()} pose", ""]
        lines += markdown_table(["target", "cheapest overall", "roundedmesh", "clumps", "level sets"],
                                [[f"{target:g} %"] + [answer(rows, target, statistic, family)
                                                      for family in (None,) + FAMILIES] for target in TARGETS])
        lines += ["", *comparison(rows, statistic, COMPARED_AT), ""]
    copy_only = [dict(r, error={s: r["partners"].get(("self", s)) for s in STATISTICS}) for r in rows]
    lines += [f"### {shape.replace('_', ' ')} on {shape.replace('_', ' ')} only (copy partner, median pose)", "",
              "Most contacts of S1 are between bodies; against YADE's Wall a clump's sphere gets R* = r/2 where a "
              "plane has r, so clumps are judged here on the copy alone.", "",
              *comparison(copy_only, "median", COMPARED_AT), ""]
    return lines


def uncosted_guide(shape, rows):
    """The guide's section of a shape without S1 costs: the fewest-node roundedmesh meeting each target (median
    pose) and the best error a clump and a level set reach."""
    lines = [f"## {shape.replace('_', ' ')} (no S1 cost: ranked by nodes)", ""]
    lines += markdown_table(["target", "roundedmesh, fewest nodes (median pose)"],
                            [[f"{target:g} %", answer(rows, target, "median", "roundedmesh")] for target in TARGETS])
    lines.append("")
    for family, name in (("clumps", "clump"), ("level_sets", "level set")):
        best = most_accurate(rows, "median", family)
        lines.append(f"Best {name}: " + ("none in the study." if best is None else describe(best, "median") + "."))
    return lines + [""]


def guide(shapes, machines):
    """guide.md: which model does my scene need, shape by shape."""
    lines = ["# Which model does my scene need", "",
             "Error: NRMSE of the force against Hertz, the worse of plane and copy; median over the poses "
             "(headline), worst pose beside it. Shapes with S1 costs: the cheapest configuration; shapes without: "
             "the fewest nodes (then the regime cheaper on S1).", ""]
    for shape, rows in shapes.items():
        lines += costed_guide(shape, rows, machines.get(shape, ())) if has_costs(rows) else uncosted_guide(shape, rows)
    return "\n".join(lines)


def summary(shapes):
    """guide_summary.md: one row per shape, median pose, worse partner (the README's table)."""
    lines = ["# Which model does my scene need: the summary", "",
             "Median pose, the worse of plane and copy. Ranked by the CPU ms per step of the shape's S1 packing "
             "where it has costs, else by nodes (spheres); 'none (best: X %)': the family does not meet the target.",
             ""]
    lines += markdown_table(
        ["shape", "ranked by"] + [f"roundedmesh at {t:g} %" for t in TARGETS]
        + [f"clump at {COMPARED_AT:g} %", f"level set at {COMPARED_AT:g} %"],
        [[shape.replace("_", " "), "S1 cost" if has_costs(rows) else "nodes"]
         + [answer(rows, t, "median", "roundedmesh") for t in TARGETS]
         + [answer(rows, COMPARED_AT, "median", family) for family in ("clumps", "level_sets")]
         for shape, rows in shapes.items()])
    return "\n".join(lines) + "\n"


def fraction(percent):
    """An error [%] as a fraction to 6 significant digits; None stays None."""
    return None if percent is None else float(f"{percent / 100:.6g}")


def resolutions(shapes):
    """{shape: {str(N): {'median': q, 'worst': q}}}: model_choice.mesh_resolution of the study's mesh of N nodes
    (shape_error.rounded_mesh, computed curvature) for every roundedmesh node count of the shape."""
    from roundedmesh.model_choice import mesh_resolution
    import roundedmesh_study.shape_error as se
    result = {}
    for shape, rows in shapes.items():
        for nodes in sorted({r["size"] for r in rows if r["family"] == "roundedmesh"}):
            quality = mesh_resolution(se.rounded_mesh(shape, nodes).mesh)
            result.setdefault(shape, {})[str(nodes)] = {s: float(f"{quality[s]:.6g}") for s in STATISTICS}
    return result


def package_data(shapes, regimes, machines):
    """The helper's data (module docstring; speed_vs_error.json): every roundedmesh configuration of every shape,
    errors as fractions per statistic and partner ('both' the worse), cost or None and the configuration it is
    the cost of, and the resolution of each mesh."""
    entries = {}
    for shape, rows in shapes.items():
        for r in sorted((r for r in rows if r["family"] == "roundedmesh"), key=lambda r: (r["size"], r["variant"])):
            entries.setdefault(shape, []).append({
                "nodes": r["size"], **dict(zip(VARIANT, r["variant"])),
                "nrmse": {s: {**{p: fraction(r["partners"].get((p, s))) for p in PARTNERS},
                              "both": fraction(r["error"][s])} for s in STATISTICS},
                "cost_ms_per_step": None if r["cpu_ms"] is None else round(r["cpu_ms"], 3),
                "cost_from": r["cost_from"]})
    return {"study": STUDY,
            "error": "NRMSE of the force against Hertz over overlaps up to 2 % of r = 25 mm, pressed on a plane "
                     "('plane') and on a copy ('self'), 'both' the worse of the two, median or worst over the "
                     "poses; a fraction; null: not measured",
            "cost": "CPU ms per step of S1's settled packing of 250 bodies of the shape, one thread; cost_from: the "
                    "configuration timed (prescribed curvature costs as computed; a regime or law option not timed "
                    "for the shape as 'curvature computed, auto'); null: not timed",
            "machine": "; ".join(sorted(set().union(*machines.values()))) or None, "regimes_by_cost": regimes,
            "shapes": entries, "resolution": resolutions(shapes)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--input", default=os.path.join("out", "speed_vs_error"),
                        help="folder with errors.csv (and costs.csv, the default of --costs)")
    parser.add_argument("--costs", nargs="+", metavar="PATH",
                        help="costs.csv files to merge, a later file's row replacing an earlier one's "
                             "(default: <input>/costs.csv)")
    parser.add_argument("--output", default=os.path.join("out", "speed_vs_error"))
    parser.add_argument("--package-data", action="store_true",
                        help="also write py/roundedmesh_study/speed_vs_error.json, the study's data, and "
                             "py/roundedmesh/model_table.json, the table rm.cheapest_model reads")
    args = parser.parse_args(argv)
    errors_path = os.path.join(args.input, "errors.csv")
    if not os.path.exists(errors_path):
        parser.error(f"no {errors_path}: scripts/studies/speed_vs_error.py writes it")
    costs, machines = read_costs(args.costs or [os.path.join(args.input, "costs.csv")])
    rows = table(read_errors(errors_path), costs)
    regimes = regimes_by_cost(rows)
    rank_rows(rows, regimes)
    shapes = by_shape(rows)
    os.makedirs(args.output, exist_ok=True)
    for shape, shape_rows in shapes.items():
        if has_costs(shape_rows):
            fronts = {s: pareto_front(shape_rows, s) for s in STATISTICS}
            write_table(shape_rows, fronts, os.path.join(args.output, f"pareto_{shape}.csv"))
            plot(shape, shape_rows, fronts, os.path.join(args.output, f"pareto_{shape}.png"))
    text, short = guide(shapes, machines), summary(shapes)
    for name, content in (("guide.md", text), ("guide_summary.md", short)):
        with open(os.path.join(args.output, name), "w") as f:
            f.write(content)
    data = package_data(shapes, regimes, machines)
    path = os.path.join(args.output, "speed_vs_error.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    if args.package_data:
        shutil.copyfile(path, model_table.DATA)
        model_table.write_model_table(data=data)
    print(text)
    print(short)
