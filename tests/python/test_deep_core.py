"""The deep-overlap core (issue 38; doc/physics.md, "Deep overlaps and fast impacts", The core): rm.Mesh.inscribed_spheres, the option
rm.engine(core_inset=...), a core that adds nothing within the Hertz range and keeps pushing harder past it, on a
Facet sheet from either side, and rm.add_body's warning of a body placed inside another."""
import math
import warnings

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=1200)
FLOOR = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000)
NO_CORE = {"core_inset": 1.0}


@pytest.fixture(scope="module")
def bear():
    return rm.Mesh.reference_shape("gummy_bear")


def r_eq(mesh):
    return (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)


def test_inscribed_spheres_lie_inside_the_mesh(bear):
    from roundedmesh_study.mesh_distance import signed_distance
    centres, radii = bear.inscribed_spheres
    assert centres.shape == (len(radii), 3) and 1 < len(radii) <= 32
    assert np.all(np.diff(radii) <= 0)  # largest first
    # each sphere's radius is its centre's distance to the mesh (signed_distance, independent of the C++ code)
    np.testing.assert_allclose(-signed_distance(np.asarray(bear.vertices), np.asarray(bear.triangles), centres), radii,
                               rtol=1e-9)


@pytest.mark.parametrize("inset", [0.0, -0.5, 1.5, math.nan])
def test_core_inset_out_of_range_is_refused_by_name(inset):
    with pytest.raises(ValueError, match="core_inset"):
        rm.engine(core_inset=inset)


def test_the_core_adds_nothing_within_the_hertz_range(bear):
    # Two bears 0.1 r_eq deep and a bear 0.1 r_eq into a Wall: the same force, bit for bit, with and without the core
    # (its spheres lie at least a quarter of their radii, 0.07 r_eq and more, under the surface).
    vertices = np.asarray(bear.vertices)
    size = r_eq(bear)
    gap = vertices[:, 2].max() - vertices[:, 2].min()
    for depth in (0.01, 0.05, 0.1):
        with_core = rm.body_contact(bear, (0, 0, 0), Quaternion.Identity, bear, (0, 0, gap - depth * size),
                                    Quaternion.Identity, RUBBER, RUBBER)
        without = rm.body_contact(bear, (0, 0, 0), Quaternion.Identity, bear, (0, 0, gap - depth * size),
                                  Quaternion.Identity, RUBBER, RUBBER, **NO_CORE)
        assert with_core[2] == without[2] and with_core[3] == without[3], depth
        position = Vector3(0, 0, -vertices[:, 2].min() - depth * size)
        on_wall = rm.plane_contact(bear, position, Quaternion.Identity, (0, 0, 0), (0, 0, 1), RUBBER, FLOOR)
        assert on_wall == rm.plane_contact(bear, position, Quaternion.Identity, (0, 0, 0), (0, 0, 1), RUBBER, FLOOR,
                                           **NO_CORE), depth


@pytest.mark.parametrize("side", [1, -1])
def test_a_bear_pushed_into_a_sheet_meets_a_core_that_keeps_pushing_harder(bear, side):
    # A Facet much larger than the bear, pushed into from above (side 1) and from below (-1), from 0.3 r_eq until its
    # centre is 0.1 r_eq from the sheet: the core's part of the force (with minus without) rises at every step and
    # pushes the bear back to its own side.
    sheet = utils.facet([(-2, -2, 0), (3, -2, 0), (0, 3, 0)])
    vertices = np.asarray(bear.vertices)
    size = r_eq(bear)
    lowest = vertices[:, 2].min() if side == 1 else -vertices[:, 2].max()
    last = 0.0
    for depth in np.arange(0.3, -lowest / size - 0.1, 0.05):
        position = Vector3(0, 0, side * (-lowest - depth * size))
        core = (rm.partner_contact(bear, position, Quaternion.Identity, sheet, RUBBER, FLOOR)[0]
                - rm.partner_contact(bear, position, Quaternion.Identity, sheet, RUBBER, FLOOR, **NO_CORE)[0])
        assert side * core[2] >= last and side * core[2] > 0 or depth < 0.35, (depth, core)
        last = side * core[2]
    assert last > 100  # N: the bear weighs 0.8 N
    # Past the sheet the body's centre is on the other side: the run stops there (StopRules.hpp, a centre through a
    # Facet), which test_fast_impacts.py checks.


def test_add_body_warns_of_a_body_placed_inside_another_by_name(bear):
    O.reset()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        first = rm.add_body(bear, (0, 0, 0), material=RUBBER)
        rm.add_body(bear, (0.1, 0, 0), material=RUBBER)
        assert not [w for w in caught if "placed inside" in str(w.message)]
        inside = rm.add_body(bear, (0.003, 0, 0), material=RUBBER)
    messages = [str(w.message) for w in caught if "placed inside" in str(w.message)]
    assert len(messages) == 1
    assert f"rounded body {inside} is placed inside rounded body {first}" in messages[0]


def test_two_bodies_placed_deep_in_each_other_are_pushed_apart(bear):
    # 0.3 r_eq apart along x: the cores push them apart within a few steps, no stop.
    O.reset()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a = rm.add_body(bear, (0, 0, 0), material=RUBBER)
        b = rm.add_body(bear, (0.3 * r_eq(bear), 0, 0), material=RUBBER)
        O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0)]
        O.dt = 1e-5
        O.run(50, True)
    assert O.bodies[b].state.vel[0] > 0.1 > -0.1 > O.bodies[a].state.vel[0]
    assert rm.statistics()["core_contacts"] >= 0
