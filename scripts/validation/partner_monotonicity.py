"""Does a body pressed into a flat partner push back harder the deeper it goes? (scene S8)

    /usr/bin/python3 scripts/validation/partner_monotonicity.py [--orientations 200] [--shape gummy_bear] [--seed 1]
                                                                [--output out/partner_monotonicity]

The code, and what it writes: roundedmesh_study.partner_monotonicity.
"""
import sys

from roundedmesh_study.partner_monotonicity import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
