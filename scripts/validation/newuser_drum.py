"""The new user's drum of scene S8 (doc/scenes.md): YADE's facetCylinder with thin-plate lifters, soft horses and
gummy bears dropped in from a lattice, with the defaults; or the same drum filled with YADE's 40-sphere clumps.

    /usr/bin/python3 scripts/validation/newuser_drum.py [--contents mixed|bears] [--run roundedmesh|clumps]
        [--steps 20000] [--seed 1] [--threads 1] [--output out/newuser_drum]

The code, and what it writes: roundedmesh_study.newuser_drum.
"""
import sys

from roundedmesh_study.newuser_drum import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
