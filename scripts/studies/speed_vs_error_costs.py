"""Speed against error, the cost axis (issue 14; doc/speed-vs-error.md).

    /usr/bin/python3 scripts/studies/speed_vs_error_costs.py [--quick] [--output out/speed_vs_error]
        [--shapes gummy_bear [spheroid pill tetra_grain]] [--poses-folder bench/data]

The code, and what it writes: roundedmesh_study.speed_vs_error_costs.
"""
import sys

from roundedmesh_study.speed_vs_error_costs import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
