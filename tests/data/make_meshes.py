"""Writes the small mesh files of tests/data: one good shape in every supported format, and one broken
file per defect class that Mesh.load must repair or name. Written with numpy alone, independently of CGAL
(the reader under test). Run from anywhere: /usr/bin/python3 tests/data/make_meshes.py

The good shape is an octahedron with semi-axes 1.5, 1 and 0.75 along x, y, z: coordinates exact in binary
and decimal, so that every format (STL keeps single precision) stores exactly the same numbers."""
import os
import struct

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
VERTICES = np.array([[1.5, 0, 0], [-1.5, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 0.75], [0, 0, -0.75]])
# Counter-clockwise seen from outside.
TRIANGLES = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])


def path(name):
    return os.path.join(HERE, name)


def number(x):
    return repr(float(x))


def write_obj(name, vertices, faces, comment="octahedron"):
    with open(path(name), "w") as f:
        f.write(f"# {comment}\n")
        f.writelines(f"v {' '.join(number(c) for c in v)}\n" for v in vertices)
        f.writelines(f"f {' '.join(str(i + 1) for i in face)}\n" for face in faces)


def write_off(name, vertices, faces):
    with open(path(name), "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        f.writelines(f"{' '.join(number(c) for c in v)}\n" for v in vertices)
        f.writelines(f"{len(face)} {' '.join(str(i) for i in face)}\n" for face in faces)


def normal(vertices, face):
    a, b, c = (np.asarray(vertices[i], float) for i in face)
    n = np.cross(b - a, c - a)
    return n / np.linalg.norm(n)


def write_ascii_stl(name, vertices, faces):
    with open(path(name), "w") as f:
        f.write("solid octahedron\n")
        for face in faces:
            f.write(f"  facet normal {' '.join(number(c) for c in normal(vertices, face))}\n    outer loop\n")
            f.writelines(f"      vertex {' '.join(number(c) for c in vertices[i])}\n" for i in face)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid octahedron\n")


def binary_stl(vertices, faces, declared=None, header=b"binary STL written by tests/data/make_meshes.py"):
    data = bytearray(header.ljust(80, b" "))
    data += struct.pack("<I", len(faces) if declared is None else declared)
    for face in faces:
        data += struct.pack("<3f", *normal(vertices, face))
        for i in face:
            data += struct.pack("<3f", *vertices[i])
        data += struct.pack("<H", 0)
    return bytes(data)


def write_ply(name, vertices, faces, binary):
    header = ["ply", "format binary_little_endian 1.0" if binary else "format ascii 1.0",
              f"element vertex {len(vertices)}", "property double x", "property double y", "property double z",
              f"element face {len(faces)}", "property list uchar int vertex_indices", "end_header"]
    with open(path(name), "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        if binary:
            for v in vertices:
                f.write(struct.pack("<3d", *v))
            for face in faces:
                f.write(struct.pack("<B", len(face)) + struct.pack(f"<{len(face)}i", *face))
        else:
            f.writelines(f"{' '.join(number(c) for c in v)}\n".encode() for v in vertices)
            f.writelines(f"{len(face)} {' '.join(str(i) for i in face)}\n".encode() for face in faces)


def write_gts(name, vertices, faces, comment="octahedron", order=None, after=""):
    """GTS (GNU Triangulated Surface): the counts, the vertices, the edges (1-based vertex numbers) and the faces
    (1-based edge numbers). A face's corners are met by walking its edges in the order listed (the corner the
    first two share is the second), counter-clockwise seen from outside, as libgts has it. Faces start at different
    edges and the edges run either way, so that a reader must follow the walk, not the edges' own directions.
    `order` edits the list of lines (for broken files); `after` is appended to the file."""
    edges, numbers, lines = [], {}, []
    for f, face in enumerate(faces):
        walk = []
        for k in range(3):
            a, b = face[k], face[(k + 1) % 3]
            key = (min(a, b), max(a, b))
            if key not in numbers:
                numbers[key] = len(edges)
                edges.append(key if (len(edges) % 2 == 0) else key[::-1])
            walk.append(numbers[key] + 1)
        start = f % 3
        lines.append(walk[start:] + walk[:start])
    text = [f"# {comment}, written by tests/data/make_meshes.py",
            f"{len(vertices)} {len(edges)} {len(lines)} GtsSurface GtsFace GtsEdge GtsVertex"]
    text += [" ".join(number(c) for c in v) for v in vertices]
    text += ["", "# edges"] + [f"{a + 1} {b + 1}" for a, b in edges]
    text += ["# faces"] + [" ".join(str(e) for e in walk) for walk in lines]
    if order is not None:
        text = order(text)
    with open(path(name), "w") as f:
        f.write("\n".join(text) + "\n" + after)


def main():
    # Good: the same octahedron in every format.
    write_obj("octahedron.obj", VERTICES, TRIANGLES)
    write_off("octahedron.off", VERTICES, TRIANGLES)
    write_ascii_stl("octahedron_ascii.stl", VERTICES, TRIANGLES)
    with open(path("octahedron_binary.stl"), "wb") as f:
        f.write(binary_stl(VERTICES, TRIANGLES))
    with open(path("octahedron_binary_solid_header.stl"), "wb") as f:  # as many exporters write them
        f.write(binary_stl(VERTICES, TRIANGLES, header=b"solid octahedron, but binary"))
    write_ply("octahedron_ascii.ply", VERTICES, TRIANGLES, binary=False)
    write_ply("octahedron_binary.ply", VERTICES, TRIANGLES, binary=True)
    write_gts("octahedron.gts", VERTICES, TRIANGLES)

    # Repaired silently.
    each_own = np.array([VERTICES[i] for face in TRIANGLES for i in face])
    write_obj("duplicate_vertices.obj", each_own, np.arange(len(each_own)).reshape(-1, 3),
              "octahedron, every triangle with its own three vertices (unwelded)")
    write_ascii_stl("inside_out.stl", VERTICES, TRIANGLES[:, ::-1])
    doubled_corner = [list(face) for face in TRIANGLES]
    doubled_corner[0] = [0, 2, 6, 4]  # vertex 6 repeats vertex 4: the face is a triangle once welded
    write_obj("repeated_corner.obj", np.vstack([VERTICES, VERTICES[4]]), doubled_corner,
              "octahedron whose face 0 runs through two copies of the same point")
    flipped = TRIANGLES.copy()
    flipped[2] = flipped[2][::-1]
    write_obj("inconsistent.obj", VERTICES, flipped, "octahedron with face 2 reversed")
    cube = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    write_obj("cube_quads.obj", cube, [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6],
                                       [3, 0, 4, 7]], "unit cube as six quads")

    # Refused, each with the defect named.
    write_obj("open.obj", VERTICES, TRIANGLES[1:], "octahedron with one face missing")
    unit = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
    mirrored = [1, 1, 0] - unit  # a second octahedron sharing the edge from (1, 0, 0) to (0, 1, 0)
    faces = np.vstack([TRIANGLES, TRIANGLES[:, ::-1] + 6])  # mirroring reverses orientation
    write_off("nonmanifold_edge.off", np.vstack([unit, mirrored]), faces)
    write_off("degenerate.off", [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2], [1, 0, 0]],
              [[0, 2, 4], [4, 2, 1], [0, 1, 3], [1, 4, 0], [0, 3, 2], [1, 2, 3]])
    write_obj("flat.obj", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 1]],
              "two triangles back to back: closed, but no volume")
    broken = VERTICES.copy()
    broken[3, 1] = np.nan
    write_ply("nan.ply", broken, TRIANGLES, binary=True)
    write_obj("nan.obj", broken, TRIANGLES, "octahedron with a NaN coordinate in vertex 4")
    write_off("nan.off", broken, TRIANGLES)
    write_ascii_stl("nan_ascii.stl", broken, TRIANGLES)
    write_off("opposite_parts.off", np.vstack([VERTICES, VERTICES + [5, 0, 0]]),
              np.vstack([TRIANGLES, TRIANGLES[:, ::-1] + 6]))
    write_obj("collapsed_face.obj", np.vstack([VERTICES, VERTICES[0], VERTICES[2]]),
              [list(face) for face in TRIANGLES] + [[0, 6, 7, 2]], "octahedron plus a face that welds down to two corners")
    open(path("empty.stl"), "wb").close()
    with open(path("truncated.stl"), "wb") as f:
        f.write(binary_stl(VERTICES, TRIANGLES)[:84 + 3 * 50 + 20])
    with open(path("not_a_mesh.off"), "w") as f:
        f.write("This is a text file, not a mesh.\n")
    # GTS files our own parser refuses, naming the line (pkg/io/GtsFile.cpp); also the seeds of gts_reader_fuzzer.
    write_gts("truncated.gts", VERTICES, TRIANGLES, "octahedron, the last two faces cut off", lambda t: t[:-2])
    write_gts("trailing_data.gts", VERTICES, TRIANGLES, "octahedron, with a line after its last face",
              after="1 2 3\n")
    write_gts("edge_out_of_range.gts", VERTICES, TRIANGLES, "octahedron whose edge 4 starts at vertex 7 of 6",
              lambda t: t[:13] + ["7 " + t[13].split()[1]] + t[14:])
    write_gts("degenerate_edge.gts", VERTICES, TRIANGLES, "octahedron whose edge 2 joins vertex 3 to itself",
              lambda t: t[:11] + ["3 3"] + t[12:])
    write_gts("unclosed_face.gts", VERTICES, TRIANGLES, "octahedron whose face 4 has its first edge twice",
              lambda t: t[:-5] + [t[-5].split()[0] + " " + t[-5].split()[0] + " " + t[-5].split()[2]] + t[-4:])


if __name__ == "__main__":
    main()
