"""The paper's reference particle shapes (pear, gummy bear; doc/scenes.md, S1), defined in shapes.json:
smooth blends of spheres and capsules, meshed with CGAL and scaled to the volume-equivalent radius given
there (0.025 m)."""
import functools
import json
import math
import os

from ._core import Mesh

_DEFINITIONS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "shapes.json")


@functools.lru_cache(maxsize=None)
def definitions():
    """The contents of shapes.json."""
    with open(_DEFINITIONS) as f:
        return json.load(f)


def names():
    """Names of the reference shapes."""
    return sorted(definitions()["shapes"])


def mesh_with_scale(name, nodes=None, curvature="computed"):
    """(mesh, scale): the reference shape meshed with about `nodes` nodes (default: the paper's count) and
    the factor [m per shape unit] that gives it the volume of a sphere of the volume-equivalent radius;
    curvature as for reference_shape."""
    shapes = definitions()["shapes"]
    if name not in shapes:
        raise ValueError(f"name: unknown reference shape {name!r}; known: {', '.join(names())}")
    return _meshed(name, shapes[name]["paper_node_count"] if nodes is None else int(nodes), curvature)


@functools.lru_cache(maxsize=None)
def _meshed(name, nodes, curvature):
    shape = definitions()["shapes"][name]
    primitives = []
    for p in shape["primitives"]:
        if p["type"] == "sphere":
            primitives.append((tuple(p["center"]), tuple(p["center"]), p["radius"]))
        elif p["type"] == "capsule":
            primitives.append((tuple(p["a"]), tuple(p["b"]), p["radius"]))
        else:
            raise ValueError(f"shapes.json: {name} has a primitive of unknown type {p['type']!r}")
    radius = definitions()["volume_equivalent_radius"]
    return Mesh._blended_shape(shape["blend_k"], primitives, nodes, 4 / 3 * math.pi * radius**3, curvature)


def reference_shape(name, nodes=None, curvature="computed"):
    """Mesh.reference_shape(name, nodes=None, curvature='computed'): the reference shape `name` ('pear' or
    'gummy_bear') of shapes.json, meshed from its implicit function with CGAL into near-equilateral triangles with
    about `nodes` nodes (typically within 2 %; default the paper's 486 and 554), scaled so that its volume is that
    of a sphere of radius 0.025 m. curvature: 'computed' (the paper's: each triangle's mean curvature from the mesh,
    Eq. 1, and both principal curvatures estimated from it) or 'exact' (the smooth shape's, from the implicit
    function's shape operator at the triangle). Concave regions (the gummy bear's neck, between the legs) get
    negative curvature. Meshes are cached: asking again for the same shape, node count and curvature returns the
    same Mesh."""
    return mesh_with_scale(name, nodes, curvature)[0]
