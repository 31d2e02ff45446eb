"""Friction that holds (doc/physics.md, "Friction"): the default tangential spring keeps the gummy bear and the pear at
rest on a 5 degree slope with mu = 0.5, lets them slide as Coulomb predicts above the friction angle, applies the
damping c the user sets whatever the pose, enters the stability limit (a large c no longer makes the bear unstable at
steps that rm.critical_timestep() accepts), and survives O.save / O.load. The paper's viscous law, still available as
rm.engine(friction='viscous'), creeps at F_t / c."""
import math
import os
import subprocess
import sys

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh_study import scenes

G = 9.81


def settled_drift(shape, settle, window, law="spring", angle=5.0):
    """The body's displacement [m] over `window` [s] after `settle` [s] on the slope scene."""
    body = scenes.build_slope(shape, angle, law=law)
    O.run(int(round(settle / O.dt)), True)
    start = np.array(O.bodies[body].state.pos)
    O.run(int(round(window / O.dt)), True)
    return np.array(O.bodies[body].state.pos) - start


# Resting on a 5 degree slope with mu = 0.5 and c = 100 N s/m (the case: the viscous law creeps at 0.19-0.31
# mm/s there). The bound is 1 um over 10 s; over half a second once settled (the bear within 0.6 s, the pear,
# which rocks onto its balance point, within 1 s), the same rate: 0.05 um. Measured over 10 s
# (scripts/validation/validate_slope.py, doc/validation.md): far below it for both.
@pytest.mark.parametrize("shape, settle", [("gummy_bear", 0.6), ("pear", 1.0)])
def test_a_body_rests_on_a_slope_below_the_friction_angle(shape, settle):
    drift = settled_drift(shape, settle=settle, window=0.5)
    assert np.linalg.norm(drift) < 0.05e-6
    assert rm.statistics()["sliding_contacts"] == 0


# The paper's viscous law (kept as an option) has no force without slip: the bear creeps down at the speed at which
# c v carries the weight's component along the slope, m g sin(5 deg) / c = 1.12 mm/s (measured 1.07 mm/s over 10 s;
# with the paper's own circle fractions, which summed to about 2.7 for the bear lying there, it crept at
# 0.24-0.40 mm/s, the 0.19-0.31). Tolerance 10 %.
def test_the_viscous_law_creeps_on_the_slope():
    drift = settled_drift("gummy_bear", settle=0.5, window=0.5, law="viscous")
    mass = rm.rounded_bodies()[0].volume * scenes.SLOPE.particle.density
    creep = mass * G * math.sin(math.radians(5)) / scenes.SLOPE.particle.tangential_damping
    assert drift[0] / 0.5 == pytest.approx(creep, rel=0.1)


# Above the friction angle (26.6 deg for mu = 0.5), at 35 deg, the body slides with Coulomb's acceleration
# g (sin a - mu cos a) = 1.609 m/s^2: the acceleration fitted to x(t) over 0.1-0.4 s, once the landing has died out.
# The bear lies free; the pear, which on its side would tumble end over end (rolling that no friction resists), has
# its rotations blocked: a sliding block, as in S4. Tolerance 0.1 % (measured: within 0.001 % from 30 to 45 deg).
@pytest.mark.parametrize("shape, blocked", [("gummy_bear", ""), ("pear", "XYZ")])
def test_a_body_slides_with_coulombs_acceleration_above_the_friction_angle(shape, blocked):
    angle = math.radians(35)
    body = scenes.build_slope(shape, 35, blocked=blocked)
    O.run(int(round(0.1 / O.dt)), True)
    times, positions = scenes.trace_slope(body, 0.3, samples=30)
    acceleration = 2 * np.polyfit(times, positions[:, 0], 2)[0]
    expected = G * (math.sin(angle) - scenes.SLOPE.particle.friction * math.cos(angle))
    assert acceleration == pytest.approx(expected, rel=1e-3)
    assert rm.contacts()["sliding"].tolist() == [True]


# The damping the user sets is the damping applied: the gummy bear pressed 0.5 mm into a plane in random poses and
# moved along it at v, slowly enough not to slide, receives -c v along the plane from both laws (the spring's
# displacement is zero in a contact evaluated once, and the viscous law shares c over its triangle contacts), where
# the paper's own circle fractions gave 0.55 to 6.5 c. Tolerance: round-off (1e-11: the tangential part of a
# force some 100 times larger, turned between frames).
@pytest.mark.parametrize("friction", ["spring", "viscous"])
def test_the_damping_applied_is_the_damping_set_in_any_pose(friction):
    bear = rm.Mesh.reference_shape("gummy_bear")
    material = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, friction=0.5, tangential_damping=40.0)
    floor = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, friction=0.5, tangential_damping=60.0)
    c = 0.5 * (40.0 + 60.0)
    rng = np.random.default_rng(7)
    for _ in range(8):
        ori = Quaternion(*rng.normal(size=4))
        ori.normalize()
        lowest = min((ori * Vector3(*x))[2] for x in bear.vertices)
        v = Vector3(*rng.normal(size=2), 0).normalized() * 2e-5
        force, _ = rm.plane_contact(bear, (0, 0, -5e-4 - lowest), ori, (0, 0, 0), (0, 0, 1), material, floor, vel=v,
                                    friction=friction)
        tangential = Vector3(force[0], force[1], 0)
        assert c * v.norm() < 0.5 * 0.5 * force[2]  # far from sliding
        assert (tangential + c * v).norm() < 1e-11 * c * v.norm()


# The tangential spring and damping enter rm.critical_timestep(): with friction the limit falls as c grows (about
# 2 m_t / c for a large c, m_t the mass a force at the contact moves, turning the body), and the engine refuses a
# step above it, naming the tangential contact. The case, the bear with c = 1000 N s/m on a flat floor, which
# never came to rest at dt_c / 20 before (dt_c the normal contact's limit), settles at 0.9 of the new limit: its
# motion dies out (slowly: c / k_t = 0.3 s is this spring-dashpot's relaxation time; measured |v| 1.8e-3 m/s at
# 0.1 s, 2.2e-4 at 0.25 s, 8.7e-7 at 1 s).
def test_a_large_tangential_damping_lowers_the_limit_and_the_bear_comes_to_rest():
    limits = {}
    for c in (0.0, 100.0, 1000.0):
        scenes.build_slope("gummy_bear", 0.0, tangential_damping=c)
        limits[c] = rm.critical_timestep()
    scenes.build_slope("gummy_bear", 0.0, friction=0.0)
    frictionless = rm.critical_timestep()
    assert frictionless >= limits[0.0] > limits[100.0] > limits[1000.0]
    assert limits[1000.0] < 0.1 * frictionless
    body = scenes.build_slope("gummy_bear", 0.0, tangential_damping=1000.0)
    O.dt = 1.01 * rm.critical_timestep()
    with pytest.raises(RuntimeError, match="stability limit .* of the tangential contact"):
        O.step()
    O.dt = 0.9 * rm.critical_timestep()
    O.run(int(round(0.1 / O.dt)), True)
    state = O.bodies[body].state
    speed, spin = state.vel.norm(), state.angVel.norm()
    O.run(int(round(0.15 / O.dt)), True)
    assert state.vel.norm() < 0.3 * speed and state.angVel.norm() < 0.3 * spin
    assert -O.forces.f(1)[2] == pytest.approx(state.mass * G, rel=1e-3)


# --- the springs are part of the saved scene ----------------------------------------------------------------------

def bear_on_slope():
    body = scenes.build_slope("gummy_bear", 5.0)
    O.run(int(round(0.3 / O.dt)), True)  # landed, its spring loaded
    return body


def final_state(body, steps):
    O.run(steps, True)
    s = O.bodies[body].state
    return [v.hex() for vector in (s.pos, s.vel, s.angVel) for v in vector] + [O.forces.f(body)[0].hex()]


# O.save / O.load and O.saveTmp / O.loadTmp, in this process (where the engine held later springs than the saved
# ones) and in a new one: the loaded scene goes on bit for bit as the saved one did. Without its springs (the tag
# emptied before loading), the run goes otherwise: the springs, not the rest of the scene, carry the difference.
def test_springs_survive_save_and_load(tmp_path):
    body = bear_on_slope()
    path = str(tmp_path / "slope.yade.gz")
    O.save(path)
    O.saveTmp("slope")
    iteration = O.iter
    assert O.tags["roundedmesh.springs"]
    reference = final_state(body, 300)
    O.load(path)
    assert O.iter == iteration
    assert final_state(body, 300) == reference
    O.loadTmp("slope")
    assert final_state(body, 300) == reference
    script = (f"import roundedmesh\nfrom yade import O\nO.load({path!r})\nO.run(300, True)\ns = O.bodies[{body}].state\n"
              "print(' '.join([v.hex() for vector in (s.pos, s.vel, s.angVel) for v in vector] + "
              f"[O.forces.f({body})[0].hex()]))")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split()[-len(reference):] == reference
    O.load(path)
    O.tags["roundedmesh.springs"] = ""
    assert final_state(body, 300) != reference


# A scene changed between steps (a body added: the engine is rebuilt from the tags) keeps its springs: the bear goes
# on bit for bit as without the ball added far from it. Had the springs been lost with the rebuild, it would not.
def test_springs_survive_a_change_of_the_scene():
    body = bear_on_slope()
    O.saveTmp("slope")
    reference = final_state(body, 300)
    for lose_springs in (False, True):
        O.loadTmp("slope")
        if lose_springs:
            O.tags["roundedmesh.springs"] = ""
        rm.add_body(rm.Mesh.icosphere(0.01, 1), pos=(1, 1, 0.5),
                    material=rm.HertzMaterial(young=1e6, poisson=0.4, density=2000))  # frictionless: the limit stays
        assert (final_state(body, 300) == reference) != lose_springs
