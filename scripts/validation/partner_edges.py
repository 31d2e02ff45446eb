"""Seams, edges and corners of partners: a ball across a seam of Facets, onto a Box's edge and a lifter's ridge, and
slid over an edge (doc/physics.md, "What each partner's surface is"; doc/figures/partner_edges.png).

    /usr/bin/python3 scripts/validation/partner_edges.py [--output out/partner_edges]

The code, and what it writes: roundedmesh_study.partner_edges.
"""
import sys

from roundedmesh_study.partner_edges import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
