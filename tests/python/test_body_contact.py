"""Rounded bodies against each other and against YADE Spheres and Facets, inside YADE scenes and through
body_contact: conservation over a collision, the friction ramp S4 (Fig. 6), partners, clumps and bad input."""
import math

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh_study import scenes

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)


def turned(angle, axis):
    q = Quaternion(Vector3(*axis).normalized(), angle)
    return q


def momentum_and_energy(ids):
    p, ang, kinetic = Vector3.Zero, Vector3.Zero, 0.0
    for i in ids:
        s = O.bodies[i].state
        p += s.mass * s.vel
        ang += s.pos.cross(s.mass * s.vel) + s.ori * Vector3(*[s.inertia[k] * (s.ori.conjugate() * s.angVel)[k]
                                                              for k in range(3)])
        kinetic += 0.5 * s.mass * s.vel.squaredNorm() + 0.5 * sum(
            s.inertia[k] * (s.ori.conjugate() * s.angVel)[k] ** 2 for k in range(3))
    return p, ang, kinetic


# Two free 642-node spheres, turned differently and one spinning, collide off-centre without damping or
# friction. Linear momentum: every contact force is applied with its exact opposite, so only round-off of the
# sums and of the leap-frog's updates remains: 1e-10 relative. Kinetic energy: the elastic Hertz force is
# conservative up to the leap-frog's O(dt^2) error and triangles switching in and out of contact; 1 % over
# the impact (measured -0.44 %). Non-spherical meshes are not bound by this: doc/physics.md.
def test_off_centre_collision_conserves_momentum_and_energy():
    O.reset()
    mesh = rm.Mesh.icosphere(0.025, 3)
    a = rm.add_body(mesh, pos=(0, 0, 0), ori=turned(0.4, (1, 0, 0)), material=RUBBER)
    b = rm.add_body(mesh, pos=(0.012, 0.006, 0.06), ori=turned(2.5, (0, 1, 1)), material=RUBBER)
    O.bodies[a].state.vel = (0, 0, 0.5)
    O.bodies[b].state.vel = (0, 0, -0.5)
    O.bodies[b].state.angVel = (0, 0, 3)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0)]
    O.dt = 0.05 * rm.critical_timestep()
    p0, _, e0 = momentum_and_energy((a, b))
    touched = False
    for _ in range(20000):
        O.step()
        contact = rm.statistics()["quadrature_contacts"] + rm.statistics()["direct_contacts"] > 0
        touched |= contact
        if touched and not contact:
            break
    assert touched and not contact, "the bodies met and separated"
    p1, _, e1 = momentum_and_energy((a, b))
    scale = O.bodies[a].state.mass * 0.5
    assert (p1 - p0).norm() < 1e-10 * scale
    assert abs(e1 - e0) < 0.01 * e0
    # Off-centre: the impact deflected the bodies sideways.
    assert abs(O.bodies[a].state.vel[0]) > 0.01


# S4 (Fig. 6): the friction force follows the applied force until mu m g, then stays there: the sliding
# regime starts within 5 % of F_max = mu m g (the bound) for 162 and 642 nodes; before it, friction
# balances the push up to the ramp's inertia (m dv/dt < 1 % of F_max, scenes.FrictionRamp).
@pytest.mark.parametrize("subdivisions", [2, 3])
def test_friction_ramp_slides_at_mu_m_g(subdivisions):
    r = scenes.friction_ramp(subdivisions)
    applied, friction = r["applied"] / r["f_max"], -r["friction"] / r["f_max"]
    first_sliding = applied[np.argmax(r["sliding"] > 0)]
    assert r["sliding"].max() > 0
    assert abs(first_sliding - 1) < 0.05
    before = applied < 0.9
    assert np.all(np.abs(friction[before] - applied[before]) < 0.02)
    after = applied > 1.1
    assert np.all(np.abs(friction[after] - 1) < 0.05)


# YADE Spheres and Facets carrying a roundedmesh material are contact partners; forces are action-reaction.
def test_sphere_and_facet_partners_in_a_scene():
    O.reset()
    ball = rm.add_body(rm.Mesh.icosphere(0.025, 3), pos=(0, 0, 0.0245), material=RUBBER)
    facet = O.bodies.append(utils.facet([(-0.1, -0.1, 0), (0.1, -0.1, 0), (0, 0.1, 0)], fixed=True))
    sphere = O.bodies.append(utils.sphere((0, 0, 0.0735), 0.025))
    for partner in (facet, sphere):
        rm.assign_material(partner, RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.step()
    f_ball, f_facet, f_sphere = (O.forces.f(i) for i in (ball, facet, sphere))
    assert f_facet[2] < 0 < f_sphere[2]
    assert (f_ball + f_facet + f_sphere).norm() < 1e-12 * f_sphere.norm()
    # The same pair through sphere_contact: the analytic sphere of the same radius.
    _, _, f_analytic, _ = rm.sphere_contact(rm.Mesh.icosphere(0.025, 3), (0, 0, 0.0245), Quaternion.Identity,
                                            (0, 0, 0.0735), 0.025, RUBBER, RUBBER)
    assert (f_analytic - f_sphere).norm() < 1e-12 * f_sphere.norm()


# A rounded body may be a clump member: its contact force goes to the member, and YADE moves the clump.
def test_clump_members_are_moved_by_their_contacts():
    O.reset()
    mesh = rm.Mesh.icosphere(0.02, 2)
    left = rm.add_body(mesh, pos=(-0.015, 0, 0.03), material=RUBBER)
    right = rm.add_body(mesh, pos=(0.015, 0, 0.03), material=RUBBER)
    clump = O.bodies.clump([left, right])
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5)]
    O.dt = 0.2 * rm.critical_timestep()
    O.run(int(1.0 / O.dt), True)
    state = O.bodies[clump].state
    # Resting on the wall: both members carry the weight, the clump is level and still.
    assert abs(O.bodies[left].state.pos[2] - O.bodies[right].state.pos[2]) < 1e-5
    assert 0.019 < state.pos[2] < 0.02
    assert state.vel.norm() < 1e-3
    assert O.forces.f(wall)[2] == pytest.approx(-state.mass * 9.81, rel=0.01)


def test_body_contact_arguments():
    mesh = rm.Mesh.icosphere(0.025, 1)
    args = dict(mesh1=mesh, pos1=(0, 0, 0), ori1=Quaternion.Identity, mesh2=mesh, pos2=(0, 0, 0.049),
                ori2=Quaternion.Identity, material1=RUBBER, material2=RUBBER)
    for name, bad, error, match in (("pos2", (0, math.nan, 0), ValueError, "pos2"),
                                    ("ori1", Quaternion(0, 0, 0, 0), ValueError, "ori1"),
                                    ("vel2", (math.inf, 0, 0), ValueError, "vel2"),
                                    ("mesh2", "sphere", TypeError, "")):
        with pytest.raises(error, match=match):
            rm.body_contact(**{**args, name: bad})
    with pytest.raises(ValueError, match="regime"):
        rm.body_contact(**args, regime="trapezoid")
    rigid = rm.HertzMaterial(young=math.inf, poisson=0.3, density=1)
    with pytest.raises(ValueError, match="young"):
        rm.body_contact(**{**args, "material1": rigid, "material2": rigid})


# The listing of triangle pairs adds up to body_contact's force, and each pair's node forces carry its Fn.
def test_triangle_contacts_add_up_to_the_body_force():
    mesh = rm.Mesh.icosphere(0.025, 3)
    args = (mesh, (0, 0, 0), turned(0.3, (1, 2, 0)), mesh, (0.003, 0, 0.0485), turned(1.0, (0, 1, 0)), RUBBER,
            RUBBER)
    f1, _, f2, _ = rm.body_contact(*args)
    pairs = rm.triangle_contacts(*args)
    assert len(pairs["triangle1"]) > 5
    total = (pairs["normal_force"][:, None] * pairs["normal"]).sum(axis=0)
    np.testing.assert_allclose(total, np.array(f2), rtol=1e-12, atol=1e-12 * np.linalg.norm(f2))
    np.testing.assert_allclose(pairs["node_forces1"].sum(axis=1), pairs["normal_force"], rtol=1e-12)
    np.testing.assert_allclose(pairs["node_forces2"].sum(axis=1), pairs["normal_force"], rtol=1e-12)
    assert np.all(pairs["effective_overlap"] <= pairs["sphere_overlap"] + 1e-15)
    assert set(pairs["regime"]) <= {"quadrature", "direct"}


# rm.statistics() reports the funnel of the last step: every candidate is either a triangle contact or rejected
# by exactly one test (exact integer counts), and the stages' times are those of a step that ran.
def test_statistics_report_the_funnel_of_the_last_step():
    O.reset()
    mesh = rm.Mesh.icosphere(0.025, 3)
    rm.add_body(mesh, pos=(0, 0, 0), material=RUBBER)
    rm.add_body(mesh, pos=(0.003, 0.002, 0.0495), ori=turned(0.7, (1, 2, 0)), material=RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0)]
    O.dt = 0.05 * rm.critical_timestep()
    O.run(3, True)
    s = rm.statistics()
    contacts = s["quadrature_contacts"] + s["direct_contacts"]
    rejected = sum(v for k, v in s.items() if k.startswith("rejected_"))
    assert s["body_pairs"] == 1 and s["touching_pairs"] == 1 and contacts > 3
    assert s["candidates"] == contacts + rejected
    assert s["candidate_rebuilds"] in (0, 1) and s["neighbour_rebuilds"] in (0, 1)
    assert s["pairs_ms"] > 0 and s["broad_phase_ms"] >= 0 and s["reduction_ms"] >= 0


# Members of one clump do not touch each other: two pears clumped while overlapping (158 triangle contacts
# between them before) exchange no force, and the clump resting on a wall carries exactly its weight (the wall
# force balances gravity to 1e-6 once still: damping 0.5 leaves velocities of 1e-9 m/s after 2 s).
def test_members_of_one_clump_do_not_touch():
    O.reset()
    pear = rm.Mesh.reference_shape("pear")
    first = rm.add_body(pear, pos=(0, 0, 0.05), material=RUBBER)
    second = rm.add_body(pear, pos=(0.03, 0, 0.05), ori=turned(1.0, (0, 1, 0)), material=RUBBER)
    overlapping = rm.triangle_contacts(pear, (0, 0, 0.05), Quaternion.Identity, pear, (0.03, 0, 0.05),
                                       turned(1.0, (0, 1, 0)), RUBBER, RUBBER)
    assert len(overlapping["triangle1"]) > 10
    clump = O.bodies.clump([first, second])
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-5
    O.step()
    assert O.forces.f(first).norm() == 0 and O.forces.f(second).norm() == 0
    assert rm.statistics()["body_pairs"] == 0
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5)]
    O.dt = 0.2 * rm.critical_timestep()
    O.run(int(2.0 / O.dt), True)
    assert O.forces.f(wall)[2] == pytest.approx(-O.bodies[clump].state.mass * 9.81, rel=1e-6)


# A rounded body whose state becomes non-finite mid-run stops the run with one message that names it, before
# any force of that step is applied.
def test_a_non_finite_state_stops_the_run_naming_the_body():
    O.reset()
    mesh = rm.Mesh.icosphere(0.025, 2)
    ball = rm.add_body(mesh, pos=(0, 0, 0.0245), material=RUBBER)
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = 0.1 * rm.critical_timestep()
    O.run(10, True)
    O.bodies[ball].state.vel = (0, math.nan, 0)
    iteration = O.iter
    with pytest.raises(RuntimeError, match=rf"body {ball}: its velocity is not finite"):
        O.step()
    assert O.iter == iteration
