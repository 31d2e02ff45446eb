"""A clump of spheres for any closed triangle mesh, built the way DEM users build clumps of arbitrary shapes:
inscribed spheres placed greedily on the shape's medial axis, after Ferellec and McDowell, Granular Matter 12
(2010) 459-467 (the "overlapping discrete element cluster" method).

    inscribed_spheres(vertices, triangles, count, spacing, min_radius)   centres (count, 3) [m], radii (count,) [m]

Ferellec and McDowell pick a surface point, grow a sphere from it along the inward normal until it touches the
surface elsewhere (a maximal inscribed sphere, centred on the medial axis), mark the surface points it passes
within a tolerance as covered, and repeat from a point not yet covered. Here the spheres are candidates on a grid
inside the mesh, each as large as it can be (radius = distance to the surface, mesh_distance.signed_distance), and
the point to grow from is the surface sample the clump misses most (inscribed_spheres gives the rule), which makes
the choice deterministic and puts spheres where the clump's surface is farthest from the shape's: its tips and
edges first, rather than piling them in the bulk as "largest sphere first" does.
"""
import numpy as np
from scipy.spatial.distance import cdist

from .mesh_distance import _check_mesh, signed_distance

CELLS_ACROSS = 50        # default grid: this many cells across the mesh's largest extent
MAX_GRID_POINTS = 4_000_000  # a finer grid is refused: its signed distances alone would take minutes
MIN_RADIUS_CELLS = 2     # default smallest sphere, in grid cells
BLOCK = 2 ** 21          # candidate-sample pairs per block when all of them are needed at once


def _surface_samples(vertices, triangles):
    """(points (v + t, 3) [m], weights (v + t,) [m^2]): the vertices and the triangles' centroids, each weighted
    by the surface area it stands for (half a triangle's area at its centroid, a sixth at each of its corners), so
    that coverage counts area, not samples, on a mesh of uneven triangles. The weights sum to the mesh's area."""
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1) / 2
    vertex_weight = np.zeros(len(vertices))
    for k in range(3):
        np.add.at(vertex_weight, triangles[:, k], area / 6)
    return np.concatenate([vertices, (a + b + c) / 3]), np.concatenate([vertex_weight, area / 2])


def _interior_grid(vertices, triangles, spacing):
    """(centres (k, 3) [m], radii (k,) [m]) of the candidate spheres: the nodes of a cubic grid of `spacing` [m]
    strictly inside the mesh, each with the largest radius that keeps it inside (its distance to the surface).
    The grid is centred on the mesh's box, so a mesh symmetric about its box centre has a node there."""
    centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    half = np.floor((vertices.max(axis=0) - centre) / spacing).astype(int)
    if np.prod(2 * half + 1) > MAX_GRID_POINTS:
        raise ValueError(f"spacing: {spacing:.3g} m gives {np.prod(2 * half + 1)} grid nodes, more than "
                         f"{MAX_GRID_POINTS}")
    axes = [centre[i] + spacing * np.arange(-half[i], half[i] + 1) for i in range(3)]
    points = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    distance = signed_distance(vertices, triangles, points)
    inside = distance < 0
    return points[inside], -distance[inside]


def _best_gaps(samples, centres, radii):
    """(s,) least gap |s - c| - r [m] of each surface sample over all candidate spheres: the best a single
    candidate can do for it, so the floor below which the grid cannot bring the clump's gap there."""
    best = np.full(len(samples), np.inf)
    rows = max(1, BLOCK // len(samples))
    for first in range(0, len(centres), rows):
        gaps = cdist(centres[first:first + rows], samples) - radii[first:first + rows, None]
        np.minimum(best, gaps.min(axis=0), out=best)
    return best


def inscribed_spheres(vertices, triangles, count, spacing=None, min_radius=None):
    """(centres (count, 3) [m], radii (count,) [m]): `count` spheres inside the closed, outward-oriented mesh
    (`vertices` (v, 3) [m], `triangles` (t, 3) int), whose union stands for it as a clump; in the mesh's frame.

    Candidates: the nodes of a cubic grid of `spacing` [m] (default: the mesh's largest extent / 50) inside the
    mesh, each with radius = its distance to the mesh, so every sphere is inside and touches the surface; those
    smaller than `min_radius` [m] are dropped (default: 2 cells, at most half the largest candidate). Below that a
    sphere only chases the mesh's own convex corners, which stand proud of any inscribed sphere (below: the fill
    without it took spheres of 0.21 mm from 80 on, for no better gap), and YADE's time step, proportional to the
    smallest member's radius for a clump's spheres (PWaveTimeStep), would pay for it. Surface samples: the vertices
    and the triangles' centroids, weighted by area (_surface_samples). The gap of a sample is the distance from it
    to the clump's surface, min over chosen spheres of |s - c| - r; its floor is the least gap any candidate gives
    it (_best_gaps); its excess is gap - floor, what the clump could still gain there.

    Rule, one sphere at a time (ties go to the lowest candidate index, so the result is deterministic):
      1. the first sphere is the largest candidate (the largest inscribed sphere);
      2. the target is the sample of the largest excess e, the point the clump misses most; the tolerance is
         tau = min(spacing / 2, e / 2): half a cell is the grid's resolution (a node may sit that far off the
         ideal centre), and e / 2 makes the new sphere at least halve the target's excess;
      3. the eligible candidates are those whose gap at the target is within tau of its floor: the spheres that
         touch the surface at or next to the target, among them the maximal one Ferellec and McDowell grow from
         the target along the inward normal;
      4. of those, take the one that covers the most area of samples not yet covered (a sample is covered when
         its excess is at most tau, and the candidate covers it when its gap there is at most floor + tau), then
         the largest.
    Why: step 2 is Gonzalez's farthest-point greedy (Theor. Comput. Sci. 38 (1985) 293; within a factor 2 of
    the least achievable largest gap), so spheres spread to the tips and edges instead of piling up in the bulk
    as largest-first does; step 4 makes each new sphere the one that helps most around there and, among equals,
    the largest, so the union keeps the volume too.

    How well it represents a 2:1 spheroid, Mesh.spheroid(0.0315, 0.0157, 1100) (1111 vertices, 2218 triangles;
    default grid 1.26 mm, smallest sphere 2.5 mm): the union's volume by counting a 0.25 mm grid, the largest
    gap over 100 000 area-uniform random surface points, time of the whole call on one core (Python 3.11,
    numpy 1.24; nearly all of it is the grid's 16 000 signed distances, the greedy choice takes ~0.1 s).

        count   union / mesh volume   largest gap [mm]   time [s]
           10        0.974                 0.66             2.2
           20        0.988                 0.26             1.9
           40        0.991                 0.21             2.0
           80        0.992                 0.18             2.0
          160        0.993                 0.17             2.0

    Largest-first on the same candidates (the 10 or 40 largest spheres, all in the bulk) gives 0.73 and 0.86 of the
    volume and gaps of 11 and 6.9 mm. Beyond 40 spheres the largest gap stays at the mesh's corners: the worst
    floor, 0.18 mm, is at a vertex near the tip (curvature radius 7.8 mm against 1.5 mm edges), which stands proud
    of the spheres tangent to the facets around it; a finer `spacing` or mesh lowers it. On the 2200-node spheroid
    (4396 triangles) count 10 gives 0.978, 0.61 mm in 4.1 s and count 200 gives 0.996, 0.09 mm in 3.9 s.

    Raises ValueError for a bad mesh (mesh_distance.signed_distance), a count below 1 or above the number of
    candidates, or a spacing that is not positive or gives more than MAX_GRID_POINTS grid nodes."""
    vertices, triangles = _check_mesh(vertices, triangles)
    if int(count) != count or count < 1:
        raise ValueError(f"count: expected a positive integer, got {count}")
    count = int(count)
    if spacing is None:
        spacing = np.ptp(vertices, axis=0).max() / CELLS_ACROSS
    if not spacing > 0:
        raise ValueError(f"spacing: expected a positive length [m], got {spacing}")
    centres, radii = _interior_grid(vertices, triangles, spacing)
    if min_radius is None:
        min_radius = min(MIN_RADIUS_CELLS * spacing, radii.max() / 2) if len(radii) else 0.0
    keep = radii >= min_radius
    centres, radii = centres[keep], radii[keep]
    if len(centres) < count:
        raise ValueError(f"count: only {len(centres)} grid nodes at spacing {spacing:.3g} m lie at least "
                         f"{min_radius:.3g} m inside the mesh, fewer than the {count} spheres asked for; give a "
                         f"smaller spacing or min_radius")
    samples, weights = _surface_samples(vertices, triangles)
    floor = _best_gaps(samples, centres, radii)

    chosen = [int(np.argmax(radii))]                                              # rule 1
    gap = np.linalg.norm(samples - centres[chosen[0]], axis=1) - radii[chosen[0]]
    while len(chosen) < count:
        excess = gap - floor
        target = int(np.argmax(excess))                                           # rule 2
        tolerance = min(spacing / 2, excess[target] / 2)
        at_target = np.linalg.norm(samples[target] - centres, axis=1) - radii
        eligible = np.flatnonzero(at_target <= at_target.min() + tolerance)      # rule 3
        eligible = eligible[~np.isin(eligible, chosen)]
        if len(eligible) == 0:  # only when every sample sits on its floor (tau = 0): any sphere not yet taken
            eligible = np.setdiff1d(np.arange(len(radii)), chosen)
        uncovered = np.flatnonzero(excess > tolerance)
        covers = (cdist(centres[eligible], samples[uncovered]) - radii[eligible, None]
                  <= floor[uncovered] + tolerance)
        area = covers @ weights[uncovered]
        best = eligible[np.lexsort((eligible, -radii[eligible], -area))[0]]      # rule 4
        chosen.append(int(best))
        np.minimum(gap, np.linalg.norm(samples - centres[best], axis=1) - radii[best], out=gap)
    return centres[chosen], radii[chosen]
