"""A gummy bear at rest on every flat partner (issue 21; doc/validation.md, "Resting on a Wall, a Box and Facets"):
dropped from 5 mm in random orientations onto a fixed YADE Wall, a YADE Box (0.1 m thick) and a floor of two YADE
Facets, all at z = 0, with S1's materials, mu = 0.5 and c = 100 N s/m (the slope scene's,
roundedmesh_study.scenes.SLOPE). It settles for `settle` seconds; then its drift (how far its centre moves) over
`duration` seconds, and the force the partner carries against the bear's weight. A Box used to stop such runs on
phantom overlaps of its far faces.

    /usr/bin/python3 scripts/validation/validate_resting_on_partners.py [--orientations 20] [--settle 2.5]
                                                                        [--duration 2] [--partners wall box facets]
                                                                        [--output out/resting]

The code, and what it writes: roundedmesh_study.resting_on_partners.
"""
import sys

from roundedmesh_study.resting_on_partners import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
