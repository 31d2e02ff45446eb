"""Speed against error, the error axis (issue 14; doc/speed-vs-error.md): every representation of the sphere, the
pear and the gummy bear pressed on a rigid plane and on a copy of itself at random orientations, force against
overlap up to 2 % of r = 25 mm, against Hertz's solution at the smooth shape's contact point
(roundedmesh_study.hertz_reference, roundedmesh_study.shape_error).

    /usr/bin/python3 scripts/studies/speed_vs_error.py [--quick] [--poses N] [--shapes ...] [--families ...]
                                                       [--costs] [--report] [--output out/speed_vs_error]

Representations (CONFIGURATIONS): roundedmesh at several mesh sizes with the curvature computed (Eq. 1) in the
'auto', 'quadrature' and 'direct' regimes and prescribed ('auto'); YADE's clumps of spheres built from the
primitives of shapes.json (10, 20, 40, 80 spheres for the gummy bear; the pear's two primitives; one sphere for
the sphere) and level-set bodies at three grid spacings and node counts, both with YADE's Hertz-Mindlin law.
Poses: validation.pair_poses(N, seed=1) (the body frames, then random pairs of orientations); on the plane the
first orientation of each pair, on a copy both. A pose is left out for every configuration of a shape when
Hertz is no reference there at the shape's own contact point (hertz_reference.hertz_holds at the frame of the
paper's mesh: concave, flat, crease, second contact).

Writes, for each shape and family run, parts/<shape>_<family>.csv (one row per configuration, partner and pose),
then from every part present:
    errors.csv     shape, family, configuration, size, partner, poses used, poses left out (by reason), poses
                   with no force at the deepest overlap, NRMSE median and worst [%], force-direction angle
                   median and worst [deg]
    errors.md      the same as a markdown table
    errors_side_by_side.md   one row per configuration, plane and copy side by side (doc/speed-vs-error.md)
so that the families can be run one at a time (each well under 10 minutes on two busy cores with --poses 30).
--quick: 3 poses, two configurations per family, every shape (under a minute).
--costs: then the cost axis, scripts/studies/speed_vs_error_costs.py (with --quick if given) into the same folder;
--report: then the report, scripts/studies/speed_vs_error_report.py (pareto.csv, pareto.png, guide.md,
speed_vs_error.json) from that folder's errors.csv and costs.csv. The whole study: --poses 60 --costs --report.
"""
import argparse
import collections
import csv
import glob
import os
import subprocess
import sys

import numpy as np

from roundedmesh.export import write_csv

from . import SCRIPTS, grains, shape_error as se
from .model_table import variant_label
from .validation import pair_poses


SHAPES = ("sphere", "pear", "gummy_bear", "spheroid", "pill", "tetra_grain")
FAMILIES = ("roundedmesh", "clumps", "level_sets")
MESH_NODES = {"sphere": (42, 162, 642, 2562), "pear": (150, 300, 486, 1100, 2200),
              "gummy_bear": (150, 300, 554, 1100, 2200), **{g: (150, 300, 600, 1100, 2200) for g in grains.NAMES}}
CLUMP_COUNTS = {"sphere": (1,), "pear": (2,), "gummy_bear": (10, 20, 40, 80),
                **{g: (10, 20, 40, 80, 160) for g in grains.NAMES}}
# The pear's and the gummy bear's clumps are their primitives (exact on them); a user with a mesh fills it instead
# (peers.clump_spheres, method 'fill'), as every grain's clump is.
FILLED_TOO, FILL_COUNTS = ("pear", "gummy_bear"), (10, 20, 40, 80, 160)
LEVEL_SETS = ((2e-3, 255), (1e-3, 511), (1e-3, 2047), (0.5e-3, 2047))   # (grid spacing [m], surface nodes)
REASONS = ("concave", "flat", "crease", "second contact")
# The contact law's options (rm.engine): (mesh curvature, regime, law curvature, normal). The regimes only with the
# defaults of the rest; the ellipse and the energy normal only in the default regime.
VARIANTS = (("computed", "auto", "mean", "pressure"), ("computed", "quadrature", "mean", "pressure"),
            ("computed", "direct", "mean", "pressure"), ("computed", "exact", "mean", "pressure"),
            ("computed", "auto", "principal", "pressure"),
            ("computed", "auto", "mean", "energy"), ("prescribed", "auto", "mean", "pressure"),
            ("prescribed", "auto", "principal", "pressure"))


def configurations(shape, family, quick):
    """[(configuration label, size, factory)] of a family for a shape; factory() -> representation."""
    result = []
    if family == "roundedmesh":
        nodes = MESH_NODES[shape]
        if quick:
            nodes = nodes[1:4:2]
        for variant in VARIANTS[:1] if quick else VARIANTS:
            for n in nodes:
                result.append((variant_label(*variant), n, lambda n=n, v=variant: se.rounded_mesh(shape, n, *v)))
    elif family == "clumps":
        counts = CLUMP_COUNTS[shape]
        for count in (counts[1:3] if quick and len(counts) > 2 else counts):
            label = "sphere" if shape == "sphere" else "clump"
            result.append((label, count, lambda c=count: se.Clump(shape, c)))
        if shape in FILLED_TOO:   # shapes.json's: the clump a user builds from the mesh, beside the one of primitives
            for count in (FILL_COUNTS[1:2] if quick else FILL_COUNTS):
                result.append(("clump, sphere fill", count, lambda c=count: se.Clump(shape, c, "fill")))
    elif family == "level_sets" and shape != "sphere":
        for spacing, nodes in (LEVEL_SETS[:2] if quick else LEVEL_SETS):
            result.append((f"level set, grid {spacing * 1e3:g} mm", nodes,
                           lambda s=spacing, n=nodes: se.LevelSetBody(shape, s, n)))
    return result


def run_part(shape, family, poses, quick, output):
    """Errors of every configuration of `family` for `shape`, per pose and partner; writes the part's CSV. The
    reference of each pose (Hertz, or the half-space solution) is computed once, on the shape's common frame."""
    common = se.SmoothShape(shape)
    references = {}
    for partner in se.PARTNERS:
        for index, (upper, lower) in enumerate(poses):
            geometry = se.press_geometry(common, upper, None if partner == "plane" else lower)
            references[partner, index] = (geometry, None if geometry.left_out else geometry.reference(se.overlaps()))
    rows = []
    for label, size, factory in configurations(shape, family, quick):
        representation = factory()
        for (partner, index), (reference, forces) in references.items():
            upper, lower = poses[index]
            row = {"shape": shape, "family": family, "configuration": label, "size": size, "partner": partner,
                   "pose": index, "left_out": reference.left_out or "", "reference": reference.reference_kind}
            if reference.left_out is None:
                geometry = se.press_geometry(representation.shape, upper, None if partner == "plane" else lower)
                error, angle, _ = se.pose_errors(representation, geometry, reference=forces)
                row.update(nrmse=error, angle=angle, r_major=geometry.r_major, r_minor=geometry.r_minor)
            rows.append(row)
        print(f"{shape:10s} {family:11s} {label:34s} {size:5d} done", flush=True)
    os.makedirs(os.path.join(output, "parts"), exist_ok=True)
    columns = ["shape", "family", "configuration", "size", "partner", "pose", "left_out", "nrmse", "angle",
               "r_major", "r_minor", "reference"]
    write_csv(os.path.join(output, "parts", f"{shape}_{family}.csv"), columns,
              [[row.get(c, "") for c in columns] for row in rows])


def summarize(output):
    """errors.csv and errors.md from every part in output/parts."""
    groups = collections.OrderedDict()
    order = {s: i for i, s in enumerate(SHAPES)}
    family_order = {f: i for i, f in enumerate(FAMILIES)}
    for path in sorted(glob.glob(os.path.join(output, "parts", "*.csv"))):
        with open(path) as f:
            for row in csv.DictReader(f):
                key = (row["shape"], row["family"], row["configuration"], int(row["size"]), row["partner"])
                groups.setdefault(key, []).append(row)
    keys = sorted(groups, key=lambda k: (order[k[0]], family_order[k[1]], k[2], k[4], k[3]))
    summary = []
    for key in keys:
        rows = groups[key]
        used = [r for r in rows if not r["left_out"]]
        errors = np.array([float(r["nrmse"]) for r in used]) * 100
        angles = np.array([float(r["angle"]) for r in used])
        reasons = collections.Counter(r["left_out"] for r in rows if r["left_out"])
        summary.append({
            "shape": key[0], "family": key[1], "configuration": key[2], "nodes or spheres": key[3],
            "partner": key[4], "poses used": len(used), "poses left out": sum(reasons.values()),
            "left out (concave/flat/crease/second contact)": "/".join(str(reasons[r]) for r in REASONS),
            "no force at 2 % r": int(np.sum(angles == 90.0)),
            "NRMSE median [%]": f"{np.median(errors):.3g}" if len(used) else "",
            "NRMSE worst [%]": f"{errors.max():.3g}" if len(used) else "",
            "angle median [deg]": f"{np.median(angles):.2g}" if len(used) else "",
            "angle worst [deg]": f"{angles.max():.2g}" if len(used) else ""})
    if not summary:
        return summary
    write_csv(os.path.join(output, "errors.csv"), list(summary[0]), [list(row.values()) for row in summary])
    with open(os.path.join(output, "errors.md"), "w") as f:
        f.write("| " + " | ".join(summary[0]) + " |\n|" + "---|" * len(summary[0]) + "\n")
        for row in summary:
            f.write("| " + " | ".join(str(v) for v in row.values()) + " |\n")
    write_side_by_side(summary, os.path.join(output, "errors_side_by_side.md"))
    return summary


def write_side_by_side(summary, path):
    """The table of doc/speed-vs-error.md: one row per configuration, plane and copy side by side."""
    rows = collections.OrderedDict()
    for r in summary:
        key = (r["shape"], r["family"], r["configuration"], r["nodes or spheres"])
        rows.setdefault(key, {})[r["partner"]] = r
    header = ["shape", "representation", "nodes or spheres", "plane: poses (left out) [no force]",
              "plane: NRMSE median / worst [%]", "copy: poses (left out) [no force]", "copy: NRMSE median / worst [%]",
              "copy: angle median / worst [deg]"]
    with open(path, "w") as f:
        f.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for (shape, family, configuration, size), partners in rows.items():
            cells = [shape, f"{family}: {configuration}", str(size)]
            for partner in ("plane", "self"):
                r = partners.get(partner)
                if r is None:
                    cells += ["", ""] + ([""] if partner == "self" else [])
                    continue
                cells += [f"{r['poses used']} ({r['poses left out']}) [{r['no force at 2 % r']}]",
                          f"{r['NRMSE median [%]']} / {r['NRMSE worst [%]']}"]
                if partner == "self":
                    cells.append(f"{r['angle median [deg]']} / {r['angle worst [deg]']}")
            f.write("| " + " | ".join(cells) + " |\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="3 poses, two configurations per family")
    parser.add_argument("--poses", type=int, default=30, help="orientation pairs (default 30)")
    parser.add_argument("--shapes", nargs="+", choices=SHAPES, default=list(SHAPES))
    parser.add_argument("--families", nargs="+", choices=FAMILIES, default=list(FAMILIES))
    parser.add_argument("--costs", action="store_true", help="then the S1 costs (speed_vs_error_costs.py)")
    parser.add_argument("--report", action="store_true", help="then the report (speed_vs_error_report.py)")
    parser.add_argument("--output", default=os.path.join("out", "speed_vs_error"))
    args = parser.parse_args(argv)
    poses = list(pair_poses(3 if args.quick else args.poses, seed=1))
    for shape in args.shapes:
        for family in args.families:
            if configurations(shape, family, args.quick):
                run_part(shape, family, poses, args.quick, args.output)
    for row in summarize(args.output):
        print(" | ".join(str(v) for v in row.values()))
    if args.costs:
        subprocess.run([sys.executable, os.path.join(SCRIPTS, "studies", "speed_vs_error_costs.py"), "--output", args.output]
                       + (["--quick"] if args.quick else []), check=True)
    if args.report:
        subprocess.run([sys.executable, os.path.join(SCRIPTS, "studies", "speed_vs_error_report.py"), "--input", args.output,
                        "--output", args.output], check=True)
