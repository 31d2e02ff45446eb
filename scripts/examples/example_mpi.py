"""Rounded bodies on several processes with YADE's own MPI decomposition (yade.mpy): S1's box filled by dropping
48 icospheres (or S1's gummy bears), on one process or on the master and workers, the same scene either way.

    yade -n -x scripts/examples/example_mpi.py [--count 48] [--shape icosphere162|gummy_bear] [--steps 4000]
        [--shake] [--split-axis 0|1|2] [--seed 1] [--threads 1] [--output out/mpi]
    mpiexec --allow-run-as-root --oversubscribe -n 3 yade -n -x scripts/examples/example_mpi.py [the same]

The code, and what it writes: roundedmesh_study.mpi_drop; how it runs: roundedmesh.mpi and doc/user-guide.md.
"""
import sys

from roundedmesh_study.mpi_drop import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
