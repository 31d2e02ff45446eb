"""Rounded bodies in a YADE scene: creating them, naming their contact partners, and the engine that
adds their contact forces each step.

A rounded body is an ordinary YADE Body with a bare Shape and no bound, which YADE's colliders and
dispatchers skip: YADE owns its mass, inertia, position, orientation and velocities and moves it with
NewtonIntegrator (also as a member of a clump); this module owns its mesh and material. YADE Walls, Boxes,
Facets and Spheres become contact partners when given a HertzMaterial with assign_material. A sphere body
(add_sphere) is a YADE Sphere that YADE's collider never pairs (groupMask 0): every contact it has, also with
the other partners, is this module's.

What this module knows about a scene is kept in the scene, in O.tags, so that O.save/O.load,
O.saveTmp/O.loadTmp and the GUI's reload keep the rounded bodies:
    roundedmesh.mesh.<key>     one record per distinct mesh
    roundedmesh.body.<id>      a rounded body: its mesh key and material
    roundedmesh.partner.<id>   a contact partner: its material
    roundedmesh.sphere.<id>    a sphere body: its material
    roundedmesh.revision       changes with every edit; the engine rebuilds its state when it differs
    roundedmesh.springs        the contacts' tangential springs after the last step (doc/physics.md, "Friction"):
                               "<token>:<base64 of Engine.springs()>", written after every step that has or had
                               springs; a token the engine did not write itself (a loaded scene) makes it take them
YADE cannot delete a tag; an entry set to "" is a deleted one.
"""
import ast
import base64
import functools
import itertools
import hashlib
import json
import math
import numbers
import sys
import uuid
import warnings
import weakref

import numpy as np
from yade import Body, ForceResetter, Material, NewtonIntegrator, O, PyRunner, Shape
from yade import Sphere as YadeSphere
from yade.minieigenHP import Quaternion, Vector3

from ._core import DEEPEST_OVERLAP, STOP_OVERLAP, Engine, HertzMaterial, Mesh, partner_kind

_PREFIX = "roundedmesh."
_REVISION = _PREFIX + "revision"
_ENGINE_COMMAND = "__import__('roundedmesh').scene.step"
# STOP_OVERLAP (from _core, kStopOverlap of pkg/engine/ContactModel.hpp): past this overlap, as a fraction of the
# smaller side's size (a rounded body's volume-equivalent radius r_eq, a sphere's radius), a pair whose overlap grows
# stops the run (doc/physics.md, "Deep overlaps and fast impacts").
_ENGINE_OPTIONS = {"gamma": 10.0, "regime": "auto", "friction": "spring", "stop_overlap": STOP_OVERLAP,
                   "curvature": "mean"}
_FRICTION_LAWS = ("spring", "viscous")


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
    return [material.young, material.poisson, material.density, material.damping, material.friction,
            material.tangential_damping]


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


# --- input checks: each names the argument and runs before anything in the scene changes ---------------

def _require_material(material, name):
    if not isinstance(material, HertzMaterial):
        raise TypeError(f"{name}: expected a roundedmesh.HertzMaterial, got {material!r}")
    return material


def _finite_vector(value, name):
    try:
        components = [] if isinstance(value, (str, bytes)) else [float(c) for c in value]
    except (TypeError, ValueError):
        components = []
    if len(components) != 3:
        raise TypeError(f"{name}: expected three numbers, got {value!r}")
    if not all(math.isfinite(c) for c in components):
        raise ValueError(f"{name}: must be finite, got {tuple(components)}")
    return Vector3(*components)


def _rotation(value, name):
    if not isinstance(value, Quaternion):
        raise TypeError(f"{name}: expected a Quaternion, got {value!r}")
    if not all(math.isfinite(c) for c in value) or value.norm() == 0:
        raise ValueError(f"{name}: must be a finite, non-zero quaternion, got {value!r}")
    q = Quaternion(value)
    q.normalize()
    return q


def _body_or_none(body_id):
    try:
        return O.bodies[body_id]
    except IndexError:
        return None


def _existing_body(body_id, name):
    if isinstance(body_id, bool) or not isinstance(body_id, numbers.Integral) or body_id < 0:
        raise TypeError(f"{name}: expected a body id (a non-negative integer), got {body_id!r}")
    body = _body_or_none(int(body_id))
    if body is None:
        raise ValueError(f"{name}: there is no body {body_id} in the scene")
    return body


def _materials(kind):
    return {int(i): HertzMaterial(*(json.loads(r)["material"] if kind == "body" else json.loads(r)))
            for i, r in _tags_named(kind).items()}


_ALL_KINDS = ("body", "sphere", "partner")


def _require_one_deformable(material, others, name, other_kind=None, exclude=None):
    """Two rigid bodies (young = inf) have no Hertz contact: refuse a rigid material if a rigid one is
    already among those it can touch (`others`: among 'body', 'sphere', 'partner'; body `exclude` is the one
    whose material changes). `other_kind` names them in the message; without it, the kinds of the rigid ones
    found (rounded and sphere bodies)."""
    if math.isinf(material.young):
        found = {kind: sorted(i for i, m in _materials(kind).items() if math.isinf(m.young) and i != exclude)
                 for kind in others}
        rigid = sorted(i for ids in found.values() for i in ids)
        if other_kind is None:
            other_kind = " or ".join(word for kind, word in (("body", "rounded"), ("sphere", "sphere"))
                                     if found.get(kind)) + " bod(ies)"
        if rigid:
            raise ValueError(f"{name}: a rigid material (young=inf) cannot touch the rigid {other_kind} "
                             f"{', '.join(map(str, rigid))}; give one side a finite modulus")


_YADE_LABEL = "roundedmesh"  # the bridge (py/module/YadeBridge.cpp) checks it on every rounded body each step


def _yade_material(material):
    """The YADE Material of a rounded body: O.bodies.clump needs one, and its label tells the engine that the
    body's material is still the HertzMaterial it knows."""
    return Material(density=material.density, label=_YADE_LABEL)


def _set_mass(body, mesh, material):
    body.state.mass = material.density * mesh.volume
    body.state.inertia = Vector3(*(material.density * mesh.inertia))


def _set_sphere_mass(body, material):
    radius = body.shape.radius
    body.state.mass = material.density * 4 / 3 * math.pi * radius ** 3
    body.state.inertia = Vector3(*[0.4 * body.state.mass * radius ** 2] * 3)


def _positive_length(value, name):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a number, got {value!r}")
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"{name}: must be positive and finite, got {value!r}")
    return float(value)


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
    _require_one_deformable(material, _ALL_KINDS, "material", "bod(ies)")

    body = Body()
    # O.bodies.clump needs a shape and a material on every member (it dereferences both, then uses the
    # state's mass and inertia). The bare Shape has no class index, so a bound dispatcher that meets it aborts
    # YADE ("No functor for type Shape"). bounded=False, saved with the body, makes BoundDispatcher (run by
    # the colliders) skip the body before it looks for a functor: the body gets no bound, the collider never
    # pairs it and YADE's InteractionLoop never sees it, whenever the collider was made. A groupMask of 0
    # would not do (the bound is still dispatched), nor a stock shape with a bound functor (the collider would
    # pair the body with its neighbours, and a stock Ig2 functor would add YADE's contact law to ours).
    body.shape = Shape()
    body.bounded = False
    body.material = _yade_material(material)
    body.aspherical = True
    _set_mass(body, mesh, material)
    body.state.pos = pos
    body.state.ori = ori
    key = _store_mesh(mesh)
    body_id = O.bodies.append(body)
    _set_tag(f"body.{body_id}", json.dumps({"mesh": key, "material": _material_record(material)}))
    _new_revision()
    return body_id


def add_sphere(pos, radius, material, ori=Quaternion.Identity):
    """Adds a sphere body: a YADE Sphere of `radius` [m] centred at `pos` [m], turned by `ori`, made of `material`
    (a HertzMaterial), whose every contact the roundedmesh engine computes with the law of the rounded bodies
    (the damped Hertz force of Eq. 7 and the Coulomb friction of Eqs. 19-21): with other sphere bodies, with
    rounded bodies, and with the contact partners (Walls, Boxes, Facets, partner Spheres). Mass and inertia
    come from the material's density. YADE's collider never pairs it (groupMask 0), so YADE's own contact laws
    never add to it. Returns the new body's id. On bad input nothing is added."""
    pos = _finite_vector(pos, "pos")
    radius = _positive_length(radius, "radius")
    material = _require_material(material, "material")
    ori = _rotation(ori, "ori")
    _require_one_deformable(material, _ALL_KINDS, "material", "bod(ies)")

    body = Body()
    body.shape = YadeSphere(radius=radius)
    body.material = _yade_material(material)
    body.groupMask = 0
    _set_sphere_mass(body, material)
    body.state.pos = pos
    body.state.ori = ori
    body_id = O.bodies.append(body)
    _set_tag(f"sphere.{body_id}", json.dumps(_material_record(material)))
    _new_revision()
    return body_id


def assign_material(body_id, material):
    """Makes the YADE-native body `body_id` (a Wall, Box, Facet or Sphere) a contact partner of the rounded
    bodies, made of `material`. Assigning again replaces the material, and a rounded or sphere body's
    material is changed as by set_material. Partners touch rounded bodies only: contacts among them stay with YADE's own
    engines, if the scene has any."""
    material = _require_material(material, "material")
    body = _existing_body(body_id, "body_id")
    if _tag(f"body.{body.id}") or _tag(f"sphere.{body.id}"):
        return set_material(body.id, material)
    partner_kind(body)
    _require_one_deformable(material, ("body", "sphere"), "material")
    _set_tag(f"partner.{body.id}", json.dumps(_material_record(material)))
    _new_revision()


def set_material(body_id, material):
    """Gives the rounded body, sphere body or contact partner `body_id` the HertzMaterial `material` from the
    next step on, e.g. friction after settling without it. A rounded or sphere body's mass and inertia follow
    the new density (refused for a clump member, whose mass is part of its clump's); a partner's mass stays
    YADE's. On bad input nothing changes."""
    material = _require_material(material, "material")
    body = _existing_body(body_id, "body_id")
    record, sphere = _tag(f"body.{body.id}"), _tag(f"sphere.{body.id}")
    if record or sphere:
        r = json.loads(record) if record else {"material": json.loads(sphere)}
        if material.density != r["material"][2] and body.isClumpMember:
            raise ValueError(f"material: body {body.id} is a member of clump {body.clumpId}, whose mass and inertia "
                             f"were fixed by O.bodies.clump; a new density ({material.density:g} instead of "
                             f"{r['material'][2]:g} kg/m^3) must be given before clumping")
        _require_one_deformable(material, _ALL_KINDS, "material", "bod(ies)", exclude=body.id)
        body.material = _yade_material(material)
        if record:
            if material.density != r["material"][2]:
                _set_mass(body, _load_mesh(r["mesh"]), material)
            _set_tag(f"body.{body.id}", json.dumps({**r, "material": _material_record(material)}))
        else:
            _set_sphere_mass(body, material)
            _set_tag(f"sphere.{body.id}", json.dumps(_material_record(material)))
    elif _tag(f"partner.{body.id}"):
        _require_one_deformable(material, ("body", "sphere"), "material")
        _set_tag(f"partner.{body.id}", json.dumps(_material_record(material)))
    else:
        raise ValueError(f"body_id: body {body.id} is neither a rounded body nor a contact partner nor a "
                         "sphere body; make a Wall, Box, Facet or Sphere a partner with assign_material")
    _new_revision()


def engine(label="", **options):
    """The engine to put in O.engines between ForceResetter and NewtonIntegrator. Options:
      gamma        -- expected number of quadrature points in a contact circle below which a triangle contact
                      uses the direct regime (Eq. 14); default 10, as in the paper
      regime       -- 'auto' (Eq. 14), or 'quadrature' / 'direct' to force one regime (for validation)
      friction     -- the tangential law of every contact: 'spring' (default), an elastic spring-dashpot per body
                      pair capped by Coulomb, with which bodies rest on slopes; or 'viscous', the paper's no-slip
                      force -c v_t (Eqs. 18-21), with which nothing in contact ever stands still (doc/physics.md,
                      "Friction")
      stop_overlap -- a pair whose overlap grows past this fraction of the smaller side's size (r_eq, or a
                      sphere's radius) stops the run; default STOP_OVERLAP = 0.5, math.inf never
      curvature    -- 'mean' (default): the paper's contact circle from each triangle's mean curvature (Eq. 1);
                      'principal': Hertz's contact ellipse from both principal curvatures of each triangle
                      (Mesh.principal_curvatures), concave triangles following the smooth surface
                      (doc/physics.md, "Principal curvatures: the contact ellipse")
    A body whose centre passes through a Wall, Facet or Box it was near in the step before stops the run too
    (doc/user-guide.md, "Choosing the time step").
    """
    unknown = sorted(set(options) - set(_ENGINE_OPTIONS))
    if unknown:
        raise TypeError(f"engine: unknown option(s) {', '.join(unknown)}; known: {', '.join(_ENGINE_OPTIONS)}, label")
    chosen = {**_ENGINE_OPTIONS, **options}
    if isinstance(chosen["gamma"], bool) or not isinstance(chosen["gamma"], numbers.Real):
        raise TypeError(f"gamma: expected a number, got {chosen['gamma']!r}")
    chosen["gamma"] = float(chosen["gamma"])
    if isinstance(chosen["stop_overlap"], bool) or not isinstance(chosen["stop_overlap"], numbers.Real):
        raise TypeError(f"stop_overlap: expected a number, got {chosen['stop_overlap']!r}")
    if not chosen["stop_overlap"] > 0:
        raise ValueError(f"stop_overlap: must be positive (math.inf: never), got {chosen['stop_overlap']!r}")
    chosen["stop_overlap"] = float(chosen["stop_overlap"])
    for name, value in (("regime", chosen["regime"]), ("friction", chosen["friction"]),
                        ("curvature", chosen["curvature"]), ("label", label)):
        if not isinstance(value, str):
            raise TypeError(f"{name}: expected a string, got {value!r}")
    Engine().set_options(**chosen)
    arguments = ", ".join(f"{k}={_literal(v)}" for k, v in chosen.items())
    return PyRunner(command=f"{_ENGINE_COMMAND}({arguments})", iterPeriod=1, initRun=True, label=label)


def _literal(value):
    """`value` as Python source that evaluates to it (repr(math.inf) is 'inf', which does not)."""
    return f"float('{value}')" if isinstance(value, float) and not math.isfinite(value) else repr(value)


def critical_timestep(impact_speed=None):
    """Largest stable O.dt for the current scene's contacts of rounded bodies and sphere bodies with each other
    and with partners [s], inf if there are none (see doc/physics.md, "Time step"): the normal contacts' limit and,
    with friction, the tangential one (its stiffness and damping c), for the friction law of the roundedmesh
    engine in O.engines (the default 'spring' if there is none yet). Use a fraction of it for accuracy.

    With impact_speed [m/s], the largest impact speed the scene will see, the step is also small enough to resolve
    such an impact: bodies meeting at that speed move in one step at most a tenth of the depth the impact
    reaches, and at most a tenth of the Hertz depth 0.1 r_eq (doc/physics.md, "Deep overlaps and fast impacts")."""
    if impact_speed is not None:
        if isinstance(impact_speed, bool) or not isinstance(impact_speed, numbers.Real):
            raise TypeError(f"impact_speed: expected a number [m/s], got {impact_speed!r}")
        if not (math.isfinite(impact_speed) and impact_speed >= 0):
            raise ValueError(f"impact_speed: must be a finite speed >= 0 [m/s], got {impact_speed!r}")
    state = _current_state()
    return state.stability(_engine_options(), impact_speed or 0.0)[0] if state else math.inf


_STATISTICS = ("body_pairs", "touching_pairs", "candidates", "rejected_not_facing", "rejected_no_overlap",
               "rejected_outside_circle", "rejected_empty_polygon", "rejected_beyond_contact_circle",
               "rejected_through_body",
               "quadrature_contacts", "direct_contacts", "sphere_contacts", "sliding_contacts", "neighbour_rebuilds",
               "candidate_rebuilds", "near_rebuilds", "broad_phase_ms", "pairs_ms", "reduction_ms", "read_ms",
               "write_ms")


def statistics():
    """The last contact step, stage by stage (doc/architecture.md):
      body_pairs               pairs whose bounds overlapped (the broad phase's output), sphere bodies' included
      touching_pairs           of those, pairs with at least one triangle contact or a sphere contact
      candidates               triangle pairs (and triangle-partner pairs) put through the narrow phase
      rejected_*               how many of them each test rejected, in the order they run (Appendix B):
                               not_facing (Eq. B.5), no_overlap (Eq. 10), outside_circle (projected
                               circumcircle against the contact circle), empty_polygon (S), beyond_contact_circle,
                               through_body (a pair deeper than 0.1 r_eq whose caps do not reach into the other
                               body: doc/physics.md, "Which triangle pairs touch")
      quadrature_contacts, direct_contacts   triangle contacts in each regime of Eq. 14 (a sphere body against a
                               rounded body counts here: the rounded body's triangles meet the sphere)
      sphere_contacts          contacts of a sphere body with another sphere body or a partner, one per pair
                               (the whole contact circle: no triangles, so not in candidates or rejected_*)
      sliding_contacts         triangle and sphere contacts sliding: all of a pair's whose spring slides (under the
                               viscous law, each by Eq. 21)
      neighbour_rebuilds       whether the broad phase's neighbour list was rebuilt (0 or 1)
      candidate_rebuilds       pairs whose candidate triangle pairs were rebuilt (from their near list)
      near_rebuilds            pairs whose near list was searched again in the triangle trees
      broad_phase_ms, pairs_ms, reduction_ms   wall time of each stage of the C++ step
      read_ms, write_ms        wall time of reading the states from YADE and adding the forces to it
    """
    state = _current_state()
    return state.engine.statistics if state else dict.fromkeys(_STATISTICS, 0)


_NO_CONTACTS = {"id1": ((0,), int), "id2": ((0,), int), "force1": ((0, 3), float), "torque1": ((0, 3), float),
                "force2": ((0, 3), float), "torque2": ((0, 3), float), "point": ((0, 3), float),
                "normal": ((0, 3), float), "overlap": ((0,), float), "depth": ((0,), float),
                "triangle_contacts": ((0,), int),
                "sliding": ((0,), bool)}


def contacts():
    """Every pair of bodies that touched in the last contact step, as numpy arrays with one row per pair, as the
    engine computed them (nothing is evaluated again; cheap enough for a PyRunner):
      id1, id2            YADE ids: id1 a rounded body, id2 a rounded body or a partner
      force1, torque1     contact force [N] and torque [N m] on id1, torque about id1's position
      force2, torque2     the same on id2 (force2 = -force1), torque about id2's position
      point               centre of pressure [m]: where the pair's total normal force acts (the points of
                          application of its triangle contacts' normal forces, weighted by those forces)
      normal              unit vector along the pair's total normal force, from id1 toward id2
      overlap             the deepest effective overlap of its triangle contacts [m] (delta_eff, Eq. B.4)
      depth               the deepest delta_eff along `normal` [m]: how far the bodies overlap (the deepest triangle
                          contact alone can run through both bodies at a slant); what the stop rule compares
      triangle_contacts   number of triangle contacts (1 for a sphere body against a sphere body or a partner:
                          one contact over the whole circle)
      sliding             whether the pair's tangential spring slides (under the viscous law: whether any of
                          its triangle contacts does, Eq. 21)
    A pair's forces are the sums of its triangle contacts', normal and tangential (friction)."""
    state = _current_state()
    if state is None or state.stepped_iteration is None:
        return {key: np.zeros(shape, dtype) for key, (shape, dtype) in _NO_CONTACTS.items()}
    return state.engine.contacts()


def _gravity():
    for e in O.engines:
        if isinstance(e, NewtonIntegrator):
            return e.gravity
    return Vector3.Zero


def unbalanced_force(use_max_force=False):
    """YADE's unbalanced force (utils.unbalancedForce) with roundedmesh's contacts counted: the mean (or, with
    use_max_force, the largest) magnitude of the resultant force, gravity included, on the dynamic bodies that are
    not clump members (a clump with its members' forces), divided by the mean magnitude of the contact forces:
    roundedmesh's body pairs of the last step (the force on either side) and YADE's real interactions
    (|normalForce + shearForce|). Call it after a step (from a PyRunner after NewtonIntegrator, or between runs);
    nan if nothing touches."""
    gravity = _gravity()
    resultants = []
    for body in O.bodies:
        if body is None or body.isClumpMember or not body.dynamic:
            continue
        force = O.forces.f(body.id, sync=True)
        if body.isClump and force.norm() == 0:  # before NewtonIntegrator has summed the members', as YADE does
            force = sum((O.forces.f(i, sync=True) for i in body.shape.members.keys()), Vector3.Zero)
        resultants.append((force + body.state.mass * gravity).norm())
    contact = [(i.phys.normalForce + i.phys.shearForce).norm() for i in O.interactions
               if i.isReal and hasattr(i.phys, "normalForce")]
    contact.extend(np.linalg.norm(contacts()["force1"], axis=1))
    if not resultants or not contact:
        return math.nan
    return (max(resultants) if use_max_force else np.mean(resultants)) / np.mean(contact)


def rounded_bodies():
    """{body id: Mesh} of the current scene's rounded bodies."""
    return {int(i): _load_mesh(json.loads(record)["mesh"]) for i, record in _tags_named("body").items()
            if _body_or_none(int(i)) is not None}


def sphere_bodies():
    """{body id: radius [m]} of the current scene's sphere bodies (add_sphere)."""
    return {int(i): _body_or_none(int(i)).shape.radius for i in _tags_named("sphere")
            if _body_or_none(int(i)) is not None}


# --- the engine's step ----------------------------------------------------------------------------------

class _SceneState:
    """The contact engine built from one revision of the scene's tags."""

    def __init__(self, revision):
        self.revision = revision
        self.engine = Engine()
        self.meshes = {}  # keeps the meshes alive, and shared between bodies, while this state lives
        self.body_ids, self.partner_ids = [], []
        materials = []
        for body_id, record in sorted(_tags_named("body").items(), key=lambda item: int(item[0])):
            r = json.loads(record)
            mesh = self.meshes.setdefault(r["mesh"], _load_mesh(r["mesh"]))
            materials.append(HertzMaterial(*r["material"]))
            self.engine.add_body(int(body_id), mesh, materials[-1])
            self.body_ids.append(int(body_id))
        partners = [(int(i), r, kind) for kind in ("sphere", "partner") for i, r in _tags_named(kind).items()]
        for body_id, record, kind in sorted(partners):
            body = _body_or_none(body_id)
            if body is not None:
                materials.append(HertzMaterial(*json.loads(record)))
                (self.engine.add_sphere if kind == "sphere" else self.engine.add_partner)(body, materials[-1])
                self.partner_ids.append(body_id)
        self.materials = materials
        self.options = None
        self.checked_dt = None
        self.stepped_iteration = None  # O.iter of the last step computed; None before the first
        self.warned_fast = False  # whether a body has been too fast for the step (_warn_fast_bodies)
        self.spring_token = None  # the token of the springs the engine holds (roundedmesh.springs); None: none

    def set_options(self, options):
        if options != self.options:
            self.engine.set_options(**options)
            if options["friction"] == "viscous" and (self.options is None or self.options["friction"] != "viscous"):
                _warn_viscous_without_damping(self.materials)
            self.options = options
            self.checked_dt = None

    def stability(self, options, impact_speed=0.0):
        """(limit [s], body id, id of the other body, whether the tangential contact sets it) for the masses and
        inertias the bodies have in YADE now and the engine options, and with impact_speed > 0 for impacts at that
        speed [m/s]. A body erased since the last step (the next step forgets it) is left out: infinite mass puts
        no limit."""
        self.set_options(options)
        bodies = [_body_or_none(i) for i in self.body_ids]
        partners = [_body_or_none(i) for i in self.partner_ids]
        return self.engine.stability_limit([b.state.mass if b else math.inf for b in bodies],
                                           [p.state.mass if p and p.dynamic else 0.0 for p in partners],
                                           [b.state.inertia if b else Vector3.Zero for b in bodies],
                                           [p.state.inertia if p and p.dynamic else Vector3.Zero for p in partners],
                                           float(impact_speed))

    def prepare(self, options):
        self.set_options(options)
        _check_engines()
        if O.dt != self.checked_dt:
            limit, body, other, tangential = self.stability(options)
            if O.dt > limit:
                which = ("tangential contact (friction: its stiffness and tangential damping c)" if tangential
                         else "contact")
                raise ValueError(
                    f"O.dt = {O.dt:g} s is above the stability limit {limit:g} s of the {which} between "
                    f"{'rounded' if body in self.body_ids else 'sphere'} body {body} and body {other} "
                    "(roundedmesh.critical_timestep()); reduce O.dt")
            self.checked_dt = O.dt

    def take_springs(self):
        """Before a step: the scene's springs (roundedmesh.springs) into the engine, unless it wrote them itself."""
        record = _tag("springs")
        token, _, data = record.partition(":")
        if (token or None) != self.spring_token:
            self.engine.restore_springs(base64.b64decode(data) if token else None)
            self.spring_token = token or None

    def keep_springs(self):
        """After a step: the engine's springs into the scene, so that O.save keeps them."""
        data = self.engine.springs()
        if data is None and self.spring_token is None:
            return
        self.spring_token = None if data is None else f"{_PROCESS}.{next(_SPRING_WRITES)}"
        _set_tag("springs", "" if data is None else self.spring_token + ":" + base64.b64encode(data).decode("ascii"))


_state = None
_PROCESS = uuid.uuid4().hex[:12]   # with a count, makes each write of roundedmesh.springs unique
_SPRING_WRITES = itertools.count()


def _warn_viscous_without_damping(materials):
    for m in materials:
        if m.friction > 0 and m.tangential_damping == 0 and not any(o.tangential_damping > 0 for o in materials):
            warnings.warn(f"roundedmesh: friction={m.friction:g} with tangential_damping=0 on every material under "
                          "the viscous friction law: Eq. 21 lets no contact slide and the no-slip force is zero, so "
                          "there is no friction; give a tangential damping c, or use the default friction='spring' "
                          "(doc/physics.md)", RuntimeWarning)
            break


def _engine_options():
    """The options of the roundedmesh engine in O.engines (its PyRunner's command), the defaults for any it does not
    name (a scene saved before the option existed) or if there is no such engine."""
    for e in O.engines:
        if isinstance(e, PyRunner) and e.command.startswith(_ENGINE_COMMAND):
            try:
                call = ast.parse(e.command, mode="eval").body
                given = {k.arg: ast.literal_eval(k.value) for k in call.keywords}
            except (SyntaxError, ValueError, AttributeError):
                given = {}
            return {**_ENGINE_OPTIONS, **{k: v for k, v in given.items() if k in _ENGINE_OPTIONS}}
    return dict(_ENGINE_OPTIONS)


def _current_state():
    global _state
    revision = O.tags[_REVISION] if O.tags.has_key(_REVISION) else None
    if revision is None:
        return None
    if _state is None or _state.revision != revision:
        _state = _SceneState(revision)
    return _state


def _check_engines():
    """One roundedmesh engine, running every step, after ForceResetter and before NewtonIntegrator."""
    engines = O.engines
    ours = [i for i, e in enumerate(engines) if isinstance(e, PyRunner) and e.command.startswith(_ENGINE_COMMAND)]
    if len(ours) != 1:
        raise ValueError(f"O.engines holds {len(ours)} roundedmesh engines; it needs exactly one")
    runner = engines[ours[0]]
    if runner.iterPeriod != 1 or runner.virtPeriod != 0 or runner.realPeriod != 0:
        raise ValueError("O.engines: the roundedmesh engine must run every step (iterPeriod=1, no virtPeriod "
                         "or realPeriod)")
    before = engines[:ours[0]]
    if not any(isinstance(e, ForceResetter) for e in before) or any(isinstance(e, NewtonIntegrator) for e in before):
        raise ValueError("O.engines: the roundedmesh engine must come after ForceResetter and before "
                         "NewtonIntegrator")


def _forget(body_ids):
    for body_id in body_ids:
        _set_tag(f"body.{body_id}", "")
        _set_tag(f"partner.{body_id}", "")
        _set_tag(f"sphere.{body_id}", "")
    _new_revision()


def _stop_the_run(step):
    """Runs `step` so that an error stops the run with a message that names its cause, and no traceback.

    YADE's PyRunner prints the traceback of an exception leaving its command (PyErr_Print), then throws it on
    as "PyRunner error ... STACK TRACE ..."; the ThreadRunner of O.run logs that as a FATAL ERROR, and
    O.run(n, True) or O.step() raise it once more as a RuntimeError. The exception has to leave the
    command, since only that aborts the step before NewtonIntegrator moves the bodies without their contact
    forces (O.pause() would let the step finish) and makes a script's O.run(n, True) raise instead of
    carrying on. What can go is the traceback through roundedmesh: the error is raised with a message that
    stands alone, and the excepthook that PyErr_Print calls for it prints nothing and drops the traceback
    that YADE formats into its message. The hook is restored as soon as it has run."""
    @functools.wraps(step)
    def stopping_step(**options):
        try:
            step(**options)
        except Exception as cause:
            if getattr(cause, "stops_the_run", False):  # from the step's own retry after erased bodies
                raise
            error = RuntimeError(f"roundedmesh stopped the run at iteration {O.iter}: {cause}")
            error.stops_the_run = True
            _rewind_engines()
            _quiet_in_pyrunner(error)
            raise error from None
    return stopping_step


def _rewind_engines():
    """PyRunner, a PeriodicEngine, has counted the failed step as run (iterLast = O.iter) and would skip the
    step when the user runs again, which would then go by without contact forces: make it due again."""
    for e in O.engines:
        if isinstance(e, PyRunner) and e.command.startswith(_ENGINE_COMMAND):
            e.iterLast = O.iter - max(e.iterPeriod, 1)


def _quiet_in_pyrunner(error):
    previous = sys.excepthook

    def hook(kind, value, traceback):
        if sys.excepthook is hook:
            sys.excepthook = previous
        # Only PyRunner's PyErr_Print, whose outermost frame is its command "<string>", is kept quiet: the same
        # error escaping a script (a direct call of step) is printed as usual.
        if value is error and traceback is not None and traceback.tb_frame.f_code.co_filename == "<string>":
            sys.last_traceback = None
            return
        previous(kind, value, traceback)

    sys.excepthook = hook


@_stop_the_run
def step(**options):
    """One contact step on the current scene; run by the engine's PyRunner."""
    state = _current_state()
    if state is None:
        return
    options = {**_ENGINE_OPTIONS, **options}  # a scene saved before an option existed has the default
    state.prepare(options)
    state.engine.keep_triangle_contacts = _keeps_triangle_forces()
    state.take_springs()
    missing = state.engine.step(O)
    if missing:  # bodies erased from the scene leave the engine too
        _forget(missing)
        step(**options)
        return
    stops = state.engine.stops()
    if stops:  # nothing was applied, and the step is not kept: redoing it stops again
        raise ValueError(_stop_message(state, stops))
    state.keep_springs()
    first = state.stepped_iteration is None
    state.stepped_iteration = O.iter
    if O.trackEnergy:
        _track_energy(state.engine.energy())
    if first:
        _warn_deep_overlaps(state)
    _warn_fast_bodies(state)


# Energy keys in O.energy, named as YADE names its own: the elastic energy of the contacts, set every step (a state,
# as YADE's elastPotential), and the energies dissipated by normal damping and by friction, accumulated (as
# YADE's plastDissip and viscDamp). doc/physics.md, "Energy".
ELASTIC_ENERGY, NORMAL_DAMPING_ENERGY, FRICTION_ENERGY = "rmElastPotential", "rmNormDamp", "rmFrictDissip"


def _track_energy(energy):
    elastic, damping_power, friction_power = energy
    keys = set(O.energy.keys())
    O.energy[ELASTIC_ENERGY] = elastic
    for key, power in ((NORMAL_DAMPING_ENERGY, damping_power), (FRICTION_ENERGY, friction_power)):
        O.energy[key] = (O.energy[key] if key in keys else 0.0) + power * O.dt


# Beyond DEEPEST_OVERLAP (from _core, kDeepestOverlap of pkg/engine/ContactModel.hpp), as a fraction of the smaller
# volume-equivalent radius, a pair is deeper than a Hertz contact is meant to reach: at the start of a run it is a
# body placed inside another, not a contact. DEEP_OVERLAP, its older name here, stays for scripts that use it.
DEEP_OVERLAP = DEEPEST_OVERLAP
_WARNED_PAIRS = 10


def _equivalent_radius(volume):
    return (3 * volume / (4 * math.pi)) ** (1 / 3)


def _warn_deep_overlaps(state):
    """Warns, after the first step of a scene's engine (and after every change of its bodies or partners), of the
    pairs that overlap by more than DEEP_OVERLAP of the smaller body's volume-equivalent radius: by their depth
    (contacts()['depth']), what the stop rule compares. The deepest triangle contact can run through two bodies at a
    slant: in a settled packing of S1 it reached 0.34 r_eq where no pair was deeper than 0.09 r_eq."""
    found = contacts()
    radius = {i: _equivalent_radius(mesh.volume) for i, mesh in rounded_bodies().items()}
    radius.update(sphere_bodies())
    deep = []
    for id1, id2, overlap in zip(found["id1"], found["id2"], found["depth"]):
        fraction = overlap / min(radius[int(i)] for i in (id1, id2) if int(i) in radius)
        if fraction > DEEP_OVERLAP:
            deep.append((fraction, int(id1), int(id2), overlap))
    if not deep:
        return
    deep.sort(reverse=True)
    listed = "; ".join(f"bodies {a} and {b} by {overlap:.3g} m ({fraction:.2f} r_eq)"
                       for fraction, a, b, overlap in deep[:_WARNED_PAIRS])
    more = f"; and {len(deep) - _WARNED_PAIRS} more pairs" if len(deep) > _WARNED_PAIRS else ""
    warnings.warn(f"roundedmesh: {len(deep)} pair(s) start overlapped deeper than {DEEP_OVERLAP:g} of the smaller "
                  f"body's volume-equivalent radius r_eq, beyond what a Hertz contact describes: {listed}{more}. "
                  "Move the bodies apart before the run", RuntimeWarning)


# A body that moves more than this fraction of its contact depth (0.1 r_eq) in one step is warned of, once per run
# (doc/physics.md, "Deep overlaps and fast impacts"): an impact reaching that depth is integrated with its energy off
# by up to about 2.5 %, at one full depth per step by 15 %, and past 1.5 the step is unstable for it.
FAST_STEP = 0.5


def _describe(state, body_id):
    """'rounded body 3', 'sphere body 4', 'Wall 0', ... ."""
    if body_id in state.body_ids:
        return f"rounded body {body_id}"
    if _tag(f"sphere.{body_id}"):
        return f"sphere body {body_id}"
    body = _body_or_none(body_id)
    return f"{partner_kind(body) if body is not None else 'body'} {body_id}"


def _size_name(state, body_id):
    return "r_eq" if body_id in state.body_ids else "radius"


def _relative_speed(body_id, other_id):
    body, other = _body_or_none(body_id), _body_or_none(other_id)
    velocity = body.state.vel if body is not None else Vector3.Zero
    if other is not None:
        velocity = velocity - other.state.vel
    return velocity.norm()


def _stop_message(state, stops):
    """Why the run stops, naming the body, with the remedy: a time step for its speed, or that no step helps."""
    cause, body, other, overlap, size, point = stops[0]
    where = "at ({}) m".format(", ".join(f"{round(x, 9) + 0.0:.4g}" for x in point))  # to the nanometre, no -0
    name, other_name = _describe(state, body), _describe(state, other)
    both_sized = other in state.body_ids or bool(_tag(f"sphere.{other}"))
    unit = _size_name(state, body) if not both_sized or _size_name(state, body) == _size_name(state, other) else "size"
    if cause == "crossed":
        what = (f"the centre of {name} has passed through {other_name} since the last step (their bounds overlapped "
                f"then), and the contact now pushes it on through; it is {where}")
    else:
        what = (f"{name} overlaps {other_name} by {overlap:.3g} m ({overlap / size:.2f} "
                f"{'of the smaller ' + unit if both_sized else unit}, {unit} = {size:.3g} m) {where}, and the overlap grows: "
                f"past {state.options['stop_overlap']:g} {unit} (rm.engine(stop_overlap=...)) the contact no longer "
                "describes it")
    speed = _relative_speed(body, other)
    own = _size_name(state, body)
    own_size = size if not both_sized else None
    if speed > 0:
        bound = state.stability(state.options, speed)[0]
        moves = f"{speed * O.dt / own_size:.2g} {own}" if own_size else f"{speed * O.dt:.3g} m"
        if O.dt > bound:
            advice = (f"At {speed:.3g} m/s it moves {moves} per step (O.dt = {O.dt:.3g} s): reduce O.dt to "
                      f"rm.critical_timestep(impact_speed={speed:.3g}) = {bound:.3g} s or less and start again from a "
                      "state before the impact (rm.checkpoint)")
        else:
            advice = (f"O.dt = {O.dt:.3g} s is already within rm.critical_timestep(impact_speed={speed:.3g}) = "
                      f"{bound:.3g} s: no smaller step helps, the contact cannot hold these bodies apart (an impact "
                      "too fast, or a load too large, for such soft materials)")
    else:
        advice = "The bodies are at rest: the contact cannot hold them apart (a load too large for such soft materials)"
    more = ""
    if len(stops) > 1:
        others = [f"{_describe(state, b)} with {_describe(state, o)}" for _, b, o, *_ in stops[1:4]]
        more = f" Also: {'; '.join(others)}{'; ...' if len(stops) > 4 else ''}."
    return f"{what}. {advice}.{more}"


def _warn_fast_bodies(state):
    """Warns, once per run, of a body that moved more than FAST_STEP of its contact depth in the last step."""
    if state.warned_fast:
        return
    body, speed, fraction, depth = state.engine.fastest()
    if not fraction > FAST_STEP:
        return
    state.warned_fast = True
    bound = state.stability(state.options, speed)[0]
    warnings.warn(f"roundedmesh: {_describe(state, body)} moves {fraction:.2g} of its contact depth ({depth:.3g} m, "
                  f"0.1 {_size_name(state, body)}) in one step at {speed:.3g} m/s with O.dt = {O.dt:.3g} s: an impact "
                  f"at this speed is not resolved; use O.dt <= rm.critical_timestep(impact_speed={speed:.3g}) = "
                  f"{bound:.3g} s", RuntimeWarning)


def keep_triangle_forces(keep=True):
    """From the next step on, keep the contact force of every triangle of the current scene (triangle_forces(),
    the export's cell data). Off by default: it copies every triangle contact each step. Kept in O.tags."""
    _set_tag("triangle_forces", "1" if keep else "")


def _keeps_triangle_forces():
    return bool(_tag("triangle_forces"))


def triangle_forces():
    """{rounded body id: (n_triangles, 3) array}: the contact force [N] on each triangle of the body in the last
    step (the sum of its triangle contacts' normal and friction forces), for the bodies that touched anything;
    {} before the first step. None if they are not kept (keep_triangle_forces() was off for the last step)."""
    state = _current_state()
    if state is None or state.stepped_iteration is None:
        return {} if _keeps_triangle_forces() else None
    if not state.engine.keep_triangle_contacts:
        return None
    return {int(i): f for i, f in state.engine.triangle_forces().items()}
