"""Is the contact force conservative? (issue 12, group 1)

    /usr/bin/python3 scripts/validation/energy_conservation.py [--quick] [--output out/energy] [--only loops collisions facing]

The code, and what it writes: roundedmesh_study.energy_conservation.
"""
import sys

from roundedmesh_study.energy_conservation import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
