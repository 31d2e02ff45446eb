"""ParaView-readable export of the rounded bodies and of YADE's spheres.

    write_vtp(path)          one VTK XML PolyData file with every rounded body's surface in global
                             coordinates; cell data: body id, radius of curvature [m], mean curvature [1/m],
                             and, when the last step kept them (keep_triangle_forces()), the contact force [N]
                             each triangle received in it and its magnitude per area, contact_pressure [Pa]
    write_spheres_vtp(path)  YADE's Spheres of the scene (partners or not, clump members too) as points;
                             point data: body id, radius [m], velocity [m/s]; ParaView's Glyph filter (sphere,
                             scale by "radius", factor 2) draws them
    write_partners_vtp(path) YADE's Facets and Boxes of the scene (contact partners or not) as polygons in
                             global coordinates, posed by their bodies' pos and ori: a Facet as its triangle, a Box
                             as its six faces (quads, counter-clockwise seen from outside); cell data: body id,
                             shape (0 Facet, 1 Box), partner (1 if rm.assign_material made the body a contact
                             partner of the rounded bodies), force [N] on the body in the last step (O.forces,
                             the same on every face of a Box); what a drum, silo or hopper of Facets looks like
                             in ParaView without YADE's VTKRecorder. Walls, infinite planes, are left out
    write_mesh_vtp(mesh, path)  one Mesh in its own (principal) frame; cell data: radius, curvature,
                             principal_curvatures (k1, k2) [1/m], principal_direction (of k1; kept out of
                             the scene's frames, which they would double);
                             point data: node curvature computed from the mesh (Eq. 1)
    write_csv(path, header, rows)  a table of results, one header row then the rows (the CSV beside each plot)
    VtkSeries(directory, spheres=False, partners=False)  numbered .vtp files plus a .pvd collection indexed
                             by simulated time; call .write() when a frame is wanted, e.g. from a PyRunner (it
                             turns keep_triangle_forces() on, so frames have the contact forces). With
                             spheres=True each frame also has the spheres, and with partners=True the Facets and
                             Boxes, as further parts of the collection (part 1, then 2 with both), so that
                             ParaView shows them all in one time series

Arrays are written in VTK's binary XML encoding: each DataArray holds base64 text of its zlib-compressed
little-endian values, preceded by VTK's compression header (UInt64: number of blocks, block size, size of
the last block, compressed size of each block; base64-encoded on its own). Values are read back exactly
and a frame is a quarter of the same arrays as decimal text: 6.7 MB for the 250 gummy bears of scene S1
(doc/scenes.md) against 27.7 MB. ParaView and VTK read the files as their own.
"""
import base64
import csv
import os
import xml.etree.ElementTree as ElementTree
import zlib

import numpy as np
from yade import Box, Facet, O, Sphere

from . import scene
from .scene import rounded_bodies

# Bytes of values per compressed block. VTK's own writers use 32 kB; bodies sharing a mesh repeat its
# per-triangle arrays (9 kB per gummy bear), which zlib finds again only within a block: 1 MiB blocks make
# a frame of S1 6.7 MB instead of 8.1 MB. VTK's reader takes any block size the header gives.
_BLOCK = 1 << 20
_TYPES = {np.dtype("<f8"): "Float64", np.dtype("<i8"): "Int64"}


def write_csv(path, header, rows):
    """Writes `header` then `rows` (sequences of values) to the CSV file `path`."""
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)


def _surfaces():
    """Points, triangles and cell data of every rounded body in global coordinates. The contact force of each
    triangle (scene.triangle_forces()) goes with them when the engine keeps it."""
    forces = scene.triangle_forces()
    with_forces = forces is not None
    points, triangles = [np.zeros((0, 3))], [np.zeros((0, 3), int)]
    cells = {"body_id": [np.zeros(0, int)], "radius": [np.zeros(0)], "curvature": [np.zeros(0)]}
    if with_forces:
        cells.update(contact_force=[np.zeros((0, 3))], contact_pressure=[np.zeros(0)])
    offset = 0
    for body_id, mesh in sorted(rounded_bodies().items()):
        state = O.bodies[body_id].state
        points.append(mesh.vertices @ np.array(state.ori.toRotationMatrix()).T + np.array(state.pos))
        triangles.append(mesh.triangles + offset)
        cells["body_id"].append(np.full(len(mesh.triangles), body_id))
        cells["radius"].append(mesh.radii)
        cells["curvature"].append(mesh.curvatures)
        if with_forces:
            force = forces.get(body_id, np.zeros((len(mesh.triangles), 3)))
            cells["contact_force"].append(force)
            cells["contact_pressure"].append(np.linalg.norm(force, axis=1) / mesh.areas)
        offset += len(mesh.vertices)
    return np.vstack(points), np.vstack(triangles), {name: np.concatenate(v) for name, v in cells.items()}


def _encoded(values):
    """VTK's compressed binary encoding of `values` (a little-endian array)."""
    raw = values.tobytes()
    blocks = [zlib.compress(raw[i:i + _BLOCK]) for i in range(0, len(raw), _BLOCK)]
    header = np.array([len(blocks), _BLOCK, len(raw) % _BLOCK] + [len(b) for b in blocks], dtype="<u8")
    return (base64.b64encode(header.tobytes()) + base64.b64encode(b"".join(blocks))).decode("ascii")


def _data_array(parent, name, values, components=1):
    values = np.asarray(values)
    values = values.astype("<i8" if np.issubdtype(values.dtype, np.integer) else "<f8")
    array = ElementTree.SubElement(parent, "DataArray", type=_TYPES[values.dtype], Name=name, format="binary")
    if components > 1:
        array.set("NumberOfComponents", str(components))
    array.text = _encoded(np.ascontiguousarray(values))


def _polydata(points, cells, cell_kind):
    """The VTKFile and Piece of a PolyData with `cells` of `cell_kind` ('Polys' or 'Verts'): one row of point
    indices per cell, or a list of such rows of any lengths (polygons of several sizes)."""
    root = ElementTree.Element("VTKFile", type="PolyData", version="1.0", byte_order="LittleEndian",
                               header_type="UInt64", compressor="vtkZLibDataCompressor")
    if isinstance(cells, list):
        sizes = np.array([len(c) for c in cells], np.int64)
        connectivity = np.concatenate([np.zeros(0, np.int64)] + [np.asarray(c, np.int64) for c in cells])
    else:
        cells = np.asarray(cells, np.int64)
        sizes, connectivity = np.full(len(cells), cells.shape[1], np.int64), cells.reshape(-1)
    piece = ElementTree.SubElement(ElementTree.SubElement(root, "PolyData"), "Piece",
                                   NumberOfPoints=str(len(points)),
                                   **{f"NumberOf{kind}": str(len(sizes) if kind == cell_kind else 0)
                                      for kind in ("Verts", "Lines", "Strips", "Polys")})
    _data_array(ElementTree.SubElement(piece, "Points"), "Points", np.asarray(points, float).reshape(-1, 3), 3)
    element = ElementTree.SubElement(piece, cell_kind)
    _data_array(element, "connectivity", connectivity)
    _data_array(element, "offsets", np.cumsum(sizes))
    return root, piece


def _write(root, path):
    ElementTree.ElementTree(root).write(path, xml_declaration=True, encoding="utf-8")
    return path


def _write_polydata(path, points, triangles, cell_data, point_data=None):
    root, piece = _polydata(points, np.asarray(triangles).reshape(-1, 3), "Polys")
    if point_data:
        points_element = ElementTree.SubElement(piece, "PointData", Scalars=next(iter(point_data)))
        for name, values in point_data.items():
            _data_array(points_element, name, values)
    cells = ElementTree.SubElement(piece, "CellData", Scalars="radius")
    for name, values in cell_data.items():
        values = np.asarray(values)
        _data_array(cells, name, values, values.shape[1] if values.ndim == 2 else 1)
    return _write(root, path)


def write_vtp(path):
    """Writes the rounded bodies of the current scene to `path` (.vtp) and returns the path."""
    points, triangles, cell_data = _surfaces()
    return _write_polydata(path, points, triangles, cell_data)


def write_spheres_vtp(path):
    """Writes YADE's Spheres of the current scene to `path` (.vtp) and returns the path."""
    spheres = [b for b in O.bodies if isinstance(b.shape, Sphere)]
    root, piece = _polydata([list(b.state.pos) for b in spheres], np.arange(len(spheres)).reshape(-1, 1), "Verts")
    data = ElementTree.SubElement(piece, "PointData", Scalars="radius", Vectors="velocity")
    _data_array(data, "body_id", [b.id for b in spheres])
    _data_array(data, "radius", [b.shape.radius for b in spheres])
    _data_array(data, "velocity", np.array([list(b.state.vel) for b in spheres], float).reshape(-1, 3), 3)
    return _write(root, path)


# A Box's corners (signs of its half extents along its body's axes) and its faces, counter-clockwise seen from
# outside: -x, +x, -y, +y, -z, +z.
_BOX_CORNERS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
_BOX_FACES = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]])


def _partner_surfaces():
    """Points, polygons (a list of point index rows) and cell data of the scene's Facets and Boxes in global
    coordinates. YADE keeps a Facet's vertices in its body's frame, relative to the body's position, and a Box's
    half extents along its body's axes."""
    partners = {int(i) for i in scene._tags_named("partner")}
    points, polygons = [np.zeros((0, 3))], []
    cells = {"body_id": [], "shape": [], "partner": [], "force": []}
    offset = 0
    for body in O.bodies:
        if body is None or not isinstance(body.shape, (Facet, Box)):
            continue
        rotation, position = np.array(body.state.ori.toRotationMatrix()), np.array(body.state.pos)
        if isinstance(body.shape, Facet):
            local, faces, kind = np.array([list(v) for v in body.shape.vertices], float), np.array([[0, 1, 2]]), 0
        else:
            local, faces, kind = _BOX_CORNERS * np.array(body.shape.extents), _BOX_FACES, 1
        points.append(local @ rotation.T + position)
        polygons.extend(faces + offset)
        offset += len(local)
        cells["body_id"].extend([body.id] * len(faces))
        cells["shape"].extend([kind] * len(faces))
        cells["partner"].extend([int(body.id in partners)] * len(faces))
        cells["force"].extend([list(O.forces.f(body.id))] * len(faces))
    cells = {name: np.array(values, int if name != "force" else float) for name, values in cells.items()}
    cells["force"] = cells["force"].reshape(-1, 3)
    return np.vstack(points), polygons, cells


def write_partners_vtp(path):
    """Writes the current scene's Facets and Boxes (contact partners or not) to `path` (.vtp) and returns the
    path."""
    points, polygons, cell_data = _partner_surfaces()
    root, piece = _polydata(points, polygons, "Polys")
    cells = ElementTree.SubElement(piece, "CellData", Scalars="body_id", Vectors="force")
    for name, values in cell_data.items():
        _data_array(cells, name, values, 3 if name == "force" else 1)
    return _write(root, path)


def write_mesh_vtp(mesh, path):
    """Writes `mesh` in its principal frame to `path` (.vtp) with its curvature, and returns the path."""
    cells = {"radius": mesh.radii, "curvature": mesh.curvatures, "principal_curvatures": mesh.principal_curvatures,
             "principal_direction": mesh.principal_directions}
    return _write_polydata(path, mesh.vertices, mesh.triangles, cells, {"node_curvature": mesh.node_curvatures})


class VtkSeries:
    """Frames `<prefix>_<iteration>.vtp` (and `<prefix>_spheres_<iteration>.vtp` with spheres=True,
    `<prefix>_partners_<iteration>.vtp` with partners=True) in `directory`, and the collection `<prefix>.pvd` that
    ParaView opens as one time series: rounded bodies as part 0, then spheres and then Facets and Boxes, each
    that is asked for as the next part."""

    def __init__(self, directory, prefix="rounded_bodies", spheres=False, partners=False):
        scene.keep_triangle_forces()
        self.directory = directory
        self.prefix = prefix
        self.spheres = spheres
        self.partners = partners
        self.frames = []
        os.makedirs(directory, exist_ok=True)

    def write(self):
        names = [f"{self.prefix}_{O.iter:08d}.vtp"]
        write_vtp(os.path.join(self.directory, names[0]))
        if self.spheres:
            names.append(f"{self.prefix}_spheres_{O.iter:08d}.vtp")
            write_spheres_vtp(os.path.join(self.directory, names[-1]))
        if self.partners:
            names.append(f"{self.prefix}_partners_{O.iter:08d}.vtp")
            write_partners_vtp(os.path.join(self.directory, names[-1]))
        self.frames.append((O.time, names))
        root = ElementTree.Element("VTKFile", type="Collection", version="1.0")
        collection = ElementTree.SubElement(root, "Collection")
        for time, frame in self.frames:
            for part, name in enumerate(frame):
                ElementTree.SubElement(collection, "DataSet", timestep=repr(time), part=str(part), file=name)
        _write(root, os.path.join(self.directory, self.prefix + ".pvd"))
