"""Does a rounded body pressed into a flat partner always push back harder the deeper it goes? (scene S8 of
doc/scenes.md: a bear on a Wall, a Facet and a Box pressed from first touch to 0.5 r_eq along random directions at
200 random orientations; doc/validation.md, "Flat partners".)

    /usr/bin/python3 scripts/validation/partner_monotonicity.py [--orientations 200] [--shape gummy_bear] [--seed 1]
                                                                [--output out/partner_monotonicity]

The code, and what it writes: roundedmesh_study.partner_monotonicity.
"""
import sys

from roundedmesh_study.partner_monotonicity import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
