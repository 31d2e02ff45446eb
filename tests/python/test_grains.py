"""The speed-against-error study's shapes not made of spheres (roundedmesh_study.grains): each of the volume of a
25 mm sphere, its f zero on its mesh's nodes and 1-Lipschitz (what the study's second-contact check needs), its frames
consistent, and YADE's peers built from it standing inside it."""
import math

import numpy as np
import pytest

import roundedmesh as rm
from roundedmesh_study import grains, peers, shape_error as se
from roundedmesh_study.validation import pair_poses


@pytest.mark.parametrize("name", ["spheroid", "pill"])
def test_the_closed_form_grains_have_the_volume_of_the_25_mm_sphere(name):
    grain = grains.grain(name)
    if grain.kind == "spheroid":
        a, b = grain.parameters
        volume = 4 / 3 * math.pi * a * b * b
    else:
        a, b, c, p = grain.parameters
        volume = 8 * a * b * c * math.gamma(1 + 1 / p) ** 3 / math.gamma(1 + 3 / p)
    assert volume == pytest.approx(grains.VOLUME, rel=1e-12)


def test_the_tetrahedral_grain_unit_volume_is_the_extrapolated_mesh_volume():
    # The inscribed meshes fall short by C / N; two meshes extrapolate it. With 2000 and 4000 nodes the estimate
    # differs from the constant's (3988 and 7993 nodes) by the next order, measured 1.7e-4: 5e-4 bounds it.
    meshes = [rm.Mesh.rounded_tetrahedron(1.0, grains.TETRA_ROUNDING, n, curvature="computed") for n in (2000, 4000)]
    (n1, v1), (n2, v2) = [(len(m.vertices), m.volume) for m in meshes]
    assert (n2 * v2 - n1 * v1) / (n2 - n1) == pytest.approx(grains.TETRA_UNIT_VOLUME, rel=5e-4)


@pytest.mark.parametrize("name", grains.NAMES)
def test_f_vanishes_on_the_mesh_and_is_1_lipschitz(name):
    grain = grains.grain(name)
    vertices, _ = grain.surface(600)
    # The C++ mesher's Newton stops at round-off of its own f; ours is the same surface written otherwise: 1e-9 m.
    assert np.abs(grain.distance(vertices)).max() < 1e-9
    # |grad f| <= 1 everywhere (module docstring), checked by central differences (step 1e-7 m: error ~1e-7) at
    # random points inside and around the body.
    rng = np.random.default_rng(1)
    points = rng.uniform(-0.05, 0.05, (2000, 3))
    step = 1e-7
    gradient = np.column_stack([(grain.distance(points + step * e) - grain.distance(points - step * e)) / (2 * step)
                                for e in np.eye(3)])
    assert np.linalg.norm(gradient, axis=1).max() < 1 + 1e-6


@pytest.mark.parametrize("name", grains.NAMES)
def test_the_reference_frame_is_the_reference_mesh_s_principal_frame(name):
    grain = grains.grain(name)
    vertices, triangles = grain.surface(grains.REFERENCE_NODES, frame="reference")
    np.testing.assert_allclose(vertices, np.array(grain.mesh(grains.REFERENCE_NODES).vertices), atol=1e-15)
    np.testing.assert_array_equal(triangles, np.array(grain.mesh(grains.REFERENCE_NODES).triangles))
    # peers.body_frame gives the same frame, with the grain's own frame as the input frame (scale 1)
    _, scale, rotation, centroid = peers.body_frame(name)
    assert scale == 1.0
    np.testing.assert_allclose(rotation, grain.frame()[0], atol=1e-15)
    np.testing.assert_allclose(centroid, grain.frame()[1], atol=1e-15)


def test_a_grain_clump_stands_inside_the_grain_in_the_peers_frame():
    # The clump's spheres, seen in the grain's own frame through the reference frame, are inside f = 0: the fill
    # sits in the 2200-node mesh, inscribed in the convex grain, so every point of every sphere has f <= 0 (to the
    # fill's round-off, 1e-12 m). Checked at 400 points spread over each sphere.
    rotation, centroid = grains.grain("tetra_grain").frame()
    centres, radii = peers.clump_spheres("tetra_grain", 20)
    assert len(radii) == 20
    k = np.arange(400) + 0.5
    polar, azimuth = np.arccos(1 - 2 * k / 400), math.pi * (1 + 5 ** 0.5) * k
    directions = np.column_stack([np.sin(polar) * np.cos(azimuth), np.sin(polar) * np.sin(azimuth), np.cos(polar)])
    points = (centres[:, None, :] + radii[:, None, None] * directions[None]).reshape(-1, 3)
    assert grains.grain("tetra_grain").distance(points @ rotation.T + centroid).max() < 1e-12


def test_a_grain_s_representations_touch_where_its_smooth_shape_does():
    # Every representation of a grain is placed in its own frame; pressed at one pose, the contact point of the
    # smooth shape seen from each frame is the same point of the grain, to the support search's accuracy (0.1 % of r).
    upper, lower = list(pair_poses(3, seed=1))[2]
    points = []
    for shape in (se.SmoothShape("pill"), se.peer_frame("pill"), se.rounded_mesh("pill", 1100).shape):
        geometry = se.press_geometry(shape, upper, lower)
        rotation = np.eye(3) if shape.rotation is None else np.asarray(shape.rotation)
        offset = np.zeros(3) if shape.offset is None else np.asarray(shape.offset)
        points.append(rotation @ geometry.upper_point + offset)
    for point in points[1:]:
        assert np.linalg.norm(point - points[0]) < 1e-3 * se.RADIUS


def test_unknown_grains_are_named():
    with pytest.raises(ValueError, match="not a study grain"):
        grains.grain("cube")
