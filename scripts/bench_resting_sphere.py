"""Whole-step cost in YADE: a meshed sphere of scene S3 resting on a Wall (every step has a contact),
for 162, 642 and 2562 nodes. Prints the machine and the median over repetitions of ms per step, for the
complete YADE step (ForceResetter, the roundedmesh engine, NewtonIntegrator).

    yade -n -x scripts/bench_resting_sphere.py [--steps 2000] [--repetitions 7]
"""
import argparse
import os
import platform
import sys
import time

import numpy as np
from yade import O

import roundedmesh as rm
from roundedmesh.scenes import build_bouncing_sphere


def machine():
    model = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")),
                 platform.processor())
    return f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}, YADE {O.tags['author'] and ''}".rstrip(", YADE ")


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--repetitions", type=int, default=7)
    args = parser.parse_args(argv)
    print(f"machine: {machine()}")
    print(f"{'nodes':>6} {'ms/step (median)':>17} {'min':>7} {'max':>7} {'triangle contacts':>18}")
    for subdivisions, nodes in ((2, 162), (3, 642), (4, 2562)):
        build_bouncing_sphere(subdivisions)
        O.bodies[0].state.pos = (0, 0, 0.0245)  # resting: about 2 % overlap
        O.run(2000, True)                     # settle
        samples = []
        for _ in range(args.repetitions):
            start = time.perf_counter()
            O.run(args.steps, True)
            samples.append((time.perf_counter() - start) / args.steps * 1e3)
        contacts = rm.statistics()
        print(f"{nodes:6d} {np.median(samples):17.4f} {min(samples):7.4f} {max(samples):7.4f} "
              f"{contacts['quadrature_contacts'] + contacts['direct_contacts']:18d}")


main(sys.argv[1:])
