"""roundedmesh_study.coarse_clearance (issue 41, item 3): its least distance between flat meshes against exact
values, and two of YADE's GTS horses prepared to 0.02 r_eq, placed as the study places them, in the orientations
where Appendix B once pushed them apart across a gap."""
import os

import numpy as np
import pytest
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh_study import coarse_clearance as cc
from roundedmesh_study.deep_monotonicity import random_orientations
from roundedmesh_study.hard_cases import box_arrays


def turned(vertices, degrees):
    """The vertices turned about z."""
    a = np.radians(degrees)
    return np.asarray(vertices) @ np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]]).T


def test_least_distance_of_boxes():
    """Two 2 cm cubes 1 mm apart face to face, then one turned 45 deg about z so that its edge faces the other's
    face 0.5 mm away, then within a gap larger than the cutoff: exact by construction."""
    v, t = box_arrays(0.02, 0.02, 0.02)
    v = np.asarray(v, dtype=float)
    t = np.asarray(t)
    assert cc.least_distance(v, t, v + [0.021, 0, 0], t, 0.01) == pytest.approx(1e-3, abs=1e-15)
    edge = turned(v, 45) + [0.01 + 0.01 * np.sqrt(2) + 5e-4, 0.003, 0.004]
    assert cc.least_distance(v, t, edge, t, 0.01) == pytest.approx(5e-4, abs=1e-15)
    assert cc.least_distance(v, t, v + [0.05, 0, 0], t, 0.01) == 0.01


def test_bodies_without_a_core():
    """Two 1 x 20 x 50 mm plates as they are (12 triangles; the study's sliver plate): too thin for the core's grid,
    they have no inscribed sphere, and the engine read the radius of the empty core (a segfault, which stopped
    coarse_clearance.py) before such a pair's core was skipped. Side by side 12 mm apart, their caps (27 mm tall on
    the slivers) overlap, and push them apart along the line of their centres."""
    v, t = box_arrays(0.001, 0.02, 0.05)
    plate = rm.Mesh(v, t, tolerance=None)
    assert len(plate.inscribed_spheres[1]) == 0
    q = Quaternion.Identity
    thin = int(np.argmin(np.ptp(np.asarray(plate.vertices), axis=0)))  # the principal frame's axis across the plate
    offset = Vector3(0, 0, 0)
    offset[thin] = 0.012
    force = rm.body_contact(plate, Vector3(0, 0, 0), q, plate, offset, q, cc.RUBBER, cc.RUBBER)[2]
    assert force[thin] > 0
    assert all(abs(force[k]) < 1e-9 * force[thin] for k in range(3) if k != thin)


@pytest.mark.slow
@pytest.mark.skipif(not os.path.exists(cc.HORSE), reason="Debian's yade package ships the GTS horse")
def test_horses_do_not_push_across_a_gap():
    """Seed 1's orientations 54, 117 and 169: before the segment q1 q2 was asked to lie in both bodies for every pair
    (it was asked only past 0.1 r_eq, and then only against distance fields too coarse to see a gap under 2.4 mm), 21,
    3 and 9 triangle pairs pushed, 1.3 to 3.0 mm deep, where the two flat meshes are farther apart than the caps
    reach: thin legs and ears lying across each other, a line along n12 that leaves one and crosses the gap into the
    other. Now none does. Orientation 50 still pushes (5 pairs, 0.06 mm deep): there the flat meshes come within
    the caps' reach of each other, so the rounded bodies do touch."""
    mesh = cc.meshes(0.02)["GTS horse, 56 mm"]
    given = cc.meshes(None)["GTS horse, 56 mm"]
    orientations = random_orientations(200, 1)
    rows = cc.clearance_forces(mesh, given, [orientations[k] for k in (54, 117, 169, 50)], 1e-3)
    reach = 2 * mesh.deviation
    print([(force, flat * 1e3) for force, _, _, flat in rows], reach * 1e3)
    for k, (force, _, _, flat) in zip((54, 117, 169), rows[:3]):
        assert force == 0, k
    force, _, _, flat = rows[3]
    assert force > 0 and flat < reach


def test_placed_apart_by_least_distance():
    """Two 2 cm cubes turned 30 deg about z, body 2 approaching along a slanted line: placed with --measure least,
    their least distance is the gap to 1e-9 of it, and more than the gap along the line; with 'along', 1 mm along
    the line from touching, and nearer than that."""
    v, t = box_arrays(0.02, 0.02, 0.02)
    v1, v2 = np.asarray(v, dtype=float), turned(v, 30)
    t = np.asarray(t)
    u = np.array([1.0, 0.3, 0.1]) / np.linalg.norm([1.0, 0.3, 0.1])
    least = cc.placed_apart(v1, t, v2, u, 1e-3, "least")
    along = cc.placed_apart(v1, t, v2, u, 1e-3, "along")
    assert cc.least_distance(v1, t, v2 + least * u, t, 0.01) == pytest.approx(1e-3, rel=1e-8)
    assert least > along
    assert cc.least_distance(v1, t, v2 + along * u, t, 0.01) < 1e-3
    assert cc.least_distance(v1, t, v2 + (along - 1e-3) * u, t, 0.01) == pytest.approx(0, abs=1e-12)


@pytest.mark.parametrize("argv", [["--gap", "0"], ["--gap", "-1e-3"], ["--tolerance", "0"], ["--orientations", "0"],
                                  ["--gap", "nan"]])
def test_bad_arguments_are_refused(argv, capsys):
    """A gap, tolerance or count that is not positive stops the study before it starts, naming the option."""
    with pytest.raises(SystemExit):
        cc.parse(argv)
    assert argv[0] in capsys.readouterr().err
