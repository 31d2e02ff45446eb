"""Fast impacts and deep overlaps in a YADE scene (doc/physics.md, "Deep overlaps and fast impacts"): a 642-node
ball thrown at 30 m/s on a Wall or a Facet floor with an ordinary time step stops the run, naming the ball, instead
of passing through; with rm.critical_timestep(impact_speed=30) a ball hard enough to be stopped bounces back and
stays above the floor; a body that passes through a Wall, a Facet or into a Box between two steps stops the run;
a step too large for a body's speed is warned of; bears settling in a box raise none of these."""
import math
import os
import re
import subprocess
import textwrap
import warnings

import numpy as np
import pytest
from conftest import open_box
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion

import roundedmesh as rm

R = 0.025
SPEED = 30.0
# S3's materials: the ball 1 MPa, the floor 5 MPa (doc/validation.md, S3).
RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
RUBBER_FLOOR = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000)
# A ball a 30 m/s impact leaves within the contact's range: 1 GPa on 5 GPa (a hard plastic). At 30 m/s it reaches
# 0.14 r_eq; the rubber ball would need 2.2 of its radii (its kinetic energy, 58 J, is seven times what its contact
# stores when pressed in by a whole radius, 8.3 J).
HARD = rm.HertzMaterial(young=1e9, poisson=0.4, density=2000)
HARD_FLOOR = rm.HertzMaterial(young=5e9, poisson=0.4, density=2000)


def floor(kind, material):
    """A Wall (both sides) or a Facet of 2.5 m at z = 0, a partner of `material`; its id."""
    if kind == "Wall":
        floor_id = O.bodies.append(utils.wall(0, axis=2, sense=0))
    else:
        floor_id = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1.5, 0)], fixed=True))
    rm.assign_material(floor_id, material)
    return floor_id


def thrown_ball(kind, ball_material, floor_material, height=0.03):
    """The 642-node ball 5 mm above the floor, falling at 30 m/s; (ball id, floor id)."""
    ball = rm.add_body(rm.Mesh.icosphere(R, 3), pos=(0, 0, height), material=ball_material)
    floor_id = floor(kind, floor_material)
    O.bodies[ball].state.vel = (0, 0, -SPEED)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    return ball, floor_id


@pytest.mark.parametrize("kind", ["Wall", "Facet"])
def test_a_ball_at_30_m_s_with_an_ordinary_step_stops_the_run_naming_it(kind):
    ball, floor_id = thrown_ball(kind, RUBBER, RUBBER_FLOOR)
    O.dt = 0.2 * rm.critical_timestep()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the step too large for its speed, warned of
        with pytest.raises(RuntimeError, match=rf"roundedmesh stopped the run at iteration \d+: .*rounded body {ball} "
                                               rf"(overlaps|has passed through) {kind} {floor_id}") as stopped:
            O.run(200, True)
    message = str(stopped.value)
    assert "critical_timestep(impact_speed=30)" in message and "reduce O.dt" in message
    # Stopped before anything went through: the ball's centre is still at the floor, not 1 m below it or leaving.
    iteration = O.iter
    assert O.bodies[ball].state.pos[2] > -0.2 * R
    assert iteration < 10
    # The step that stopped was not kept: running again stops at once, at the same iteration.
    with pytest.raises(RuntimeError, match=f"rounded body {ball}"):
        O.run(10, True)
    assert O.iter == iteration


# The rubber ball cannot be stopped within its radius whatever the step: the impact time step stops the run too, at
# the stop overlap, and says that no smaller step helps.
def test_a_ball_too_soft_for_its_impact_stops_the_run_whatever_the_step():
    ball, floor_id = thrown_ball("Wall", RUBBER, RUBBER_FLOOR)
    O.dt = rm.critical_timestep(impact_speed=SPEED)
    with pytest.raises(RuntimeError, match=rf"rounded body {ball} overlaps Wall {floor_id} by .* \(0.5\d r_eq.*"
                                           r"no smaller step helps"):
        O.run(2000, True)
    assert O.bodies[ball].state.vel[2] < -25  # the contact had barely slowed it


@pytest.mark.parametrize("kind", ["Wall", "Facet"])
def test_a_hard_ball_at_the_impact_time_step_bounces_back_and_stays_above_the_floor(kind):
    ball, _ = thrown_ball(kind, HARD, HARD_FLOOR)
    O.dt = rm.critical_timestep(impact_speed=SPEED)
    lowest = math.inf
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        while O.bodies[ball].state.vel[2] < 0 or O.bodies[ball].state.pos[2] < 0.03:
            O.step()
            lowest = min(lowest, O.bodies[ball].state.pos[2])
            assert O.iter < 2000
    # Undamped: it leaves at the speed it came (leap-frog at a tenth of the impact's depth per step: within 0.1 %),
    # having sunk 0.14 of its radius (Hertz: (15 m v^2 / (16 E* sqrt(R)))^(2/5) = 3.5 mm, plus the meshed sphere's
    # own softness).
    assert O.bodies[ball].state.vel[2] == pytest.approx(SPEED, rel=2e-3)
    assert 0.8 * R < lowest < 0.9 * R


def test_a_step_too_large_for_a_body_s_speed_is_warned_of_once():
    ball, _ = thrown_ball("Wall", HARD, HARD_FLOOR)
    O.dt = rm.critical_timestep()  # allowed: the stability limit of the contact at 0.1 r_eq
    bound = rm.critical_timestep(impact_speed=SPEED)
    with pytest.warns(RuntimeWarning, match=rf"rounded body {ball} moves 2.2 of its contact depth .* at 30 m/s .*"
                                            rf"critical_timestep\(impact_speed=30\) = {bound:.3g} s") as record:
        O.run(20, True)
    assert len([w for w in record if "contact depth" in str(w.message)]) == 1
    # Not a stop: at the stability limit this impact is not resolved (the ball gains energy), which the warning
    # is for.
    assert O.bodies[ball].state.vel[2] > SPEED


def test_the_impact_time_step():
    ball, floor_id = thrown_ball("Wall", RUBBER, RUBBER_FLOOR)
    m = O.bodies[ball].state.mass
    r = (3 * rm.rounded_bodies()[ball].volume / (4 * math.pi)) ** (1 / 3)
    e_star = 1 / (2 * (1 - 0.4**2) / 1e6)  # the ball against a body like itself: reduced mass m/2, R* = r/2

    def impact_step(speed, mass, radius, modulus):
        depth = (15 * mass * speed**2 / (16 * modulus * math.sqrt(radius))) ** 0.4
        return 0.1 * min(depth, 0.1 * r) / speed

    for speed in (0.1, 1.0, SPEED):
        wall = impact_step(speed, m, r, 1 / ((1 - 0.4**2) / 1e6 + (1 - 0.4**2) / 5e6))
        expected = min(rm.critical_timestep(), wall, impact_step(speed, m / 2, r / 2, e_star))
        assert rm.critical_timestep(impact_speed=speed) == pytest.approx(expected, rel=1e-12)
    assert rm.critical_timestep(impact_speed=0) == rm.critical_timestep() == rm.critical_timestep(impact_speed=None)
    with pytest.raises(ValueError, match="impact_speed"):
        rm.critical_timestep(impact_speed=-1)
    with pytest.raises(TypeError, match="impact_speed"):
        rm.critical_timestep(impact_speed="fast")


def touching_then_moved(partner, start, moved, material=RUBBER):
    """A ball resting at `start` on `partner` for a step, then put at `moved`; the second step."""
    ball = rm.add_body(rm.Mesh.icosphere(R, 3), pos=start, material=material)
    rm.assign_material(partner, RUBBER_FLOOR)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-6
    O.step()
    O.bodies[ball].state.pos = moved
    O.step()
    return ball


def test_a_centre_through_a_wall_a_facet_or_into_a_box_stops_the_run():
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    with pytest.raises(RuntimeError, match=rf"the centre of rounded body \d+ has passed through Wall {wall}"):
        touching_then_moved(wall, (0, 0, 0.024), (0, 0, -0.02))
    O.reset()
    facet = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1.5, 0)], fixed=True))
    with pytest.raises(RuntimeError, match=rf"has passed through Facet {facet}"):
        touching_then_moved(facet, (0, 0, 0.024), (0, 0, -0.005))
    O.reset()
    box = O.bodies.append(utils.box((0, 0, 0), (0.1, 0.1, 0.1), fixed=True))
    with pytest.raises(RuntimeError, match=rf"has passed through Box {box}"):
        touching_then_moved(box, (0, 0, 0.124), (0, 0, 0.09))


# Falling past a facet's rim is no crossing: a floor of facets can end.
def test_falling_past_a_facet_s_edge_does_not_stop_the_run():
    facet = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1.5, 0)], fixed=True))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        touching_then_moved(facet, (0.99, -0.99, 0.024), (1.03, -1.03, -0.02))


def test_stop_overlap_is_an_engine_option():
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER_FLOOR)
    ball = rm.add_body(rm.Mesh.icosphere(R, 3), pos=(0, 0, 0.024), material=RUBBER)
    O.engines = [ForceResetter(), rm.engine(stop_overlap=0.2), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-6
    O.step()
    O.bodies[ball].state.pos = (0, 0, R - 0.21 * R)
    with pytest.raises(RuntimeError, match=r"past 0.2 r_eq \(rm.engine\(stop_overlap=...\)\)"):
        O.step()
    O.engines = [ForceResetter(), rm.engine(stop_overlap=math.inf), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.step()
    for bad, error in ((0, ValueError), (-1, ValueError), ("never", TypeError), (True, TypeError)):
        with pytest.raises(error, match="stop_overlap"):
            rm.engine(stop_overlap=bad)


# No false alarm: four gummy bears dropped into a box settle without a stop or a warning, at a tenth of the
# stability limit (S1's materials: bears 1 MPa, walls 5 MPa, A = 0.01 s, frictionless).
def test_bears_settling_in_a_box_raise_nothing():
    bears = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01)
    walls = open_box(0.11, rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0.01))
    bear = rm.Mesh.reference_shape("gummy_bear")
    rng = np.random.default_rng(3)
    ids = []
    for k, (x, y) in enumerate([(-0.05, -0.05), (0.05, -0.05), (-0.05, 0.05), (0.05, 0.05)]):
        q = rng.normal(size=4)
        ids.append(rm.add_body(bear, pos=(0.6 * x, 0.6 * y, 0.06 + 0.06 * k), ori=Quaternion(*(q / np.linalg.norm(q))),
                               material=bears))
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = 0.1 * rm.critical_timestep()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        O.run(int(1.0 / O.dt), True)
    # Landed (they hit the floor and each other at up to 1.7 m/s) and settling: frictionless, they still rock.
    assert max(O.bodies[i].state.vel.norm() for i in ids) < 0.2
    assert max(O.bodies[i].state.pos[2] for i in ids) < 0.1
    found = rm.contacts()
    assert len(found["id1"]) >= 4
    assert max(found["overlap"]) < 0.1 * 0.025
    # The depth the stop rule compares: the deepest overlap along the pair's normal, at most the deepest overlap, and
    # the same against a Wall, whose contacts share one normal.
    assert np.all(found["depth"] <= found["overlap"] * (1 + 1e-12))
    on_walls = np.isin(found["id2"], walls)
    assert on_walls.any() and np.allclose(found["depth"][on_walls], found["overlap"][on_walls], rtol=1e-12)


def test_the_stop_message_stands_alone():
    # One sentence on what happened and where, one on what to do; read in a terminal without a traceback through roundedmesh.
    ball, floor_id = thrown_ball("Facet", RUBBER, RUBBER_FLOOR)
    O.dt = 0.2 * rm.critical_timestep()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        with pytest.raises(RuntimeError) as stopped:
            O.run(200, True)
    message = str(stopped.value)
    cause = message[message.index("roundedmesh stopped"):]
    cause = cause[:cause.index("\n")] if "\n" in cause else cause
    assert re.fullmatch(r"roundedmesh stopped the run at iteration \d+: rounded body \d+ overlaps Facet \d+ "
                        r"by [0-9.e-]+ m \(0\.\d\d r_eq, r_eq = 0.0249 m\) at \([-0-9.e]+, [-0-9.e]+, [-0-9.e]+\) m, and "
                        r"the overlap grows: past 0.5 r_eq "
                        r"\(rm.engine\(stop_overlap=...\)\) the contact no longer describes it\. At 30 m/s it moves "
                        r"[0-9.]+ r_eq per step \(O.dt = [0-9.e-]+ s\): reduce O.dt to "
                        r"rm.critical_timestep\(impact_speed=30\) = [0-9.e-]+ s or less and start again from a state "
                        r"before the impact \(rm.checkpoint\)\.", cause), cause


# What a user sees when the stop ends a script: YADE's report of its engine's error (FATAL ERROR, once per O.run) and
# the script's own one-frame traceback, no traceback through roundedmesh (as test_bad_input.py checks for the other
# errors of the engine).
def test_a_stopped_script_reports_without_tracebacks_through_roundedmesh(tmp_path):
    script = tmp_path / "thrown_ball.py"
    script.write_text(textwrap.dedent("""
        import roundedmesh as rm
        from yade import O, utils, ForceResetter, NewtonIntegrator
        ball = rm.add_body(rm.Mesh.icosphere(0.025, 3), pos=(0, 0, 0.03),
                           material=rm.HertzMaterial(young=1e6, poisson=0.4, density=2000))
        floor = O.bodies.append(utils.wall(0, axis=2, sense=0))
        rm.assign_material(floor, rm.HertzMaterial(young=5e6, poisson=0.4, density=2000))
        O.bodies[ball].state.vel = (0, 0, -30)
        O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
        O.dt = 0.2 * rm.critical_timestep()
        O.run(100, True)
    """))
    out = subprocess.run(["/usr/bin/python3", str(script)], capture_output=True, text=True,
                         env=os.environ)
    assert out.returncode == 1
    assert out.stderr.count("FATAL ERROR") == 1, out.stderr
    assert out.stderr.count("Traceback") == 1, out.stderr
    assert "roundedmesh/scene.py\", line" not in out.stderr
    assert "roundedmesh stopped the run at iteration 1: rounded body 0 overlaps Wall 1" in out.stderr
    assert out.stderr.count("RuntimeWarning: roundedmesh: rounded body 0 moves") == 1


# Sphere bodies are held to the same rules, named as sphere bodies.
def test_a_sphere_body_through_a_wall_stops_the_run():
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER_FLOOR)
    sphere = rm.add_sphere((0, 0, 0.024), R, RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-6
    O.step()
    O.bodies[sphere].state.pos = (0, 0, -0.01)
    with pytest.raises(RuntimeError, match=rf"the centre of sphere body {sphere} has passed through Wall {wall}"):
        O.step()
