"""Rounded bodies and sphere bodies in a YADE scene, and the materials of their contact partners.

A rounded body is an ordinary YADE Body with a bare Shape and no bound, which YADE's colliders and
dispatchers skip: YADE owns its mass, inertia, position, orientation and velocities and moves it with
NewtonIntegrator (also as a member of a clump); roundedmesh owns its mesh and material (in the scene's tags,
_records.py). YADE Walls, Boxes, Facets and Spheres become contact partners when given a HertzMaterial with
assign_material. A sphere body (add_sphere) is a YADE Sphere that YADE's collider never pairs (groupMask 0):
every contact it has, also with the other partners, is roundedmesh's.
"""
import json
import math
import numbers
import warnings

import numpy as np

from yade import Body, Material, O, Shape
from yade import Sphere as YadeSphere
from yade.minieigenHP import Quaternion, Vector3

from ._core import DEEPEST_OVERLAP, HertzMaterial, Mesh, partner_kind
from .meshfiles import equivalent_radius
from .model_choice import cheapest_model
from ._records import (_engine_options, _load_mesh, _material, _material_record, _new_revision, _set_tag, _store_mesh,
                       _tag, _tags_named)


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
    return {int(i): _material(json.loads(r)["material"] if kind == "body" else json.loads(r))
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

def add_body(mesh, pos, ori=Quaternion.Identity, material=None, error=None):
    """Adds a rounded body with `mesh` (in its principal frame) centred at `pos` [m], turned by `ori`, made of
    `material` (a HertzMaterial), to the current scene. Returns the new body's id. Mass and principal inertia
    come from the mesh and the material's density. On bad input nothing is added.

    error: a force error the body must keep (a fraction: 0.05 for 5 %, the worse of a plane and a copy, median
    pose; doc/speed-vs-error.md): the body gets rm.cheapest_model(mesh, error).mesh(), the mesh remeshed to the
    fewest nodes the study's fits say meet it (once per mesh and target; every body added so shares it), or the
    mesh itself when it has about those nodes; a ValueError naming the nodes needed when it is too coarse for the
    target. The engine's options that choice was
    measured with are ModelChoice.engine_options; a warning says so when the scene's engine has others."""
    if not isinstance(mesh, Mesh):
        raise TypeError(f"mesh: expected a roundedmesh.Mesh, got {mesh!r}")
    pos = _finite_vector(pos, "pos")
    ori = _rotation(ori, "ori")
    material = _require_material(material, "material")
    _require_one_deformable(material, _ALL_KINDS, "material", "bod(ies)")
    if error is not None:
        mesh = _mesh_for_error(mesh, error)

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
    others = _rounded_body_meshes()
    body_id = O.bodies.append(body)
    _set_tag(f"body.{body_id}", json.dumps({"mesh": key, "material": _material_record(material)}))
    _new_revision()
    _warn_placed_inside(body_id, mesh, pos, ori, others)
    _placed.update(revision=_tag("revision"), meshes={**others, body_id: key})
    return body_id


# {body id: mesh key} of the scene's rounded bodies at its revision, kept by add_body: a scene built body by body
# reads its records once, not once per body.
_placed = {"revision": None, "meshes": {}}


def set_velocity(body_id, vel=None, angVel=None):
    """Sets a body's velocity `vel` [m/s] and angular velocity `angVel` [rad/s], both in the global frame; None leaves
    it as it is. Any body of the scene that moves on its own: rounded, sphere, clump or YADE's. YADE moves an
    aspherical body (a rounded body, a clump) by its angular momentum and recomputes the angular velocity from it each
    step, so a spin set through state.angVel alone is lost on the first step: this sets the angular momentum with it,
    L = R diag(I) R^T angVel (R the body's orientation, I its principal inertia). On bad input nothing changes."""
    body = _existing_body(body_id, "body_id")
    if body.isClumpMember:
        raise ValueError(f"body_id: body {body_id} is a member of clump {body.clumpId}, which moves it: set the clump's")
    vel = None if vel is None else _finite_vector(vel, "vel")
    angVel = None if angVel is None else _finite_vector(angVel, "angVel")
    state = body.state
    if vel is not None:
        state.vel = vel
    if angVel is not None:
        local = state.ori.conjugate() * angVel
        state.angVel = angVel
        state.angMom = state.ori * Vector3(*(state.inertia[k] * local[k] for k in range(3)))


def _rounded_body_meshes():
    """{body id: mesh key} of the current scene's rounded bodies."""
    if _placed["revision"] is None or _placed["revision"] != _tag("revision"):
        _placed.update(revision=None, meshes={int(i): json.loads(r)["mesh"] for i, r in _tags_named("body").items()})
    return _placed["meshes"]


def _inscribed(mesh, pos, ori):
    """(centres (k, 3) [m], radii (k,) [m]) of the mesh's inscribed spheres placed at pos, turned by ori."""
    centres, radii = mesh.inscribed_spheres
    rotation = np.array([[ori.toRotationMatrix()[i, j] for j in range(3)] for i in range(3)])
    return np.asarray(centres) @ rotation.T + np.array(pos), np.asarray(radii)


def _warn_placed_inside(body_id, mesh, pos, ori, others):
    """Warns when the new body overlaps rounded bodies already there (`others`, {id: mesh key}) by more than
    DEEPEST_OVERLAP of the smaller r_eq, naming them: by the overlap of the bodies' inscribed spheres
    (Mesh.inscribed_spheres), which lie inside the bodies, so the bodies overlap at least that much. The run would
    start with a contact past the Hertz range, held apart only by the bodies' cores (doc/physics.md, "Deep overlaps and fast
    impacts", The core)."""
    states = {i: body.state for i in others if (body := _body_or_none(i)) is not None}
    if not states:
        return
    centres, radii = _inscribed(mesh, pos, ori)
    reach = float((np.linalg.norm(centres - np.array(pos), axis=1) + radii).max())
    size = equivalent_radius(mesh)
    within = (reach + 3 * size) ** 2  # no mesh reaches farther than 3 r_eq beyond its inscribed spheres
    inside = []
    for other_id in [i for i, state in states.items() if (state.pos - pos).squaredNorm() < within]:
        other_mesh = _load_mesh(others[other_id])
        state = states[other_id]
        others_centres, other_radii = _inscribed(other_mesh, state.pos, state.ori)
        overlap = float((radii[:, None] + other_radii[None, :]
                         - np.linalg.norm(centres[:, None] - others_centres[None, :], axis=2)).max())
        smaller = min(size, equivalent_radius(other_mesh))
        if overlap > DEEPEST_OVERLAP * smaller:
            inside.append((overlap / smaller, other_id, overlap))
    if inside:
        listed = "; ".join(f"rounded body {other_id} by at least {overlap:.3g} m ({fraction:.2f} of the smaller r_eq)"
                           for fraction, other_id, overlap in sorted(inside, reverse=True)[:10])
        warnings.warn(f"add_body: rounded body {body_id} is placed inside {listed}: deeper than a Hertz contact "
                      f"reaches ({DEEPEST_OVERLAP:g} r_eq), where only the bodies' cores push them apart, and hard. "
                      "Place it apart, or remove it with O.bodies.erase", RuntimeWarning, stacklevel=3)


def _mesh_for_error(mesh, error):
    """The mesh of rm.cheapest_model(mesh, error), warning when the scene's engine options are not the ones its
    error was measured with (they belong to rm.engine, not to a body)."""
    choice = cheapest_model(mesh, error)
    scene_options = {k: _engine_options().record()[k] for k in choice.engine_options}
    if scene_options != choice.engine_options:
        warnings.warn(f"add_body(error={error}): the mesh's error was measured with rm.engine options "
                      f"{choice.engine_options}; this scene's engine has {scene_options}: give "
                      f"rm.engine(**rm.cheapest_model(mesh, {error}).engine_options)", stacklevel=3)
    return choice.mesh()


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
        density = _material(r["material"]).density
        if material.density != density and body.isClumpMember:
            raise ValueError(f"material: body {body.id} is a member of clump {body.clumpId}, whose mass and inertia "
                             f"were fixed by O.bodies.clump; a new density ({material.density:g} instead of "
                             f"{density:g} kg/m^3) must be given before clumping")
        _require_one_deformable(material, _ALL_KINDS, "material", "bod(ies)", exclude=body.id)
        body.material = _yade_material(material)
        if record:
            if material.density != density:
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



def set_edge_radius(body_ids, radius):
    """Rounds the convex edges and corners of the contact partners `body_ids` (a body id or a list of them: Boxes, or
    the Facets of a surface) by `radius` [m] from the next step on: a rounded body meets such an edge as Hertz's
    contact with a cylinder of that radius, and a Box's corner as one with a sphere (doc/physics.md, "What each
    partner's surface is"); 0 makes them sharp. By default a partner's edges are rounded by a tenth of the
    volume-equivalent radius of the body touching it, the deepest a Hertz contact is meant to reach. Give one radius to
    every Facet of a surface. ValueError, and nothing changes, for a radius that is negative or not finite or a body
    that is not a Box or Facet partner (Walls and Spheres have no edges)."""
    ids = [body_ids] if isinstance(body_ids, numbers.Integral) else list(body_ids)
    try:
        radius = float(radius)
    except (TypeError, ValueError):
        raise TypeError(f"radius: expected a number, got {radius!r}") from None
    if not (math.isfinite(radius) and radius >= 0):
        raise ValueError(f"radius: must be finite and not negative, got {radius:g} m")
    for body_id in ids:
        body = _existing_body(body_id, "body_ids")
        if not _tag(f"partner.{body.id}") or partner_kind(body) not in ("Box", "Facet"):
            raise ValueError(f"body_ids: body {body.id} is not a Box or Facet contact partner (assign_material makes "
                             "one); only their edges are rounded")
    for body_id in ids:
        _set_tag(f"edge_radius.{int(body_id)}", repr(radius))
    _new_revision()


def rounded_bodies():
    """{body id: Mesh} of the current scene's rounded bodies."""
    return {int(i): _load_mesh(json.loads(record)["mesh"]) for i, record in _tags_named("body").items()
            if _body_or_none(int(i)) is not None}


def sphere_bodies():
    """{body id: radius [m]} of the current scene's sphere bodies (add_sphere)."""
    return {int(i): _body_or_none(int(i)).shape.radius for i in _tags_named("sphere")
            if _body_or_none(int(i)) is not None}

