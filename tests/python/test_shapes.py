"""The paper's shapes: spheroids and cylinders (S5), pear and gummy bear (shapes.json, S1 and S6)."""
import math

import numpy as np
import pytest

import roundedmesh as rm
from roundedmesh import shapes

TARGET_VOLUME = 4 / 3 * math.pi * 0.025**3


def input_frame(mesh):
    rotation = np.array(mesh.orientation.toRotationMatrix())
    return mesh.vertices @ rotation.T + np.array(mesh.centroid)


def signed_volume(vertices, triangles):
    """Divergence theorem, independently of the C++ mass properties."""
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6


def edge_use(triangles):
    """How often each directed edge occurs, and whether its reverse does."""
    directed = {}
    for t in triangles:
        for i in range(3):
            edge = (t[i], t[(i + 1) % 3])
            directed[edge] = directed.get(edge, 0) + 1
    return directed


def shape_function(name):
    """f of shapes.json in numpy, written from its definition, independent of the C++ one."""
    shape = shapes.definitions()["shapes"][name]

    def distance(p, primitive):
        if primitive["type"] == "sphere":
            return np.linalg.norm(p - primitive["center"], axis=1) - primitive["radius"]
        a, b = np.array(primitive["a"]), np.array(primitive["b"])
        t = np.clip((p - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
        return np.linalg.norm(p - (a + t[:, None] * (b - a)), axis=1) - primitive["radius"]

    def f(p):
        k = shape["blend_k"]
        d = distance(p, shape["primitives"][0])
        for primitive in shape["primitives"][1:]:
            e = distance(p, primitive)
            h = np.maximum(k - np.abs(d - e), 0) / k
            d = np.minimum(d, e) - h * h * k / 4
        return d
    return f


@pytest.mark.parametrize("name, paper_nodes", [("pear", 486), ("gummy_bear", 554)])
def test_reference_shapes_are_closed_outward_and_of_the_target_volume(name, paper_nodes):
    mesh, scale = shapes.mesh_with_scale(name)
    assert mesh is rm.Mesh.reference_shape(name)  # cached
    assert abs(len(mesh.vertices) / paper_nodes - 1) < 0.10
    directed = edge_use(mesh.triangles)
    assert all(count == 1 and directed.get((b, a)) == 1 for (a, b), count in directed.items())
    assert len(mesh.vertices) - len(directed) // 2 + len(mesh.triangles) == 2  # a sphere's Euler characteristic
    assert signed_volume(mesh.vertices, mesh.triangles) == pytest.approx(TARGET_VOLUME, rel=0.005)
    # Every node on the shape's surface f = 0, in shape units.
    assert np.abs(shape_function(name)(input_frame(mesh) / scale)).max() < 1e-9
    assert mesh.curvature_mode == "computed"
    assert mesh.distortion < 0.3


def test_gummy_bear_has_concave_regions_and_the_pear_none():
    bear, pear = rm.Mesh.reference_shape("gummy_bear"), rm.Mesh.reference_shape("pear")
    assert np.mean(bear.curvatures < 0) > 0.05  # neck, armpits, between the legs: 14 % measured
    np.testing.assert_allclose(bear.radii[bear.curvatures < 0], bear.max_radius)
    assert np.all(pear.curvatures > 0)
    assert np.all(np.isfinite(bear.radii)) and np.all(bear.radii > 0)


def test_reference_shapes_are_reproducible_and_take_a_node_count():
    first = shapes.mesh_with_scale("pear", 300)[0]
    shapes._meshed.cache_clear()
    again = shapes.mesh_with_scale("pear", 300)[0]
    np.testing.assert_array_equal(first.vertices, again.vertices)
    assert abs(len(first.vertices) / 300 - 1) < 0.10
    with pytest.raises(ValueError, match="unknown reference shape 'banana'; known: gummy_bear, pear"):
        rm.Mesh.reference_shape("banana")


# The spheroid's exact curvature is its mean curvature under each triangle; the computed one (Eq. 1) agrees
# to about 1 % RMS on a near-regular mesh (CurvatureTest has the per-node analysis).
def test_spheroid_exact_and_computed_curvature_agree():
    a, b = 0.03, 0.015
    exact = rm.Mesh.spheroid(a, b, 642)
    computed = rm.Mesh.spheroid(a, b, 642, curvature="computed")
    assert abs(len(exact.vertices) / 642 - 1) < 0.02
    relative = computed.curvatures / exact.curvatures - 1
    assert np.sqrt(np.mean(relative**2)) < 0.02
    # At the equator (a prolate spheroid's long axis is z in the input frame) H = (1/b + b/a^2) / 2.
    x = input_frame(exact)
    equator = np.abs(x[exact.triangles].mean(axis=1)[:, 2]) < 0.1 * a
    np.testing.assert_allclose(exact.curvatures[equator], (1 / b + b / a**2) / 2, rtol=0.02)
    # The inscribed polyhedron lacks 1.05 % of the volume at 642 nodes (GeneratorsTest: O(h^2) convergence).
    assert exact.volume == pytest.approx(4 / 3 * math.pi * a * b * b, rel=0.015)


def test_cylinder_hull_has_twice_the_radius_and_flat_caps_the_maximum():
    cylinder = rm.Mesh.cylinder(0.01, 0.08, 642)
    x = input_frame(cylinder)
    on_cap = np.all(np.abs(np.abs(x[cylinder.triangles][:, :, 2]) - 0.04) < 1e-12, axis=1)
    np.testing.assert_allclose(cylinder.radii[~on_cap], 0.02, rtol=1e-12)
    np.testing.assert_allclose(cylinder.radii[on_cap], cylinder.max_radius, rtol=1e-12)
    computed = rm.Mesh.cylinder(0.01, 0.08, 642, curvature="computed")
    # The paper: "At the hull, the calculated mean radius of curvature is twice the cylinder radius."
    middle = np.all(np.abs(x[cylinder.triangles][:, :, 2]) < 0.03, axis=1)
    np.testing.assert_allclose(computed.radii[middle], 0.02, rtol=0.01)
