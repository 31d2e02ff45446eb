"""Speed against error, the error axis (issue 14; doc/speed-vs-error.md): every representation of the sphere, the
pear and the gummy bear pressed on a rigid plane and on a copy of itself at random orientations, force against
overlap up to 2 % of r = 25 mm, against Hertz's solution at the smooth shape's contact point
(roundedmesh_study.hertz_reference, roundedmesh_study.shape_error).

    /usr/bin/python3 scripts/studies/speed_vs_error.py [--quick] [--poses N] [--shapes ...] [--families ...]
                                                       [--costs] [--report] [--output out/speed_vs_error]

The code, and what it writes: roundedmesh_study.speed_vs_error.
"""
import sys

from roundedmesh_study.speed_vs_error import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
