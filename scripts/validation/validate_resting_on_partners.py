"""A gummy bear at rest on every flat partner (issue 21; doc/validation.md).

    /usr/bin/python3 scripts/validation/validate_resting_on_partners.py [--orientations 20] [--settle 2.5]
                                                                        [--duration 2] [--partners wall box facets]
                                                                        [--output out/resting]

The code, and what it writes: roundedmesh_study.resting_on_partners.
"""
import sys

from roundedmesh_study.resting_on_partners import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
