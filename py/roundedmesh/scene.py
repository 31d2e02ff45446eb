"""Rounded bodies in a YADE scene: creating them, naming their contact partners, and the engine that
adds their contact forces each step.

A rounded body is an ordinary YADE Body without a shape: YADE owns its mass, inertia, position,
orientation and velocities and moves it with NewtonIntegrator; this module owns its mesh and material.
YADE Walls and Boxes become contact partners when given a HertzMaterial with assign_material.

What this module knows about a scene is kept in the scene, in O.tags, so that O.save/O.load,
O.saveTmp/O.loadTmp and the GUI's reload keep the rounded bodies:
    roundedmesh.mesh.<key>     one record per distinct mesh
    roundedmesh.body.<id>      a rounded body: its mesh key and material
    roundedmesh.partner.<id>   a contact partner: its material
    roundedmesh.revision       changes with every edit; the engine rebuilds its state when it differs
YADE cannot delete a tag; an entry set to "" is a deleted one.
"""
import base64
import hashlib
import json
import math
import uuid

import numpy as np
from yade import Body, ForceResetter, NewtonIntegrator, O, PyRunner
from yade.minieigenHP import Quaternion, Vector3

from ._core import Engine, HertzMaterial, Mesh, partner_kind

_PREFIX = "roundedmesh."
_REVISION = _PREFIX + "revision"
_ENGINE_COMMAND = "__import__('roundedmesh').scene.step"
_ENGINE_OPTIONS = {"gamma": 10.0, "regime": "auto"}


# --- what the scene's tags hold -----------------------------------------------------------------------

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
    return [material.young, material.poisson, material.density, material.damping, material.friction]


def _encode(array, dtype):
    return base64.b64encode(np.ascontiguousarray(array, dtype=dtype).tobytes()).decode("ascii")


def _decode(text, dtype, columns=None):
    array = np.frombuffer(base64.b64decode(text), dtype=dtype)
    return array.reshape(-1, columns) if columns else array


_meshes = {}  # mesh key -> Mesh: bodies that share a mesh share it in memory
_known = {}   # id(Mesh) -> (key, Mesh); holding the Mesh keeps its id from being reused


def _mesh_record(mesh):
    x, y, z, w = mesh.orientation  # YADE's Quaternion iterates as x, y, z, w
    return json.dumps({
        "vertices": _encode(mesh.vertices, "<f8"), "triangles": _encode(mesh.triangles, "<i8"),
        "radii": _encode(mesh.radii, "<f8"), "centroid": list(mesh.centroid),
        "orientation": [w, x, y, z]}, sort_keys=True)


def _store_mesh(mesh):
    """The key of `mesh` in the scene's tags, writing its record there if the scene lacks it."""
    record = None
    if id(mesh) not in _known:
        record = _mesh_record(mesh)
        key = hashlib.sha1(record.encode()).hexdigest()[:16]
        _known[id(mesh)] = (key, mesh)
        _meshes.setdefault(key, mesh)
    key = _known[id(mesh)][0]
    if not _tag("mesh." + key):
        _set_tag("mesh." + key, record or _mesh_record(mesh))
    return key


def _load_mesh(key):
    if key not in _meshes:
        r = json.loads(_tag("mesh." + key))
        w, x, y, z = r["orientation"]
        mesh = Mesh._restore(_decode(r["vertices"], "<f8", 3), _decode(r["triangles"], "<i8", 3),
                             _decode(r["radii"], "<f8"), Vector3(*r["centroid"]), Quaternion(w, x, y, z))
        _meshes[key] = mesh
        _known[id(mesh)] = (key, mesh)
    return _meshes[key]


# --- input checks: each names the argument and runs before anything in the scene changes ---------------

def _require_material(material, name):
    if not isinstance(material, HertzMaterial):
        raise TypeError(f"{name}: expected a roundedmesh.HertzMaterial, got {material!r}")
    return material


def _finite_vector(value, name):
    try:
        components = [float(c) for c in value]
    except (TypeError, ValueError):
        components = []
    if len(components) != 3:
        raise TypeError(f"{name}: expected three numbers, got {value!r}")
    v = Vector3(*components)
    if not all(math.isfinite(c) for c in v):
        raise ValueError(f"{name}: must be finite, got {tuple(v)}")
    return v


def _rotation(value, name):
    if not isinstance(value, Quaternion):
        raise TypeError(f"{name}: expected a Quaternion, got {value!r}")
    if not all(math.isfinite(c) for c in value) or value.norm() == 0:
        raise ValueError(f"{name}: must be a finite, non-zero quaternion, got {value!r}")
    q = Quaternion(value)
    q.normalize()
    return q


def _existing_body(body_id, name):
    try:
        body = O.bodies[body_id]
    except (IndexError, TypeError):
        body = None
    if body is None:
        raise ValueError(f"{name}: there is no body {body_id!r} in the scene")
    return body


# --- the public API ---------------------------------------------------------------------------------------

def add_body(mesh, pos, ori=Quaternion.Identity, material=None):
    """Adds a rounded body with `mesh` (in its principal frame) centred at `pos` [m], turned by `ori`, made of
    `material` (a HertzMaterial), to the current scene. Returns the new body's id. Mass and principal inertia
    come from the mesh and the material's density. On bad input nothing is added."""
    if not isinstance(mesh, Mesh):
        raise TypeError(f"mesh: expected a roundedmesh.Mesh, got {mesh!r}")
    pos = _finite_vector(pos, "pos")
    ori = _rotation(ori, "ori")
    material = _require_material(material, "material")

    body = Body()
    body.aspherical = True
    body.state.mass = material.density * mesh.volume
    body.state.inertia = Vector3(*(material.density * mesh.inertia))
    body.state.pos = pos
    body.state.ori = ori
    key = _store_mesh(mesh)
    body_id = O.bodies.append(body)
    _set_tag(f"body.{body_id}", json.dumps({"mesh": key, "material": _material_record(material)}))
    _new_revision()
    return body_id


def assign_material(body_id, material):
    """Makes the YADE-native body `body_id` (a Wall or a Box) a contact partner of the rounded bodies, made of
    `material`. Assigning again replaces the material."""
    material = _require_material(material, "material")
    body = _existing_body(body_id, "body_id")
    if _tag(f"body.{body_id}"):
        raise ValueError(f"body_id: body {body_id} is a rounded body; its material is the one given to add_body")
    partner_kind(body)
    _set_tag(f"partner.{body_id}", json.dumps(_material_record(material)))
    _new_revision()


def engine(label="", **options):
    """The engine to put in O.engines between ForceResetter and NewtonIntegrator. Options:
      gamma  -- expected number of quadrature points in a contact circle below which a triangle contact
                uses the direct regime (Eq. 14); default 10, as in the paper
      regime -- 'auto' (Eq. 14), or 'quadrature' / 'direct' to force one regime (for validation)
    """
    unknown = sorted(set(options) - set(_ENGINE_OPTIONS))
    if unknown:
        raise TypeError(f"engine: unknown option(s) {', '.join(unknown)}; known: {', '.join(_ENGINE_OPTIONS)}, label")
    chosen = {**_ENGINE_OPTIONS, **options}
    try:
        chosen["gamma"] = float(chosen["gamma"])
    except (TypeError, ValueError):
        raise TypeError(f"gamma: expected a number, got {chosen['gamma']!r}") from None
    Engine().set_options(**chosen)
    arguments = ", ".join(f"{k}={v!r}" for k, v in chosen.items())
    return PyRunner(command=f"{_ENGINE_COMMAND}({arguments})", iterPeriod=1, initRun=True, label=label)


def critical_timestep():
    """Largest stable O.dt for the current scene's contacts between rounded bodies and partners [s], inf if
    there are none (see doc/physics.md, "Time step"). Use a fraction of it for accuracy."""
    state = _current_state()
    return state.stability[0] if state else math.inf


def statistics():
    """Counts of the last contact step: body pairs whose bounds overlapped, and triangle contacts in the
    quadrature and direct regimes."""
    state = _current_state()
    return state.engine.statistics if state else {"body_pairs": 0, "quadrature_contacts": 0, "direct_contacts": 0}


def rounded_bodies():
    """{body id: Mesh} of the current scene's rounded bodies."""
    return {int(i): _load_mesh(json.loads(record)["mesh"]) for i, record in _tags_named("body").items()}


# --- the engine's step ----------------------------------------------------------------------------------

class _SceneState:
    """The contact engine built from one revision of the scene's tags."""

    def __init__(self, revision):
        self.revision = revision
        self.engine = Engine()
        for body_id, record in sorted(_tags_named("body").items(), key=lambda item: int(item[0])):
            r = json.loads(record)
            self.engine.add_body(int(body_id), _load_mesh(r["mesh"]), HertzMaterial(*r["material"]))
        partner_masses = []
        for body_id, record in sorted(_tags_named("partner").items(), key=lambda item: int(item[0])):
            body = O.bodies[int(body_id)]
            if body is None:
                continue
            self.engine.add_partner(body, HertzMaterial(*json.loads(record)))
            partner_masses.append(body.state.mass if body.dynamic else 0.0)
        self.stability = self.engine.stability_limit(partner_masses)
        self.options = None
        self.checked_dt = None
        self.engines_checked = False

    def prepare(self, options):
        if options != self.options:
            self.engine.set_options(**options)
            self.options = options
        if not self.engines_checked:
            _check_engine_order()
            self.engines_checked = True
        if O.dt != self.checked_dt:
            limit, body, partner = self.stability
            if O.dt > limit:
                raise ValueError(
                    f"O.dt = {O.dt:g} s is above the stability limit {limit:g} s of the contact between rounded "
                    f"body {body} and body {partner} (roundedmesh.critical_timestep()); reduce O.dt")
            self.checked_dt = O.dt


_state = None


def _current_state():
    global _state
    revision = O.tags[_REVISION] if O.tags.has_key(_REVISION) else None
    if revision is None:
        return None
    if _state is None or _state.revision != revision:
        _state = _SceneState(revision)
    return _state


def _check_engine_order():
    kinds = [type(e) for e in O.engines]
    ours = [i for i, e in enumerate(O.engines)
            if isinstance(e, PyRunner) and e.command.startswith(_ENGINE_COMMAND)]
    if len(ours) != 1:
        raise ValueError(f"O.engines holds {len(ours)} roundedmesh engines; it needs exactly one")
    resetters = [i for i, k in enumerate(kinds) if k is ForceResetter]
    integrators = [i for i, k in enumerate(kinds) if k is NewtonIntegrator]
    if not any(i < ours[0] for i in resetters) or any(i < ours[0] for i in integrators):
        raise ValueError("O.engines: the roundedmesh engine must come after ForceResetter and before "
                         "NewtonIntegrator")


def _forget(body_ids):
    for body_id in body_ids:
        _set_tag(f"body.{body_id}", "")
        _set_tag(f"partner.{body_id}", "")
    _new_revision()


def step(**options):
    """One contact step on the current scene; run by the engine's PyRunner."""
    state = _current_state()
    if state is None:
        return
    state.prepare(options)
    missing = state.engine.step(O)
    if missing:  # bodies erased from the scene leave the engine too
        _forget(missing)
        step(**options)
