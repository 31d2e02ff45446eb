"""Scene S8 of doc/scenes.md: the hard cases every contact change must pass, pass or fail.

    /usr/bin/python3 scripts/hard_cases.py [--quick] [--only s1 drum newuser pressed coarse collisions]
        [--shapes gummy_bear pear ...] [--seeds 1 2 3 4 5] [--threads 2] [--orientations 200] [--output out/hard_cases]

The code, and what it writes: roundedmesh_study.hard_cases.
"""
import sys

from roundedmesh_study.hard_cases import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
