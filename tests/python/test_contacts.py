"""rm.contacts(): the body pairs of the last contact step as the engine computed them, checked against what the
engine wrote to O.forces, against the same contacts evaluated alone (rm.body_contact, rm.plane_contact) at the
poses and velocities of that step, and against Newton's third law."""
import math

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, PyRunner, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from conftest import open_box

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2, friction=0.3, tangential_damping=20)
STEEL = rm.HertzMaterial(young=2e11, poisson=0.3, density=7800, damping=1e-2, friction=0.3, tangential_damping=20)
R = 0.02
GRAVITY = (0, 0, -9.81)
# What the engine saw in the step: the states recorded just before it (see `bodies_in_a_box`).
_states = {}


def record_states():
    _states.clear()
    for b in O.bodies:
        s = b.state
        # Copies: YADE hands out vel and angVel as references into the state, which NewtonIntegrator then changes.
        _states[b.id] = (Vector3(s.pos), Quaternion(s.ori), Vector3(s.vel), Vector3(s.angVel))


def bodies_in_a_box(steps):
    """Three spheres and a gummy bear dropped on each other into a box of four Walls and a floor, with friction,
    run until bodies press on each other and on the walls. A PyRunner just before the engine records every
    state, so that a contact can be evaluated again exactly as the step saw it: under the paper's viscous friction,
    whose force depends on the state alone (the default spring also remembers the pair's past)."""
    icosphere = rm.Mesh.icosphere(R, 2)
    bear = rm.Mesh.reference_shape("gummy_bear")
    bodies = [rm.add_body(icosphere, pos=(x, 0.004 * x / 0.02, 0.021 + 0.038 * i), material=RUBBER)
              for i, x in enumerate((0.0, 0.012, -0.01))]
    bodies.append(rm.add_body(bear, pos=(0.005, 0.0, 0.16), material=RUBBER))
    walls = open_box(0.06, STEEL)
    recorder = PyRunner(command=f"__import__('sys').modules[{__name__!r}].record_states()", iterPeriod=1, initRun=True)
    O.engines = [ForceResetter(), recorder,
                 rm.engine(friction="viscous"), NewtonIntegrator(gravity=GRAVITY, damping=0)]
    O.dt = 0.2 * rm.critical_timestep()
    O.run(steps, True)
    return bodies, walls


@pytest.fixture(scope="module")
def packed():
    """The scene after 2,700 steps (0.37 s): the bear has landed on a sphere, and the spheres press on the floor and
    one on a side wall. Returned as (bodies, walls, contacts, forces and torques on every body)."""
    O.reset()
    bodies, walls = bodies_in_a_box(2700)
    found = rm.contacts()
    wrenches = {b.id: (np.array(O.forces.f(b.id)), np.array(O.forces.t(b.id))) for b in O.bodies}
    states = dict(_states)
    meshes = rm.rounded_bodies()
    planes = {w: (O.bodies[w].shape.axis, O.bodies[w].shape.sense) for w in walls}
    O.reset()
    return bodies, planes, found, wrenches, states, meshes


def test_pairs_of_every_kind_are_listed(packed):
    bodies, walls, found, _, _, _ = packed
    ids2 = set(found["id2"].tolist())
    assert ids2 & set(bodies) and ids2 & set(walls), "the scene must have body-body and body-wall contacts"
    assert set(found["id1"].tolist()) <= set(bodies)
    n = len(found["id1"])
    for key, shape in (("force1", (n, 3)), ("torque1", (n, 3)), ("force2", (n, 3)), ("torque2", (n, 3)),
                       ("point", (n, 3)), ("normal", (n, 3)), ("overlap", (n,)), ("triangle_contacts", (n,)),
                       ("sliding", (n,))):
        assert found[key].shape == shape, key
    assert found["sliding"].dtype == bool
    assert np.all(found["triangle_contacts"] > 0)
    assert np.all(found["overlap"] > 0)
    np.testing.assert_allclose(np.linalg.norm(found["normal"], axis=1), 1, rtol=1e-14)


def test_summed_per_body_they_are_what_the_engine_wrote_to_o_forces(packed):
    _, _, found, wrenches, _, _ = packed
    summed = {i: [np.zeros(3), np.zeros(3)] for i in wrenches}
    for k in range(len(found["id1"])):
        for side in ("1", "2"):
            body = int(found["id" + side][k])
            summed[body][0] += found["force" + side][k]
            summed[body][1] += found["torque" + side][k]
    scale = max(np.linalg.norm(f) for f, _ in wrenches.values())
    for body, (force, torque) in wrenches.items():
        # The engine sums the same pair wrenches in the same order: only the order of YADE's own sums differs.
        np.testing.assert_allclose(summed[body][0], force, rtol=0, atol=1e-13 * scale, err_msg=f"body {body}")
        np.testing.assert_allclose(summed[body][1], torque, rtol=0, atol=1e-13 * scale * R, err_msg=f"body {body}")


def test_each_pair_obeys_newtons_third_law(packed):
    _, _, found, _, states, _ = packed
    np.testing.assert_array_equal(found["force2"], -found["force1"])
    for k in range(len(found["id1"])):
        p1, p2 = (np.array(states[int(found[i][k])][0]) for i in ("id1", "id2"))
        if int(found["id2"][k]) not in packed[0]:
            continue  # a Wall's position is any point of its plane: the moment balance needs bodies' positions
        # Moments about the origin: the two torques plus the moments of the two forces at the bodies' positions
        # cancel, to round-off of terms of size |F| |x|.
        total = (found["torque1"][k] + np.cross(p1, found["force1"][k]) + found["torque2"][k]
                 + np.cross(p2, found["force2"][k]))
        size = np.linalg.norm(found["force1"][k]) * max(np.linalg.norm(p1), np.linalg.norm(p2))
        assert np.linalg.norm(total) <= 1e-13 * size


def test_each_pair_is_what_the_same_contact_gives_alone(packed):
    bodies, walls, found, _, states, meshes = packed
    checked = 0
    for k in range(len(found["id1"])):
        a, b = int(found["id1"][k]), int(found["id2"][k])
        pos1, ori1, vel1, ang1 = states[a]
        if b in meshes:
            pos2, ori2, vel2, ang2 = states[b]
            f1, t1, f2, t2 = rm.body_contact(meshes[a], pos1, ori1, meshes[b], pos2, ori2, RUBBER, RUBBER, vel1=vel1,
                                             ang_vel1=ang1, vel2=vel2, ang_vel2=ang2, friction="viscous")
        else:
            axis, sense = walls[b]
            point = np.zeros(3)
            point[axis] = states[b][0][axis]
            normal = np.zeros(3)
            normal[axis] = sense
            f1, t1 = rm.plane_contact(meshes[a], pos1, ori1, point, normal, RUBBER, STEEL, vel=vel1, ang_vel=ang1,
                                      friction="viscous")
        scale = np.linalg.norm(found["force1"][k])
        # The engine took this pair's triangle pairs from its lists kept between steps, the evaluation alone
        # finds them afresh: the same triangle contacts, summed in another order (round-off of a few ulp per
        # term, relative 1e-12 for a few hundred terms).
        np.testing.assert_allclose(found["force1"][k], f1, rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(found["torque1"][k], t1, rtol=0, atol=1e-12 * scale * R)
        checked += 1
    assert checked == len(found["id1"]) and checked >= 5


def held_on_a_wall(mesh, pos, ori=Quaternion.Identity, material=RUBBER, vel=(0, 0, 0)):
    ball = rm.add_body(mesh, pos=pos, ori=ori, material=material)
    O.bodies[ball].state.blockedDOFs = "xyzXYZ"
    O.bodies[ball].state.vel = vel
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, STEEL)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=GRAVITY, damping=0)]
    O.dt = 1e-6
    O.step()
    return ball, wall


def test_a_sphere_on_a_wall_overlap_normal_and_count():
    # An icosphere with exact curvature: every triangle has the sphere's centre and radius, so the triangle
    # containing the lowest point has delta_eff = delta_s = the overlap given.
    overlap = 7e-4
    ball, wall = held_on_a_wall(rm.Mesh.icosphere(R, 3), (0.01, -0.02, R - overlap))
    found = rm.contacts()
    assert found["id1"].tolist() == [ball] and found["id2"].tolist() == [wall]
    assert found["overlap"][0] == pytest.approx(overlap, rel=1e-12)
    np.testing.assert_array_equal(found["normal"][0], [0, 0, -1])
    stats = rm.statistics()
    assert found["triangle_contacts"][0] == stats["quadrature_contacts"] + stats["direct_contacts"]
    assert not found["sliding"][0]
    np.testing.assert_array_equal(found["force1"][0], O.forces.f(ball))


def test_tilted_bear_on_a_wall_torque_is_the_force_at_the_centre_of_pressure():
    frictionless = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
    bear = rm.Mesh.reference_shape("gummy_bear")
    ori = Quaternion(Vector3(1, 0.4, 0.2).normalized(), 0.7)
    lowest = min((np.array(ori.toRotationMatrix()) @ v)[2] for v in bear.vertices)
    pos = (0.003, 0.001, -lowest - 1.5e-3)
    ball, wall = held_on_a_wall(bear, pos, ori, material=frictionless)
    found = rm.contacts()
    assert found["triangle_contacts"][0] > 3
    force, torque, point = found["force1"][0], found["torque1"][0], found["point"][0]
    assert point[2] == pytest.approx(0, abs=1e-12)  # on the wall's plane, where the contact circles lie
    # On a plane all normal forces are parallel, so the centre of pressure is exactly where their sum acts, and
    # a frictionless contact's torque about the body's position is (point - pos) x force. The torque comes from
    # the node forces of Eq. 15 at the corners (Eqs. 16-17), the point from the law's moments Mn: two routes
    # to one moment, equal to round-off (|F| |x| times 1e-12).
    np.testing.assert_allclose(torque, np.cross(point - np.array(pos), force), rtol=0,
                               atol=1e-12 * np.linalg.norm(force) * 0.03)
    np.testing.assert_allclose(found["normal"][0], [0, 0, -1], atol=1e-15)


def test_a_sliding_contact_is_reported_sliding():
    # Pushed along the wall at 1 m/s with c = 20 N s/m: c |v_t| = 20 N, far above mu F_n (< 1 N) (Eq. 21).
    held_on_a_wall(rm.Mesh.icosphere(R, 2), (0, 0, R - 5e-4), vel=(1, 0, 0))
    found = rm.contacts()
    assert found["sliding"].tolist() == [True]
    assert rm.statistics()["sliding_contacts"] > 0
    # Sliding friction opposes the motion with mu times the normal force (Eq. 19), the normal force being the
    # sum of the triangle contacts' (their normals are the wall's).
    force = found["force1"][0]
    assert force[0] == pytest.approx(-0.3 * force[2], rel=1e-12)


def test_no_contacts_before_the_first_step_and_without_rounded_bodies():
    empty = rm.contacts()
    assert all(len(v) == 0 for v in empty.values())
    assert empty["force1"].shape == (0, 3)
    rm.add_body(rm.Mesh.icosphere(R, 1), pos=(0, 0, 1), material=RUBBER)
    assert len(rm.contacts()["id1"]) == 0
    assert math.isnan(rm.unbalanced_force())
