"""What roundedmesh knows about a scene, kept in the scene itself, in O.tags, so that O.save/O.load,
O.saveTmp/O.loadTmp and the GUI's reload keep the rounded bodies:
    roundedmesh.mesh.<key>     one record per distinct mesh
    roundedmesh.body.<id>      a rounded body: its mesh key and material (HertzMaterial.record(): by field name)
    roundedmesh.partner.<id>   a contact partner: its material
    roundedmesh.sphere.<id>    a sphere body: its material
    roundedmesh.revision       changes with every edit; the engine rebuilds its state when it differs
    roundedmesh.options.<key>  the options of an engine (rm.engine), as EngineOptions.record()'s JSON; its
                               PyRunner's command names the key, a hash of the record
    roundedmesh.options        the options of the engine made or run last: those rm.critical_timestep uses
    roundedmesh.springs        the contacts' tangential springs after the last step (doc/physics.md, "Friction"),
                               written by the step itself (py/module/ExposeEngine.cpp; the record is
                               pkg/io/SpringRecord.hpp's): "<token>:<record>"; a token the engine did not write
                               itself (a loaded scene) makes it take them
YADE cannot delete a tag; an entry set to "" is a deleted one.
"""
import base64
import hashlib
import json
import uuid
import weakref

import numpy as np
from yade import O
from yade.minieigenHP import Quaternion, Vector3

from ._core import EngineOptions, HertzMaterial, Mesh

_PREFIX = "roundedmesh."
_REVISION = _PREFIX + "revision"


def _tag(name):
    key = _PREFIX + name
    return O.tags[key] if O.tags.has_key(key) else ""


def _set_tag(name, value):
    O.tags[_PREFIX + name] = value


def _tags_named(kind):
    """{id or key: value} of the live entries roundedmesh.<kind>.<...>."""
    start = _PREFIX + kind + "."
    return {key[len(start):]: O.tags[key] for key in O.tags.keys() if key.startswith(start) and O.tags[key]}


def _new_revision():
    O.tags[_REVISION] = uuid.uuid4().hex


def _material_record(material):
    return material.record()


def _material(record):
    """The HertzMaterial of a record: by field name, or (scenes saved before) in the constructor's order."""
    return HertzMaterial(**record) if isinstance(record, dict) else HertzMaterial(*record)


def _encode(array, dtype):
    return base64.b64encode(np.ascontiguousarray(array, dtype=dtype).tobytes()).decode("ascii")


def _decode(text, dtype, columns=None):
    array = np.frombuffer(base64.b64decode(text), dtype=dtype)
    return array.reshape(-1, columns) if columns else array


_meshes = weakref.WeakValueDictionary()  # mesh key -> Mesh: bodies that share a mesh share it in memory
_keys = weakref.WeakKeyDictionary()      # Mesh -> its key, so that a mesh is hashed once


def _mesh_record(mesh):
    x, y, z, w = mesh.orientation  # YADE's Quaternion iterates as x, y, z, w
    return json.dumps({
        "vertices": _encode(mesh.vertices, "<f8"), "triangles": _encode(mesh.triangles, "<i8"),
        "radii": _encode(mesh.radii, "<f8"), "centroid": list(mesh.centroid),
        "orientation": [w, x, y, z], "curvatures": _encode(mesh.curvatures, "<f8"),
        "curvature_mode": mesh.curvature_mode, "max_radius": mesh.max_radius}, sort_keys=True)


def _store_mesh(mesh):
    """The key of `mesh` in the scene's tags, writing its record there if the scene lacks it."""
    record = None
    if mesh not in _keys:
        record = _mesh_record(mesh)
        _keys[mesh] = hashlib.sha1(record.encode()).hexdigest()[:16]
        _meshes.setdefault(_keys[mesh], mesh)
    key = _keys[mesh]
    if not _tag("mesh." + key):
        _set_tag("mesh." + key, record or _mesh_record(mesh))
    return key


def _restore_mesh(vertices, triangles, radii, centroid, orientation, curvatures=None, mode="prescribed",
                  max_radius=None, principal_curvatures=None, principal_directions=None):
    """Unpickles a Mesh (see Mesh.__reduce__), also from a scene's record. Meshes saved before curvatures were
    kept have only radii: their curvature was then the prescribed 1/R, and no radius exceeded the largest. Meshes
    saved before principal curvatures were kept get both equal to 1/R."""
    radii = np.asarray(radii, float)
    if curvatures is None:
        curvatures = 1 / radii
    if max_radius is None:
        max_radius = float(radii.max())
    if principal_curvatures is None:
        return Mesh._restore(vertices, triangles, radii, centroid, orientation, curvatures, mode, max_radius)
    k = np.asarray(principal_curvatures, float)
    return Mesh._restore(vertices, triangles, radii, centroid, orientation, curvatures, mode, max_radius,
                         k[:, 0].copy(), k[:, 1].copy(), principal_directions)


def _load_mesh(key):
    mesh = _meshes.get(key)
    if mesh is None:
        r = json.loads(_tag("mesh." + key))
        w, x, y, z = r["orientation"]
        # Scenes saved before curvatures were kept lack the last three fields; _restore_mesh fills them in.
        curvatures = _decode(r["curvatures"], "<f8") if "curvatures" in r else None
        mesh = _restore_mesh(_decode(r["vertices"], "<f8", 3), _decode(r["triangles"], "<i8", 3),
                             _decode(r["radii"], "<f8"), Vector3(*r["centroid"]), Quaternion(w, x, y, z),
                             curvatures, r.get("curvature_mode", "prescribed"), r.get("max_radius"))
        _meshes[key] = mesh
        _keys[mesh] = key
    return mesh



def _options_from_record(text):
    """The EngineOptions of a record (JSON); a field the record lacks (a scene saved before it existed) at its
    default."""
    given = json.loads(text) if text else {}
    return EngineOptions(**{k: v for k, v in given.items() if k in EngineOptions.fields})


def _engine_options():
    """The options of the scene's engine made or run last (roundedmesh.options); the defaults if it has none."""
    return _options_from_record(_tag("options"))


def _store_engine_options(options):
    """Keeps `options` (EngineOptions) in the scene as those of its engine made last; returns the key of their
    record, which the engine's command names."""
    text = json.dumps(options.record(), sort_keys=True)
    key = hashlib.sha1(text.encode()).hexdigest()[:12]
    _set_tag("options." + key, text)
    _set_tag("options", text)
    return key
