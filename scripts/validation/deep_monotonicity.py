"""Is the force of two gummy bears monotone in their overlap up to half a radius? (issue 12, group 2)

    /usr/bin/python3 scripts/validation/deep_monotonicity.py [--orientations 200] [--seed 1] [--volume] [--output DIR]

The code, and what it writes: roundedmesh_study.deep_monotonicity.
"""
import sys

from roundedmesh_study.deep_monotonicity import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
