"""Bodies that start deeply overlapped: a warning on the first step naming the two bodies and the overlap as a
fraction of the smaller body's volume-equivalent radius r_eq, beyond rm.scene.DEEP_OVERLAP = 0.1 r_eq (the
deepest overlap a Hertz contact is meant to reach; a body resting under its weight overlaps about 0.01 r_eq)."""
import re
import warnings

import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils

import roundedmesh as rm

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
R = 0.02


def run_first_step():
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = 1e-6
    O.step()


def warned_overlaps(record):
    """(id1, id2, fraction of r_eq) of every pair named by the warnings in `record`."""
    found = []
    for w in record:
        found += [(int(a), int(b), float(f)) for a, b, f in
                  re.findall(r"bodies (\d+) and (\d+) by [0-9.e-]+ m \(([0-9.]+) r_eq\)", str(w.message))]
    return found


def test_a_body_pushed_half_into_a_wall():
    # An icosphere with exact curvature: the deepest triangle contact overlaps by exactly R/2; r_eq is the
    # radius of the sphere of the mesh's volume, a little below R (0.4 % for 162 nodes).
    ball = rm.add_body(rm.Mesh.icosphere(R, 2), pos=(0, 0, R / 2), material=RUBBER)
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER)
    with pytest.warns(RuntimeWarning, match="start overlapped") as record:
        run_first_step()
    r_eq = (3 * rm.rounded_bodies()[ball].volume / (4 * 3.141592653589793)) ** (1 / 3)
    (a, b, fraction), = warned_overlaps(record)
    assert (a, b) == (ball, wall)
    assert fraction == pytest.approx(0.5 * R / r_eq, abs=0.005)  # printed with two decimals


def test_two_copies_of_one_mesh_at_one_place():
    bear = rm.Mesh.reference_shape("gummy_bear")
    first = rm.add_body(bear, pos=(0, 0, 1), material=RUBBER)
    second = rm.add_body(bear, pos=(0, 0, 1), material=RUBBER)
    with pytest.warns(RuntimeWarning, match="start overlapped") as record:
        run_first_step()
    pairs = warned_overlaps(record)
    assert [(a, b) for a, b, _ in pairs] == [(first, second)]
    assert pairs[0][2] > 0.1


# Sphere bodies count with their radius: two of radius R with centres R apart overlap by R, 1.0 r_eq; a third
# touching the second by 0.05 R is not named.
def test_sphere_bodies_overlapping_at_the_start():
    first = rm.add_sphere((0, 0, 1), R, RUBBER)
    second = rm.add_sphere((R, 0, 1), R, RUBBER)
    rm.add_sphere((2.95 * R, 0, 1), R, RUBBER)
    with pytest.warns(RuntimeWarning, match="start overlapped") as record:
        run_first_step()
    ((a, b, fraction),) = warned_overlaps(record)
    assert (a, b) == (first, second) and fraction == pytest.approx(1.0, abs=0.005)  # printed with two decimals


def test_only_on_the_first_step_and_not_for_a_resting_body():
    ball = rm.add_body(rm.Mesh.icosphere(R, 2), pos=(0, 0, R - 0.0015), material=RUBBER)  # 0.075 r_eq: no warning
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        run_first_step()
    O.bodies[ball].state.pos = (0, 0, R / 2)  # pushed in by hand after the start: the contact's business
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        O.step()
