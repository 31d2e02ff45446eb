"""ParaView export: a .vtp per frame and a .pvd collection, in VTK's compressed binary XML encoding, read
back here with the standard library alone (xml.etree, base64, zlib) by the rules of VTK's file format."""
import base64
import os
import xml.etree.ElementTree as ElementTree
import zlib

import numpy as np
import pytest
from yade import O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh.export import VtkSeries, write_mesh_vtp, write_partners_vtp, write_spheres_vtp, write_vtp

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
TYPES = {"Float64": "<f8", "Int64": "<i8"}


def decode(array):
    """The values of a binary DataArray of a file with header_type UInt64 and the zlib compressor: the header
    [blocks, block size, last block size, compressed sizes...] is base64 on its own, then the blocks."""
    text = array.text.strip()
    words = lambda count: 4 * -(-8 * count // 3)  # base64 characters of `count` UInt64 words
    blocks = int(np.frombuffer(base64.b64decode(text[:words(3)]), "<u8")[0])
    header = np.frombuffer(base64.b64decode(text[:words(3 + blocks)]), "<u8")
    data = base64.b64decode(text[words(3 + blocks):])
    block_size, last, sizes = int(header[1]), int(header[2]), header[3:]
    raw, start = b"", 0
    for i, size in enumerate(sizes):
        chunk = zlib.decompress(data[start:start + int(size)])
        assert len(chunk) == (last if i == blocks - 1 and last else block_size)
        raw += chunk
        start += int(size)
    assert start == len(data)
    values = np.frombuffer(raw, TYPES[array.get("type")])
    return values.reshape(-1, int(array.get("NumberOfComponents", 1))) if array.get("NumberOfComponents") else values


def read_piece(path):
    root = ElementTree.parse(path).getroot()
    assert (root.get("header_type"), root.get("compressor"), root.get("byte_order")) == \
        ("UInt64", "vtkZLibDataCompressor", "LittleEndian")
    piece = root.find("PolyData/Piece")
    arrays = {}
    for a in piece.iter("DataArray"):
        assert a.get("format") == "binary"
        arrays[a.get("Name")] = decode(a)
    return piece, arrays


def test_vtp_holds_every_body_in_global_coordinates(tmp_path):
    mesh = rm.Mesh.icosphere(0.5, 1)
    turn = Quaternion(Vector3(0, 0, 1), 0.5)
    rm.add_body(mesh, pos=(0, 0, 0), material=RUBBER)
    rm.add_body(mesh, pos=(3, 0, 1), ori=turn, material=RUBBER)
    piece, arrays = read_piece(write_vtp(str(tmp_path / "bodies.vtp")))
    assert int(piece.get("NumberOfPoints")) == 2 * 42 and int(piece.get("NumberOfPolys")) == 2 * 80
    points = arrays["Points"]
    expected = mesh.vertices @ np.array(turn.toRotationMatrix()).T + [3, 0, 1]
    np.testing.assert_allclose(points[42:], expected, atol=1e-14)  # the rotation's round-off only
    np.testing.assert_array_equal(np.unique(arrays["body_id"]), [0, 1])
    np.testing.assert_allclose(arrays["radius"], 0.5)
    np.testing.assert_allclose(arrays["curvature"], 2.0)
    np.testing.assert_array_equal(arrays["offsets"], 3 * np.arange(1, 161))
    assert arrays["connectivity"].max() == 2 * 42 - 1


# Binary values come back bit for bit, also when an array spans several compressed blocks (a 2562-node
# sphere's connectivity, 123 kB, in blocks of 32 kB).
def test_a_mesh_alone_with_its_curvature(tmp_path, monkeypatch):
    monkeypatch.setattr(rm.export, "_BLOCK", 32768)
    for mesh in (rm.Mesh.reference_shape("gummy_bear"), rm.Mesh.icosphere(1.0, 4)):
        piece, arrays = read_piece(write_mesh_vtp(mesh, str(tmp_path / "mesh.vtp")))
        np.testing.assert_array_equal(arrays["Points"], mesh.vertices)
        np.testing.assert_array_equal(arrays["connectivity"].reshape(-1, 3), mesh.triangles)
        np.testing.assert_array_equal(arrays["curvature"], mesh.curvatures)
        np.testing.assert_array_equal(arrays["node_curvature"], mesh.node_curvatures)
        np.testing.assert_array_equal(arrays["principal_curvatures"], mesh.principal_curvatures)
        np.testing.assert_array_equal(arrays["principal_direction"], mesh.principal_directions)
        assert piece.find("PointData") is not None


def test_an_empty_scene_writes_an_empty_piece(tmp_path):
    piece, arrays = read_piece(write_vtp(str(tmp_path / "none.vtp")))
    assert piece.get("NumberOfPoints") == "0" and len(arrays["Points"]) == 0 and len(arrays["body_id"]) == 0


def test_spheres_are_points_with_radius_and_velocity(tmp_path):
    rm.add_body(rm.Mesh.icosphere(0.5, 0), pos=(0, 0, 0), material=RUBBER)
    first = O.bodies.append(utils.sphere((1, 2, 3), 0.25))
    O.bodies.appendClumped([utils.sphere((5, 0, 0), 0.5), utils.sphere((6, 0, 0), 0.5)])
    O.bodies[first].state.vel = (0.5, 0, -1)
    piece, arrays = read_piece(write_spheres_vtp(str(tmp_path / "spheres.vtp")))
    assert piece.get("NumberOfVerts") == "3" and piece.get("NumberOfPolys") == "0"
    np.testing.assert_array_equal(arrays["body_id"], [first, first + 1, first + 2])
    np.testing.assert_array_equal(arrays["Points"], [[1, 2, 3], [5, 0, 0], [6, 0, 0]])
    np.testing.assert_array_equal(arrays["radius"], [0.25, 0.5, 0.5])
    np.testing.assert_array_equal(arrays["velocity"][0], [0.5, 0, -1])
    np.testing.assert_array_equal(arrays["connectivity"], [0, 1, 2])


def test_series_indexes_frames_by_time(tmp_path):
    rm.add_body(rm.Mesh.icosphere(0.5, 0), pos=(0, 0, 0), material=RUBBER)
    series = VtkSeries(str(tmp_path))
    series.write()
    O.dt = 0.1
    O.step()
    series.write()
    datasets = ElementTree.parse(tmp_path / "rounded_bodies.pvd").getroot().findall("Collection/DataSet")
    assert [float(d.get("timestep")) for d in datasets] == [0.0, O.time]
    assert all((tmp_path / d.get("file")).exists() for d in datasets)


def test_series_with_spheres_has_them_as_a_second_part(tmp_path):
    rm.add_body(rm.Mesh.icosphere(0.5, 0), pos=(0, 0, 0), material=RUBBER)
    O.bodies.append(utils.sphere((1, 2, 3), 0.25))
    series = VtkSeries(str(tmp_path), prefix="mixed", spheres=True)
    series.write()
    O.dt = 0.1
    O.step()
    series.write()
    datasets = ElementTree.parse(tmp_path / "mixed.pvd").getroot().findall("Collection/DataSet")
    assert [(float(d.get("timestep")), d.get("part"), d.get("file")) for d in datasets] == [
        (0.0, "0", "mixed_00000000.vtp"), (0.0, "1", "mixed_spheres_00000000.vtp"),
        (O.time, "0", "mixed_00000001.vtp"), (O.time, "1", "mixed_spheres_00000001.vtp")]
    assert read_piece(tmp_path / "mixed_spheres_00000001.vtp")[1]["radius"] == [0.25]


# S1's 250 gummy bears (554 nodes each): 27.7 MB of arrays as decimal text; the compressed binary frame is a
# quarter of that (6.7 MB measured; 7 MB leaves room for other random poses, whose points compress alike).
def test_a_frame_of_s1_is_small(tmp_path):
    mesh = rm.Mesh.reference_shape("gummy_bear")
    rng = np.random.default_rng(1)
    for _ in range(250):
        q = Quaternion(*rng.normal(size=4))
        q.normalize()
        rm.add_body(mesh, pos=tuple(rng.uniform(-0.2, 0.2, 3)), ori=q, material=RUBBER)
    assert os.path.getsize(write_vtp(str(tmp_path / "s1.vtp"))) < 7e6


# The contact force each triangle received in the last step, as cell data: a 642-node ball settled on a Wall
# (damped, 0.3 s) presses on it with its weight, and only the triangles near its lowest point touch it.
def test_cells_hold_the_contact_force_of_the_last_step(tmp_path):
    from yade import ForceResetter, NewtonIntegrator
    material = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
    ball = rm.add_body(rm.Mesh.icosphere(0.025, 3), pos=(0, 0, 0.0249), material=material)
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, material)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    series = VtkSeries(str(tmp_path))  # keeps the forces per triangle from the next step on
    O.dt = 0.2 * rm.critical_timestep()
    O.run(int(0.3 / O.dt), True)
    series.write()
    piece, arrays = read_piece(os.path.join(str(tmp_path), f"rounded_bodies_{O.iter:08d}.vtp"))
    force, pressure = arrays["contact_force"], arrays["contact_pressure"]
    mesh = rm.rounded_bodies()[ball]
    assert force.shape == (len(mesh.triangles), 3)
    # The cells add up to what the engine gave the body (the same terms, summed in another order: round-off) ...
    np.testing.assert_allclose(force.sum(axis=0), O.forces.f(ball), rtol=1e-12, atol=1e-15)
    # ... which, settled, is its weight: the remaining bounce of A = 0.01 s damping decays as exp(-t / 2A)-like
    # within 0.3 s to well below 0.1 % of it.
    weight = O.bodies[ball].state.mass * 9.81
    assert force.sum(axis=0)[2] == pytest.approx(weight, rel=1e-3)
    np.testing.assert_allclose(pressure, np.linalg.norm(force, axis=1) / mesh.areas, rtol=1e-15)
    # Cells whose triangle lies wholly above the overlap (0.3 mm) do not touch the wall: exactly zero.
    corners = arrays["Points"][arrays["connectivity"].reshape(-1, 3)]
    lowest = corners[:, :, 2].min(axis=1)
    assert np.all(force[lowest > 1e-3] == 0) and np.count_nonzero(force[lowest > 1e-3]) == 0
    assert np.count_nonzero(np.linalg.norm(force, axis=1)) >= 3


def test_no_force_cells_unless_kept(tmp_path):
    rm.add_body(rm.Mesh.icosphere(0.5, 1), pos=(0, 0, 0), material=RUBBER)
    _, arrays = read_piece(write_vtp(str(tmp_path / "bodies.vtp")))
    assert "contact_force" not in arrays and "contact_pressure" not in arrays
    rm.keep_triangle_forces()
    _, arrays = read_piece(write_vtp(str(tmp_path / "bodies.vtp")))
    np.testing.assert_array_equal(arrays["contact_force"], 0)  # before any step: no contact force yet


def rotation(axis, angle):
    """The rotation matrix of `angle` [rad] about the unit vector `axis` (Rodrigues' formula)."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]], float)
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


# Facets and Boxes, partners or not, as polygons in global coordinates: a Facet's corners where utils.facet was
# given them, a Box's eight corners at pos +- its half extents along its turned axes; cell data per polygon.
def test_partners_are_the_facets_and_boxes_in_global_coordinates(tmp_path):
    corners = np.array([[0.1, 0.2, 0.3], [0.5, 0.2, 0.3], [0.1, 0.6, 0.4]])
    facet = O.bodies.append(utils.facet([Vector3(*c) for c in corners]))
    turn = Quaternion(Vector3(1, 1, 0).normalized(), 0.7)
    box = O.bodies.append(utils.box((1, 2, 3), (0.1, 0.2, 0.3), orientation=turn))
    rm.add_body(rm.Mesh.icosphere(0.05, 1), pos=(0, 0, 1), material=RUBBER)  # neither: not in the file
    O.bodies.append(utils.sphere((5, 5, 5), 0.1))
    O.bodies.append(utils.wall(0, axis=2))
    rm.assign_material(box, RUBBER)
    piece, arrays = read_piece(write_partners_vtp(str(tmp_path / "partners.vtp")))
    assert (piece.get("NumberOfPoints"), piece.get("NumberOfPolys"), piece.get("NumberOfVerts")) == ("11", "7", "0")
    points = arrays["Points"]
    np.testing.assert_allclose(points[:3], corners, atol=1e-15)
    # the box: every corner at pos + R (+-a, +-b, +-c), R the turn
    half = np.array([0.1, 0.2, 0.3])
    expected = [np.array([1, 2, 3]) + rotation(np.array([1, 1, 0]) / np.sqrt(2), 0.7) @ (np.array(s) * half)
                for s in [(sx, sy, sz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]]
    np.testing.assert_allclose(points[3:], expected, atol=1e-14)
    np.testing.assert_array_equal(arrays["offsets"], [3, 7, 11, 15, 19, 23, 27])
    faces = arrays["connectivity"][3:].reshape(6, 4)
    assert sorted(np.unique(faces)) == list(range(3, 11))
    for face in faces:  # a quad in a plane, counter-clockwise seen from outside: its normal points away from pos
        a, b, c, d = points[face]
        normal = np.cross(b - a, d - a)
        assert np.dot(normal, (a + b + c + d) / 4 - [1, 2, 3]) > 0
        assert abs(np.dot(normal / np.linalg.norm(normal), c - a)) < 1e-14
    np.testing.assert_array_equal(arrays["body_id"], [facet] + [box] * 6)
    np.testing.assert_array_equal(arrays["shape"], [0] + [1] * 6)
    np.testing.assert_array_equal(arrays["partner"], [0] + [1] * 6)
    np.testing.assert_array_equal(arrays["force"], np.zeros((7, 3)))


# A drum's Facets turned by YADE's RotationEngine: each body's pos and ori move, its vertices stay in its own frame;
# the file has the triangles where the turn put them (Rodrigues' formula about the engine's axis and point), and
# the force YADE's O.forces holds for each body.
def test_facets_turned_by_a_rotation_engine(tmp_path):
    from yade import ForceResetter, NewtonIntegrator, RotationEngine
    triangles = [np.array([[0.15, -0.06, 0.0], [0.15, 0.06, 0.0], [0.1, 0.0, 0.1]]),
                 np.array([[0.0, 0.0, -0.15], [0.1, 0.05, -0.1], [-0.1, 0.0, -0.12]])]
    ids = [O.bodies.append(utils.facet([Vector3(*p) for p in t], fixed=True)) for t in triangles]
    centre = np.array([0.01, 0.0, -0.02])
    O.engines = [ForceResetter(), RotationEngine(ids=ids, rotationAxis=(0, 1, 0), angularVelocity=3,
                                                 rotateAroundZero=True, zeroPoint=tuple(centre)),
                 NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-3
    O.run(250, True)
    O.forces.addF(ids[1], Vector3(1, 2, 3))
    _, arrays = read_piece(write_partners_vtp(str(tmp_path / "drum.vtp")))
    turned = [(t - centre) @ rotation(np.array([0, 1, 0]), 3 * O.time).T + centre for t in triangles]
    np.testing.assert_allclose(arrays["Points"], np.vstack(turned), atol=1e-12)
    np.testing.assert_array_equal(arrays["connectivity"], range(6))
    np.testing.assert_array_equal(arrays["force"], [[0, 0, 0], [1, 2, 3]])


def test_a_scene_without_facets_or_boxes_writes_an_empty_piece(tmp_path):
    O.bodies.append(utils.wall(0, axis=2))
    piece, arrays = read_piece(write_partners_vtp(str(tmp_path / "none.vtp")))
    assert piece.get("NumberOfPoints") == "0" and piece.get("NumberOfPolys") == "0"
    assert len(arrays["Points"]) == 0 and len(arrays["body_id"]) == 0 and arrays["force"].shape == (0, 3)


def test_series_with_partners_has_them_as_the_last_part(tmp_path):
    rm.add_body(rm.Mesh.icosphere(0.5, 0), pos=(0, 0, 0), material=RUBBER)
    O.bodies.append(utils.facet([(0, 0, -1), (1, 0, -1), (0, 1, -1)]))
    for spheres, parts in ((False, ["0", "1"]), (True, ["0", "1", "2"])):
        folder = tmp_path / str(spheres)
        VtkSeries(str(folder), prefix="drum", spheres=spheres, partners=True).write()
        datasets = ElementTree.parse(folder / "drum.pvd").getroot().findall("Collection/DataSet")
        assert [d.get("part") for d in datasets] == parts
        assert datasets[-1].get("file") == "drum_partners_00000000.vtp"
        piece, arrays = read_piece(folder / datasets[-1].get("file"))
        assert piece.get("NumberOfPolys") == "1"
        np.testing.assert_array_equal(arrays["Points"], [[0, 0, -1], [1, 0, -1], [0, 1, -1]])
