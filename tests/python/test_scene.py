"""Rounded bodies inside YADE scenes: bodies, partners, reactions, save/load, erased bodies."""
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh import scene as rm_scene
from roundedmesh.export import write_vtp
from roundedmesh_study.scenes import S3, build_bouncing_sphere

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
STIFF = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-3)


def test_a_rounded_body_is_an_ordinary_aspherical_yade_body():
    mesh = rm.Mesh.icosphere(0.025, 2)
    ori = Quaternion(Vector3(1, 1, 0).normalized(), 0.3)
    body_id = rm.add_body(mesh, pos=(1, 2, 3), ori=ori, material=RUBBER)
    body = O.bodies[body_id]
    assert type(body.shape).__name__ == "Shape" and body.bound is None and not body.bounded
    assert body.aspherical and body.dynamic and body.material.label == "roundedmesh"
    assert body.state.mass == pytest.approx(RUBBER.density * mesh.volume, rel=1e-14)
    np.testing.assert_allclose(np.array(body.state.inertia), RUBBER.density * mesh.inertia, rtol=1e-14)
    assert body.state.pos == Vector3(1, 2, 3)
    assert (body.state.ori.conjugate() * ori).toAxisAngle()[1] == pytest.approx(0, abs=1e-12)
    assert rm.rounded_bodies()[body_id].volume == mesh.volume


def test_set_velocity_keeps_a_spin_that_yade_would_drop():
    """YADE moves an aspherical body by its angular momentum: a spin set through state.angVel alone is gone after one
    step. rm.set_velocity sets L = R diag(I) R^T omega with it, and the body then spins free of torque: L stays as
    set (bitwise: the integrator adds dt times a zero torque), the rotational energy omega.L / 2 within the
    integrator's error, about (omega dt)^2 = 1e-8 relative over the run (tolerance 1e-6), and the body drifts at
    its velocity. On bad input nothing changes."""
    mesh = rm.Mesh.reference_shape("gummy_bear")  # three distinct principal inertias: the spin precesses
    ori = Quaternion(Vector3(1, 2, 3).normalized(), 0.7)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
    O.dt = 1e-5
    dropped = rm.add_body(mesh, pos=(0, 0, 0), ori=ori, material=RUBBER)
    O.bodies[dropped].state.angVel = Vector3(3, -7, 5)
    body = rm.add_body(mesh, pos=(1, 0, 0), ori=ori, material=RUBBER)
    omega, vel = np.array([3.0, -7.0, 5.0]), np.array([0.1, 0.2, -0.3])
    rm.set_velocity(body, vel=tuple(vel), angVel=tuple(omega))
    state = O.bodies[body].state
    rotation = np.array(state.ori.toRotationMatrix())
    momentum = rotation @ np.diag(np.array(state.inertia)) @ rotation.T @ omega
    np.testing.assert_allclose(np.array(state.angMom), momentum, rtol=1e-14)
    energy = 0.5 * omega @ momentum
    for bad in ({"angVel": (float("nan"), 0, 0)}, {"vel": (1, 2)}):
        with pytest.raises((TypeError, ValueError)):
            rm.set_velocity(body, **bad)
    with pytest.raises(ValueError, match="no body 99"):
        rm.set_velocity(99, vel=(0, 0, 0))
    members = [O.bodies.append(utils.sphere(centre, 0.01)) for centre in ((5, 0, 0), (5.02, 0, 0))]
    clump = O.bodies.clump(members)
    with pytest.raises(ValueError, match=f"member of clump {clump}"):
        rm.set_velocity(members[0], vel=(1, 0, 0))
    assert O.bodies[members[0]].state.vel == Vector3(0, 0, 0)
    assert np.array(state.angVel) == pytest.approx(omega, abs=0) and np.array(state.vel) == pytest.approx(vel, abs=0)
    O.run(1000, True)
    assert np.array(O.bodies[dropped].state.angVel) == pytest.approx(0, abs=1e-12)
    assert np.array(state.angMom) == pytest.approx(momentum, rel=1e-15, abs=0)
    spun = np.array(state.angVel)
    assert np.linalg.norm(spun - omega) > 0.01 * np.linalg.norm(omega)  # it precessed, so the check below is not void
    assert 0.5 * spun @ np.array(state.angMom) == pytest.approx(energy, rel=1e-6)
    np.testing.assert_allclose(np.array(state.pos), np.array([1, 0, 0]) + vel * 1000 * O.dt, rtol=1e-12)


def one_step_against(partner, position):
    ball = rm.add_body(rm.Mesh.icosphere(0.025, 3), pos=position, material=RUBBER)
    rm.assign_material(partner, STIFF)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.step()
    return ball


# The engine inside YADE gives what plane_contact gives for the same configuration, and the wall receives
# the opposite force (YADE sums forces per body, so the comparison is exact to round-off).
def test_wall_receives_the_reaction_and_forces_match_the_static_evaluation():
    wall = O.bodies.append(utils.wall((0, 0, 0), axis=2, sense=0))
    ball = one_step_against(wall, (0, 0, 0.024))
    f_ball, f_wall = O.forces.f(ball), O.forces.f(wall)
    assert f_ball[2] > 0
    assert (f_ball + f_wall).norm() < 1e-12 * f_ball.norm()
    static, _ = rm.plane_contact(rm.Mesh.icosphere(0.025, 3), (0, 0, 0.024), Quaternion.Identity, (0, 0, 0),
                                 (0, 0, 1), RUBBER, STIFF)
    assert (f_ball - static).norm() < 1e-12 * static.norm()
    assert rm.statistics()["body_pairs"] == 1


def test_box_top_acts_like_a_wall_away_from_its_edges():
    box = O.bodies.append(utils.box((0, 0, -0.05), (0.2, 0.2, 0.05), fixed=True))
    ball = one_step_against(box, (0.01, 0.02, 0.024))
    static, _ = rm.plane_contact(rm.Mesh.icosphere(0.025, 3), (0.01, 0.02, 0.024), Quaternion.Identity,
                                 (0, 0, 0), (0, 0, 1), RUBBER, STIFF)
    assert (O.forces.f(ball) - static).norm() < 1e-12 * static.norm()
    assert (O.forces.f(ball) + O.forces.f(box)).norm() < 1e-12 * static.norm()


def forget_module_memory():
    """What a new process would have: no cached engine state or meshes, only the scene's tags."""
    rm_scene._forget_process_state()


def run_and_record(steps):
    O.run(steps, True)
    s = O.bodies[0].state
    return np.array(list(s.pos) + list(s.vel) + list(s.angVel))


# O.save / O.load keep the rounded bodies: the same run continues identically after a reload, whether the
# module's in-memory state is kept (the GUI's reload) or gone (a new process).
def test_save_and_load_continue_the_same_run(tmp_path):
    build_bouncing_sphere(2)
    O.run(3000, True)
    saved = str(tmp_path / "bounce.yade.gz")
    O.save(saved)
    expected = run_and_record(1500)

    O.load(saved)
    np.testing.assert_array_equal(run_and_record(1500), expected)

    O.load(saved)
    forget_module_memory()
    np.testing.assert_array_equal(run_and_record(1500), expected)

    script = textwrap.dedent(f"""
        import numpy as np, roundedmesh
        from yade import O
        O.load({saved!r})
        O.run(1500, True)
        s = O.bodies[0].state
        print("STATE", repr(list(s.pos) + list(s.vel) + list(s.angVel)))
    """)
    output = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True,
                            env=os.environ).stdout
    state = eval(output.split("STATE", 1)[1])
    np.testing.assert_array_equal(np.array(state), expected)


def test_an_erased_body_leaves_the_engine(tmp_path):
    sphere = build_bouncing_sphere(1)
    O.run(100, True)
    O.bodies.erase(sphere)
    assert sphere not in rm.rounded_bodies()
    write_vtp(str(tmp_path / "after_erase.vtp"))
    O.run(100, True)
    assert O.forces.f(1).norm() == 0


def test_a_mesh_given_far_from_the_origin_survives_save_and_load(tmp_path):
    sphere = rm.Mesh.icosphere(0.025, 3)
    far = rm.Mesh(sphere.vertices + [3.0, 100.0, -40.0], sphere.triangles, 0.025)
    body = rm.add_body(far, pos=far.centroid, material=RUBBER)
    O.save(str(tmp_path / "far.yade"))
    O.load(str(tmp_path / "far.yade"))
    forget_module_memory()
    np.testing.assert_array_equal(rm.rounded_bodies()[body].vertices, far.vertices)


def test_reset_forgets_everything():
    build_bouncing_sphere(1)
    assert rm.critical_timestep() < 1
    O.reset()
    assert rm.critical_timestep() == np.inf
    assert rm.rounded_bodies() == {}


# Bodies sharing a Mesh store it once in the scene.
def test_a_shared_mesh_is_stored_once():
    mesh = rm.Mesh.icosphere(0.02, 2)
    for i in range(5):
        rm.add_body(mesh, pos=(i, 0, 0), material=RUBBER)
    assert sum(1 for key in O.tags.keys() if key.startswith("roundedmesh.mesh.")) == 1


# The wiring of the stability limit: the body's YADE mass, its volume-equivalent radius, E* and A of the
# pair (the formula itself is checked against the leap-frog's amplification matrix in CriticalTimeStep).
def test_critical_timestep_matches_the_formula_for_the_bouncing_sphere():
    build_bouncing_sphere(3)
    radius = (3 * rm.rounded_bodies()[0].volume / (4 * np.pi)) ** (1 / 3)
    mass = O.bodies[0].state.mass
    e_star = 1 / ((1 - 0.4 ** 2) / 1e6 + (1 - 0.4 ** 2) / 5e6)
    omega = np.sqrt(2 * e_star * np.sqrt(radius * radius / 10) / mass)
    zeta = 1e-3 * omega / 3
    assert rm.critical_timestep() == pytest.approx(2 / omega * (np.sqrt(1 + zeta ** 2) - zeta), rel=1e-12)
    assert S3.timestep < rm.critical_timestep() / 100
