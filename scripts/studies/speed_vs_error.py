"""Speed against error, the error axis (issue 14; doc/speed-vs-error.md).

    /usr/bin/python3 scripts/studies/speed_vs_error.py [--quick] [--poses N] [--shapes ...] [--families ...]
                                                       [--costs] [--report] [--output out/speed_vs_error]

The code, and what it writes: roundedmesh_study.speed_vs_error.
"""
import sys

from roundedmesh_study.speed_vs_error import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
