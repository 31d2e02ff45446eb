"""A gummy bear dropped onto the top edge of a thin plate of two Facets (issue 38): is the plate ever passed through?

    /usr/bin/python3 scripts/validation/edge_drops.py [--heights 0.1 0.3 1.0] [--orientations 20] [--seed 1]
        [--output out/edge_drops]

The code, and what it writes: roundedmesh_study.edge_drops.
"""
import sys

from roundedmesh_study.edge_drops import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
