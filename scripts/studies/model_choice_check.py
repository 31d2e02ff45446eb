"""Does rm.cheapest_model choose well for a mesh it has not seen? (issue 27; doc/speed-vs-error.md, "Any mesh")

For every shape of the study and each target error, the shape's 2200-node mesh (the 2562-node icosphere for the
sphere) is handed to rm.cheapest_model as a plain Mesh, as a user's STL would be: it predicts from the study's fits
the fewest nodes and the law options that meet the target, and remeshes the mesh to them. That choice is then
measured as the study measures its configurations (shape_error: the same poses, partners and references), and set
against the cheapest configuration the study measured for that shape and target (rm.cheapest_model by name):

    met          the choice's measured error (the worse of plane and copy, the pose statistic asked) <= the target
    cost ratio   its S1 cost over the cheapest measured configuration's, and over the cheapest with the curvature
                 computed from the mesh (all a user's mesh can have; prescribed curvature needs the smooth shape):
                 the gummy bear's cost model at both node counts where the shape's own costs are missing, so that
                 both sides are estimated alike

    /usr/bin/python3 scripts/studies/model_choice_check.py [--poses 60] [--targets 0.01 0.05 0.2]
                                       [--statistic median] [--data speed_vs_error.json] [--output out/model_choice_check]

Writes check.csv and check.md (one row per shape and target) and prints the table. --quick: 3 poses, one target.
"""
import argparse
import os
import sys
import warnings

import numpy as np

import roundedmesh as rm
from roundedmesh.export import write_csv
from roundedmesh.study import model_choice as mc, shape_error as se
from roundedmesh.study.validation import pair_poses

SHAPES = ("sphere", "pear", "gummy_bear", "spheroid", "pill", "tetra_grain")


def measured_error(name, choice, poses, statistic):
    """The study's error of `choice` (a ModelChoice for a mesh of `name`): the worse of plane and copy, the
    `statistic` over the poses where the shape has a reference, as a fraction."""
    mesh = choice.mesh()
    representation = se.RoundedMesh(mesh, se.remeshed_frame(name, mesh), choice.regime, choice.law_curvature,
                                    choice.normal)
    common = se.SmoothShape(name)
    per_partner = {}
    for partner in se.PARTNERS:
        errors = []
        for upper, lower in poses:
            lower = None if partner == "plane" else lower
            reference = se.press_geometry(common, upper, lower)
            if reference.left_out:
                continue
            geometry = se.press_geometry(representation.shape, upper, lower)
            errors.append(se.pose_errors(representation, geometry, reference=reference.reference(se.overlaps()))[0])
        per_partner[partner] = np.median(errors) if statistic == "median" else np.max(errors)
    return max(per_partner.values())


def check(name, target, poses, statistic, data):
    """One row of the table."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # a finer-needed warning is reported in the row instead
        choice = rm.cheapest_model(se.source_mesh(name), target, pose_statistic=statistic, data=data)
    computed_only = {**data, "shapes": {name: [e for e in data["shapes"][name] if e["curvature"] == "computed"]}}
    error = measured_error(name, choice, poses, statistic)
    nodes = len(choice.mesh().vertices)
    ours = mc.estimated_cost(nodes, choice.regime, data)
    row = {"shape": name, "target [%]": 100 * target, "statistic": statistic,
           "choice": f"{nodes} nodes, {choice.regime}, {choice.law_curvature}, {choice.normal}"
                     + (" (finer mesh needed)" if choice.finer_needed else ""),
           "predicted [%]": 100 * choice.nrmse, "measured [%]": 100 * error, "met": error <= target}
    for kind, study in (("", data), (", computed", computed_only)):
        try:
            best = rm.cheapest_model(name, target, pose_statistic=statistic, data=study)
        except ValueError:
            best = None
        theirs = None if best is None else (best.cost_ms_per_step if best.cost_ms_per_step is not None
                                            else mc.estimated_cost(best.nodes, best.regime, data))
        row[f"cheapest measured{kind}"] = "none" if best is None else (
            f"{best.nodes} nodes, {best.curvature}, {best.regime}, {best.law_curvature}, {best.normal}: "
            f"{100 * best.nrmse:.3g} %")
        row[f"cost ratio{kind}"] = None if ours is None or theirs is None else ours / theirs
    return row


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", type=int, default=60)
    parser.add_argument("--targets", type=float, nargs="+", default=[0.01, 0.05, 0.2])
    parser.add_argument("--statistic", default="median", choices=mc.POSE_STATISTICS)
    parser.add_argument("--shapes", nargs="+", default=list(SHAPES), choices=SHAPES)
    parser.add_argument("--quick", action="store_true", help="3 poses, the 5 % target only")
    parser.add_argument("--data", default=None, help="the study's data (default the package's speed_vs_error.json)")
    parser.add_argument("--output", default=os.path.join("out", "model_choice_check"))
    args = parser.parse_args(argv)
    poses = list(pair_poses(3 if args.quick else args.poses, seed=1))
    targets = [0.05] if args.quick else args.targets
    data = mc.study_data() if args.data is None else mc.study_data(args.data)
    rows = []
    for name in args.shapes:
        for target in targets:
            rows.append(check(name, target, poses, args.statistic, data))
            print(" | ".join(f"{v:.3g}" if isinstance(v, float) else str(v) for v in rows[-1].values()), flush=True)
    os.makedirs(args.output, exist_ok=True)
    header = list(rows[0])
    cells = [["" if v is None else f"{v:.3g}" if isinstance(v, float) else str(v) for v in r.values()] for r in rows]
    write_csv(os.path.join(args.output, "check.csv"), header, cells)
    with open(os.path.join(args.output, "check.md"), "w") as f:
        f.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for line in cells:
            f.write("| " + " | ".join(line) + " |\n")


if __name__ == "__main__":
    sys.exit(main())
