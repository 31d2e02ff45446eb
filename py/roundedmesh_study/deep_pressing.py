"""Pressed to half a radius: does the contact keep repelling where the bodies' overlap keeps growing? (issue 38;
doc/physics.md, "Deep overlaps and fast impacts", The core; doc/validation.md, "Deep overlaps".)

    /usr/bin/python3 scripts/validation/deep_pressing.py [--cases bears pears wall sheet-front sheet-back]
        [--orientations 200] [--seed 1] [--output out/deep_pressing]

Cases (rm.Mesh.reference_shape, E = 1 MPa, nu = 0.4; the partners E = 5 MPa): two gummy bears, two pears
(deep_monotonicity's pushes: body 2 approaches body 1 along a random u, both turned at random), a gummy bear on a
Wall, and a gummy bear on a Facet sheet (one Facet much larger than the bear) pushed into it from its front and from
its back (partner_monotonicity's pushes: within 60 degrees of the normal). Each push runs from first touch to
0.5 r_eq in steps of 0.01 r_eq, with the engine's defaults (the core, rm.engine(core_inset=0.25)) and without the
core (core_inset=1). Along each push it records the force along the push and the slope dV/d(overlap) of the overlap
volume V (voxels of 0.3 mm; for a flat partner the volume of the body beyond the plane), over 5 steps (0.05 r_eq):
the force of a contact whose energy grows as V, the reference that says where the shapes themselves let the
repulsion fall (a limb passing through the other body, a limb leaving the plane behind).

A curve falls where it drops below its running maximum: the force by more than 1e-9 of it (round-off), the volume's
slope by more than 5 % (its voxels' noise). A force's fall is explained where, over the same 0.05 r_eq window or the
one before, the volume's slope falls too. Prints per case and law: pushes whose force falls, pushes with a fall the
volume does not explain, and the worst fall; writes deep_pressing.csv (case, law, orientation, overlap, force,
volume slope) and deep_pressing.png.
"""
import argparse
import math
import os
import shlex
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade import utils  # noqa: E402
from yade.minieigenHP import Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402

from . import deep_monotonicity as deep  # noqa: E402
from . import partner_monotonicity as flat  # noqa: E402
from .benchmarking import machine  # noqa: E402

CASES = ("bears", "pears", "wall", "sheet-front", "sheet-back")
LAWS = {"core": {}, "no core": {"core_inset": 1.0}}
STEP, DEEPEST = 0.01, 0.5           # of r_eq
WINDOW = 5                          # steps per volume slope
VOLUME_NOISE = 0.05
FORCE_NOISE = 1e-9


def falls(values, noise):
    """Indices where `values` lie below their running maximum by more than `noise` of it."""
    peak, out = 0.0, []
    for i, v in enumerate(values):
        peak = max(peak, v)
        if peak > 0 and peak - v > noise * peak:
            out.append(i)
    return out


def worst_fall(values, noise):
    peak, worst = 0.0, 0.0
    for v in values:
        peak = max(peak, v)
        if peak > 0 and peak - v > noise * peak:
            worst = max(worst, (peak - v) / peak)
    return worst


def unexplained(forces, slopes):
    """Force samples that fall where the volume's slope does not fall in their window or the one before."""
    slope_falls = set(falls(slopes, VOLUME_NOISE))
    return [i for i in falls(forces, FORCE_NOISE)
            if not ({(i - 1) // WINDOW, (i - 1) // WINDOW - 1} & slope_falls)]


def pair_push(mesh, voxels, points, r_eq, q1, q2, u, options):
    """(forces along the approach [N], volume slopes [m^2]) of two copies of `mesh`."""
    d0 = deep.first_touch(mesh, q1, q2, u)
    overlaps = np.arange(int(round(DEEPEST / STEP)) + 1) * STEP * r_eq
    forces = {name: [float(np.dot(rm.body_contact(mesh, (0, 0, 0), q1, mesh, tuple((d0 - s) * u), q2, deep.RUBBER,
                                                  deep.RUBBER, **opts)[2], u)) for s in overlaps]
              for name, opts in options.items()}
    return forces, deep.volume_slopes(voxels, points, q1, q2, u, d0, r_eq)


def flat_push(mesh, points, r_eq, ori, u, partner, back, options):
    """(push-back forces along u [N], volume slopes [m^2]) of the body pushed into the plane z = 0, from above, or
    with `back` from below (the body and the push mirrored through the plane)."""
    vertices = np.asarray(mesh.vertices)
    rotation = np.asarray(ori.toRotationMatrix())
    reach = 2 * np.linalg.norm(vertices, axis=1).max()
    side = -1.0 if back else 1.0
    u = u * np.array([1, 1, side])
    heights = side * (vertices @ rotation.T)[:, 2]
    start = np.array([0, 0, side * (0.001 - heights.min())]) - (reach / 2) * u

    def force(s, opts):
        f = rm.partner_contact(mesh, Vector3(*(start + s * u)), ori, partner, deep.RUBBER, flat.FLOOR, **opts)[0]
        return -float(np.dot(np.array(f), u))
    low, high = 0.0, reach
    for _ in range(60):
        middle = 0.5 * (low + high)
        low, high = (low, middle) if force(middle, {}) > 0 else (middle, high)
    pushes = low + np.arange(int(round(DEEPEST / STEP)) + 1) * STEP * r_eq
    forces = {name: [force(s, opts) for s in pushes] for name, opts in options.items()}
    cells = points @ rotation.T
    volumes = [np.count_nonzero(side * (cells + start + s * u)[:, 2] < 0) for s in pushes[::WINDOW]]
    h3 = deep.VOXEL ** 3
    return forces, np.diff(np.array(volumes) * h3) / (WINDOW * STEP * r_eq)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", nargs="+", choices=CASES, default=list(CASES))
    parser.add_argument("--orientations", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--output", default=os.path.join("out", "deep_pressing"))
    args = parser.parse_args(argv)
    if args.orientations < 1:
        parser.error("--orientations must be positive")
    os.makedirs(args.output, exist_ok=True)
    command = shlex.join([sys.executable] + sys.argv)
    print(f"machine: {machine()}\ncommand: {command}", flush=True)
    rows, summary = [], []
    figure, axes = plt.subplots(1, len(args.cases), figsize=(3.2 * len(args.cases), 3.4), squeeze=False)
    for case, ax in zip(args.cases, axes[0]):
        shape = "pear" if case == "pears" else "gummy_bear"
        mesh = rm.Mesh.reference_shape(shape)
        r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
        voxels = deep.Voxels(mesh, deep.VOXEL)
        points = voxels.centres()
        started = time.time()
        results = []
        if case in ("bears", "pears"):
            for q1, q2, u in deep.random_orientations(args.orientations, args.seed):
                results.append(pair_push(mesh, voxels, points, r_eq, q1, q2, u, LAWS))
        else:
            partner = utils.wall(0, axis=2, sense=0) if case == "wall" else utils.facet([(-2, -2, 0), (3, -2, 0),
                                                                                         (0, 3, 0)])
            rng = np.random.default_rng(args.seed)
            for _ in range(args.orientations):
                ori, u = flat.random_push(rng)
                results.append(flat_push(mesh, points, r_eq, ori, u, partner, case == "sheet-back", LAWS))
        steps = np.arange(int(round(DEEPEST / STEP)) + 1) * STEP
        for law in LAWS:
            falling = [worst_fall(forces[law], FORCE_NOISE) for forces, _ in results]
            strange = [len(unexplained(forces[law], slopes)) > 0 for forces, slopes in results]
            summary.append((case, law, sum(f > 0 for f in falling), sum(strange), 100 * max(falling)))
            print(f"{case:12s} {law:8s}: force falls in {summary[-1][2]:3d} of {len(results)}, unexplained by the "
                  f"volume in {summary[-1][3]:3d}, worst fall {summary[-1][4]:5.1f} %  [{time.time() - started:.0f} s]",
                  flush=True)
        slope_falls = sum(worst_fall(slopes, VOLUME_NOISE) > 0 for _, slopes in results)
        print(f"{case:12s} volume slope falls in {slope_falls} of {len(results)}", flush=True)
        for k, (forces, slopes) in enumerate(results):
            for i, x in enumerate(steps):
                slope = slopes[i // WINDOW - 1] if i and i % WINDOW == 0 else float("nan")
                rows.append((case, k, x, forces["core"][i], forces["no core"][i], slope))
            strange = len(unexplained(forces["core"], slopes)) > 0
            ax.plot(steps, forces["no core"], lw=0.4, color="0.75")
            ax.plot(steps, forces["core"], lw=1.0 if strange else 0.4, color="C3" if strange else "C0")
        ax.set(title=case, xlabel="push from first touch [r_eq]", yscale="log")
    axes[0][0].set_ylabel("force along the push [N]\n(blue: core; grey: none; red: unexplained fall)")
    figure.tight_layout()
    figure.savefig(os.path.join(args.output, "deep_pressing.png"), dpi=120)
    write_csv(os.path.join(args.output, "deep_pressing.csv"),
              ["case", "orientation", "overlap_r_eq", "force_core_n", "force_no_core_n", "volume_slope_m2"], rows)
    print(f"\nmachine: {machine()}\ncommand: {command}")
    print("case, law, force falls, unexplained by the volume, worst fall [%]")
    for row in summary:
        print("  " + ", ".join(str(round(x, 2)) if isinstance(x, float) else str(x) for x in row))
    return summary
