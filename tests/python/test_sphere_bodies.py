"""Sphere bodies (rm.add_sphere) in YADE scenes: every contact of theirs is the engine's, with the rounded
bodies' law (the damped Hertz force of Eq. 7 and the Coulomb friction of Eqs. 19-21). Collisions against
conservation laws and against Eq. 7 integrated with scipy, a sphere resting on a Wall, a sphere against a fine
rounded body, a mixed box, saving and loading, statistics, the time-step limit, bad input."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from yade import ForceResetter, Material, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm

SOFT = rm.HertzMaterial(young=1e7, poisson=0.3, density=1000, damping=0)
STIFF = rm.HertzMaterial(young=2e7, poisson=0.4, density=1500, damping=0)


def effective_modulus(a, b):
    return 1 / ((1 - a.poisson ** 2) / a.young + (1 - b.poisson ** 2) / b.young)


def engines(gravity=(0, 0, 0), damping=0):
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=gravity, damping=damping)]


def with_damping(material, damping):
    return rm.HertzMaterial(young=material.young, poisson=material.poisson, density=material.density, damping=damping)


R1, R2, V1, V2 = 0.01, 0.015, 0.3, -0.2  # radii [m], velocities along x [m/s]


def head_on(m1, m2, fraction):
    """Two sphere bodies of unequal size and material meeting head-on at O.dt = fraction * critical_timestep();
    returns the bodies, their kinetic energy and momentum before, and the steps run until they have parted."""
    a = rm.add_sphere((0, 0, 0), R1, m1)
    b = rm.add_sphere((R1 + R2 + 1e-4, 0, 0), R2, m2)
    O.bodies[a].state.vel, O.bodies[b].state.vel = Vector3(V1, 0, 0), Vector3(V2, 0, 0)
    engines()
    O.dt = fraction * rm.critical_timestep()
    before = kinetic_energy(a, b), momentum(a, b)
    touched = False
    for steps in range(1, 100000):
        O.step()
        touching = rm.statistics()["sphere_contacts"] == 1
        touched |= touching
        if touched and not touching:
            return a, b, before, steps
    raise AssertionError("the spheres never parted")


def kinetic_energy(*ids):
    return sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm() for i in ids)


def momentum(a, b):
    return O.bodies[a].state.mass * O.bodies[a].state.vel + O.bodies[b].state.mass * O.bodies[b].state.vel


def reduced_mass(a, b):
    m1, m2 = O.bodies[a].state.mass, O.bodies[b].state.mass
    return m1 * m2 / (m1 + m2)


# Undamped: the collision gives back the kinetic energy it took. The leap-frog conserves a shadow energy that
# differs from the true one by at most (omega dt)^2 / 4 of it for a linear spring of frequency omega; the
# contact's stiffest point is the deepest overlap, delta_max = (15 mu v^2 / (16 E* sqrt(R*)))^(2/5), where
# k = 2 E* sqrt(R* delta_max): the energy after must lie within that bound (1.2e-3 here; 2.6e-5 is measured,
# the bound holds over the whole oscillation while a collision leaves only what the shadow energy keeps of it).
# Momentum: the two forces are equal and opposite, so it changes by round-off only (1e-13 of m1 |v1| over the
# ~100 steps, each adding a few ulps).
def test_undamped_head_on_collision_conserves_energy_and_momentum():
    a, b, (energy, p), steps = head_on(SOFT, STIFF, 0.05)
    mu, e_star, r_star = reduced_mass(a, b), effective_modulus(SOFT, STIFF), R1 * R2 / (R1 + R2)
    depth = (15 * mu * (V1 - V2) ** 2 / (16 * e_star * math.sqrt(r_star))) ** 0.4
    omega = math.sqrt(2 * e_star * math.sqrt(r_star * depth) / mu)
    bound = (omega * O.dt) ** 2 / 4
    assert 1e-6 < bound < 1e-2
    assert kinetic_energy(a, b) == pytest.approx(energy, rel=bound)
    assert (momentum(a, b) - p).norm() < 1e-13 * O.bodies[a].state.mass * V1
    assert O.bodies[a].state.vel[0] < 0  # the lighter one bounced back


def restitution_of_eq7(mu, e_star, r_star, damping, speed):
    """The coefficient of restitution of Eq. 7 for reduced mass mu [kg] meeting at `speed` [m/s]: the overlap's
    ODE mu delta'' = -F(delta, delta'), F = (4/3) E* sqrt(R*) (delta^3/2 + A delta' delta^1/2) >= 0, from
    delta = 0 until it returns to 0, integrated with scipy to rtol 1e-10."""
    def rhs(_, y):
        delta, rate = y
        force = 4 / 3 * e_star * math.sqrt(r_star) * (max(delta, 0) ** 1.5 + damping * rate * math.sqrt(max(delta, 0)))
        return [rate, -max(force, 0) / mu]

    def parted(t, y):
        return y[0] if t > 0 else 1.0
    parted.terminal, parted.direction = True, -1
    solution = solve_ivp(rhs, (0, 1), [0, speed], events=parted, rtol=1e-10, atol=1e-14, method="DOP853")
    assert solution.status == 1
    return -solution.y_events[0][0][1] / speed


# Damped, with unequal damping constants (A = (A1 + A2) / 2 = 2e-4 s): the restitution converges to the one of
# Eq. 7's ODE (scipy, rtol 1e-10) as O.dt shrinks. The leap-frog's damping force uses the velocity half a step
# behind the overlap, an error of first order in O.dt: measured, the simulated restitution is below the ODE's by
# 1.3e-4, 1.1e-4, 6.7e-5 and 3.7e-5 at 0.025, 0.0125, 0.00625 and 0.003125 of the critical step. Tolerances:
# 2e-4 at 0.025 and 1e-4 at 0.00625, each about 1.5 times the measured gap.
@pytest.mark.parametrize("fraction, tolerance", [(0.025, 2e-4), (0.00625, 1e-4)])
def test_damped_head_on_collision_has_the_restitution_of_eq7(fraction, tolerance):
    m1, m2 = with_damping(SOFT, 1e-4), with_damping(STIFF, 3e-4)
    a, b, _, _ = head_on(m1, m2, fraction)
    simulated = (O.bodies[b].state.vel[0] - O.bodies[a].state.vel[0]) / (V1 - V2)
    expected = restitution_of_eq7(reduced_mass(a, b), effective_modulus(m1, m2), R1 * R2 / (R1 + R2), 2e-4, V1 - V2)
    assert 0.5 < expected < 0.8
    assert simulated == pytest.approx(expected, abs=tolerance)


# A sphere body dropped on a Wall comes to rest carrying its weight: the contact force on it balances m g. After
# 0.3 s, over 30 times the contact's damping time 3 m / (A k) ~ 8 ms at rest, the leftover oscillation is below
# 1e-9 of m g; tolerance 1e-6 relative.
def test_sphere_resting_on_a_wall_carries_its_weight():
    ball = rm.add_sphere((0, 0, 0.0102), 0.01, with_damping(SOFT, 2e-3))
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(floor, STIFF)
    engines(gravity=(0, 0, -9.81))
    O.dt = 0.05 * rm.critical_timestep()
    O.run(int(0.3 / O.dt), True)
    weight = O.bodies[ball].state.mass * Vector3(0, 0, -9.81)
    assert (O.forces.f(ball) + weight).norm() < 1e-6 * weight.norm()
    assert (O.forces.f(floor) - weight).norm() < 1e-6 * weight.norm()


# The resting ball of the test above seen through rm.contacts(): one row (sphere body, wall), the force on the
# ball its weight's opposite, the overlap the Hertz overlap under that weight (F = (4/3) E* sqrt(R) delta^1.5,
# R* = R against a wall; the ball rests, so damping adds no force: 1e-6 as above, 1e-5 on delta = (F/k)^(2/3)
# for the residual motion), and O.energy's elastic entry (2/5) F delta.
def test_a_resting_sphere_body_is_listed_by_contacts_and_energy():
    ball = rm.add_sphere((0, 0, 0.0102), 0.01, with_damping(SOFT, 2e-3))
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(floor, STIFF)
    engines(gravity=(0, 0, -9.81))
    O.trackEnergy = True
    O.dt = 0.05 * rm.critical_timestep()
    O.run(int(0.3 / O.dt), True)
    contacts = rm.contacts()
    assert list(contacts["id1"]) == [ball] and list(contacts["id2"]) == [floor]
    assert list(contacts["triangle_contacts"]) == [1] and not contacts["sliding"][0]
    weight = O.bodies[ball].state.mass * 9.81
    assert np.allclose(contacts["force1"][0], (0, 0, weight), rtol=0, atol=1e-6 * weight)
    assert np.allclose(contacts["force2"][0], (0, 0, -weight), rtol=0, atol=1e-6 * weight)
    assert np.allclose(contacts["normal"][0], (0, 0, -1), atol=1e-9)
    overlap = (weight / (4 / 3 * effective_modulus(SOFT, STIFF) * math.sqrt(0.01))) ** (2 / 3)
    assert math.isclose(contacts["overlap"][0], overlap, rel_tol=1e-5)
    assert math.isclose(O.energy["rmElastPotential"], 0.4 * weight * overlap, rel_tol=2e-5)


# A sphere body against a rounded body, a 2562-node icosphere of the same radius, through the rounded bodies'
# own path: the force is rm.sphere_contact's (same code, to round-off), and Hertz's for R* = R/2 within 0.5 %
# (measured: 0.25 % low at this pose; the meshed sphere against a plane at this refinement has a worst NRMSE of
# 0.093 % over poses, two meshed spheres 0.25 % at 642 nodes: doc/validation.md).
def test_sphere_body_against_a_fine_rounded_body_gives_hertz():
    radius, overlap = 0.02, 4e-4
    mesh = rm.Mesh.icosphere(radius, 4)
    body = rm.add_body(mesh, pos=(0, 0, 0), material=SOFT)
    ball = rm.add_sphere((0, 0, 2 * radius - overlap), radius, STIFF)
    engines()
    O.dt = 1e-7
    O.step()
    force = O.forces.f(ball)
    _, _, f_partner, _ = rm.sphere_contact(mesh, (0, 0, 0), Quaternion.Identity, (0, 0, 2 * radius - overlap),
                                           radius, SOFT, STIFF)
    assert (force - f_partner).norm() < 1e-12 * force.norm()
    hertz = 4 / 3 * effective_modulus(SOFT, STIFF) * math.sqrt(radius / 2) * overlap ** 1.5
    assert force[2] == pytest.approx(hertz, rel=5e-3)
    assert (force + O.forces.f(body)).norm() < 1e-12 * force.norm()
    s = rm.statistics()
    assert s["sphere_contacts"] == 0 and s["quadrature_contacts"] + s["direct_contacts"] > 0


# 24 sphere bodies and 6 rounded bodies thrown about in a closed box of six Walls, with gravity, damping and
# friction, for 400 steps: every body stays inside the box, sphere-sphere, sphere-wall and sphere-rounded
# contacts all occur, and the forces are action-reaction overall (the walls' reactions included).
def test_mixed_box_keeps_every_body_inside():
    rng = np.random.default_rng(4)
    material = rm.HertzMaterial(young=1e6, poisson=0.4, density=1000, damping=1e-3, friction=0.4,
                                tangential_damping=0.05)
    half = 0.06
    walls = [O.bodies.append(utils.wall(s * half, axis=k, sense=-s)) for k in range(3) for s in (-1, 1)]
    for w in walls:
        rm.assign_material(w, material)
    mesh = rm.Mesh.icosphere(0.012, 2)
    grid = [Vector3(x, y, z) for x in (-0.035, 0, 0.035) for y in (-0.035, 0, 0.035) for z in (-0.04, -0.013, 0.014, 0.04)]
    ids = []
    for k, centre in enumerate(rng.permutation(grid)[:30]):
        pos = Vector3(*centre)
        ids.append(rm.add_body(mesh, pos, material=material) if k < 6 else rm.add_sphere(pos, 0.01 + 0.003 * rng.random(), material))
        O.bodies[ids[-1]].state.vel = Vector3(*rng.uniform(-1, 1, 3))
    engines(gravity=(0, 0, -9.81))
    O.dt = 0.2 * rm.critical_timestep()
    seen = {"sphere_contacts": 0, "touching_pairs": 0}
    for _ in range(400):
        O.step()
        s = rm.statistics()
        for key in seen:
            seen[key] += s[key]
        total = sum((O.forces.f(i) for i in ids + walls), Vector3.Zero)
        assert total.norm() <= 1e-9 * max(O.forces.f(i).norm() for i in ids + walls)
    assert seen["sphere_contacts"] > 50
    assert seen["touching_pairs"] > seen["sphere_contacts"]  # rounded bodies touched too
    spheres = rm.sphere_bodies()
    for i in ids:
        reach = spheres.get(i, 0.012 * 1.01)  # a 162-node icosphere's corners lie on its radius
        assert all(abs(c) < half - 0.5 * reach for c in O.bodies[i].state.pos), i


# Saved and loaded (O.saveTmp / O.loadTmp, as O.save / O.load and rm.checkpoint do), a sphere body stays one:
# same radius and material, YADE still kept from pairing it, and the next step gives the same forces.
def test_sphere_bodies_survive_save_and_load():
    a = rm.add_sphere((0, 0, 0), 0.01, SOFT)
    b = rm.add_sphere((0.0199, 0, 0.001), 0.01, STIFF)
    engines()
    O.dt = 1e-6
    O.saveTmp("spheres")
    O.step()
    forces = [O.forces.f(i) for i in (a, b)]
    O.reset()
    O.loadTmp("spheres")
    assert rm.sphere_bodies() == {a: 0.01, b: 0.01}
    assert O.bodies[a].groupMask == 0 and isinstance(O.bodies[a].shape, type(utils.sphere((0, 0, 0), 1).shape))
    O.step()
    assert [O.forces.f(i) for i in (a, b)] == forces


# A checkpoint (rm.checkpoint, a .yade.gz file through O.save) of a scene of sphere bodies only resumes, in a fresh
# scene, with the sphere bodies, and the run goes on bit for bit: 50 steps after the checkpoint, through contacts
# with the floor, give the very positions the uninterrupted run reached.
def test_sphere_bodies_resume_from_a_checkpoint_bit_for_bit(tmp_path):
    ids = [rm.add_sphere((0.021 * k, 0, 0.0099 + 0.002 * k), 0.01, with_damping(SOFT, 1e-3)) for k in range(3)]
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(floor, STIFF)
    engines(gravity=(0, 0, -9.81))
    O.dt = 0.1 * rm.critical_timestep()
    O.run(20, True)
    path = str(tmp_path / "spheres.yade.gz")
    rm.checkpoint.save(path)
    O.run(50, True)
    uninterrupted = [O.bodies[i].state.pos for i in ids]
    O.reset()
    rm.checkpoint.resume(path)
    assert sorted(rm.sphere_bodies()) == ids and O.iter == 20
    contacts = 0
    for _ in range(50):
        O.step()
        contacts += rm.statistics()["sphere_contacts"]
    assert [O.bodies[i].state.pos for i in ids] == uninterrupted
    assert contacts > 0  # the resumed steps had contacts to reproduce


def test_mass_inertia_and_yade_view():
    ball = rm.add_sphere((1, 2, 3), 0.02, STIFF)
    b = O.bodies[ball]
    mass = 1500 * 4 / 3 * math.pi * 0.02 ** 3
    assert b.state.mass == pytest.approx(mass, rel=1e-15)
    assert b.state.inertia == pytest.approx(Vector3(*[0.4 * mass * 0.02 ** 2] * 3), rel=1e-15)
    assert b.shape.radius == 0.02 and b.groupMask == 0 and b.state.pos == Vector3(1, 2, 3)
    rm.set_material(ball, SOFT)  # a new density gives a new mass
    assert b.state.mass == pytest.approx(1000 * 4 / 3 * math.pi * 0.02 ** 3, rel=1e-15)


# The limit of two equal sphere bodies: the formula of CriticalTimeStep.hpp at the reduced mass m/2, R* = r/2 and
# an overlap of r/10 (k = 2 E* sqrt(R* delta), zeta = A omega / 3), written out here.
def test_critical_timestep_of_sphere_bodies():
    material = with_damping(SOFT, 1e-3)
    r = 0.01
    for x in (0, 0.5):
        rm.add_sphere((x, 0, 0), r, material)
    m = O.bodies[0].state.mass
    k = 2 * effective_modulus(material, material) * math.sqrt(r / 2 * r / 10)
    omega = math.sqrt(k / (m / 2))
    zeta = 1e-3 * omega / 3
    assert rm.critical_timestep() == pytest.approx(2 / omega * (math.sqrt(1 + zeta ** 2) - zeta), rel=1e-12)


@pytest.mark.parametrize("radius, error", [(0, ValueError), (-0.01, ValueError), (math.nan, ValueError),
                                           (math.inf, ValueError), ("0.01", TypeError), (True, TypeError)])
def test_bad_radius_is_refused_naming_it(radius, error):
    before = len(O.bodies), dict(O.tags)
    with pytest.raises(error, match="radius"):
        rm.add_sphere((0, 0, 0), radius, SOFT)
    assert (len(O.bodies), dict(O.tags)) == before


@pytest.mark.parametrize("arguments, name", [(((0, 0, math.nan), 0.01, SOFT), "pos"),
                                             (((0, 0, 0), 0.01, Material()), "material"),
                                             (((0, 0, 0), 0.01, None), "material")])
def test_bad_position_or_material_is_refused_naming_it(arguments, name):
    with pytest.raises((TypeError, ValueError), match=name):
        rm.add_sphere(*arguments)
    assert len(O.bodies) == 0


# A sphere body whose YADE shape or material was replaced by hand stops the run naming it, before any force.
def test_a_sphere_body_changed_behind_the_engine_stops_the_run():
    ball = rm.add_sphere((0, 0, 0), 0.01, SOFT)
    engines()
    O.dt = 1e-6
    O.bodies[ball].material = Material(density=1000)
    with pytest.raises(RuntimeError, match=f"sphere body {ball}: its YADE material was replaced"):
        O.step()
    O.bodies[ball].material = Material(density=1000, label="roundedmesh")
    O.bodies[ball].shape = utils.box((0, 0, 0), (1, 1, 1)).shape
    with pytest.raises(RuntimeError, match=f"sphere body {ball}: its YADE shape is no longer a Sphere"):
        O.step()


# Two rigid sides have no Hertz contact: a rigid sphere body is refused beside a rigid partner, and a rigid
# partner beside a rigid sphere body, each naming the other; the scene stays as it was.
def test_rigid_sphere_body_beside_a_rigid_partner_is_refused():
    rigid = rm.HertzMaterial(young=math.inf, poisson=0.3, density=1000)
    ball = rm.add_sphere((0, 0, 0), 0.01, rigid)
    wall = O.bodies.append(utils.wall(-0.01, axis=2))
    before = len(O.bodies), dict(O.tags)
    with pytest.raises(ValueError, match=f"rigid sphere bod\\(ies\\) {ball}"):
        rm.assign_material(wall, rigid)
    rm.assign_material(wall, SOFT)
    with pytest.raises(ValueError, match=f"rigid bod\\(ies\\) {ball}"):
        rm.add_sphere((1, 0, 0), 0.01, rigid)
    assert len(O.bodies) == before[0]


# The time-step check names a sphere body as such when its contact sets the limit.
def test_time_step_above_the_limit_names_the_sphere_body():
    a = rm.add_sphere((0, 0, 0), 0.01, SOFT)
    rm.add_sphere((0.5, 0, 0), 0.01, SOFT)
    engines()
    O.dt = 1.5 * rm.critical_timestep()
    with pytest.raises(RuntimeError, match=f"stability limit .* sphere body {a} and body"):
        O.step()
    assert O.iter == 0 and O.bodies[a].state.pos == Vector3(0, 0, 0)
