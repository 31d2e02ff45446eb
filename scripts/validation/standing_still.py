"""A settled packing standing still: its kinetic energy, fastest spin and energy balance (issue 41, item 1).

    /usr/bin/python3 scripts/validation/standing_still.py [--shapes gummy_bear spheroid pill tetra_grain]
        [--normal pressure energy] [--time 0.5] [--output out/standing_still]

The code, and what it writes: roundedmesh_study.standing_still.
"""
import sys

from roundedmesh_study.standing_still import main

if __name__ == "__main__":
    main(sys.argv[1:])
