"""Scene S7 of doc/scenes.md, the rotating drum: a drum of YADE Facets made here in the manner of YADE's
examples/baraban (a mantle of 24 flat panels, two end caps and 4 lifter ridges, all Facets), turning about the
horizontal y axis at 3 rad/s with YADE's RotationEngine, filled with 30 gummy bears, 30 pears (rounded bodies) and
40 YADE spheres of radius 0.01 m (rm.add_sphere), with friction mu = 0.5. O.dt = 1e-4 s, 20,000 steps (2 s).

    yade -n -x scripts/examples/example_drum.py [--steps 20000] [--out out/drum] [--seed 1] [--sample 100]
        [--vtk-every 1000] [--threads 1] [--peers clumps] [--start-overlap 0.3] [--place-only] [--contents horses]
    /usr/bin/python3 scripts/examples/example_drum.py [the same options]

The code, and what it writes: roundedmesh_study.drum.
"""
import sys

from roundedmesh_study.drum import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
