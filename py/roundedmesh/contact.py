"""One contact evaluated without a YADE scene, through the same pipeline the engine runs each step: for
validation, for pictures, and to look inside a contact.

    plane_contact(mesh, pos, ori, plane_point, plane_normal, mesh_material, plane_material, ...) -> (F1, T1)
    body_contact(mesh1, pos1, ori1, mesh2, pos2, ori2, material1, material2, ...) -> (F1, T1, F2, T2)
    sphere_contact(mesh, pos, ori, centre, radius, mesh_material, sphere_material, ...) -> (F1, T1, F2, T2)
    partner_contact(mesh, pos, ori, partner, mesh_material, partner_material, ...) -> (F1, T1, F2, T2)
    triangle_contacts(mesh1, pos1, ori1, mesh2_or_radius, pos2, ori2, ...) -> the triangle pairs in contact

Forces [N] and torques [N m] are global; each torque is about its own body's position. Velocities [m/s] and
angular velocities [rad/s] are global. The engine's options apply as for engine(): `options=` an EngineOptions, or
its fields by name (gamma=, regime=, friction=, curvature=, normal=, ...), not both; a contact evaluated once has
no history, so the spring's displacement is zero and only its damping -c v_t acts (capped by Coulomb).
"""
import math
import numbers

import numpy as np

from ._core import EngineOptions, _body_contact, _partner_contact, _plane_contact, _sphere_contact

_ZERO = (0.0, 0.0, 0.0)


def engine_options(options=None, **named):
    """`options` (an EngineOptions) or, without it, the EngineOptions of the fields `named`: what engine() and the
    contact functions take. TypeError for both at once, an unknown name or a value of the wrong type, ValueError for
    a value out of range, each naming the option."""
    if options is None:
        return EngineOptions(**named)
    if not isinstance(options, EngineOptions):
        raise TypeError(f"options: expected an EngineOptions, got {options!r}")
    if named:
        raise TypeError(f"options= and options by name ({', '.join(named)}) together; use one: "
                        "EngineOptions(**{**options.record(), ...}) for a variant")
    return options


def plane_contact(mesh, pos, ori, plane_point, plane_normal, mesh_material, plane_material, vel=_ZERO,
                  ang_vel=_ZERO, options=None, **named):
    """(force, torque) on a rounded body (Mesh `mesh` at pos, turned by ori, moving with vel, ang_vel) pressed
    against the fixed plane through plane_point whose normal plane_normal points toward the body. Torque about
    pos."""
    return _plane_contact(mesh, pos, ori, plane_point, plane_normal, mesh_material, plane_material, vel, ang_vel,
                          engine_options(options, **named))


def body_contact(mesh1, pos1, ori1, mesh2, pos2, ori2, material1, material2, vel1=_ZERO, ang_vel1=_ZERO,
                 vel2=_ZERO, ang_vel2=_ZERO, options=None, **named):
    """(force on 1, torque on 1, force on 2, torque on 2) of two rounded bodies: Mesh mesh1 in its principal
    frame placed at pos1 turned by ori1, likewise mesh2; materials are HertzMaterials."""
    return _body_contact(mesh1, pos1, ori1, mesh2, pos2, ori2, material1, material2, vel1, ang_vel1, vel2, ang_vel2,
                         False, engine_options(options, **named))[:4]


def sphere_contact(mesh, pos, ori, centre, radius, mesh_material, sphere_material, vel=_ZERO, ang_vel=_ZERO,
                   sphere_vel=_ZERO, sphere_ang_vel=_ZERO, options=None, **named):
    """(force on the body, torque on it, force on the sphere, torque on it) of a rounded body against an
    analytic sphere of `radius` [m] centred at `centre` (what a YADE Sphere partner is)."""
    return _sphere_contact(mesh, pos, ori, centre, radius, mesh_material, sphere_material, vel, ang_vel, sphere_vel,
                           sphere_ang_vel, False, engine_options(options, **named))[:4]


def partner_contact(mesh, pos, ori, partner, mesh_material, partner_material, vel=_ZERO, ang_vel=_ZERO, details=False,
                    edge_radius=None, options=None, **named):
    """(force on the body, torque on it, force on the partner, torque on it about its position) of a rounded body
    (Mesh `mesh` placed at pos, turned by ori) against `partner`, a YADE Body with a Wall, Box, Facet or Sphere shape
    at its own pose and velocity (it need not be in O.bodies), made of `partner_material`. What the engine computes
    for that pair in a step. `partner` may also be a list of such bodies, all of `partner_material`: a surface, its
    Facets welded as in a scene (doc/physics.md, "What each partner's surface is"); then the body's force and torque
    are the sums, and the third and fourth items list the force and torque on each partner. With details=True a fifth
    item lists the triangle contacts as dicts (as triangle_contacts' rows). edge_radius [m]: what the partners' convex
    edges and corners are rounded by, as rm.set_edge_radius gives it in a scene (None: its default, a tenth of the
    body's volume-equivalent radius)."""
    bodies = [partner] if hasattr(partner, "id") else list(partner) if isinstance(partner, (list, tuple)) else None
    if not bodies or not all(hasattr(b, "id") and hasattr(b, "shape") for b in bodies):
        raise TypeError(f"partner: expected a YADE Body or a non-empty list of them, got {partner!r}")
    if edge_radius is not None and not (isinstance(edge_radius, numbers.Real) and math.isfinite(edge_radius)
                                        and edge_radius >= 0):
        raise ValueError(f"edge_radius: must be None or a finite radius >= 0 [m], got {edge_radius!r}")
    evaluated = _partner_contact(mesh, pos, ori, partner, mesh_material, partner_material, vel, ang_vel, details,
                                 -1.0 if edge_radius is None else float(edge_radius), engine_options(options, **named))
    return evaluated if details else evaluated[:4]


def triangle_contacts(mesh1, pos1, ori1, mesh2, pos2, ori2, material1, material2, vel1=_ZERO, ang_vel1=_ZERO,
                      vel2=_ZERO, ang_vel2=_ZERO, options=None, **named):
    """The triangle pairs in contact in body_contact's configuration, as a dict of numpy arrays with one row
    per pair. `mesh2` may instead be a number: the radius of an analytic sphere centred at pos2 (ori2 is then
    ignored). Columns:
        triangle1, triangle2     triangle indices (-1 for the analytic sphere)
        sphere_overlap           delta_s of the encompassing spheres, Eq. 10 [m]
        effective_overlap        delta_eff, Eq. B.4 [m]
        radius, contact_radius   R* (Eq. 3) and a (Eq. 5) [m]
        point, normal            c_eff [m] and n12 (rows of 3, global)
        regime                   'quadrature' or 'direct' (Eq. 14), or 'exact'
        normal_force             F_n on body 2 along n12 [N]
        elastic_energy           the energy the contact stores under the normal law [J]: the pressure's (2/5) F_el
                                 delta_s, or the energy density's integral over S in closed form (regime 'exact');
                                 under normal='energy' that integral times the facing ramp (doc/physics.md), the
                                 energy whose gradient the elastic force is (but for a partner's rounded edge or
                                 corner, whose ellipse pushes as under the paper's law)
        tangential_force         F_t on body 2 (rows of 3, global) [N]; body 1 receives the opposite. With the
                                 spring, each triangle's share of the pair's force (by its normal force) and twist
        sliding                  whether the pair's spring slides (viscous: whether Eq. 21 chose sliding)
        node_forces1, node_forces2   Eq. 15 on each triangle's corners [N] (NaN for the analytic sphere)
    With curvature='principal', an elliptical contact lists its approach delta as sphere_overlap, and as radius and
    contact_radius those of the circle its ellipse is mapped to, sqrt(a b) (doc/physics.md, "Principal
    curvatures")."""
    options = engine_options(options, **named)
    if isinstance(mesh2, (int, float)):
        listed = _sphere_contact(mesh1, pos1, ori1, pos2, float(mesh2), material1, material2, vel1, ang_vel1, vel2,
                                 ang_vel2, True, options)[4]
    else:
        listed = _body_contact(mesh1, pos1, ori1, mesh2, pos2, ori2, material1, material2, vel1, ang_vel1, vel2,
                               ang_vel2, True, options)[4]
    columns = {}
    for name in ("triangle1", "triangle2"):
        columns[name] = np.array([c[name] for c in listed], dtype=int)
    for name in ("sphere_overlap", "effective_overlap", "radius", "contact_radius", "normal_force",
                 "elastic_energy"):
        columns[name] = np.array([c[name] for c in listed], dtype=float)
    for name in ("point", "normal", "tangential_force", "node_forces1"):
        columns[name] = np.array([list(c[name]) for c in listed], dtype=float).reshape(-1, 3)
    columns["node_forces2"] = np.array([list(c.get("node_forces2", (np.nan,) * 3)) for c in listed],
                                       dtype=float).reshape(-1, 3)
    columns["regime"] = np.array([c["regime"] for c in listed], dtype=str)
    columns["sliding"] = np.array([c["sliding"] for c in listed], dtype=bool)
    return columns
