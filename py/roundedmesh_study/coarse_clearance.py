"""Do coarse meshes push from a distance? Two copies of a coarse mesh, turned at random, 1 mm apart along the line of
their centres, must feel no force (doc/validation.md, "Coarse meshes"; issue 24).

    /usr/bin/python3 scripts/validation/coarse_clearance.py [--orientations 200] [--gap 1e-3] [--measure along|least]
        [--seed 1] [--tolerance 0.05] [--meshes horse bar plate] [--output out/coarse_clearance]

Meshes: YADE's GTS horse (examples/gts-horse/horse.coarse.gts, 336 nodes, 668 triangles, scaled to 56 mm long;
skipped with a message where Debian's YADE examples are not installed), a 12-triangle bar (2 x 2 x 5 cm) and a plate
whose sides are slivers (1 x 20 x 50 mm, 12 triangles, 50:1); each loaded with the curvature computed from the mesh,
once as it is (tolerance=None) and once prepared to --tolerance (remeshed until every cap is within it; 0.05 r_eq,
Mesh.load's default). Two bodies prepared to t r_eq reach at most 2 t r_eq towards each other beyond their meshes.

Per orientation: body 1 at the origin turned by q1, body 2 turned by q2 on the line u from it (uniform random
rotations and direction), at the distance at which body 2 can move exactly `gap` towards body 1 along u before the
flat meshes touch (computed exactly on the input mesh, which the prepared one follows: every vertex against every
triangle, every edge against every edge). With --measure least, at the distance along u at which the least distance
between the two input meshes is `gap` instead. The force is rm.body_contact's on body 2 (E = 1 MPa, nu = 0.4).

Moved 1 mm along u, two surfaces that face each other slantwise are nearer than 1 mm: so each orientation also
gets the least distance between the two flat meshes the rounded bodies are built on (least_distance: corner against
triangle and edge against edge). The rounded bodies lie within their tallest cap of them (Mesh.deviation), so where
that distance exceeds twice the tallest cap they cannot touch: a force there is a force across a gap, a defect.

Prints the machine, the command and the table (orientations with a force, the largest force, those across a gap
and their largest force, the least flat distance at which a force acts, the caps' reach, the tallest cap); writes
coarse_clearance.csv (one row per mesh, tolerance and orientation) and coarse_clearance.png (the largest forces;
each force against its flat distance over the caps' reach).
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
MESHES = {"GTS horse, 56 mm": "horse", "12-triangle bar 2 x 2 x 5 cm": "bar", "sliver plate 1 x 20 x 50 mm": "plate"}


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


def _point_segment(p, a, b):
    """Distance from points p to segments ab, row by row [m]."""
    ab = b - a
    along = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
    return np.linalg.norm(p - (a + along[:, None] * ab), axis=1)


def _point_triangle(p, a, b, c):
    """Distance from points p to triangles abc, row by row [m]: to the plane where p projects inside the triangle,
    else to the nearest edge."""
    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    height = np.einsum("ij,ij->i", p - a, normal)
    foot = p - height[:, None] * normal
    inside = np.ones(len(p), dtype=bool)
    for x, y in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ij,ij->i", np.cross(y - x, foot - x), normal) >= 0
    edges = np.minimum(np.minimum(_point_segment(p, a, b), _point_segment(p, b, c)), _point_segment(p, c, a))
    return np.where(inside, np.abs(height), edges)


def _segment_segment(p, q, r, s):
    """Least distance between segments pq and rs, row by row [m] (Ericson, Real-Time Collision Detection, 5.1.9)."""
    d1, d2, w = q - p, s - r, p - r
    a, e = np.einsum("ij,ij->i", d1, d1), np.einsum("ij,ij->i", d2, d2)
    b, c, f = np.einsum("ij,ij->i", d1, d2), np.einsum("ij,ij->i", d1, w), np.einsum("ij,ij->i", d2, w)
    denominator = a * e - b * b
    along1 = np.where(denominator > 1e-30 * a * e, np.clip((b * f - c * e) / np.where(denominator > 0, denominator, 1),
                                                          0, 1), 0)
    along2 = (b * along1 + f) / e
    low, high = along2 < 0, along2 > 1
    along1 = np.where(low, np.clip(-c / a, 0, 1), np.where(high, np.clip((b - c) / a, 0, 1), along1))
    along2 = np.clip(along2, 0, 1)
    return np.linalg.norm((p + along1[:, None] * d1) - (r + along2[:, None] * d2), axis=1)


def least_distance(v1, t1, v2, t2, cutoff):
    """The least distance between two closed flat meshes that do not cross [m], or `cutoff` if none is nearer:
    over the triangle pairs whose bounding balls come within the cutoff, the least of the six corner-triangle and
    nine edge-edge distances."""
    from scipy.spatial import cKDTree
    a1, a2 = v1[t1], v2[t2]                                   # (m, 3 corners, 3)
    c1, c2 = a1.mean(axis=1), a2.mean(axis=1)
    r1 = np.linalg.norm(a1 - c1[:, None], axis=2).max(axis=1)
    r2 = np.linalg.norm(a2 - c2[:, None], axis=2).max(axis=1)
    near = cKDTree(c1).sparse_distance_matrix(cKDTree(c2), cutoff + r1.max() + r2.max(), output_type="ndarray")
    keep = near["v"] - r1[near["i"]] - r2[near["j"]] < cutoff
    i, j = near["i"][keep], near["j"][keep]
    if len(i) == 0:
        return cutoff
    P, Q = a1[i], a2[j]
    least = np.full(len(i), np.inf)
    for k in range(3):
        least = np.minimum(least, _point_triangle(P[:, k], Q[:, 0], Q[:, 1], Q[:, 2]))
        least = np.minimum(least, _point_triangle(Q[:, k], P[:, 0], P[:, 1], P[:, 2]))
        for m in range(3):
            least = np.minimum(least, _segment_segment(P[:, k], P[:, (k + 1) % 3], Q[:, m], Q[:, (m + 1) % 3]))
    return min(float(least.min()), cutoff)


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


def placed_apart(v1, t, v2, u, gap, measure):
    """Where body 2 (vertices v2, at the origin) goes along u so that the flat meshes are `gap` apart [m]: moved
    `gap` along u from where they touch (measure 'along'), or with their least distance `gap` (measure 'least',
    found by bisection to 1e-9 of the gap: the least distance grows by at most the distance moved, so the position
    lies at least `gap` beyond touching)."""
    size = 2 * np.linalg.norm(np.vstack([v1, v2]), axis=1).max()
    touching = size - approach_gap(v1, t, v2 + size * u, t, u)
    if measure == "along":
        return touching + gap
    near, far = touching + gap, touching + 2 * gap
    while least_distance(v1, t, v2 + far * u, t, 4 * gap) < gap:
        near, far = far, far + gap
    while far - near > 1e-9 * gap:
        middle = 0.5 * (near + far)
        near, far = (middle, far) if least_distance(v1, t, v2 + middle * u, t, 4 * gap) < gap else (near, middle)
    return far


def clearance_forces(mesh, given, orientations, gap, measure="along"):
    """[(|F|, along, input distance, flat distance)] of body 2 for each (q1, q2, u), the flat input meshes (`given`)
    `gap` apart (placed_apart's measure): the force, its component along u, and the least distances between the
    two input meshes and between the two flat meshes the rounded bodies are built on (up to 2 gap) [N, N, m, m]."""
    v, t = input_mesh_in_frame(mesh, given)
    flat, flat_triangles = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    rows = []
    for q1, q2, u in orientations:
        v1, v2 = v @ rotation(q1).T, v @ rotation(q2).T
        distance = placed_apart(v1, t, v2, u, gap, measure)
        force = rm.body_contact(mesh, Vector3(0, 0, 0), q1, mesh, Vector3(*(distance * u)), q2, RUBBER, RUBBER)[2]
        apart = least_distance(v1, t, v2 + distance * u, t, 2 * gap)
        flat_apart = least_distance(flat @ rotation(q1).T, flat_triangles, flat @ rotation(q2).T + distance * u,
                                    flat_triangles, 2 * gap)
        rows.append((force.norm(), float(np.dot([force[0], force[1], force[2]], u)), apart, flat_apart))
    return rows


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--orientations", type=int, default=200)
    parser.add_argument("--gap", type=float, default=1e-3, help="gap between the flat input meshes [m]")
    parser.add_argument("--measure", choices=("along", "least"), default="along",
                        help="the gap along the line of the centres, or the meshes' least distance")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tolerance", type=float, default=0.05, help="Mesh.load's tolerance [r_eq]")
    parser.add_argument("--meshes", nargs="+", choices=sorted(set(MESHES.values())), default=sorted(set(MESHES.values())))
    parser.add_argument("--output", default="out/coarse_clearance")
    args = parser.parse_args(argv)
    for name in ("orientations", "gap", "tolerance"):
        if not getattr(args, name) > 0:
            parser.error(f"--{name}: expected a positive number, got {getattr(args, name)}")
    return args


def main(argv):
    args = parse(argv)
    os.makedirs(args.output, exist_ok=True)
    orientations = random_orientations(args.orientations, args.seed)
    rows, table = [], []
    given = meshes(None)
    prepared = f"prepared, {args.tolerance:g} r_eq"
    for label, tolerance in (("as it is", None), (prepared, args.tolerance)):
        for name, mesh in meshes(tolerance).items():
            if MESHES[name] not in args.meshes:
                continue
            start = time.perf_counter()
            forces = clearance_forces(mesh, given[name], orientations, args.gap, args.measure)
            req = (3 * mesh.volume / (4 * np.pi)) ** (1 / 3)
            reach = 2 * mesh.deviation
            for k, (magnitude, along, apart, flat_apart) in enumerate(forces):
                rows.append({"mesh": name, "caps": label, "orientation": k, "force_N": magnitude, "along_u_N": along,
                             "input_distance_mm": apart * 1e3, "flat_distance_mm": flat_apart * 1e3,
                             "caps_reach_mm": reach * 1e3, "across_gap": int(magnitude > 0 and flat_apart > reach)})
            magnitudes = np.array([f[0] for f in forces])
            flat = np.array([f[3] for f in forces])
            across = magnitudes[(magnitudes > 0) & (flat > reach)]
            table.append((name, label, int((magnitudes > 0).sum()), magnitudes.max(), len(across),
                          across.max() if len(across) else 0.0,
                          flat[magnitudes > 0].min() * 1e3 if (magnitudes > 0).any() else float("nan"),
                          reach * 1e3, mesh.deviation / req, len(mesh.vertices), time.perf_counter() - start))
    write_csv(os.path.join(args.output, "coarse_clearance.csv"), list(rows[0]), [list(r.values()) for r in rows])
    print(machine())
    print("command: /usr/bin/python3 scripts/validation/coarse_clearance.py " + shlex.join(argv))
    print("across a gap: a force where the two flat meshes are farther apart than the caps can reach (2 x the tallest "
          "cap), so that the rounded bodies cannot touch")
    print(f"{'mesh':30s} {'caps':22s} {'with force':>11s} {'largest [N]':>12s} {'across a gap':>13s} "
          f"{'largest [N]':>12s} {'least flat distance [mm]':>25s} {'caps reach [mm]':>16s} {'tallest cap':>12s} "
          f"{'nodes':>8s} {'[s]':>6s}")
    for name, label, count, largest, across, largest_across, nearest, reach, tallest, nodes, seconds in table:
        print(f"{name:30s} {label:22s} {count:5d}/{args.orientations:<5d} {largest:12.4g} {across:7d}/{args.orientations:<5d} "
              f"{largest_across:12.4g} {nearest:25.3f} {reach:16.3f} {tallest:9.3f} r_eq {nodes:8d} {seconds:6.1f}")
    figure, (bars, scatter) = plt.subplots(1, 2, figsize=(12, 4.5))
    names = sorted({r["mesh"] for r in rows})
    for offset, label in ((-0.2, "as it is"), (0.2, prepared)):
        largest = [max(r["force_N"] for r in rows if r["mesh"] == n and r["caps"] == label) for n in names]
        bars.bar(np.arange(len(names)) + offset, np.maximum(largest, 1e-6), width=0.4, label=f"caps {label}")
    bars.set_yscale("log")
    bars.set_xticks(range(len(names)), names, fontsize=8)
    bars.set_ylabel(f"largest force over {args.orientations} orientations [N]\n(1e-6: none)")
    apart = "along the line of their centres" if args.measure == "along" else "(least distance)"
    bars.set_title(f"Two copies {args.gap * 1e3:g} mm apart {apart}", fontsize=10)
    bars.legend()
    for name in names:
        for label, marker in (("as it is", "x"), (prepared, "o")):
            hit = [r for r in rows if r["mesh"] == name and r["caps"] == label and r["force_N"] > 0]
            if hit:
                scatter.scatter([r["flat_distance_mm"] / r["caps_reach_mm"] for r in hit], [r["force_N"] for r in hit],
                                marker=marker, label=f"{name}, {label}", alpha=0.7)
    scatter.axvline(1, color="k", lw=0.8)
    scatter.set_xscale("log")
    scatter.set_yscale("log")
    scatter.set_xlabel("least distance of the flat meshes / the caps' reach (right of 1: across a gap)")
    scatter.set_ylabel("force [N]")
    scatter.set_title("Each orientation with a force", fontsize=10)
    scatter.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(os.path.join(args.output, "coarse_clearance.png"), dpi=120)
    print(f"wrote {args.output}/coarse_clearance.csv and coarse_clearance.png")
