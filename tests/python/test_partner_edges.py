"""Issue 37: partners' edges rounded by a radius the user sets (rm.set_edge_radius), and surfaces of welded Facets in a
YADE scene (doc/physics.md, "What each partner's surface is"; doc/user-guide.md)."""
import math

import pytest

import roundedmesh as rm
from yade import ForceResetter, NewtonIntegrator, O, Quaternion, Vector3, utils

BODY = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0)
FLOOR = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0)
BALL = rm.Mesh.icosphere(0.025, 3)
TURN = Quaternion(Vector3(1, 2, 3).normalized(), 0.4)
# The ball 1 mm into the rounded 90-degree edge of a Box of half-size 0.1 m at the origin, pushed along the diagonal.
DIAGONAL = Vector3(1, 0, 1).normalized()


def _edge_pose(radius):
    """The ball's centre 1 mm into the edge rounded by `radius`: its axis lies `radius` behind both faces."""
    return Vector3(0.1 - radius, 0, 0.1 - radius) + (radius + 0.025 - 0.001) * DIAGONAL


def _step_with_box(radius=None):
    O.reset()
    box = O.bodies.append(utils.box((0, 0, 0), (0.1, 0.1, 0.1), fixed=True))
    rm.assign_material(box, FLOOR)
    if radius is not None:
        rm.set_edge_radius(box, radius)
    ball = rm.add_body(BALL, pos=_edge_pose(0.002), ori=TURN, material=BODY)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-6
    O.step()
    return O.forces.f(ball)


def test_a_scene_rounds_a_box_edge_by_the_radius_set():
    """In a scene the Box's edge is rounded as rm.partner_contact computes it with that radius (round-off: the same
    pipeline), and a different radius gives a different force (a sharp edge, 0, gives none 1 mm into the rounded
    edge's place: the caps' circles do not reach its faces yet)."""
    for radius in (0.002, 0.0, None):
        expected = rm.partner_contact(BALL, _edge_pose(0.002), TURN, utils.box((0, 0, 0), (0.1, 0.1, 0.1)), BODY,
                                      FLOOR, edge_radius=radius)[0]
        force = _step_with_box(radius)
        assert (force - expected).norm() <= 1e-12 * max(expected.norm(), 1e-300), radius
    assert _step_with_box(0.002).dot(DIAGONAL) > 0.1
    assert _step_with_box(0.0).norm() < 0.01 * _step_with_box(0.002).norm()


@pytest.mark.parametrize("radius, error", [(-1e-3, "radius: must be finite and not negative"),
                                           (math.nan, "radius: must be finite and not negative"),
                                           (math.inf, "radius: must be finite and not negative")])
def test_set_edge_radius_refuses_a_bad_radius(radius, error):
    O.reset()
    box = O.bodies.append(utils.box((0, 0, 0), (0.1, 0.1, 0.1), fixed=True))
    rm.assign_material(box, FLOOR)
    tags = dict(O.tags)
    with pytest.raises(ValueError, match=error):
        rm.set_edge_radius(box, radius)
    assert dict(O.tags) == tags


def test_set_edge_radius_names_a_body_without_edges():
    O.reset()
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, FLOOR)
    loose = O.bodies.append(utils.box((1, 0, 0), (0.1, 0.1, 0.1)))
    box = O.bodies.append(utils.box((0, 0, 0), (0.1, 0.1, 0.1)))
    rm.assign_material(box, FLOOR)
    tags = dict(O.tags)
    for body in (wall, loose):
        with pytest.raises(ValueError, match=f"body {body} is not a Box or Facet contact partner"):
            rm.set_edge_radius([box, body], 0.001)
    assert dict(O.tags) == tags  # nothing changed, not even the Box listed first
    with pytest.raises(TypeError, match="radius: expected a number"):
        rm.set_edge_radius(box, "thin")


def test_a_sphere_body_across_a_seam_gets_the_plane_force_once():
    """A sphere body resting across the diagonal seam of a square of two Facets: one push, a Wall's (each facet used to
    push with the whole Hertz force at the seam, twice the Wall's)."""
    forces = []
    for partner in ("wall", "facets"):
        O.reset()
        if partner == "wall":
            ids = [O.bodies.append(utils.wall(0, axis=2, sense=1))]
        else:
            corners = [(-0.2, -0.2, 0), (0.2, -0.2, 0), (0.2, 0.2, 0), (-0.2, 0.2, 0)]
            ids = [O.bodies.append(utils.facet([corners[a], corners[b], corners[c]], fixed=True))
                   for a, b, c in ((0, 1, 2), (0, 2, 3))]
        for i in ids:
            rm.assign_material(i, FLOOR)
        sphere = rm.add_sphere((0.05, 0.05, 0.01 - 0.0005), 0.01, BODY)  # on the seam x = y, 0.5 mm deep
        O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
        O.dt = 1e-6
        O.step()
        forces.append(O.forces.f(sphere))
    wall, facets = forces
    assert wall[2] > 0.1
    assert (facets - wall).norm() <= 1e-12 * wall.norm()


def test_a_ball_slides_across_a_seam_of_facets_as_on_a_wall():
    """A ball held 1 mm deep and moved across the seam of two coplanar Facets in a scene: the Wall's force at every
    pose (it used to lose most of it within its contact's reach of the seam)."""
    O.reset()
    corners = [(-0.2, -0.2, 0), (0.2, -0.2, 0), (0.2, 0.2, 0), (-0.2, 0.2, 0)]
    ids = [O.bodies.append(utils.facet([corners[a], corners[b], corners[c]], fixed=True))
           for a, b, c in ((0, 1, 2), (0, 2, 3))]
    for i in ids:
        rm.assign_material(i, FLOOR)
    ball = rm.add_body(BALL, pos=(0, 0, 0.05), ori=TURN, material=BODY)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-6
    for k in range(21):
        x = -0.02 + 0.002 * k  # across the seam x = y at (0, 0)
        pos = Vector3(x, -x, 0.025 - 0.001)
        O.bodies[ball].state.pos = pos
        O.step()
        wall = rm.plane_contact(BALL, pos, TURN, (0, 0, 0), (0, 0, 1), BODY, FLOOR)[0]
        assert (O.forces.f(ball) - wall).norm() <= 1e-9 * wall.norm(), x


def test_partner_contact_names_a_bad_partner_or_edge_radius():
    box = utils.box((0, 0, 0), (0.1, 0.1, 0.1))
    for partner in ([], 3, [box, 3]):
        with pytest.raises(TypeError, match="partner: expected a YADE Body or a non-empty list of them"):
            rm.partner_contact(BALL, _edge_pose(0.002), TURN, partner, BODY, FLOOR)
    for radius in (-1e-3, math.nan, "thin"):
        with pytest.raises(ValueError, match="edge_radius: must be None or a finite radius >= 0"):
            rm.partner_contact(BALL, _edge_pose(0.002), TURN, box, BODY, FLOOR, edge_radius=radius)
