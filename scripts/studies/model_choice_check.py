"""Does rm.cheapest_model choose well for a mesh it has not seen? (issue 27; doc/speed-vs-error.md, "Any mesh"):
roundedmesh_study.model_check for every shape of the study and each target error.

    /usr/bin/python3 scripts/studies/model_choice_check.py [--poses 60] [--targets 0.01 0.05 0.2]
                                       [--statistic median] [--table model_table.json] [--output out/model_choice_check]

Writes check.csv and check.md (one row per shape and target) and prints the table. --quick: 3 poses, one target.
"""
import argparse
import os
import sys

from roundedmesh.export import write_csv
from roundedmesh.model_choice import POSE_STATISTICS, model_table
from roundedmesh_study.model_check import SHAPES, check
from roundedmesh_study.validation import pair_poses


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", type=int, default=60)
    parser.add_argument("--targets", type=float, nargs="+", default=[0.01, 0.05, 0.2])
    parser.add_argument("--statistic", default="median", choices=POSE_STATISTICS)
    parser.add_argument("--shapes", nargs="+", default=list(SHAPES), choices=SHAPES)
    parser.add_argument("--quick", action="store_true", help="3 poses, the 5 %% target only")
    parser.add_argument("--table", default=None, help="the model table (default the package's model_table.json)")
    parser.add_argument("--output", default=os.path.join("out", "model_choice_check"))
    args = parser.parse_args(argv)
    poses = list(pair_poses(3 if args.quick else args.poses, seed=1))
    targets = [0.05] if args.quick else args.targets
    table = model_table() if args.table is None else model_table(args.table)
    rows = []
    for name in args.shapes:
        for target in targets:
            rows.append(check(name, target, poses, args.statistic, table))
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
