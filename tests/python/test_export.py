"""ParaView export: a .vtp per frame and a .pvd collection."""
import xml.etree.ElementTree as ElementTree

import numpy as np
from yade import O
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh.export import VtkSeries, write_mesh_vtp, write_vtp

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)


def read_piece(path):
    piece = ElementTree.parse(path).getroot().find("PolyData/Piece")
    arrays = {a.get("Name"): np.array(a.text.split(), float) for a in piece.iter("DataArray")}
    return piece, arrays


def test_vtp_holds_every_body_in_global_coordinates(tmp_path):
    mesh = rm.Mesh.icosphere(0.5, 1)
    turn = Quaternion(Vector3(0, 0, 1), 0.5)
    rm.add_body(mesh, pos=(0, 0, 0), material=RUBBER)
    rm.add_body(mesh, pos=(3, 0, 1), ori=turn, material=RUBBER)
    piece, arrays = read_piece(write_vtp(str(tmp_path / "bodies.vtp")))
    assert int(piece.get("NumberOfPoints")) == 2 * 42 and int(piece.get("NumberOfPolys")) == 2 * 80
    points = arrays["Points"].reshape(-1, 3)
    expected = mesh.vertices @ np.array(turn.toRotationMatrix()).T + [3, 0, 1]
    np.testing.assert_allclose(points[42:], expected, atol=1e-14)
    np.testing.assert_array_equal(np.unique(arrays["body_id"]), [0, 1])
    np.testing.assert_allclose(arrays["radius"], 0.5)
    np.testing.assert_allclose(arrays["curvature"], 2.0)
    assert arrays["connectivity"].max() == 2 * 42 - 1


def test_a_mesh_alone_with_its_curvature(tmp_path):
    mesh = rm.Mesh.reference_shape("gummy_bear")
    piece, arrays = read_piece(write_mesh_vtp(mesh, str(tmp_path / "bear.vtp")))
    np.testing.assert_array_equal(arrays["Points"].reshape(-1, 3), mesh.vertices)
    np.testing.assert_array_equal(arrays["connectivity"].reshape(-1, 3), mesh.triangles)
    np.testing.assert_array_equal(arrays["curvature"], mesh.curvatures)
    np.testing.assert_array_equal(arrays["node_curvature"], mesh.node_curvatures)
    assert piece.find("PointData") is not None


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
