"""Does a rounded body pressed into a flat partner always push back harder the deeper it goes? (scene S8 of
doc/scenes.md: a bear on a Wall, a Facet and a Box pressed from first touch to 0.5 r_eq along random directions at
200 random orientations; doc/validation.md, "Flat partners".)

    /usr/bin/python3 scripts/validation/partner_monotonicity.py [--orientations 200] [--shape gummy_bear] [--seed 1]
                                                                [--output out/partner_monotonicity]

The body (rm.Mesh.reference_shape, E = 1 MPa, nu = 0.4) is turned by a uniform random rotation and pushed along a
random direction u within 60 degrees of the partner's inward normal (-z): a Wall at z = 0, a Facet much larger than
the body in that plane, and a Box 0.1 m thick whose top is that plane (rm.partner_contact: the engine's own pipeline).
"Overlap" is the push along u from first touch (the largest offset at which a triangle touches, by bisection to
round-off), in steps of 0.01 r_eq up to 0.5 r_eq. The force is the partner's push on the body against u, -F.u. A
curve "falls" where it drops below its largest value so far by more than 1e-9 of it (round-off); the worst fall is
the largest such drop, in per cent of that value.

Prints the machine, the command and the table; writes partner_monotonicity.csv (one row per partner, orientation and
step) and partner_monotonicity.png (the curves). About 30 s for 200 orientations.
"""
import argparse
import math
import os
import shlex
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402

from .benchmarking import machine  # noqa: E402
from yade import utils  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
FLOOR = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000)
STEPS = np.arange(0, 51) * 0.01  # overlaps, fractions of r_eq
MAX_TILT = math.radians(60)


def partners():
    """The three partners, their top or plane at z = 0: YADE bodies made here, not in a scene."""
    return {"wall": utils.wall(0, axis=2, sense=1),
            "facet": utils.facet([(-2, -2, 0), (3, -2, 0), (0, 3, 0)]),
            "box": utils.box((0, 0, -0.05), (1, 1, 0.05))}


def random_push(rng):
    """(orientation, unit push direction u with u.(-z) >= cos 60 degrees)."""
    q = rng.normal(size=4)
    tilt, turn = math.acos(1 - rng.uniform() * (1 - math.cos(MAX_TILT))), rng.uniform(0, 2 * math.pi)
    u = np.array([math.sin(tilt) * math.cos(turn), math.sin(tilt) * math.sin(turn), -math.cos(tilt)])
    return Quaternion(*(q / np.linalg.norm(q))), u


def push_force(mesh, ori, start, u, s, partner):
    f = rm.partner_contact(mesh, Vector3(*(start + s * u)), ori, partner, RUBBER, FLOOR)[0]
    return -np.dot(np.array(f), u)


def first_touch(mesh, ori, start, u, partner, reach):
    """The push s [m] along u from `start` at which the body first touches the partner (bisection)."""
    low, high = 0.0, reach
    for _ in range(60):
        middle = 0.5 * (low + high)
        if rm.partner_contact(mesh, Vector3(*(start + middle * u)), ori, partner, RUBBER, FLOOR)[0].norm() > 0:
            high = middle
        else:
            low = middle
    return low


def worst_fall(forces):
    peak, worst = 0.0, 0.0
    for f in forces:
        peak = max(peak, f)
        if f < peak - 1e-9 * peak:
            worst = max(worst, (peak - f) / peak * 100)
    return worst


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--orientations", type=int, default=200)
    parser.add_argument("--shape", default="gummy_bear", choices=["gummy_bear", "pear"])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--output", default=os.path.join("out", "partner_monotonicity"))
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    mesh = rm.Mesh.reference_shape(args.shape)
    vertices = np.array(mesh.vertices)
    r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    reach = 2 * np.linalg.norm(vertices, axis=1).max()
    rng = np.random.default_rng(args.seed)
    bodies = partners()
    rows, falls = [], {name: [] for name in bodies}
    fig, axes = plt.subplots(1, len(bodies), figsize=(12, 3.5), sharey=True)
    for k in range(args.orientations):
        ori, u = random_push(rng)
        m = ori.toRotationMatrix()
        rotation = np.array([[m[i][j] for j in range(3)] for i in range(3)])
        # Start clear of the plane (the lowest vertex 1 mm above it), backed off along u by half the body's reach:
        # a push of `reach` along u then always ends in contact.
        lowest = (vertices @ rotation.T)[:, 2].min()
        start = np.array([0, 0, 0.001 - lowest]) - (reach / 2) * u
        for (name, partner), ax in zip(bodies.items(), axes):
            touch = first_touch(mesh, ori, start, u, partner, reach)
            forces = [push_force(mesh, ori, start, u, touch + x * r_eq, partner) for x in STEPS]
            falls[name].append(worst_fall(forces))
            rows += [(name, k, x, f) for x, f in zip(STEPS, forces)]
            ax.plot(STEPS, forces, lw=0.5, color="C3" if falls[name][-1] > 0 else "0.6")
    for (name, _), ax in zip(bodies.items(), axes):
        ax.set_title(f"{args.shape} on a {name}: {sum(f > 0 for f in falls[name])} of {args.orientations} fall")
        ax.set_xlabel("push from first touch [r_eq]")
        ax.set_yscale("log")
    axes[0].set_ylabel("push-back force along the push [N]")
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "partner_monotonicity.png"), dpi=120)
    write_csv(os.path.join(args.output, "partner_monotonicity.csv"), ["partner", "orientation", "overlap_r_eq", "force_n"],
              rows)
    print(machine())
    print(shlex.join([sys.executable] + sys.argv))
    print(f"{args.shape}, {args.orientations} orientations, pushes within 60 degrees of the normal, 0 to 0.5 r_eq:")
    for name, worst in falls.items():
        falling = [w for w in worst if w > 0]
        print(f"  {name}: {len(falling)} fall" + (f", worst by {max(falling):.3g} %" if falling else ""))
