"""Whole-step cost in YADE: a meshed sphere of scene S3 resting on a Wall (every step has a contact),
for 162, 642 and 2562 nodes. Prints the machine and, over repetitions, the median wall and CPU time per
complete YADE step (ForceResetter, the roundedmesh engine, NewtonIntegrator). CPU time is the steadier
figure on a shared machine.

    yade -n -x scripts/benchmarks/bench_resting_sphere.py [--steps 2000] [--repetitions 7]
"""
import argparse
import sys

import numpy as np
from yade import O

import roundedmesh as rm
from roundedmesh_study.benchmarking import machine, step_times_ms
from roundedmesh_study.scenes import build_bouncing_sphere


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--repetitions", type=int, default=7)
    args = parser.parse_args(argv)
    print(f"machine: {machine()}")
    print(f"{'nodes':>6} {'wall ms/step':>13} {'CPU ms/step':>12} {'CPU min':>8} {'CPU max':>8} {'contacts':>9}")
    for subdivisions, nodes in ((2, 162), (3, 642), (4, 2562)):
        build_bouncing_sphere(subdivisions)
        O.bodies[0].state.pos = (0, 0, 0.0245)  # resting: about 2 % overlap
        O.run(2000, True)                     # settle
        wall, cpu = step_times_ms(args.steps, args.repetitions)
        contacts = rm.statistics()
        print(f"{nodes:6d} {np.median(wall):13.4f} {np.median(cpu):12.4f} {min(cpu):8.4f} {max(cpu):8.4f} "
              f"{contacts['quadrature_contacts'] + contacts['direct_contacts']:9d}")


if __name__ == "__main__":
    main(sys.argv[1:])
