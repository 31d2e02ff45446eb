"""Peers built from any closed triangle mesh (roundedmesh_study.mesh_distance, sphere_fill, peers.level_set_from_mesh):
the mesh's signed distance against exact distances (a cube, an icosphere within its sagitta), the inscribed-sphere
clump of a spheroid, and a level set of an icosphere against the mesh's volume."""
import numpy as np
import pytest
from scipy.spatial.distance import cdist

import roundedmesh as rm
from roundedmesh_study import peers
from roundedmesh_study.mesh_distance import signed_distance
from roundedmesh_study.sphere_fill import inscribed_spheres

HALF = 0.01  # the cube's half side [m]
CUBE_VERTICES = HALF * np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
# Two triangles per face, counter-clockwise seen from outside (vertex index = 4 [x > 0] + 2 [y > 0] + [z > 0]).
CUBE_TRIANGLES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5],     # x = -h, x = +h
                           [0, 4, 5], [0, 5, 1], [2, 3, 7], [2, 7, 6],     # y = -h, y = +h
                           [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])    # z = -h, z = +h


def box_distance(points):
    """Exact signed distance [m] to the cube [-HALF, HALF]^3."""
    q = np.abs(points) - HALF
    return np.linalg.norm(np.maximum(q, 0), axis=1) + np.minimum(q.max(axis=1), 0)


def arrays(mesh):
    return np.array(mesh.vertices), np.array(mesh.triangles)


def test_cube_distance_is_exact_inside_and_outside():
    points = np.random.default_rng(0).uniform(-2 * HALF, 2 * HALF, (4000, 3))
    points = np.vstack([points, [[0, 0, 0], [HALF, HALF, HALF], [2 * HALF, 0, 0], [0.5 * HALF, 0, -HALF]]])
    # The cube's distance is piecewise the distance to a plane, an edge or a corner: exact up to rounding.
    np.testing.assert_allclose(signed_distance(CUBE_VERTICES, CUBE_TRIANGLES, points), box_distance(points),
                               rtol=0, atol=1e-15)
    d = signed_distance(CUBE_VERTICES, CUBE_TRIANGLES, np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.5 * HALF]]))
    assert d[0] == pytest.approx(-HALF, abs=1e-15) and d[1] == pytest.approx(0.5 * HALF, abs=1e-15)


def test_icosphere_distance_is_the_spheres_within_the_sagitta():
    vertices, triangles = arrays(rm.Mesh.icosphere(0.025, 3))
    radius = 0.025
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    inradius = np.einsum("ij,ij->i", a, normals).min()
    sagitta = radius - inradius  # the facets lie between the spheres of radius r - sagitta and r
    assert 0 < sagitta < 2e-4
    points = np.random.default_rng(1).uniform(-0.04, 0.04, (3000, 3))
    d = signed_distance(vertices, triangles, points)
    # The mesh lies between the spheres r - s and r, so its signed distance at |x| is bracketed by the spheres':
    # |x| - r <= d <= |x| - (r - s), inside and outside alike (1e-15 m: rounding).
    excess = d - (np.linalg.norm(points, axis=1) - radius)
    assert excess.min() >= -1e-15 and excess.max() <= sagitta + 1e-15
    # Straight out of a triangle's centroid the nearest point of a convex mesh is that centroid: exact.
    centroids = (a + b + c) / 3
    out = signed_distance(vertices, triangles, centroids + 1e-3 * normals)
    np.testing.assert_allclose(out, 1e-3, rtol=0, atol=1e-15)


def test_sign_is_negative_inside_and_positive_outside():
    vertices, triangles = arrays(rm.Mesh.spheroid(0.0315, 0.0157, 1100))
    inside = np.array([[0, 0, 0], [0.030, 0, 0], [0, 0.015, 0], [-0.02, 0.005, -0.005]])
    outside = np.array([[0.032, 0, 0], [0, 0, 0.0165], [0.1, 0.1, 0.1], [0.025, 0.012, 0]])
    assert (signed_distance(vertices, triangles, inside) < 0).all()
    assert (signed_distance(vertices, triangles, outside) > 0).all()
    assert signed_distance(vertices, triangles, np.zeros((0, 3))).shape == (0,)


@pytest.mark.parametrize("vertices, triangles, points, message", [
    (CUBE_VERTICES[:, :2], CUBE_TRIANGLES, np.zeros((1, 3)), "vertices"),
    (np.zeros((0, 3)), CUBE_TRIANGLES, np.zeros((1, 3)), "vertices"),
    (CUBE_VERTICES, np.zeros((0, 3), dtype=int), np.zeros((1, 3)), "triangles"),
    (CUBE_VERTICES, CUBE_TRIANGLES.astype(float), np.zeros((1, 3)), "integer"),
    (CUBE_VERTICES, CUBE_TRIANGLES + 1, np.zeros((1, 3)), "indices"),
    (np.where(np.arange(24).reshape(8, 3) == 5, np.nan, CUBE_VERTICES), CUBE_TRIANGLES, np.zeros((1, 3)), "NaN"),
    (CUBE_VERTICES, CUBE_TRIANGLES[1:], np.zeros((1, 3)), "closed"),           # one triangle missing
    (CUBE_VERTICES, CUBE_TRIANGLES[:, ::-1], np.zeros((1, 3)), "volume"),      # inward-facing
    (CUBE_VERTICES, CUBE_TRIANGLES, np.zeros(3), "points"),
    (CUBE_VERTICES, CUBE_TRIANGLES, np.array([[0.0, np.nan, 0.0]]), "NaN"),
], ids=["2d vertices", "no vertices", "no triangles", "float indices", "index out of range", "NaN vertex",
        "open mesh", "inward mesh", "one flat point", "NaN point"])
def test_bad_input_is_refused(vertices, triangles, points, message):
    with pytest.raises(ValueError, match=message):
        signed_distance(vertices, triangles, points)


# --- inscribed_spheres ----------------------------------------------------------------------------------

def union_volume(centres, radii, spacing=5e-4):
    """Volume [m^3] of the union of spheres by counting cell centres of a cubic grid of `spacing` [m]. Over the
    spheroid's 5.5e-3 m^2 of surface the 0.5 mm cells err by ~0.02 % of its volume, far below the 1.7 %
    between 10 and 40 spheres."""
    low, high = (centres - radii[:, None]).min(axis=0), (centres + radii[:, None]).max(axis=0)
    axes = [np.arange(low[i], high[i], spacing) + spacing / 2 for i in range(3)]
    points = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    inside = np.zeros(len(points), dtype=bool)
    for first in range(0, len(points), 50000):
        inside[first:first + 50000] = (cdist(points[first:first + 50000], centres) <= radii).any(axis=1)
    return inside.sum() * spacing ** 3


def surface_points(vertices, triangles, count, seed=2):
    """The vertices and `count` area-uniform random points of the mesh's triangles."""
    rng = np.random.default_rng(seed)
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    pick = rng.choice(len(triangles), count, p=area / area.sum())
    u, v = rng.random(count), rng.random(count)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    return np.vstack([vertices, a[pick] + u[:, None] * (b - a)[pick] + v[:, None] * (c - a)[pick]])


@pytest.fixture(scope="module")
def spheroid():
    mesh = rm.Mesh.spheroid(0.0315, 0.0157, 1100)
    vertices, triangles = arrays(mesh)
    return mesh, vertices, triangles, {n: inscribed_spheres(vertices, triangles, n) for n in (10, 40)}


def test_spheres_are_inside_the_mesh_and_count_is_honoured(spheroid):
    _, vertices, triangles, fills = spheroid
    for count, (centres, radii) in fills.items():
        assert centres.shape == (count, 3) and radii.shape == (count,)
        assert len(np.unique(centres, axis=0)) == count  # no sphere twice
        # Each radius is the centre's distance to the surface, recomputed here by the same exact function:
        # equal up to rounding (1e-12 m), so no sphere pokes out of the mesh.
        assert (radii > 0).all()
        assert (radii <= -signed_distance(vertices, triangles, centres) + 1e-12).all()


def test_fill_is_deterministic(spheroid):
    _, vertices, triangles, fills = spheroid
    centres, radii = inscribed_spheres(vertices, triangles, 10)
    assert np.array_equal(centres, fills[10][0]) and np.array_equal(radii, fills[10][1])


def test_coverage_improves_from_10_to_40_spheres(spheroid):
    mesh, vertices, triangles, fills = spheroid
    samples = surface_points(vertices, triangles, 20000)
    volume, gap = {}, {}
    for count, (centres, radii) in fills.items():
        volume[count] = union_volume(centres, radii) / mesh.volume
        gap[count] = (cdist(samples, centres) - radii).min(axis=1).max()
    assert volume[40] > volume[10] and gap[40] < gap[10]
    # Measured (sphere_fill's docstring): 0.974 and 0.991 of the volume, gaps 0.66 and 0.21 mm. Largest-first
    # on the same candidates gives 0.73 / 11 mm and 0.86 / 6.9 mm: these bounds tell the two rules apart.
    assert volume[10] > 0.95 and volume[40] > 0.98
    assert gap[10] < 1.5e-3 and gap[40] < 0.5e-3


def test_one_sphere_in_a_sphere_mesh_is_its_inscribed_sphere():
    vertices, triangles = arrays(rm.Mesh.icosphere(0.025, 2))
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    inradius = (np.einsum("ij,ij->i", a, normals) / np.linalg.norm(normals, axis=1)).min()
    centres, radii = inscribed_spheres(vertices, triangles, 1)
    # The grid is centred on the mesh's box, so it has a node at the centre (1e-15 m: the box centre's
    # rounding), and the centre's distance to the facets is the inradius (2e-15 m: rounding of the two
    # computations of a plane distance).
    assert np.abs(centres[0]).max() < 1e-15
    assert radii[0] == pytest.approx(inradius, abs=2e-15)


def test_fill_refuses_bad_counts_and_spacings():
    for count in (0, 2.5):
        with pytest.raises(ValueError, match="count"):
            inscribed_spheres(CUBE_VERTICES, CUBE_TRIANGLES, count)
    with pytest.raises(ValueError, match="spacing"):
        inscribed_spheres(CUBE_VERTICES, CUBE_TRIANGLES, 5, spacing=-1e-3)
    # A 5 mm grid has 3 x 3 x 3 nodes inside the 20 mm cube, all at least 5 mm (the default smallest radius,
    # half the largest) deep: 27 spheres can be had, 28 cannot.
    assert len(inscribed_spheres(CUBE_VERTICES, CUBE_TRIANGLES, 27, spacing=5e-3)[1]) == 27
    with pytest.raises(ValueError, match="count"):
        inscribed_spheres(CUBE_VERTICES, CUBE_TRIANGLES, 28, spacing=5e-3)


# --- level_set_from_mesh ----------------------------------------------------------------------------------

def test_level_set_of_a_mesh_has_the_meshs_volume():
    mesh = rm.Mesh.icosphere(0.025, 2)  # 320 triangles: a quarter of the cost of the 1280 of level 3
    vertices, triangles = arrays(mesh)
    spacing = 1e-3
    shape = peers.level_set_from_mesh(vertices, triangles, spacing=spacing, surface_nodes=200)
    nodes = np.array([tuple(n) for n in shape.surfNodes])
    assert len(nodes) == 200  # a convex mesh about its centre: one crossing per ray
    # The signed distance phi of a convex mesh is convex, so its trilinear interpolant I phi, a convex
    # combination of the 8 corner values, is >= phi (Jensen): YADE's zero surface lies inside the mesh, up to
    # the ray tracing's stopping tolerance (spacing / nodesTol = 20 um). It exceeds phi by at most the gradient's
    # turn across a cell times the cell's diagonal: sqrt(3) h |n_i - n_j|, the normals of facets sharing a vertex.
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    turn = max(np.linalg.norm(normals[f][:, None] - normals[f][None], axis=2).max()
               for f in (np.flatnonzero((triangles == v).any(axis=1)) for v in range(len(vertices))))
    depth = signed_distance(vertices, triangles, nodes)
    assert depth.max() <= spacing / shape.nodesTol                  # measured 5e-18 m
    assert depth.min() >= -np.sqrt(3) * spacing * turn             # bound 0.63 mm, measured 0.05 mm
    # Volume: the body is inside the mesh, its nodes at most 0.05 mm deep, over the mesh's 7.9e-3 m^2 a deficit
    # up to 0.6 %, plus the error of YADE's voxel sum: 1 %. Measured +1.5e-4. A wrong sign (the box minus the
    # sphere) or a wrong spacing would be off by tens of per cent.
    assert shape.volume() == pytest.approx(mesh.volume, rel=0.01)
