"""Pressed to half a radius, with and without the deep-overlap core, against the overlap volume's slope (issue 38).

    /usr/bin/python3 scripts/validation/deep_pressing.py [--cases bears pears wall sheet-front sheet-back]
        [--orientations 200] [--seed 1] [--output out/deep_pressing]

The code, and what it writes: roundedmesh_study.deep_pressing.
"""
import sys

from roundedmesh_study.deep_pressing import main

if __name__ == "__main__":
    main(sys.argv[1:])
