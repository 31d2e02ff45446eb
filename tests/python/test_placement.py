"""Placing bodies in a container without overlap (roundedmesh.placement): a seeded lattice start, the bodies pushed
apart at their size by the contact engine, and the check that they start apart."""
import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion

import roundedmesh as rm
from roundedmesh import placement

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
RADIUS, HALF = 0.02, 0.06   # the balls' radius and the box's half width [m]


def nodes(spacing):
    axis = spacing * (np.arange(-2, 2) + 0.5)
    return np.array([(x, y, z) for x in axis for y in axis for z in axis if max(abs(x), abs(y), abs(z)) < HALF / 2])


def test_lattice_poses_are_a_seeded_choice_of_nodes_jittered_and_turned():
    candidates = nodes(0.036)
    poses = placement.lattice_poses(candidates, 8, np.random.default_rng(3), jitter=1e-3)
    again = placement.lattice_poses(candidates, 8, np.random.default_rng(3), jitter=1e-3)
    assert len(poses) == 8
    for (position, q), (position_again, q_again) in zip(poses, again):
        assert np.array_equal(position, position_again) and np.array_equal(q, q_again)
        assert np.abs(candidates - position).max(axis=1).min() <= 1e-3      # a node, moved by the jitter at most
        assert np.linalg.norm(q) == pytest.approx(1, abs=1e-12)
    chosen = [np.argmin(np.abs(candidates - p).max(axis=1)) for p, _ in poses]
    assert len(set(chosen)) == 8                                            # each node once
    with pytest.raises(ValueError, match="the lattice has 8 nodes for 9 bodies"):
        placement.lattice_poses(candidates, 9, np.random.default_rng(3))


def overlapping_balls_in_a_box():
    """8 meshed balls 39 mm apart (1 mm overlap with each neighbour, 0.05 of their radius) in a box of Walls 120 mm
    wide, no gravity."""
    O.reset()
    for axis in range(3):
        for sense in (1, -1):
            rm.assign_material(O.bodies.append(utils.wall(-sense * HALF, axis=axis, sense=sense)), RUBBER)
    mesh = rm.Mesh.icosphere(RADIUS, 2)
    for position, q in placement.lattice_poses(nodes(0.039), 8, np.random.default_rng(1)):
        rm.add_body(mesh, tuple(position), Quaternion(*q), RUBBER)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0.3, gravity=(0, 0, 0))]
    O.dt = 0.1 * rm.critical_timestep()


def test_bodies_pushed_apart_start_apart():
    overlapping_balls_in_a_box()
    with pytest.raises(RuntimeError, match=r"12 pairs touch at the start, the deepest by 1\.\d+ mm"):
        placement.touching()
    deepest = placement.push_apart(1e-6, 20000)
    assert deepest < 1e-6
    assert placement.touching(allowed=1e-6) >= 0
    for body in rm.rounded_bodies():
        assert np.abs(np.array(O.bodies[body].state.pos)).max() < HALF - RADIUS + 1e-6    # inside the box


def test_push_apart_names_the_overlap_left_when_the_steps_run_out():
    overlapping_balls_in_a_box()
    with pytest.raises(RuntimeError, match=r"still overlap by \d\.\d+ mm after 10 steps \(wanted: 0\.001 mm\)"):
        placement.push_apart(1e-6, 10, chunk=10)
