"""Spheres pressed into the gummy bear's concave grooves, against Hertz's elliptical solution.

    /usr/bin/python3 scripts/validation/validate_concave_contact.py [--curvature both|mean|principal]
                                                                    [--mesh-curvature both|computed|exact] [--quick]
                                                                    [--output out/concave_contact]

The code, and what it writes: roundedmesh_study.concave_contact.
"""
import sys

from roundedmesh_study.concave_contact import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
