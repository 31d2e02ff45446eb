"""Scene S6 (paper Section 3.3, Fig. 9): the pear pressed by a rigid plate, against Hertz.

    /usr/bin/python3 scripts/validation/validate_pear_compression.py [--nodes 486 1000 2200] [--ratio 1.6]
        [--orientations 400] [--seed 1] [--output out/validation]

The code, and what it writes: roundedmesh_study.pear_compression.
"""
import sys

from roundedmesh_study.pear_compression import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
