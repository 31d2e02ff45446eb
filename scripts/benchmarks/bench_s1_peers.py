"""Whole-step cost of scene S1 as roundedmesh bodies and as YADE's own representations.

    /usr/bin/python3 scripts/benchmarks/bench_s1_peers.py [--shape gummy_bear] [--poses bench/data/s1_settled.csv]
        [--peers roundedmesh clumps spheres [levelset] [roundedmesh-principal]] [--nodes N] [--regime auto]
        [--count 40]
        [--spacing 1e-3] [--surface-nodes 511]
        [--level-set-verlet 0] [--warmup 100] [--blocks 5] [--block-steps 200] [--min-block-seconds 2]
        [--output out/bench_s1_peers/peers.csv]

The code, and what it writes: roundedmesh_study.bench_s1_peers.
"""
import os
import sys

# Before YADE loads OpenMP: its engines must run on one thread.
if os.environ.get("OMP_NUM_THREADS") != "1":
    os.environ["OMP_NUM_THREADS"] = "1"
    os.execv(sys.executable, [sys.executable] + sys.argv)

from roundedmesh_study.bench_s1_peers import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
