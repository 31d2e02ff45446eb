"""Do coarse meshes push from a distance? Two copies of a coarse mesh, turned at random, 1 mm apart along the line of
their centres, must feel no force (doc/validation.md, "Coarse meshes"; issue 24).

    /usr/bin/python3 scripts/validation/coarse_clearance.py [--orientations 200] [--gap 1e-3] [--seed 1]
        [--tolerance 0.05] [--output out/coarse_clearance]

Meshes: YADE's GTS horse (examples/gts-horse/horse.coarse.gts, 336 nodes, 668 triangles, scaled to 56 mm long;
skipped with a message where Debian's YADE examples are not installed), a 12-triangle bar (2 x 2 x 5 cm) and a plate
whose sides are slivers (1 x 20 x 50 mm, 12 triangles, 50:1); each loaded with the curvature computed from the mesh,
once as it is (tolerance=None) and once prepared to --tolerance (remeshed until every cap is within it; 0.05 r_eq,
Mesh.load's default). Two bodies prepared to t r_eq reach at most 2 t r_eq towards each other beyond their meshes.

Per orientation: body 1 at the origin turned by q1, body 2 turned by q2 on the line u from it (uniform random
rotations and direction), at the distance at which body 2 can move exactly `gap` towards body 1 along u before the
flat meshes touch (computed exactly on the input mesh, which the prepared one follows: every vertex against every
triangle, every edge against every edge). The force is rm.body_contact's on body 2 (E = 1 MPa, nu = 0.4).

Prints the machine, the command and the table (orientations with a force, the largest force, the tallest cap);
writes coarse_clearance.csv (one row per mesh, tolerance and orientation) and coarse_clearance.png.
"""
import argparse
import os
import shlex
import time
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade.minieigenHP import Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402

from .benchmarking import machine  # noqa: E402
from .deep_monotonicity import random_orientations  # noqa: E402
from .hard_cases import box_arrays  # noqa: E402

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
HORSE = "/usr/share/doc/yade/examples/gts-horse/horse.coarse.gts"
HORSE_LENGTH = 0.056  # [m]


def meshes(tolerance):
    """{name: Mesh} of the coarse meshes, curvature computed, prepared to `tolerance` (None: as they are)."""
    out = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        if os.path.exists(HORSE):
            extent = np.ptp(np.asarray(rm.Mesh.load(HORSE, tolerance=None).vertices), axis=0).max()
            out["GTS horse, 56 mm"] = rm.Mesh.load(HORSE, scale=HORSE_LENGTH / extent, tolerance=tolerance)
        else:
            print(f"skipped the horse: {HORSE} is not installed (Debian's yade package ships it)")
        out["12-triangle bar 2 x 2 x 5 cm"] = rm.Mesh(*box_arrays(0.02, 0.02, 0.05), tolerance=tolerance)
        out["sliver plate 1 x 20 x 50 mm"] = rm.Mesh(*box_arrays(0.001, 0.02, 0.05), tolerance=tolerance)
    return out


def edges(triangles):
    e = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    return np.unique(e, axis=0)


def _vertex_rays(points, direction, vertices, triangles):
    """Smallest t >= 0 at which a point + t direction meets a triangle (Moller-Trumbore), inf if none."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    e1, e2 = b - a, c - a
    h = np.cross(direction, e2)
    det = np.einsum("ij,ij->i", e1, h)
    ok = np.abs(det) > 1e-300
    inv = np.where(ok, 1 / np.where(ok, det, 1), 0)
    s = points[:, None, :] - a[None]
    u = np.einsum("pij,ij->pi", s, h) * inv
    q = np.cross(s, e1[None])
    v = (q @ direction) * inv
    t = np.einsum("pij,ij->pi", q, e2) * inv
    hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t >= 0)
    return np.where(hit, t, np.inf).min()


def _edge_sweeps(p1, d1, p2, d2, direction):
    """Smallest t >= 0 at which an edge p1 + a d1 moved by t direction meets an edge p2 + b d2 (a, b in [0, 1])."""
    rhs = p2[None] - p1[:, None]                              # (n1, n2, 3): solve a d1 - b d2 + t u = rhs
    m_d1 = np.broadcast_to(d1[:, None], rhs.shape)
    m_d2 = np.broadcast_to(-d2[None], rhs.shape)
    m_u = np.broadcast_to(direction, rhs.shape)
    det = np.einsum("ijk,ijk->ij", m_d1, np.cross(m_d2, m_u))
    ok = np.abs(det) > 1e-18 * np.linalg.norm(d1, axis=1)[:, None] * np.linalg.norm(d2, axis=1)[None]
    det = np.where(ok, det, 1)
    a = np.einsum("ijk,ijk->ij", rhs, np.cross(m_d2, m_u)) / det
    b = np.einsum("ijk,ijk->ij", m_d1, np.cross(rhs, m_u)) / det
    t = np.einsum("ijk,ijk->ij", m_d1, np.cross(m_d2, rhs)) / det
    hit = ok & (a >= 0) & (a <= 1) & (b >= 0) & (b <= 1) & (t >= 0)
    return np.where(hit, t, np.inf).min()


def approach_gap(v1, t1, v2, t2, direction):
    """How far body 2 (vertices v2) can move along -direction before its flat mesh touches body 1's [m]."""
    e1, e2 = edges(t1), edges(t2)
    return min(_vertex_rays(v2, -direction, v1, t1), _vertex_rays(v1, direction, v2, t2),
               _edge_sweeps(v2[e2[:, 0]], v2[e2[:, 1]] - v2[e2[:, 0]], v1[e1[:, 0]], v1[e1[:, 1]] - v1[e1[:, 0]],
                            -direction))


def rotation(q):
    m = q.toRotationMatrix()
    return np.array([[m[i][j] for j in range(3)] for i in range(3)])


def input_mesh_in_frame(mesh, given):
    """The vertices and triangles of `given` (the input mesh as it is) in `mesh`'s principal frame: both have the
    input frame in common (Mesh.centroid, Mesh.orientation map each principal frame to it)."""
    to_input = rotation(given.orientation)
    to_body = rotation(mesh.orientation).T
    points = np.asarray(given.vertices) @ to_input.T + np.asarray(given.centroid) - np.asarray(mesh.centroid)
    return points @ to_body.T, np.asarray(given.triangles)


def clearance_forces(mesh, given, orientations, gap):
    """[(|F|, along)] of body 2 for each (q1, q2, u), the flat input meshes (`given`) `gap` apart along u."""
    v, t = input_mesh_in_frame(mesh, given)
    size = 2 * np.linalg.norm(v, axis=1).max()
    rows = []
    for q1, q2, u in orientations:
        v1 = v @ rotation(q1).T
        v2 = v @ rotation(q2).T + (size + gap) * u
        distance = size + gap - approach_gap(v1, t, v2, t, u) + gap
        force = rm.body_contact(mesh, Vector3(0, 0, 0), q1, mesh, Vector3(*(distance * u)), q2, RUBBER, RUBBER)[2]
        rows.append((force.norm(), float(np.dot([force[0], force[1], force[2]], u))))
    return rows


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--orientations", type=int, default=200)
    parser.add_argument("--gap", type=float, default=1e-3, help="gap between the flat meshes along u [m]")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tolerance", type=float, default=0.05, help="Mesh.load's tolerance [r_eq]")
    parser.add_argument("--output", default="out/coarse_clearance")
    return parser.parse_args(argv)


def main(argv):
    args = parse(argv)
    os.makedirs(args.output, exist_ok=True)
    orientations = random_orientations(args.orientations, args.seed)
    rows, table = [], []
    given = meshes(None)
    prepared = f"prepared, {args.tolerance:g} r_eq"
    for label, tolerance in (("as it is", None), (prepared, args.tolerance)):
        for name, mesh in meshes(tolerance).items():
            start = time.perf_counter()
            forces = clearance_forces(mesh, given[name], orientations, args.gap)
            req = (3 * mesh.volume / (4 * np.pi)) ** (1 / 3)
            for k, (magnitude, along) in enumerate(forces):
                rows.append({"mesh": name, "caps": label, "orientation": k, "force_N": magnitude, "along_u_N": along})
            magnitudes = np.array([f for f, _ in forces])
            table.append((name, label, int((magnitudes > 0).sum()), magnitudes.max(), mesh.deviation / req,
                          len(mesh.vertices), time.perf_counter() - start))
    write_csv(os.path.join(args.output, "coarse_clearance.csv"), list(rows[0]), [list(r.values()) for r in rows])
    print(machine())
    print("command: /usr/bin/python3 scripts/validation/coarse_clearance.py " + shlex.join(argv))
    print(f"{'mesh':30s} {'caps':22s} {'with force':>11s} {'largest [N]':>12s} {'tallest cap':>12s} "
          f"{'nodes':>8s} {'[s]':>6s}")
    for name, label, count, largest, tallest, nodes, seconds in table:
        print(f"{name:30s} {label:22s} {count:5d}/{args.orientations:<5d} {largest:12.4g} {tallest:9.3f} r_eq "
              f"{nodes:8d} {seconds:6.1f}")
    figure, axes = plt.subplots(figsize=(8, 4))
    names = sorted({r["mesh"] for r in rows})
    for offset, label in ((-0.2, "as it is"), (0.2, prepared)):
        largest = [max(r["force_N"] for r in rows if r["mesh"] == n and r["caps"] == label) for n in names]
        axes.bar(np.arange(len(names)) + offset, np.maximum(largest, 1e-6), width=0.4, label=f"caps {label}")
    axes.set_yscale("log")
    axes.set_xticks(range(len(names)), names, fontsize=8)
    axes.set_ylabel(f"largest force over {args.orientations} orientations [N]\n(1e-6: none)")
    axes.set_title(f"Two copies {args.gap * 1e3:g} mm apart along the line of their centres")
    axes.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(args.output, "coarse_clearance.png"), dpi=120)
    print(f"wrote {args.output}/coarse_clearance.csv and coarse_clearance.png")
