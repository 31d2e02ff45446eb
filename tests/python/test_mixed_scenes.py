"""Rounded bodies in scenes that also run YADE's own collider and InteractionLoop: YADE spheres touch each
other, Walls, Facets and Boxes through YADE's engines, and touch rounded bodies through roundedmesh (the
spheres given a HertzMaterial with assign_material); clumps of both kinds; whatever the order in which the
scene is built, and across O.save / O.load.

The checks are balances that hold whatever the contact laws: NewtonIntegrator (damping 0) changes the
momentum of the dynamic bodies by exactly dt times their forces plus gravity, and every contact gives its
two bodies opposite forces, so the total momentum change equals the impulse of gravity minus the impulse
taken up by the fixed bodies; and a settled scene rests with the weight of each stack on its support.

InsertionSortCollider is the collider used here, as in YADE's own examples. SpatialQuickSortCollider is not:
in YADE 2023.02a it sorts one entry per body but fills only those of bodies with a bound, and reads the ids
of the others (every clump, and every rounded body) from uninitialized memory, which crashes at random in
any scene with a clump (SpatialQuickSortCollider.cpp, action()). FlatGridCollider knows only Spheres."""
import numpy as np
import pytest
from yade import (Bo1_Box_Aabb, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, FlatGridCollider, ForceResetter,
                  Ig2_Box_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                  InsertionSortCollider, InteractionLoop, Ip2_ViscElMat_ViscElMat_ViscElPhys,
                  Law2_ScGeom_ViscElPhys_Basic, NewtonIntegrator, O, ViscElMat, utils)

import roundedmesh as rm

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
STIFF = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-2)
R = 0.025   # rounded bodies (162-node icospheres) [m]
r = 0.02    # YADE spheres [m]
GRAVITY = 9.81
# 0.4 of the rounded contacts' stability limit (1.3 ms) and 1/20 of the YADE contacts' duration tc.
DT = 5e-4
FIXED = ("floor", "box", "facet")


def engines():
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb(), Bo1_Box_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(),
                             Ig2_Box_Sphere_ScGeom()],
                            [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
            rm.engine(), NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]


def build(engines_first=True, stacks_upright=False):
    """The mixed scene; returns {name: body id}. Bodies start 1 mm above their supports. Two stacks (a rounded
    body carrying a partner sphere carrying a YADE sphere; a partner sphere carrying a rounded body) stand on
    the floor, which they only do for long when `stacks_upright` keeps them from tipping (blockedDOFs)."""
    if engines_first:
        O.engines = engines()
    viscel = O.materials.append(ViscElMat(tc=0.01, en=0.3, et=1.0, density=2000, frictionAngle=0.3))
    mesh = rm.Mesh.icosphere(R, 2)
    ids = {}

    def partner(name, body):
        ids[name] = O.bodies.append(body)
        rm.assign_material(ids[name], STIFF)

    def rounded(x, y, z):
        return rm.add_body(mesh, pos=(x, y, z), material=RUBBER)

    def sphere(x, y, z):
        return utils.sphere((x, y, z), r, material=viscel)

    partner("floor", utils.wall(0, axis=2, sense=1, material=viscel))
    partner("box", utils.box((0.3, 0, 0.02), (0.08, 0.05, 0.02), fixed=True, material=viscel))
    partner("facet", utils.facet([(-0.3, -0.1, 0.05), (-0.1, -0.1, 0.05), (-0.2, 0.1, 0.05)], fixed=True,
                                 material=viscel))
    ids["A"] = rounded(0, 0, R)
    partner("S1", sphere(0, 0, 2 * R + r + 1e-3))
    ids["S2"] = O.bodies.append(sphere(0, 0, 2 * R + 3 * r + 2e-3))
    partner("S3", sphere(0.15, 0, r))
    ids["B"] = rounded(0.15, 0, 2 * r + R + 1e-3)
    ids["C"] = O.bodies.clump([rounded(0.3 - R, 0, 0.04 + R + 1e-3), rounded(0.3 + R, 0, 0.04 + R + 1e-3)])
    ids["D"] = rounded(-0.2, -0.03, 0.05 + R + 1e-3)
    ids["S4"] = O.bodies.append(sphere(-0.2, 0.03, 0.05 + r + 1e-3))
    ids["E"], _ = O.bodies.appendClumped([sphere(0, 0.15, r), sphere(0.04, 0.15, r)])
    if stacks_upright:
        for name in ("A", "S1", "S2", "S3", "B"):
            O.bodies[ids[name]].state.blockedDOFs = "xyXYZ"
    if not engines_first:
        O.engines = engines()
    O.dt = DT
    return ids


def dynamic_names(ids):
    return [name for name in ids if name not in FIXED]


def dynamic(ids):
    return [ids[name] for name in dynamic_names(ids)]


def momentum(ids):
    return sum(O.bodies[i].state.mass * np.array(O.bodies[i].state.vel) for i in dynamic(ids))


def run_with_impulse(ids, steps):
    """Runs `steps` steps; returns the impulse the fixed bodies received [N s]."""
    impulse = np.zeros(3)
    for _ in range(steps):
        O.step()
        impulse += O.dt * sum(np.array(O.forces.f(ids[name])) for name in FIXED)
    return impulse


def check_momentum_balance(ids, p0, impulse, duration):
    mass = sum(O.bodies[i].state.mass for i in dynamic(ids))
    expected = p0 + mass * np.array([0, 0, -GRAVITY]) * duration - impulse
    # Round-off only: the sums run over some hundred steps of forces of a few newtons, each rounded at 1e-16
    # relative; 1e-12 of the weight's impulse is far above that and far below any missing contact force.
    np.testing.assert_allclose(momentum(ids), expected, rtol=0, atol=1e-12 * mass * GRAVITY * duration)


@pytest.mark.parametrize("engines_first", [True, False], ids=["collider first", "bodies first"])
def test_momentum_balance_of_a_mixed_scene(engines_first):
    ids = build(engines_first)
    assert all(not O.bodies[i].bounded and O.bodies[i].bound is None for i in rm.rounded_bodies())
    p0 = momentum(ids)
    impulse = run_with_impulse(ids, 300)
    check_momentum_balance(ids, p0, impulse, O.time)
    # Both kinds of engine took part: YADE's contacts sphere-sphere (S1-S2), sphere-facet (S4) and sphere-wall
    # (S3), and none of YADE's touches a rounded body; roundedmesh's six, A-floor, A-S1, B-S3, the two clump
    # members on the box and D-facet (the clump members' own pair may be counted too).
    real = {(min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions if i.isReal}
    assert {(ids["S1"], ids["S2"]), (ids["facet"], ids["S4"]), (ids["floor"], ids["S3"])} <= real
    assert not any(i.id1 in rm.rounded_bodies() or i.id2 in rm.rounded_bodies() for i in O.interactions)
    assert rm.statistics()["body_pairs"] >= 6


# A scene continues across O.save / O.load with its collider, exactly as if it had not been saved.
def test_a_mixed_scene_continues_after_save_and_load(tmp_path):
    ids = build()
    O.run(150, True)
    saved = str(tmp_path / "mixed.yade.gz")
    O.save(saved)
    O.run(150, True)
    expected = [np.array(list(O.bodies[i].state.pos) + list(O.bodies[i].state.vel)) for i in dynamic(ids)]
    O.load(saved)
    p0 = momentum(ids)
    start = O.time
    impulse = run_with_impulse(ids, 150)
    check_momentum_balance(ids, p0, impulse, O.time - start)
    for i, state in zip(dynamic(ids), expected):
        np.testing.assert_array_equal(np.array(list(O.bodies[i].state.pos) + list(O.bodies[i].state.vel)), state)


# Settled (the slowest mode, a stack on the rubber contacts with damping ratio about 0.7, has decayed by
# e^-20 in 1000 steps), each support carries the weight of what rests on it.
def test_a_settled_scene_rests_with_the_weight_on_its_supports():
    ids = build(stacks_upright=True)
    O.run(1000, True)
    weight = {name: O.bodies[ids[name]].state.mass * GRAVITY for name in dynamic_names(ids)}
    carried = {"floor": ("A", "S1", "S2", "S3", "B", "E"), "box": ("C",), "facet": ("D", "S4")}
    for support, bodies in carried.items():
        force = O.forces.f(ids[support])
        # 1e-4: what is left of the settling in 1000 steps (measured 1.5e-5 on the floor, the slowest)
        assert -force[2] == pytest.approx(sum(weight[b] for b in bodies), rel=1e-4), support
        assert np.hypot(force[0], force[1]) < 1e-4 * -force[2], support
    assert max(O.bodies[i].state.vel.norm() for i in dynamic(ids)) < 1e-3


# FlatGridCollider knows Spheres only and refuses any other shape (a Wall, a Facet, a clump) with an error
# of its own; a rounded body gets the same error, not an abort of the process.
def test_flat_grid_collider_refuses_rounded_bodies_as_it_refuses_walls():
    rm.add_body(rm.Mesh.icosphere(R, 1), pos=(0, 0, 0.1), material=RUBBER)
    O.bodies.append(utils.sphere((0.2, 0, 0.1), r))
    O.engines = [ForceResetter(), FlatGridCollider(step=0.05, aabbMin=(-1, -1, -1), aabbMax=(1, 1, 1)),
                 rm.engine(), NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]
    O.dt = DT
    with pytest.raises(RuntimeError, match="FlatGridCollider::updateBodyCells does not handle Shape of type Shape"):
        O.step()
