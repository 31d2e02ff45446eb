"""Issue 37: Facets welded into a surface are one partner (doc/physics.md, "What each partner's surface is").

A square 0.3 m wide tiled by 2 Facets (one diagonal), 8 (two by two cells, each split along a diagonal) and 32 (a
Delaunay triangulation of its corners and 15 random points), each facet's corners in random order (half face up, half
down), is one plane where the body lies over it: a body across its seams must get the force a Wall in that plane gives.
500 random poses each of the gummy bear, the pear and a 642-node sphere, the lowest vertex from 0.1 r_eq below the plane
to 2 mm above it, anywhere over the middle third of the square. The panel computes exactly the Wall's triangle contacts,
so the forces agree to round-off; 1e-9 of the largest allows, as in test_flat_partners.py, for a contact at the very
edge of its circle (h = a, zero force) switching on in one and not the other; the issue asks for 1e-6. A body whose
rounded surface is apart from the plane gets no force."""
import math

import numpy as np
import pytest
from scipy.spatial import Delaunay

import roundedmesh as rm
from yade import Quaternion, Vector3, utils

from test_flat_partners import BODY, FLOOR, _max_cap_height, _rotation, meshes  # noqa: F401 (fixture)

POSES = 500
HALF = 0.15


def _square(tiles, rng):
    """The corners of the Facets tiling the square [-HALF, HALF]^2 in z = 0."""
    corners = np.array([(-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF)])
    if tiles == 2:
        triangles = [(corners[0], corners[1], corners[2]), (corners[0], corners[2], corners[3])]
    elif tiles == 8:
        grid = np.linspace(-HALF, HALF, 3)
        triangles = []
        for i in range(2):
            for j in range(2):
                a, b = (grid[i], grid[j]), (grid[i + 1], grid[j])
                c, d = (grid[i + 1], grid[j + 1]), (grid[i], grid[j + 1])
                triangles += [(a, b, c), (a, c, d)] if (i + j) % 2 else [(a, b, d), (b, c, d)]
    else:
        points = np.vstack([corners, rng.uniform(-0.9 * HALF, 0.9 * HALF, size=(15, 2))])
        triangles = [tuple(points[k] for k in simplex) for simplex in Delaunay(points).simplices]
    assert len(triangles) == tiles
    facets = []
    for t in triangles:
        t = list(t)
        if rng.random() < 0.5:
            t[1], t[2] = t[2], t[1]
        facets.append(utils.facet([(x, y, 0) for x, y in t]))
    return facets


@pytest.mark.parametrize("tiles", [2, 8, 32])
@pytest.mark.parametrize("name", ["gummy_bear", "pear", "sphere"])
def test_a_square_of_facets_pushes_as_its_plane(meshes, name, tiles):  # noqa: F811
    mesh = meshes[name]
    vertices = np.array(mesh.vertices)
    r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    cap = _max_cap_height(mesh)
    rng = np.random.default_rng(37 + tiles)
    facets = _square(tiles, rng)
    wall = utils.wall(0, axis=2, sense=1)
    touching = apart = worst = 0
    for _ in range(POSES):
        q = rng.normal(size=4)
        ori = Quaternion(*(q / np.linalg.norm(q)))
        lowest = (vertices @ _rotation(ori).T)[:, 2].min()
        height = rng.uniform(-0.1 * r_eq, 0.002)
        pos = Vector3(rng.uniform(-HALF / 3, HALF / 3), rng.uniform(-HALF / 3, HALF / 3), height - lowest)
        expected = rm.partner_contact(mesh, pos, ori, wall, BODY, FLOOR)[0]
        force, torque, on_facets, _ = rm.partner_contact(mesh, pos, ori, facets, BODY, FLOOR)
        largest = max(expected.norm(), force.norm())
        assert (force - expected).norm() <= 1e-9 * largest, (name, tiles, ori, pos, force, expected)
        # What the body gets, the facets get back.
        assert (force + sum(on_facets, Vector3.Zero)).norm() <= 1e-12 * max(largest, 1e-300)
        if height > cap:
            apart += 1
            assert largest == 0, (name, ori, pos, force)
        touching += largest > 0
        if largest > 0:
            worst = max(worst, (force - expected).norm() / largest)
    assert touching > POSES / 3 and apart > 10, (touching, apart)
