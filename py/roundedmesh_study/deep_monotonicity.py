"""Is the contact force of two gummy bears monotone in their overlap, up to half a volume-equivalent radius, in
any orientation? (doc/validation.md, "Deep overlaps"; issue 12, group 2.)

    /usr/bin/python3 scripts/validation/deep_monotonicity.py [--orientations 200] [--seed 1] [--volume] [--output DIR]

Two copies of rm.Mesh.reference_shape("gummy_bear") (554 nodes asked, r_eq = 25 mm), E = 1 MPa, nu = 0.4, evaluated
with rm.body_contact (the engine's own pipeline, lists built afresh). Per orientation: body 1 at the origin turned by
q1, body 2 at d u turned by q2, q1, q2 uniform random rotations and u a uniform random direction, the line of
centres. "Overlap" is the approach of the centres along u from first touch: d0 - d, d0 the largest d at which a
triangle pair touches (bisection to round-off), in steps of 0.01 r_eq up to 0.5 r_eq. The force is body 2's, along
u (F.u, the force against the approach) and its magnitude |F|. A curve "falls" where it drops below its largest
value so far by more than 1e-9 of it (round-off); the worst fall is the largest such drop over the curve, in per
cent of that largest value.

With --volume, the same for a reference with no triangle pairs at all: the slope dV/d(overlap) of the two bodies'
overlap volume V, i.e. the force along u of a contact whose energy grows as the overlap volume (voxels of 0.3 mm,
slope over 5 steps, 0.05 r_eq, to stay above the voxels' noise; a fall must exceed 5 % to count). It shows which
falls the shapes themselves make (a limb passing through another) and which the contact law makes.

Prints the machine, the command and the table; writes deep_monotonicity.csv (one row per orientation and step) and
deep_monotonicity.png (the curves that fall; the falling orientations per overlap limit).
"""
import argparse
import csv
import os
import shlex
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade.minieigenHP import Quaternion  # noqa: E402

import roundedmesh as rm  # noqa: E402

from .benchmarking import machine  # noqa: E402

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
STEP = 0.01      # of r_eq
DEEPEST = 0.5    # of r_eq
LIMITS = (0.1, 0.2, 0.3, 0.4, 0.5)
VOXEL = 3e-4     # [m]
VOLUME_STEPS = 5
VOLUME_NOISE = 0.05


# Self-contained (rm.body_contact, rm.triangle_contacts and Mesh.reference_shape only), so that it also measures older
# builds: the "before" columns of doc/validation.md. tests/python/test_deep_contact_force.py imports it.


def random_orientations(count, seed=1):
    """[(q1, q2, u)]: two uniform random rotations and a uniform random unit vector per orientation."""
    rng = np.random.default_rng(seed)
    cases = []
    for _ in range(count):
        q1, q2 = (Quaternion(*rng.normal(size=4)) for _ in range(2))
        q1.normalize()
        q2.normalize()
        u = rng.normal(size=3)
        cases.append((q1, q2, u / np.linalg.norm(u)))
    return cases


def first_touch(mesh, q1, q2, u):
    """The largest distance d [m] at which the mesh at d u turned by q2 touches the mesh at the origin turned by q1
    (a triangle pair in contact), by bisection to round-off from beyond the sum of their bound radii."""
    far, near = 2 * float(np.linalg.norm(mesh.vertices, axis=1).max()) + 1e-3, 0.0
    while True:
        middle = 0.5 * (far + near)
        if middle in (far, near):
            return far
        touching = len(rm.triangle_contacts(mesh, (0, 0, 0), q1, mesh, tuple(middle * u), q2, RUBBER, RUBBER)[
            "triangle1"]) > 0
        far, near = (far, middle) if touching else (middle, near)


def approach_sweep(mesh, q1, q2, u, overlaps):
    """(d0, forces): the second body brought toward the first along u from first touch d0 by each of `overlaps` [m]
    (the approach of the centres), the contact force on it at each (rows of 3) [N]."""
    d0 = first_touch(mesh, q1, q2, u)
    return d0, np.array([tuple(rm.body_contact(mesh, (0, 0, 0), q1, mesh, tuple((d0 - overlap) * u), q2, RUBBER,
                                               RUBBER)[2]) for overlap in overlaps])


def worst_fall(values, noise=1e-9):
    """(fraction, index): the largest drop of `values` below their running maximum, as a fraction of that maximum,
    and where; (0.0, -1) if no drop exceeds `noise` times the running maximum (round-off)."""
    peak, worst, where = 0.0, 0.0, -1
    for i, v in enumerate(values):
        peak = max(peak, v)
        if peak > 0 and (peak - v) / peak > max(worst, noise):
            worst, where = (peak - v) / peak, i
    return worst, where


def sweep(mesh, r_eq, q1, q2, u):
    """(d0, rows (overlap [m], F.u [N], |F| [N], triangle contacts, deepest effective overlap [m])) from first touch."""
    overlaps = np.arange(int(round(DEEPEST / STEP)) + 1) * STEP * r_eq
    d0, forces = approach_sweep(mesh, q1, q2, u, overlaps)
    rows = []
    for overlap, force in zip(overlaps, forces):
        listed = rm.triangle_contacts(mesh, (0, 0, 0), q1, mesh, tuple((d0 - overlap) * u), q2, RUBBER, RUBBER)
        deepest = listed["effective_overlap"].max() if len(listed["triangle1"]) else 0.0
        rows.append((overlap, force @ u, np.linalg.norm(force), len(listed["triangle1"]), deepest))
    return d0, np.array(rows)


class Voxels:
    """The mesh's solid on a grid of `h` in its own frame: parity of the crossings of each column along z."""

    def __init__(self, mesh, h):
        v, t = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
        self.h, self.low = h, v.min(axis=0) - 2 * h
        self.shape = np.ceil((v.max(axis=0) + 2 * h - self.low) / h).astype(int)
        toggles = np.zeros((self.shape[0], self.shape[1], self.shape[2] + 1), dtype=np.int8)
        for a, b, c in v[t]:
            lo = np.floor((np.minimum(np.minimum(a, b), c)[:2] - self.low[:2]) / h - 0.5).astype(int)
            hi = np.ceil((np.maximum(np.maximum(a, b), c)[:2] - self.low[:2]) / h - 0.5).astype(int)
            i, j = np.meshgrid(np.arange(lo[0], hi[0] + 1), np.arange(lo[1], hi[1] + 1), indexing="ij")
            x = self.low[0] + (i.ravel() + 0.5) * h
            y = self.low[1] + (j.ravel() + 0.5) * h
            det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
            if det == 0:
                continue
            l1 = ((b[0] - x) * (c[1] - y) - (c[0] - x) * (b[1] - y)) / det
            l2 = ((c[0] - x) * (a[1] - y) - (a[0] - x) * (c[1] - y)) / det
            l3 = 1 - l1 - l2
            hit = (l1 >= 0) & (l2 >= 0) & (l3 >= 0)
            z = l1[hit] * a[2] + l2[hit] * b[2] + l3[hit] * c[2]
            k = np.clip(np.ceil((z - self.low[2]) / h - 0.5).astype(int), 0, self.shape[2])
            np.add.at(toggles, (i.ravel()[hit], j.ravel()[hit], k), 1)
        self.inside = (np.cumsum(toggles % 2, axis=2)[:, :, :-1] % 2).astype(bool)

    def centres(self):
        """Centres of the cells inside [m], (n, 3)."""
        return self.low + (np.argwhere(self.inside) + 0.5) * self.h

    def contains(self, points):
        index = np.floor((points - self.low) / self.h).astype(int)
        ok = np.all((index >= 0) & (index < self.shape), axis=1)
        result = np.zeros(len(points), dtype=bool)
        result[ok] = self.inside[index[ok, 0], index[ok, 1], index[ok, 2]]
        return result


def rotation_matrix(q):
    return np.array([[q.toRotationMatrix()[i, j] for j in range(3)] for i in range(3)])


def volume_slopes(voxels, points, q1, q2, u, d0, r_eq):
    """dV/d(overlap) [m^2] over each VOLUME_STEPS steps from first touch."""
    r1, r2 = rotation_matrix(q1), rotation_matrix(q2)
    in_body2 = points @ (r2.T @ r1).T  # body 1's cells in body 2's frame, before the offset
    offset = r2.T @ u
    volumes = []
    for k in range(0, int(round(DEEPEST / STEP)) + 1, VOLUME_STEPS):
        d = d0 - k * STEP * r_eq
        volumes.append(voxels.contains(in_body2 - d * offset).sum() * voxels.h**3)
    return np.diff(volumes) / (VOLUME_STEPS * STEP * r_eq)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--orientations", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--volume", action="store_true", help="also the overlap volume's slope (slow: ~3 s each)")
    parser.add_argument("--output", default="out/deep_monotonicity")
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    print(f"machine: {machine()}\ncommand: {' '.join(shlex.quote(a) for a in [sys.executable] + sys.argv)}")
    mesh = rm.Mesh.reference_shape("gummy_bear")
    r_eq = (3 * mesh.volume / (4 * np.pi)) ** (1 / 3)
    voxels = Voxels(mesh, VOXEL) if args.volume else None
    points = voxels.centres() if args.volume else None
    started = time.time()
    results = []
    with open(os.path.join(args.output, "deep_monotonicity.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["orientation", "overlap_m", "overlap_r_eq", "force_along_approach_N", "force_magnitude_N",
                         "triangle_contacts", "deepest_effective_overlap_m"]
                        + (["volume_slope_m2"] if args.volume else []))
        for n, (q1, q2, u) in enumerate(random_orientations(args.orientations, args.seed)):
            d0, rows = sweep(mesh, r_eq, q1, q2, u)
            slopes = volume_slopes(voxels, points, q1, q2, u, d0, r_eq) if args.volume else None
            for k, row in enumerate(rows):
                slope = [slopes[k // VOLUME_STEPS - 1] if k and k % VOLUME_STEPS == 0 else ""] if args.volume else []
                writer.writerow([n, row[0], row[0] / r_eq, row[1], row[2], int(row[3]), row[4]] + slope)
            results.append((rows, slopes))
    print(f"{args.orientations} orientations, seed {args.seed}, {time.time() - started:.0f} s")

    volume_header = f" | {'dV/d(overlap) falls':>20}" if args.volume else ""
    print(f"\n{'overlap up to':>14} | {'F.u falls':>18} | {'|F| falls':>18}{volume_header}")
    counts = {}
    for limit in LIMITS:
        last = int(round(limit / STEP))
        row = []
        for column in (1, 2):
            falls = [worst_fall(rows[:last + 1, column])[0] for rows, _ in results]
            row.append((sum(w > 0 for w in falls), max(falls)))
        if args.volume:
            falls = [worst_fall(slopes[:last // VOLUME_STEPS], VOLUME_NOISE)[0] for _, slopes in results]
            row.append((sum(w > 0 for w in falls), max(falls)))
        counts[limit] = row
        print(f"{limit:>10.1f} r_eq | " + " | ".join(f"{c:>4} of {len(results)}, {100 * w:5.1f} %" for c, w in row))

    figure, (curves, bars) = plt.subplots(1, 2, figsize=(11, 4.5))
    for rows, _ in results:
        falls = worst_fall(rows[:, 1])[0] > 0
        curves.plot(rows[:, 0] / r_eq, rows[:, 1], lw=1.2 if falls else 0.4, color=None if falls else "0.8",
                    zorder=2 if falls else 1)
    curves.set(xlabel="overlap: approach of the centres from first touch [r_eq]",
               ylabel="force on body 2 along the approach [N]",
               title=f"two gummy bears, {len(results)} orientations (falling ones coloured)")
    width = 0.025
    labels = ["F.u", "|F|"] + (["dV/d(overlap)"] if args.volume else [])
    for j, label in enumerate(labels):
        bars.bar(np.array(LIMITS) + (j - (len(labels) - 1) / 2) * width, [counts[lim][j][0] for lim in LIMITS],
                 width, label=label)
    bars.set(xlabel="overlap up to [r_eq]", ylabel="orientations in which it falls",
             title=f"of {len(results)} random orientations")
    bars.legend()
    for axes in (curves, bars):
        axes.grid(alpha=0.3)
    figure.tight_layout()
    path = os.path.join(args.output, "deep_monotonicity.png")
    figure.savefig(path, dpi=120)
    print(f"wrote {path} and deep_monotonicity.csv")
