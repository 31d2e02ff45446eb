"""Materials that change between steps: rm.set_material (and assign_material on a rounded body) for rounded
bodies and partners, and a YADE material replaced by hand on a rounded body."""
import math

import numpy as np
import pytest
from yade import ForceResetter, FrictMat, NewtonIntegrator, O, PyRunner, utils

import roundedmesh as rm
from roundedmesh import scene as rm_scene

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
STIFF = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-2)
R = 0.025
GRAVITY = 9.81


def effective_modulus(a, b):
    return 1 / ((1 - a.poisson ** 2) / a.young + (1 - b.poisson ** 2) / b.young)


def held_against_a_wall():
    """A 642-node sphere held at 1 mm overlap on a Wall (all DOFs blocked, at rest): the normal force is the
    integrated Hertz pressure alone, proportional to E* (Eq. 3) at an unchanged overlap."""
    ball = rm.add_body(rm.Mesh.icosphere(R, 3), pos=(0, 0, R - 1e-3), material=RUBBER)
    O.bodies[ball].state.blockedDOFs = "xyzXYZ"
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, STIFF)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]
    O.dt = 1e-5
    O.step()
    return ball, wall


@pytest.mark.parametrize("change", ["set_material", "assign_material"])
def test_a_new_modulus_scales_the_force_as_e_star(change):
    ball, wall = held_against_a_wall()
    before = O.forces.f(ball)[2]
    harder = rm.HertzMaterial(young=3e6, poisson=0.3, density=2000, damping=1e-2)
    getattr(rm, change)(ball, harder)
    O.step()
    after = O.forces.f(ball)[2]
    # The pressure is E* times a function of the geometry alone, and the geometry is unchanged: only round-off.
    assert after / before == pytest.approx(effective_modulus(harder, STIFF) / effective_modulus(RUBBER, STIFF),
                                           rel=1e-12)
    softer_wall = rm.HertzMaterial(young=2e6, poisson=0.45, density=2000, damping=1e-2)
    rm.set_material(wall, softer_wall)
    O.step()
    assert O.forces.f(ball)[2] / before == pytest.approx(
        effective_modulus(harder, softer_wall) / effective_modulus(RUBBER, STIFF), rel=1e-12)
    assert O.forces.f(wall)[2] == -O.forces.f(ball)[2]


def test_a_new_density_changes_mass_and_inertia():
    ball = rm.add_body(rm.Mesh.icosphere(R, 2), pos=(0, 0, 1), material=RUBBER)
    mesh = rm.rounded_bodies()[ball]
    rm.set_material(ball, rm.HertzMaterial(young=1e6, poisson=0.4, density=1000))
    assert O.bodies[ball].state.mass == 1000 * mesh.volume
    np.testing.assert_array_equal(np.array(O.bodies[ball].state.inertia), 1000 * mesh.inertia)
    assert O.bodies[ball].material.density == 1000


# S4's sphere (rotations blocked, so that it can only slide) settles without friction on a Wall, pushed
# sideways by F_A = mu m g / 2, and slides away faster and faster. Friction turned on for both materials (a
# pair uses the smaller mu and the mean c) first brakes it at the Coulomb force mu F_n (Eq. 19), then:
# - with the paper's viscous law, once c |v_t| no longer exceeds mu F (Eq. 21), holds it at the creep speed F_A / c
#   of the no-slip force -c v_t (Eq. 20, the area fractions summing to 1), where friction carries F_A;
# - with the default spring, stops it: the spring holds F_A and the sphere stands still.
@pytest.mark.parametrize("law", ["viscous", "spring"])
def test_friction_turned_on_after_settling(law):
    ball = rm.add_body(rm.Mesh.icosphere(R, 2), pos=(0, 0, R - 1.4e-4), material=RUBBER)
    O.bodies[ball].state.blockedDOFs = "XYZ"
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, STIFF)
    mu, c = 0.5, 100.0
    mass = O.bodies[ball].state.mass
    push = 0.5 * mu * mass * GRAVITY
    O.engines = [ForceResetter(), rm.engine(friction=law),
                 PyRunner(command=f"O.forces.addF({ball}, ({push!r}, 0, 0))", iterPeriod=1, initRun=True),
                 NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]
    O.dt = 2e-4
    O.run(500, True)  # 0.1 s: 10 decay times of the bounce
    assert O.forces.f(wall)[0] == 0
    assert O.bodies[ball].state.vel[0] == pytest.approx(push / mass * O.time, rel=1e-12)

    for body, material in ((ball, RUBBER), (wall, STIFF)):
        rm.set_material(body, rm.HertzMaterial(young=material.young, poisson=material.poisson,
                                               density=material.density, damping=material.damping, friction=mu,
                                               tangential_damping=c))
    O.run(250, True)  # 0.05 s: half way to stopping, at the deceleration mu g / 2
    friction, normal = O.forces.f(wall)[0], -O.forces.f(wall)[2]
    # 1e-6: the normal force itself still settles from the switch (measured 3e-8 after 50 steps)
    assert friction == pytest.approx(mu * normal, rel=1e-6)
    if law == "viscous":
        O.run(750, True)  # 0.15 s more: stopped sliding after 0.1 s, then relaxed to creep with time m / c = 1.3 ms
        # 1e-9: the relaxation is exponential and long over (measured 5e-15)
        assert O.bodies[ball].state.vel[0] == pytest.approx(push / c, rel=1e-9)
    else:
        # Stopped sliding after 0.1 s with the spring at the cap mu F_n, twice the push: the spring gives back the
        # difference, the sphere moving back (0.1 mm) with the overdamped relaxation time c / k_t = 36 ms, k_t the
        # spring's stiffness at this overlap. 1 s more: 28 relaxation times.
        O.run(5250, True)
        assert abs(O.bodies[ball].state.vel[0]) < 1e-9 * push / c
    assert O.forces.f(wall)[0] == pytest.approx(push, rel=1e-9)


# Replacing a rounded body's YADE material by hand cannot change its HertzMaterial: the next step refuses to
# run, names the body and the function that does change it, and leaves the scene as it was.
def test_a_yade_material_replaced_by_hand_stops_the_next_step():
    ball, _ = held_against_a_wall()
    O.bodies[ball].material = FrictMat(young=1e7)
    iteration = O.iter
    with pytest.raises(RuntimeError, match=rf"rounded body {ball}: its YADE material was replaced by a FrictMat "
                                           rf".*roundedmesh.set_material\({ball}, material\)"):
        O.step()
    assert O.iter == iteration
    rm.set_material(ball, RUBBER)
    assert O.bodies[ball].material.label == "roundedmesh"
    O.step()
    assert O.iter == iteration + 1


def test_bad_material_changes_leave_the_scene_as_it_was():
    first = rm.add_body(rm.Mesh.icosphere(R, 1), pos=(0, 0, 1), material=RUBBER)
    second = rm.add_body(rm.Mesh.icosphere(R, 1), pos=(0.06, 0, 1), material=RUBBER)
    clump = O.bodies.clump([first, second])
    sphere = O.bodies.append(utils.sphere((1, 0, 1), 0.02))
    rigid = rm.HertzMaterial(young=math.inf, poisson=0.3, density=2000)
    rigid_wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(rigid_wall, rigid)
    snapshot = ({k: O.tags[k] for k in O.tags.keys()}, O.bodies[first].state.mass, O.bodies[clump].state.mass)
    with pytest.raises(ValueError, match=f"body {first} is a member of clump {clump}.* density"):
        rm.set_material(first, rm.HertzMaterial(young=1e6, poisson=0.4, density=1000))
    with pytest.raises(ValueError, match=f"body_id: body {sphere} is neither a rounded body nor a contact partner"):
        rm.set_material(sphere, RUBBER)
    with pytest.raises(ValueError, match=f"rigid bod\\(ies\\) {rigid_wall}"):
        rm.set_material(first, rigid)
    with pytest.raises(TypeError, match="material"):
        rm.set_material(first, FrictMat())
    with pytest.raises(ValueError, match="body_id: there is no body 99"):
        rm.set_material(99, RUBBER)
    assert ({k: O.tags[k] for k in O.tags.keys()}, O.bodies[first].state.mass,
            O.bodies[clump].state.mass) == snapshot
    # The same density is not a change of mass: a clump member may get a new modulus.
    rm.set_material(first, rm.HertzMaterial(young=2e6, poisson=0.4, density=2000))


# The changed material is the scene's: it survives O.save / O.load, also in a module that forgot the scene.
def test_a_changed_material_is_saved_with_the_scene(tmp_path):
    ball, _ = held_against_a_wall()
    rm.set_material(ball, STIFF)
    O.step()
    expected = O.forces.f(ball)[2]
    O.save(str(tmp_path / "changed.yade"))
    O.load(str(tmp_path / "changed.yade"))
    rm_scene._forget_process_state()
    O.step()
    assert O.forces.f(ball)[2] == expected
