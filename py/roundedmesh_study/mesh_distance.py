"""Signed distance [m] from points to a closed triangle mesh, for building YADE's peers (clumps, level sets) of any
shape given as a mesh: a spheroid, a rounded tetrahedron, a scanned part.

    signed_distance(vertices, triangles, points)   (n,) signed distance [m], negative inside

The magnitude is the exact Euclidean distance to the nearest point of the mesh's surface (point-triangle
distance, minimised over the triangles). The sign comes from the generalized winding number (Jacobson, Kavan and
Sorkine-Hornung, ACM TOG 32 (2013) 33): the solid angles of the triangles seen from the point (Van Oosterom and
Strackee, IEEE TBME 30 (1983) 125), summed over 4 pi; it is 1 inside a closed outward-oriented mesh and 0 outside,
and the point is inside where it exceeds 0.5. Unlike the sign of the nearest triangle's normal, it needs no
pseudo-normals at edges and vertices and cannot be fooled where two triangles are equally near.

Everything is vectorised numpy over blocks of points x triangles of at most CHUNK pairs, so the memory stays
bounded whatever the number of points: 100 000 points against a 5018-triangle spheroid took 10 s on one core
with a peak of 0.37 GB for the whole process (YADE included), most of the time in the winding number's arctan2.
"""
import numpy as np
from scipy.spatial import cKDTree
from scipy.spatial.distance import cdist

CHUNK = 2 ** 20  # point-triangle pairs per block: ~20 arrays of this many doubles (x3 for vectors) are alive


def _check_mesh(vertices, triangles):
    """(vertices (v, 3) float, triangles (t, 3) int) checked: finite, indices in range, closed (every directed
    edge has its reverse once) and outward (positive enclosed volume). Raises ValueError otherwise."""
    vertices = np.asarray(vertices, dtype=float)
    triangles = np.asarray(triangles)
    if vertices.ndim != 2 or vertices.shape[1] != 3 or len(vertices) == 0:
        raise ValueError(f"vertices: expected a non-empty (v, 3) array, got shape {vertices.shape}")
    if triangles.ndim != 2 or triangles.shape[1] != 3 or len(triangles) == 0:
        raise ValueError(f"triangles: expected a non-empty (t, 3) array, got shape {triangles.shape}")
    if not np.issubdtype(triangles.dtype, np.integer):
        raise ValueError(f"triangles: expected integer vertex indices, got {triangles.dtype}")
    if not np.isfinite(vertices).all():
        raise ValueError("vertices: NaN or infinite coordinates")
    if triangles.min() < 0 or triangles.max() >= len(vertices):
        raise ValueError(f"triangles: indices must lie in [0, {len(vertices)}), got [{triangles.min()}, "
                         f"{triangles.max()}]")
    # Closed and consistently oriented: each directed edge (a, b) appears as often as its reverse (b, a). The
    # winding number is only 0 or 1 off the surface for such a mesh.
    edges = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]).astype(np.int64)
    forward = np.sort(edges[:, 0] * len(vertices) + edges[:, 1])
    backward = np.sort(edges[:, 1] * len(vertices) + edges[:, 0])
    if not np.array_equal(forward, backward):
        raise ValueError("triangles: the mesh is not closed and consistently oriented (some edge lacks its "
                         "reverse in a neighbouring triangle)")
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    volume = np.einsum("ij,ij->", a, np.cross(b, c)) / 6
    if not volume > 0:
        raise ValueError(f"triangles: the mesh encloses a volume of {volume:.3g} m^3; it must be positive "
                         "(triangles counter-clockwise seen from outside)")
    return vertices, triangles.astype(np.int64)


def _check_points(points):
    """points (n, 3) float, finite; raises ValueError otherwise."""
    points = np.asarray(points, dtype=float)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError(f"points: expected an (n, 3) array, got shape {points.shape}")
    if not np.isfinite(points).all():
        raise ValueError("points: NaN or infinite coordinates")
    return points


def _pair_distances(p, a, b, c, normal, nondegenerate):
    """Exact distances (k,) from points p (k, 3) to triangles (a, b, c) (k, 3 each), `normal` their unit normals
    (zero where degenerate) and `nondegenerate` (k,) bool. If the point's projection on the plane falls inside the
    triangle, the distance is the height over the plane; otherwise the nearest point is on the boundary, so the
    distance is the least of the three point-segment distances."""
    inside = nondegenerate.copy()
    edge_distance = np.full(len(p), np.inf)
    for start, end in ((a, b), (b, c), (c, a)):
        edge = end - start
        offset = p - start
        # Left of every edge (seen along the normal) = projection inside the counter-clockwise triangle.
        inside &= np.einsum("ij,ij->i", np.cross(edge, offset), normal) >= 0
        length2 = np.maximum(np.einsum("ij,ij->i", edge, edge), np.finfo(float).tiny)
        t = np.clip(np.einsum("ij,ij->i", offset, edge) / length2, 0, 1)
        np.minimum(edge_distance, np.linalg.norm(offset - t[:, None] * edge, axis=1), out=edge_distance)
    height = np.abs(np.einsum("ij,ij->i", p - a, normal))
    return np.where(inside, height, edge_distance)


def signed_distance(vertices, triangles, points):
    """(n,) signed distance [m] from `points` (n, 3) [m] to the closed, outward-oriented triangle mesh
    (`vertices` (v, 3) [m], `triangles` (t, 3) int, counter-clockwise seen from outside): negative inside,
    positive outside, zero on the surface.

    |distance| is exact (to rounding): the least point-triangle distance. Triangles are culled per point with
    two bounds before the exact test: the nearest vertex's distance is an upper bound on the answer, and
    |p - centroid| - (triangle's circumradius about its centroid) a lower bound on each triangle's distance, so
    only triangles whose lower bound does not exceed the upper bound are tested. The sign is that of 0.5 minus
    the generalized winding number (module docstring), computed for every point and triangle with the solid
    angle Omega = 2 atan2(a . (b x c), |a||b||c| + (a . b)|c| + (b . c)|a| + (c . a)|b|), a, b, c the vertices
    relative to the point; the dot and triple products are expanded so that they are matrix products of the
    points with per-triangle constants. On the surface itself (distance 0) the sign does not matter.

    Raises ValueError for arrays of the wrong shape, NaN or infinite coordinates, an empty mesh, indices out of
    range, a mesh that is not closed and consistently oriented, or one oriented inward. Zero points give an
    empty array."""
    vertices, triangles = _check_mesh(vertices, triangles)
    points = _check_points(points)
    # Work about the mesh's box centre: the expanded products below lose |p|^2 * 1e-16, tiny for |p| ~ 0.1 m.
    origin = (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    vertices = vertices - origin
    points = points - origin
    a, b, c = (vertices[triangles[:, i]] for i in range(3))

    # Per-triangle constants of the exact distance and of its culling bounds.
    cross = np.cross(b - a, c - a)
    area2 = np.linalg.norm(cross, axis=1)
    nondegenerate = area2 > 1e-14 * np.einsum("ij,ij->i", b - a, b - a).clip(min=np.finfo(float).tiny)
    normal = np.where(nondegenerate[:, None], cross / np.where(area2 > 0, area2, 1)[:, None], 0.0)
    centroid = (a + b + c) / 3
    reach = np.max([np.linalg.norm(v - centroid, axis=1) for v in (a, b, c)], axis=0)
    vertex_tree = cKDTree(vertices)

    # Per-triangle constants of the solid angle: with a' = a - p etc.,
    #   a' . (b' x c') = a . (b x c) - p . (a x b + b x c + c x a),   a' . b' = a . b - p . (a + b) + |p|^2.
    triple = np.einsum("ij,ij->i", a, np.cross(b, c))
    normal_sum = np.cross(a, b) + np.cross(b, c) + np.cross(c, a)
    pairs = [(a, b), (b, c), (c, a)]
    pair_dot = [np.einsum("ij,ij->i", u, v) for u, v in pairs]
    pair_sum = [u + v for u, v in pairs]

    result = np.empty(len(points))
    rows = max(1, CHUNK // len(triangles))
    for first in range(0, len(points), rows):
        p = points[first:first + rows]
        # Exact unsigned distance over the triangles that survive the culling.
        upper = vertex_tree.query(p)[0]
        lower = cdist(p, centroid) - reach
        i, j = np.nonzero(lower <= upper[:, None] * (1 + 1e-12) + 1e-15)
        del lower
        d = _pair_distances(p[i], a[j], b[j], c[j], normal[j], nondegenerate[j])
        # np.nonzero lists the pairs row by row, and every point keeps at least the triangles at its nearest
        # vertex, so each row's pairs are one contiguous run.
        starts = np.flatnonzero(np.r_[True, i[1:] != i[:-1]])
        distance = np.minimum.reduceat(d, starts)
        del i, j, d

        # Generalized winding number.
        length = cdist(p, vertices)
        la, lb, lc = (np.take(length, triangles[:, k], axis=1) for k in range(3))
        del length
        p2 = np.einsum("ij,ij->i", p, p)[:, None]
        denominator = la * lb
        denominator *= lc
        for k, factor in ((0, lc), (1, la), (2, lb)):  # (a . b)|c|, (b . c)|a|, (c . a)|b|, in place
            dot = p @ -pair_sum[k].T
            dot += pair_dot[k][None, :]
            dot += p2
            dot *= factor
            denominator += dot
        del la, lb, lc, dot
        numerator = p @ -normal_sum.T
        numerator += triple[None, :]
        winding = np.arctan2(numerator, denominator).sum(axis=1) / (2 * np.pi)
        result[first:first + rows] = np.where(winding > 0.5, -distance, distance)
    return result
