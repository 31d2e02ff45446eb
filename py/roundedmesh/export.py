"""ParaView-readable export of the rounded bodies.

    write_vtp(path)          one VTK XML PolyData file with every rounded body's surface in global
                             coordinates; cell data: body id, radius of curvature [m], mean curvature [1/m]
    write_mesh_vtp(mesh, path)  one Mesh in its own (principal) frame; cell data: radius, curvature;
                             point data: node curvature computed from the mesh (Eq. 1)
    VtkSeries(directory)     numbered .vtp files plus a .pvd collection indexed by simulated time; call
                             .write() when a frame is wanted, e.g. from a PyRunner
"""
import os
import xml.etree.ElementTree as ElementTree

import numpy as np
from yade import O

from .scene import rounded_bodies


def _surfaces():
    points, triangles, body_ids, radii, curvatures = [], [], [], [], []
    offset = 0
    for body_id, mesh in sorted(rounded_bodies().items()):
        state = O.bodies[body_id].state
        points.append(mesh.vertices @ np.array(state.ori.toRotationMatrix()).T + np.array(state.pos))
        triangles.append(mesh.triangles + offset)
        body_ids.append(np.full(len(mesh.triangles), body_id))
        radii.append(mesh.radii)
        curvatures.append(mesh.curvatures)
        offset += len(mesh.vertices)
    if not points:
        return np.zeros((0, 3)), np.zeros((0, 3), int), {"body_id": np.zeros(0, int), "radius": np.zeros(0),
                                                         "curvature": np.zeros(0)}
    return np.vstack(points), np.vstack(triangles), {"body_id": np.concatenate(body_ids),
                                                     "radius": np.concatenate(radii),
                                                     "curvature": np.concatenate(curvatures)}


def _data_array(parent, name, values, components=1):
    values = np.asarray(values)
    kind = "Int64" if np.issubdtype(values.dtype, np.integer) else "Float64"
    array = ElementTree.SubElement(parent, "DataArray", type=kind, Name=name, format="ascii")
    if components > 1:
        array.set("NumberOfComponents", str(components))
    array.text = " ".join(repr(v) for v in values.ravel().tolist())


def _write_polydata(path, points, triangles, cell_data, point_data=None):
    root = ElementTree.Element("VTKFile", type="PolyData", version="1.0", byte_order="LittleEndian")
    piece = ElementTree.SubElement(ElementTree.SubElement(root, "PolyData"), "Piece",
                                   NumberOfPoints=str(len(points)), NumberOfPolys=str(len(triangles)))
    _data_array(ElementTree.SubElement(piece, "Points"), "Points", np.asarray(points, float), 3)
    polys = ElementTree.SubElement(piece, "Polys")
    _data_array(polys, "connectivity", np.asarray(triangles, np.int64))
    _data_array(polys, "offsets", 3 * np.arange(1, len(triangles) + 1, dtype=np.int64))
    if point_data:
        points_element = ElementTree.SubElement(piece, "PointData", Scalars=next(iter(point_data)))
        for name, values in point_data.items():
            _data_array(points_element, name, values)
    cells = ElementTree.SubElement(piece, "CellData", Scalars="radius")
    for name, values in cell_data.items():
        _data_array(cells, name, values)
    ElementTree.ElementTree(root).write(path, xml_declaration=True, encoding="utf-8")
    return path


def write_vtp(path):
    """Writes the rounded bodies of the current scene to `path` (.vtp) and returns the path."""
    points, triangles, cell_data = _surfaces()
    return _write_polydata(path, points, triangles, cell_data)


def write_mesh_vtp(mesh, path):
    """Writes `mesh` in its principal frame to `path` (.vtp) with its curvature, and returns the path."""
    return _write_polydata(path, mesh.vertices, mesh.triangles, {"radius": mesh.radii, "curvature": mesh.curvatures},
                           {"node_curvature": mesh.node_curvatures})


class VtkSeries:
    """Frames `<prefix>_<iteration>.vtp` in `directory` and the collection `<prefix>.pvd` that ParaView
    opens as one time series."""

    def __init__(self, directory, prefix="rounded_bodies"):
        self.directory = directory
        self.prefix = prefix
        self.frames = []
        os.makedirs(directory, exist_ok=True)

    def write(self):
        name = f"{self.prefix}_{O.iter:08d}.vtp"
        write_vtp(os.path.join(self.directory, name))
        self.frames.append((O.time, name))
        root = ElementTree.Element("VTKFile", type="Collection", version="1.0")
        collection = ElementTree.SubElement(root, "Collection")
        for time, frame in self.frames:
            ElementTree.SubElement(collection, "DataSet", timestep=repr(time), part="0", file=frame)
        ElementTree.ElementTree(root).write(os.path.join(self.directory, self.prefix + ".pvd"),
                                            xml_declaration=True, encoding="utf-8")
