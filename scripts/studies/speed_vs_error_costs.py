"""Speed against error, the cost axis (issue 14; doc/speed-vs-error.md): milliseconds per step of scene S1's settled
packing of 250 gummy bears (bench/data/s1_settled.csv, doc/scenes.md) for each configuration of the error study
that scripts/studies/speed_vs_error.py measures for the gummy bear, timed by one harness,
scripts/benchmarks/bench_s1_peers.py, one configuration after the other, each in its own process on one thread.

    /usr/bin/python3 scripts/studies/speed_vs_error_costs.py [--quick] [--output out/speed_vs_error]
        [--shapes gummy_bear [spheroid pill tetra_grain]] [--poses-folder bench/data]

The code, and what it writes: roundedmesh_study.speed_vs_error_costs.
"""
import sys

from roundedmesh_study.speed_vs_error_costs import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
