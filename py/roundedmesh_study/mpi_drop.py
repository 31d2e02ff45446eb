"""Rounded bodies dropped into S1's box (doc/scenes.md), on one process or split over several by YADE's MPI
decomposition (yade.mpy, through roundedmesh.mpi): the same scene either way, for comparing the two.

    yade -n -x scripts/examples/example_mpi.py [options]                        # one process
    mpiexec -n 3 yade -n -x scripts/examples/example_mpi.py [options]           # the master and 2 workers
    (as root, and with more processes than cores: mpiexec --allow-run-as-root --oversubscribe ...)

The scene: `--count` bodies (icospheres of 162 nodes, radius 25 mm, exact curvature, or S1's gummy bears) on S1's
lattice (layers of 4 x 4 nodes 0.10 m apart, or --lattice n x n, jittered by +-3 mm, turned at random; seeded),
falling under gravity into S1's box of five YADE Walls (0.40 m x 0.40 m, or n 0.10 m a side), S1's materials (E = 1e6 Pa, nu = 0.4, 2000 kg/m^3, A = 0.01 s; the box
E = 5e6 Pa), no friction, dt = 1e-4 s, `--steps` steps. With --shake the box moves as in S1 (A = 25 mm, T = 0.25 s)
for the first 0.75 s.

The workers own slabs of the bodies across x, or --split-axis (roundedmesh.mpi.assign_subdomains). The master writes, in --output: final_state.csv (id, x, y, z [m] of every body after the merge) and result.json
(processes, bodies merged, mean and max height [m], packing factor P(0.10 m) of Eq. 28 [%], wall time and seconds
per step, each process's part: roundedmesh.mpi.summary()).
"""
import argparse
import csv
import json
import math
import os
import time

import numpy as np

import roundedmesh as rm
from yade import (Bo1_Wall_Aabb, ForceResetter, HarmonicMotionEngine, InsertionSortCollider, NewtonIntegrator, O,
                  PyRunner, utils)
from yade.minieigenHP import Quaternion, Vector3

RADIUS = 0.025
VOLUME = 4 / 3 * math.pi * RADIUS ** 3
LATTICE_SPACING = 0.10  # between a layer's nodes [m]; the box's inner side is the lattice's side times it
LAYER_SPACING, LOWEST_LAYER, JITTER = 0.10, 0.06, 0.003
AMPLITUDE, PERIOD, SHAKING = 0.025, 0.25, 0.75
PARTICLE = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01)
BOX = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0.01)


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--shape", choices=("icosphere162", "gummy_bear"), default="icosphere162")
    parser.add_argument("--count", type=int, default=48)
    parser.add_argument("--lattice", type=int, default=4, help="nodes along a side of a layer (S1: 4; 1,000 bodies: 8)")
    parser.add_argument("--steps", type=int, default=4000)
    parser.add_argument("--dt", type=float, default=1e-4)
    parser.add_argument("--shake", action="store_true", help="move the box as S1 does for its first 0.75 s")
    parser.add_argument("--split-axis", type=int, choices=(0, 1, 2), default=0,
                        help="the axis across which the workers' slabs of bodies lie (default x)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=1, help="OpenMP threads of each process's engine")
    parser.add_argument("--output", default="out/mpi")
    args = parser.parse_args(argv)
    if args.count < 1 or args.steps < 1 or args.lattice < 1 or not args.dt > 0:
        parser.error("--count, --lattice and --steps must be positive, --dt > 0")
    return args


def half_base(lattice):
    return lattice * LATTICE_SPACING / 2


def lattice_poses(count, lattice, seed):
    """S1's start (scripts/s1_packing.py) on a lattice of `lattice` x `lattice` nodes per layer."""
    rng = np.random.default_rng(seed)
    nodes = (np.arange(lattice) + 0.5) * LATTICE_SPACING - half_base(lattice)
    poses = []
    for i in range(count):
        layer, node = divmod(i, lattice * lattice)
        row, column = divmod(node, lattice)
        position = np.array([nodes[column], nodes[row], LOWEST_LAYER + LAYER_SPACING * layer])
        position += rng.uniform(-JITTER, JITTER, 3)
        q = rng.normal(size=4)
        poses.append((position, q / np.linalg.norm(q)))
    return poses


def build(args):
    O.reset()
    mesh = rm.Mesh.icosphere(RADIUS, 2) if args.shape == "icosphere162" else rm.Mesh.reference_shape(args.shape)
    bodies = []
    side = half_base(args.lattice)
    for position, (w, x, y, z) in lattice_poses(args.count, args.lattice, args.seed):
        bodies.append(rm.add_body(mesh, tuple(position), Quaternion(w, x, y, z), PARTICLE))
        if args.shape == "icosphere162":  # the rounded body is the sphere of radius r: its mass and inertia
            state = O.bodies[bodies[-1]].state
            state.mass = PARTICLE.density * VOLUME
            state.inertia = Vector3(*[0.4 * state.mass * RADIUS ** 2] * 3)
    walls = [O.bodies.append(w) for w in (
        utils.wall(0, axis=2, sense=1), utils.wall(-side, axis=0, sense=1), utils.wall(side, axis=0, sense=-1),
        utils.wall(-side, axis=1, sense=1), utils.wall(side, axis=1, sense=-1))]
    for wall in walls:
        rm.assign_material(wall, BOX)
    engines = [ForceResetter(),
               # yade.mpy's collider (its verletDist for the walls alone): it never pairs rounded bodies
               InsertionSortCollider([Bo1_Wall_Aabb()], verletDist=0.1 * RADIUS),
               rm.engine(threads=args.threads),
               NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    if args.shake:
        omega = 2 * math.pi / PERIOD
        x = omega * args.dt / 2  # the step's mean velocity (scripts/s1_packing.py)
        engines.insert(1, HarmonicMotionEngine(A=(0, 0, AMPLITUDE * math.sin(x) / x), f=(0, 0, 1 / PERIOD),
                                               fi=(0, 0, -math.pi / 2 + x), ids=walls, label="box"))
        engines.append(PyRunner(command="__import__('roundedmesh_study.mpi_drop').mpi_drop.stop_box()", iterPeriod=1,
                                label="box_stopper"))
    O.engines = engines
    O.dt = args.dt
    return bodies, walls


def stop_box():
    """Stops the box at the end of S1's shaking, on every process (each moves its copy of the walls)."""
    if O.time >= SHAKING - 0.5 * O.dt:
        box = next(e for e in O.engines if getattr(e, "label", "") == "box")
        if not box.dead:
            box.dead = True
            for i in box.ids:
                if O.bodies[i] is not None:  # a worker holds only the walls near its bodies
                    O.bodies[i].state.vel = Vector3.Zero


def main(argv):
    args = parse(argv)
    bodies, walls = build(args)
    # Slabs across x by default: every worker gets its share of the packing as it settles.
    rm.mpi.assign_subdomains(axis=args.split_axis)
    start = time.time()
    parts = rm.mpi.mpirun(args.steps, withMerge=True)
    seconds = time.time() - start
    if parts is None:  # a worker
        return 0
    present = [b for b in bodies if O.bodies[b] is not None]
    z = np.array([O.bodies[b].state.pos[2] for b in present])
    result = {"processes": len(parts), "shape": args.shape, "bodies": args.count, "bodies_merged": len(present),
              "steps": args.steps, "mean_height_m": float(z.mean()), "max_height_m": float(z.max()),
              "packing_factor_10cm": float((z < 0.10).sum() * VOLUME / ((2 * half_base(args.lattice)) ** 2 * 0.10) * 100),
              "seconds": seconds, "seconds_per_step": seconds / args.steps, "parts": parts}
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "final_state.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["id", "x_m", "y_m", "z_m"])
        for b in present:
            writer.writerow([b, *list(O.bodies[b].state.pos)])
    with open(os.path.join(args.output, "result.json"), "w") as f:
        json.dump(result, f, indent=1)
    print(f"example_mpi: {len(parts)} process(es), {len(present)} of {args.count} bodies merged, mean height "
          f"{result['mean_height_m'] * 1e3:.3f} mm, {result['seconds_per_step'] * 1e3:.2f} ms per step", flush=True)
    return 0
