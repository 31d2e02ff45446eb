"""Issue 21: every flat partner gives the force its geometry gives (doc/physics.md, "What each partner's surface is").

A Wall, rm.plane_contact, a Facet larger than the body and the face of a Box of any thickness are the same plane where
the contact lies inside them, so the same pose must give the same force. 500 random poses of the gummy bear, the pear
and a 642-node sphere: random orientation, the lowest vertex from 0.1 r_eq below the plane to 0.05 r_eq above it, the
body anywhere over the face, the Box 1 mm to 0.5 m thick. The forces agree to 1e-9 of the largest: the four partners
run the same arithmetic on planes given in different forms (a Wall's axis, a Facet's corners, a Box's pose), whose
round-off moves a force by about 1e-14 relative; 1e-9 leaves room for a contact at the very edge of its circle
(h = a, where the force is zero) switching on in one and not the other. A body whose rounded surface is apart from the
plane (the lowest vertex higher than the tallest cap) gets no contact from any of them."""
import math

import numpy as np
import pytest

import roundedmesh as rm
from yade import Body, ForceResetter, NewtonIntegrator, O, Quaternion, Vector3, utils

POSES = 500
BODY = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
FLOOR = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-2)


def _max_cap_height(mesh):
    """The tallest cap, R - sqrt(R^2 - rho^2) over the triangles [m]: how far the rounded surface reaches past the
    mesh's vertices."""
    v = np.array(mesh.vertices)
    t = np.array(mesh.triangles)
    a, b, c = (np.linalg.norm(v[t[:, i]] - v[t[:, j]], axis=1) for i, j in ((1, 2), (2, 0), (0, 1)))
    area = np.array(mesh.areas)
    rho = a * b * c / (4 * area)
    r = np.array(mesh.radii)
    return float(np.max(r - np.sqrt(np.maximum(r * r - rho * rho, 0))))


@pytest.fixture(scope="module")
def meshes():
    return {"gummy_bear": rm.Mesh.reference_shape("gummy_bear"), "pear": rm.Mesh.reference_shape("pear"),
            "sphere": rm.Mesh.icosphere(0.025, 3)}


def _rotation(q):
    m = q.toRotationMatrix()
    return np.array([[m[i][j] for j in range(3)] for i in range(3)])


@pytest.mark.parametrize("name", ["gummy_bear", "pear", "sphere"])
def test_wall_plane_facet_and_box_face_agree(meshes, name):
    mesh = meshes[name]
    vertices = np.array(mesh.vertices)
    r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    cap = _max_cap_height(mesh)
    rng = np.random.default_rng(21)
    wall = utils.wall(0, axis=2, sense=1)
    facet = utils.facet([(-1, -1, 0), (1.5, -1, 0), (0, 1.5, 0)])
    touching = apart = 0
    for _ in range(POSES):
        q = rng.normal(size=4)
        ori = Quaternion(*(q / np.linalg.norm(q)))
        lowest = (vertices @ _rotation(ori).T)[:, 2].min()
        height = rng.uniform(-0.1 * r_eq, 0.05 * r_eq)
        pos = Vector3(rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), height - lowest)
        half = 10 ** rng.uniform(math.log10(0.0005), math.log10(0.25))
        box = utils.box((rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), -half), (0.6, 0.6, half))
        forces = [rm.partner_contact(mesh, pos, ori, partner, BODY, FLOOR)[0] for partner in (wall, facet, box)]
        forces.append(rm.plane_contact(mesh, pos, ori, (0, 0, 0), (0, 0, 1), BODY, FLOOR)[0])
        largest = max(f.norm() for f in forces)
        for f in forces[1:]:
            assert (f - forces[0]).norm() <= 1e-9 * largest, (name, ori, pos, half, forces)
        if height > cap:
            apart += 1
            assert largest == 0, (name, ori, pos, forces)
        touching += largest > 0
    # The sample covers both sides: at least a third of the poses touch, and some are apart.
    assert touching > POSES / 3 and apart > 10, (touching, apart)


def test_box_in_a_scene_pushes_up_like_a_wall(meshes):
    """The gummy bear pressed 1 mm into a Box 5 mm or 0.4 m thick, in a YADE scene: the force of a Wall at the
    Box's top, upward (the Box's other faces, behind the bear's back, play no part)."""
    mesh = meshes["gummy_bear"]
    ori = Quaternion(Vector3(1, 2, 3).normalized(), 0.7)
    lowest = (np.array(mesh.vertices) @ _rotation(ori).T)[:, 2].min()
    pos = Vector3(0, 0, -0.001 - lowest)
    expected = rm.plane_contact(mesh, pos, ori, (0, 0, 0), (0, 0, 1), BODY, FLOOR)[0]
    assert expected[2] > 0.1
    for half in (0.0025, 0.2):
        O.reset()
        bear = rm.add_body(mesh, pos=pos, ori=ori, material=BODY)
        box = O.bodies.append(utils.box((0, 0, -half), (0.3, 0.3, half), fixed=True))
        rm.assign_material(box, FLOOR)
        O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
        O.dt = 1e-6
        O.step()
        assert (O.forces.f(bear) - expected).norm() <= 1e-9 * expected.norm()


def test_partner_contact_names_a_body_that_cannot_be_a_partner(meshes):
    shapeless = O.bodies[O.bodies.append(Body())]
    with pytest.raises(ValueError, match=f"body {shapeless.id}: a no shape cannot be a roundedmesh contact partner"):
        rm.partner_contact(meshes["sphere"], (0, 0, 0.03), Quaternion.Identity, shapeless, BODY, FLOOR)


@pytest.mark.slow
def test_a_bear_dropped_on_a_box_lands_and_rests():
    """roundedmesh_study.resting_on_partners' scene (scripts/validation/validate_resting_on_partners.py), three orientations, 2 s: the bear falls 5 mm onto a
    Box 0.1 m thick, tumbles, and comes to rest on it (within 1.5 s in every orientation of the script's 20), the run
    never stops (it used to stop within 263-853 steps on a phantom overlap of the Box's bottom face), and the Box
    carries the bear's weight to 1e-6 (at rest, the bear's speed is below 1e-12 m/s by then)."""
    from roundedmesh_study import resting_on_partners as resting
    for ori in resting.random_orientations(3):
        bear, (box,) = resting.build("box", ori)
        O.run(int(2.0 / O.dt), True)
        top = O.bodies[box].state.pos[2] + O.bodies[box].shape.extents[2]
        assert O.bodies[bear].state.pos[2] > top
        weight = O.bodies[bear].state.mass * resting.G
        assert abs(-O.forces.f(box)[2] - weight) < 1e-6 * weight


def test_partner_contact_names_a_partner_whose_state_is_not_finite(meshes):
    wall = utils.wall(0, axis=2, sense=1)
    wall.state.vel = Vector3(float("nan"), 0, 0)
    with pytest.raises(ValueError, match=r"partner \(body -?\d+\): its state \(pos, ori, vel, angVel\) must be finite"):
        rm.partner_contact(meshes["sphere"], (0, 0, 0.03), Quaternion.Identity, wall, BODY, FLOOR)
