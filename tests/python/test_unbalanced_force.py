"""rm.unbalanced_force(): YADE's unbalanced force (utils.unbalancedForce) with roundedmesh's contacts counted."""
import math

import numpy as np
import pytest
from yade import (Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                  InsertionSortCollider, InteractionLoop, Ip2_ViscElMat_ViscElMat_ViscElPhys,
                  Law2_ScGeom_ViscElPhys_Basic, NewtonIntegrator, O, ViscElMat, utils)
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from conftest import open_box

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
STEEL = rm.HertzMaterial(young=2e11, poisson=0.3, density=7800, damping=1e-2)
GRAVITY = Vector3(0, 0, -9.81)


def yade_engines():
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                            [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()])]


def test_without_rounded_bodies_it_is_yades_own():
    # YADE spheres, one clump of two, on a Wall, 50 steps into their fall onto it: the same definition must give
    # YADE's number (the same sums in another order: round-off).
    grains = O.materials.append(ViscElMat(tc=0.005, en=0.3, et=1.0, density=2000, frictionAngle=0.3))
    O.bodies.append(utils.wall(0, axis=2, sense=1, material=grains))
    O.bodies.appendClumped([utils.sphere((0, 0, 0.0099), 0.01, material=grains),
                            utils.sphere((0.015, 0, 0.0099), 0.01, material=grains)])
    O.bodies.append(utils.sphere((0.1, 0, 0.0099), 0.01, material=grains))
    O.bodies.append(utils.sphere((0.104, 0.001, 0.029), 0.01, material=grains))
    O.engines = yade_engines() + [NewtonIntegrator(gravity=GRAVITY, damping=0)]
    O.dt = 1e-5
    O.run(50, True)
    assert rm.unbalanced_force() == pytest.approx(utils.unbalancedForce(), rel=1e-12)
    assert rm.unbalanced_force(True) == pytest.approx(utils.unbalancedForce(True), rel=1e-12)


def test_a_rounded_body_and_a_yade_sphere_on_a_wall_by_hand():
    # A 162-node ball pressed 0.5 mm into a Wall, at rest, and a YADE sphere resting on the same Wall through
    # YADE's own contact law. After one step: each body's resultant is its contact force plus its weight; the
    # ball's contact force comes from rm.plane_contact at the pose of the step, independently of the engine.
    grains = O.materials.append(ViscElMat(tc=0.005, en=0.3, et=1.0, density=2000, frictionAngle=0.3))
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1, material=grains))
    rm.assign_material(wall, STEEL)
    mesh = rm.Mesh.icosphere(0.02, 2)
    pos = Vector3(0, 0, 0.02 - 5e-4)
    ball = rm.add_body(mesh, pos=pos, material=RUBBER)
    sphere = O.bodies.append(utils.sphere((0.1, 0, 0.0098), 0.01, material=grains))
    O.engines = yade_engines() + [rm.engine(), NewtonIntegrator(gravity=GRAVITY, damping=0)]
    O.dt = 1e-5
    O.step()
    ball_force = np.array(rm.plane_contact(mesh, pos, Quaternion.Identity, (0, 0, 0), (0, 0, 1), RUBBER, STEEL)[0])
    interaction = O.interactions[wall, sphere]
    sphere_contact = np.array(interaction.phys.normalForce + interaction.phys.shearForce)
    g = np.array(GRAVITY)
    resultants = [np.linalg.norm(ball_force + O.bodies[ball].state.mass * g),
                  np.linalg.norm(np.array(O.forces.f(sphere)) + O.bodies[sphere].state.mass * g)]
    contacts = [np.linalg.norm(ball_force), np.linalg.norm(sphere_contact)]
    # plane_contact finds the same triangle contacts afresh and sums them in another order: round-off.
    assert rm.unbalanced_force() == pytest.approx(np.mean(resultants) / np.mean(contacts), rel=1e-12)
    assert rm.unbalanced_force(use_max_force=True) == pytest.approx(max(resultants) / np.mean(contacts), rel=1e-12)
    assert math.isnan(rm.unbalanced_force()) is False


@pytest.mark.slow
def test_falls_below_a_hundredth_as_a_packing_settles():
    # Six 42-node balls dropped into a box with normal damping (A = 0.01 s): the usual settling loop ends. YADE's
    # own utils.unbalancedForce() has no interaction to average over in this scene and gives nan.
    balls = rm.Mesh.icosphere(0.01, 1)
    for i in range(6):
        rm.add_body(balls, pos=(0.006 * (i % 2) - 0.003, 0.004 * (i % 3) - 0.004, 0.012 + 0.022 * i),
                    material=RUBBER)
    open_box(0.02, STEEL)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=GRAVITY, damping=0)]
    O.dt = 0.2 * rm.critical_timestep()
    while len(rm.contacts()["id1"]) < 6:  # until the balls have landed
        O.run(20, True)
    history = [rm.unbalanced_force()]
    while history[-1] > 1e-2 and len(history) < 200:
        O.run(100, True)
        history.append(rm.unbalanced_force())
    assert history[0] > 0.1, "the balls must be still moving when the loop starts"
    assert history[-1] < 1e-2, f"not settled after {len(history) * 100} more steps: {history[-5:]}"
    assert math.isnan(utils.unbalancedForce())
