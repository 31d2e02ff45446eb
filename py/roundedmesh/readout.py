"""What the last contact step computed, and the time step the scene's contacts allow: read from the engine's
state (stepping.py) without evaluating anything again."""
import math
import numbers

import numpy as np
from yade import O, NewtonIntegrator
from yade.minieigenHP import Vector3

from ._records import _set_tag
from .stepping import _current_state, _keeps_triangle_forces


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
    return state.stability(impact_speed or 0.0)[0] if state else math.inf


_STATISTICS = ("body_pairs", "touching_pairs", "candidates", "rejected_not_facing", "rejected_no_overlap",
               "rejected_outside_circle", "rejected_empty_polygon", "rejected_beyond_contact_circle",
               "rejected_through_body",
               "quadrature_contacts", "direct_contacts", "exact_contacts", "sphere_contacts", "core_contacts", "sliding_contacts", "neighbour_rebuilds",
               "candidate_rebuilds", "near_rebuilds", "near_pairs_scanned", "broad_phase_ms", "pairs_ms", "reduction_ms",
               "lists_cpu_ms", "near_search_cpu_ms", "narrow_phase_cpu_ms", "law_cpu_ms", "core_cpu_ms", "read_ms",
               "write_ms", "deepest_pair_overlap", "deepest_pair_fraction", "threads")


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
      quadrature_contacts, direct_contacts, exact_contacts   triangle contacts in each regime of Eq. 14, and in
                               the closed form of regime='exact' (a sphere body against a rounded body counts
                               here: the rounded body's triangles meet the sphere)
      sphere_contacts          contacts of a sphere body with another sphere body or a partner, one per pair
                               (the whole contact circle: no triangles, so not in candidates or rejected_*)
      core_contacts            touching pairs of core spheres (or of a core sphere and a partner): the deep-overlap
                               term, which acts only on pairs past the Hertz range of their own radii
                               (doc/physics.md, "Deep overlaps and fast impacts", The core)
      sliding_contacts         triangle and sphere contacts sliding: all of a pair's whose spring slides (under the
                               viscous law, each by Eq. 21)
      neighbour_rebuilds       whether the broad phase's neighbour list was rebuilt (0 or 1)
      candidate_rebuilds       pairs whose candidate triangle pairs were rebuilt (from their near list), or against a
                               Facet, whose candidate triangles were (doc/physics.md, "Lists kept between steps")
      near_rebuilds            pairs whose near list was searched again in the triangle trees
      near_pairs_scanned       triangle pairs of the near lists scanned to rebuild the candidate lists
      broad_phase_ms, pairs_ms, reduction_ms   wall time of each stage of the C++ step
      lists_cpu_ms, near_search_cpu_ms, narrow_phase_cpu_ms, law_cpu_ms, core_cpu_ms   with rm.engine(timing='stages')
                               (else 0): CPU time inside the pairs stage, summed over its threads: the candidate
                               lists brought up to date (the near searches in the triangle trees included, and also
                               given alone; a Facet's candidate triangles too), the narrow phase (Ig2), the law with
                               node forces and friction, the core
      read_ms, write_ms        wall time of reading the states from YADE (and the scene's springs, when it did not
                               write them itself) and of adding the forces (and writing the springs) to it
      deepest_pair_overlap     the overlap [m] of the pair that overlaps most for its size (contacts()['depth'])
      deepest_pair_fraction    that overlap over the smaller side's size (r_eq, or a sphere's radius): what the stop
                               rule compares with stop_overlap
      threads                  the OpenMP threads the step runs on: rm.engine(threads=...), else OMP_NUM_THREADS
                               where set (yade -jN sets it), else one
    """
    state = _current_state()
    return state.contacts.statistics if state else dict.fromkeys(_STATISTICS, 0)


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
    return state.contacts.contacts()


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



def keep_triangle_forces(keep=True):
    """From the next step on, keep the contact force of every triangle of the current scene (triangle_forces(),
    the export's cell data). Off by default: it copies every triangle contact each step. Kept in O.tags."""
    _set_tag("triangle_forces", "1" if keep else "")


def triangle_forces():
    """{rounded body id: (n_triangles, 3) array}: the contact force [N] on each triangle of the body in the last
    step (the sum of its triangle contacts' normal and friction forces), for the bodies that touched anything;
    {} before the first step. None if they are not kept (keep_triangle_forces() was off for the last step)."""
    state = _current_state()
    if state is None or state.stepped_iteration is None:
        return {} if _keeps_triangle_forces() else None
    if not state.contacts.keep_triangle_contacts:
        return None
    return {int(i): f for i, f in state.contacts.triangle_forces().items()}
