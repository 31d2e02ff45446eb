"""roundedmesh.Mesh: the Python view of a rounded mesh in its principal frame."""
import math

import numpy as np
import pytest
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm


@pytest.mark.parametrize("k, nodes", [(0, 12), (1, 42), (2, 162), (3, 642), (4, 2562)])
def test_icosphere_counts(k, nodes):
    mesh = rm.Mesh.icosphere(0.5, k)
    assert mesh.vertices.shape == (nodes, 3)
    assert mesh.triangles.shape == (20 * 4 ** k, 3)
    assert mesh.radii.shape == (20 * 4 ** k,)
    np.testing.assert_allclose(mesh.radii, 0.5, rtol=1e-15)


# The inscribed icosphere's volume and inertia are below the sphere's by O(h^2): 0.9 % and 1.4 % at 642
# nodes (MassPropertiesTest has the convergence).
def test_icosphere_mass_properties():
    mesh = rm.Mesh.icosphere(2.0, 3)
    volume = 4 / 3 * math.pi * 8
    assert mesh.volume == pytest.approx(volume, rel=0.01)
    np.testing.assert_allclose(mesh.inertia, 0.4 * volume * 4, rtol=0.02)
    np.testing.assert_allclose(mesh.centroid, 0, atol=1e-15)
    assert mesh.orientation == Quaternion.Identity


# A mesh given away from the origin is moved to its principal frame; centroid and orientation say where
# it was. Here an icosphere stretched into an ellipsoid, turned and shifted.
def test_mesh_from_arrays_is_moved_to_its_principal_frame():
    sphere = rm.Mesh.icosphere(1.0, 3)
    stretched = sphere.vertices * [3.0, 2.0, 1.0]
    turn = Quaternion(Vector3(1, 2, 3).normalized(), 0.8)
    matrix = np.array(turn.toRotationMatrix())
    given = stretched @ matrix.T + [10.0, -4.0, 2.5]
    mesh = rm.Mesh(given, sphere.triangles, 1.5)
    np.testing.assert_allclose(mesh.centroid, [10.0, -4.0, 2.5], atol=1e-12)
    back = np.array(mesh.orientation.toRotationMatrix())
    np.testing.assert_allclose(mesh.vertices @ back.T + mesh.centroid, given, atol=1e-12)
    assert np.all(np.diff(mesh.inertia) > 0)  # distinct principal moments, ascending
    assert mesh.volume == pytest.approx(sphere.volume * 6, rel=1e-12)


def test_per_triangle_arrays_describe_the_encompassing_spheres():
    mesh = rm.Mesh.icosphere(1.0, 2)
    corners = mesh.vertices[mesh.triangles]
    np.testing.assert_allclose(np.linalg.norm(corners - mesh.sphere_centres[:, None, :], axis=2), 1.0, rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, rtol=1e-14)
    assert mesh.areas.sum() < 4 * math.pi
    assert mesh.areas.sum() == pytest.approx(4 * math.pi, rel=0.02)


# Mesh.centroid and Mesh.orientation map the principal frame back to the frame the mesh was given in, whatever made
# it: a generated gummy bear (given in the frame of shapes.json; Mesh.save writes it there) and that bear's surface
# turned and shifted, written, then loaded, placed in a YADE scene by them, each lie where its vertices were given.
def test_loaded_and_generated_bodies_are_placed_where_they_were_given(tmp_path):
    from yade import O

    def obj_vertices(path):
        with open(path) as f:
            return np.array([[float(x) for x in line.split()[1:4]] for line in f if line.startswith("v ")])

    bear = rm.Mesh.reference_shape("gummy_bear")
    bear.save(str(tmp_path / "generated.obj"))
    turn = Quaternion(Vector3(1, -2, 0.5).normalized(), 2.1)
    given = bear.vertices @ np.array(turn.toRotationMatrix()).T + [0.3, -0.1, 0.05]
    rm.Mesh(given, bear.triangles, radius=bear.radii).save(str(tmp_path / "turned.obj"))
    loaded = rm.Mesh.load(str(tmp_path / "turned.obj"))
    assert loaded.remesh_passes == 0  # within the tolerance: loaded as it is
    material = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
    O.reset()
    try:
        for mesh, path in ((bear, "generated.obj"), (loaded, "turned.obj")):
            body = O.bodies[rm.add_body(mesh, pos=tuple(mesh.centroid), ori=mesh.orientation, material=material)]
            world = mesh.vertices @ np.array(body.state.ori.toRotationMatrix()).T + np.array(body.state.pos)
            expected = obj_vertices(str(tmp_path / path))
            np.testing.assert_allclose(world[np.lexsort(world.T)], expected[np.lexsort(expected.T)], atol=1e-12)
    finally:
        O.reset()
