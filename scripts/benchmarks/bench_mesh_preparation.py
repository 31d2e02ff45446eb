"""One-off cost of preparing meshes, before any simulation step: generators, curvature from the mesh, the
reference shapes (meshed afresh, not from the cache) and a file read. Prints the machine and the median
CPU time of each over repetitions.

    OMP_NUM_THREADS=1 /usr/bin/python3 scripts/benchmarks/bench_mesh_preparation.py [--repetitions 3]
"""
import argparse
import os
import sys

import yade  # noqa: F401  (roundedmesh needs YADE's converters)

import roundedmesh as rm
from roundedmesh import shapes
from roundedmesh_study.benchmarking import machine, median_cpu_ms

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "tests", "data")


def fresh_reference_shape(name):
    shapes._meshed.cache_clear()
    return rm.Mesh.reference_shape(name)


CASES = [
    ("Mesh.icosphere(1, 4)  [2562 nodes, exact]", lambda: rm.Mesh.icosphere(1, 4)),
    ("Mesh.icosphere(1, 4, curvature='computed')", lambda: rm.Mesh.icosphere(1, 4, curvature="computed")),
    ("Mesh.icosphere(1, 4, distortion=0.7)", lambda: rm.Mesh.icosphere(1, 4, distortion=0.7, seed=1)),
    ("Mesh.cylinder(1, 4, 2562)", lambda: rm.Mesh.cylinder(1, 4, 2562)),
    ("Mesh.spheroid(2, 1, 642)", lambda: rm.Mesh.spheroid(2, 1, 642)),
    ("Mesh.spheroid(2, 1, 2562)", lambda: rm.Mesh.spheroid(2, 1, 2562)),
    ("Mesh.reference_shape('pear')  [486 asked]", lambda: fresh_reference_shape("pear")),
    ("Mesh.reference_shape('gummy_bear')  [554]", lambda: fresh_reference_shape("gummy_bear")),
    ("Mesh.load('octahedron_binary.stl')", lambda: rm.Mesh.load(os.path.join(DATA, "octahedron_binary.stl"))),
]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repetitions", type=int, default=3)
    args = parser.parse_args(argv)
    print(f"machine: {machine()}")
    print(f"{'call':46s} {'CPU ms (median)':>16}")
    for label, call in CASES:
        print(f"{label:46s} {median_cpu_ms(call, args.repetitions):16.2f}")


if __name__ == "__main__":
    main(sys.argv[1:])
