"""Scene S7 of doc/scenes.md, the rotating drum of Facets filled with gummy bears, pears and spheres.

    yade -n -x scripts/examples/example_drum.py [--steps 20000] [--out out/drum] [--seed 1] [--sample 100]
        [--vtk-every 1000] [--threads 1] [--peers clumps] [--start-overlap 0.3] [--place-only] [--contents horses]
    /usr/bin/python3 scripts/examples/example_drum.py [the same options]

The code, and what it writes: roundedmesh_study.drum.
"""
import sys

from roundedmesh_study.drum import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
