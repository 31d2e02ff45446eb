"""Speed against error, the report (issues 14 and 27; doc/speed-vs-error.md).

    /usr/bin/python3 scripts/studies/speed_vs_error_report.py [--input out/speed_vs_error]
        [--costs PATH [PATH ...]] [--output out/speed_vs_error] [--package-data]

The code, and what it writes: roundedmesh_study.speed_vs_error_report.
"""
import sys

from roundedmesh_study.speed_vs_error_report import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
