"""Writes the seed corpus of surface_repair_fuzzer (fuzz/corpus/surface_repair_fuzzer/) from the OBJ and OFF
files of tests/data, good and broken, in that target's input format (fuzz/SoupFormat.hpp).
The other targets take tests/data's files as they are (fuzz/run). Run: /usr/bin/python3 fuzz/make_seeds.py"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "tests", "data")
OUT = os.path.join(HERE, "corpus", "surface_repair_fuzzer")


def read_obj(text):
    points, faces = [], []
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["v"]:
            points.append([float(w) for w in words[1:4]])
        elif words[:1] == ["f"]:
            faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return points, faces


def read_off(text):
    words = [w for line in text.splitlines() for w in line.split("#")[0].split()]
    if not words or words[0] != "OFF":
        raise ValueError("not OFF")
    nv, nf = int(words[1]), int(words[2])
    values = words[4:]
    points = [[float(v) for v in values[3 * i:3 * i + 3]] for i in range(nv)]
    faces, k = [], 3 * nv
    for _ in range(nf):
        n = int(values[k])
        faces.append([int(v) for v in values[k + 1:k + 1 + n]])
        k += n + 1
    return points, faces


def coordinate(x):
    grid = x * 16
    if grid == int(grid) and -128 <= grid < 127:
        return bytes([int(grid) + 128])
    return b"\xff" + struct.pack("<d", x)


def encode(points, faces):
    out = bytes([len(points)]) + b"".join(coordinate(c) for p in points for c in p)
    for face in faces:
        out += bytes([len(face)]) + b"".join(struct.pack("<H", i % 65536) for i in face)
    return out


os.makedirs(OUT, exist_ok=True)
for name in sorted(os.listdir(DATA)):
    reader = {".obj": read_obj, ".off": read_off}.get(os.path.splitext(name)[1])
    if reader is None:
        continue
    try:
        with open(os.path.join(DATA, name)) as f:
            points, faces = reader(f.read())
    except (ValueError, IndexError):
        continue  # a file that is broken before it is a soup: the readers' fuzzers take it
    with open(os.path.join(OUT, os.path.splitext(name)[0] + ".soup"), "wb") as f:
        f.write(encode(points, faces))
