"""Deep contacts and the criterion that tells real triangle contacts from false ones (doc/physics.md, "Which
triangle pairs touch"): two 642-node spheres and two gummy bears pressed from first contact to half a
volume-equivalent radius (12.5 mm), force against overlap, with the triangle contacts found and the deepest of
them. A real contact keeps pushing back harder the deeper it goes.

    /usr/bin/python3 scripts/validation/plot_deep_contacts.py [--output out/deep_contacts] [--bears 3]

Writes deep_contacts.csv (body pair, orientation, overlap [m], force [N], triangle contacts, deepest effective
overlap [m]) and deep_contacts.png; prints the machine, the command, and whether every force curve grows.
"""
import argparse
import csv
import os
import shlex
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh_study.analytic import hertz_force  # noqa: E402
from roundedmesh_study.benchmarking import machine  # noqa: E402

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
RADIUS = 0.025  # volume-equivalent radius of both shapes [m]
DEEPEST = 0.5 * RADIUS


def random_rotation(rng):
    q = Quaternion(*rng.normal(size=4))
    q.normalize()
    return q


def first_contact(mesh, q1, q2, axis):
    """Centre distance [m] at which the bodies first touch along `axis` (bisection on the contact count)."""
    far, near = 3 * RADIUS * 2, 0.0
    for _ in range(40):
        middle = 0.5 * (far + near)
        touching = len(rm.triangle_contacts(mesh, (0, 0, 0), q1, mesh, tuple(middle * axis), q2, RUBBER, RUBBER)[
            "triangle1"]) > 0
        far, near = (far, middle) if touching else (middle, near)
    return far


def sweep(mesh, q1, q2, axis, steps=26):
    """(overlaps, forces along the approach, triangle contacts, deepest effective overlaps)."""
    start = first_contact(mesh, q1, q2, axis)
    rows = []
    for overlap in np.linspace(0, DEEPEST, steps)[1:]:
        pos2 = tuple((start - overlap) * axis)
        force = rm.body_contact(mesh, (0, 0, 0), q1, mesh, pos2, q2, RUBBER, RUBBER)[2]
        listed = rm.triangle_contacts(mesh, (0, 0, 0), q1, mesh, pos2, q2, RUBBER, RUBBER)
        deepest = listed["effective_overlap"].max() if len(listed["triangle1"]) else 0.0
        rows.append((overlap, float(np.dot(tuple(force), axis)), len(listed["triangle1"]), deepest))
    return np.array(rows)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/deep_contacts")
    parser.add_argument("--bears", type=int, default=3, help="random orientations of the bear pair")
    parser.add_argument("--seed", type=int, default=5)
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    command = " ".join(shlex.quote(a) for a in [sys.executable] + sys.argv)
    print(f"machine: {machine()}\ncommand: {command}")
    rng = np.random.default_rng(args.seed)
    cases = [("spheres (642 nodes)", rm.Mesh.icosphere(RADIUS, 3), Quaternion.Identity, Quaternion.Identity,
              np.array([0.0, 0.0, 1.0]))]
    bear = rm.Mesh.reference_shape("gummy_bear")
    for k in range(args.bears):
        axis = rng.normal(size=3)
        cases.append((f"gummy bears, orientation {k + 1}", bear, random_rotation(rng), random_rotation(rng),
                      axis / np.linalg.norm(axis)))

    figure, (forces, counts) = plt.subplots(1, 2, figsize=(11, 4.5))
    with open(os.path.join(args.output, "deep_contacts.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["pair", "overlap_m", "force_N", "triangle_contacts", "deepest_effective_overlap_m"])
        for name, mesh, q1, q2, axis in cases:
            rows = sweep(mesh, q1, q2, axis)
            writer.writerows([name, *row] for row in rows)
            grows = bool(np.all(np.diff(rows[:, 1]) > 0))
            print(f"{name}: force {rows[0, 1]:.3g} N at {rows[0, 0] * 1e3:.1f} mm to {rows[-1, 1]:.3g} N at "
                  f"{rows[-1, 0] * 1e3:.1f} mm, {'grows' if grows else 'DOES NOT GROW'} at every step; "
                  f"{int(rows[-1, 2])} triangle contacts, deepest {rows[-1, 3] * 1e3:.2f} mm")
            forces.plot(rows[:, 0] * 1e3, rows[:, 1], "o-", ms=3, label=name)
            counts.plot(rows[:, 0] * 1e3, rows[:, 3] * 1e3, "o-", ms=3, label=name)
    delta = np.linspace(0, DEEPEST, 100)
    forces.plot(delta * 1e3, hertz_force(1 / (2 * (1 - 0.4**2) / 1e6), RADIUS / 2, delta), "k--",
                label="Hertz, spheres R* = r/2")
    forces.axvline(0.1 * RADIUS * 1e3, color="grey", lw=0.8)
    forces.set(xlabel="overlap of the bodies along the approach [mm]", ylabel="force along the approach [N]",
               title="pushed from first contact to half a radius")
    counts.plot([0, DEEPEST * 1e3], [0, DEEPEST * 1e3], "k:", lw=0.8, label="overlap of the bodies")
    counts.axhline(0.1 * RADIUS * 1e3, color="grey", lw=0.8)
    counts.set(xlabel="overlap of the bodies along the approach [mm]", ylabel="deepest triangle contact [mm]",
               title="past 0.1 r_eq (grey) pairs must lie inside both bodies")
    for axes in (forces, counts):
        axes.grid(alpha=0.3)
        axes.legend(fontsize=8)
    figure.tight_layout()
    path = os.path.join(args.output, "deep_contacts.png")
    figure.savefig(path, dpi=120)
    print(f"wrote {path} and deep_contacts.csv")


if __name__ == "__main__":
    main(sys.argv[1:])
