"""Do coarse meshes push from a distance? (doc/validation.md, "Coarse meshes"; issue 24)

    /usr/bin/python3 scripts/validation/coarse_clearance.py [--orientations 200] [--gap 1e-3] [--seed 1]
        [--tolerance 0.05] [--output out/coarse_clearance]

The code, and what it writes: roundedmesh_study.coarse_clearance.
"""
import sys

from roundedmesh_study.coarse_clearance import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
