"""The half-space contact solution (roundedmesh_study.halfspace), the speed-against-error study's reference where the
curvature changes over the contact: Love's influence coefficient against its closed forms, the solver against
Hertz's circular and elliptical solutions (analytic.py, written independently), and its complementarity
conditions; the study's gap of a pressed sphere against the sphere's sagitta."""
import math

import numpy as np
import pytest

from roundedmesh_study import halfspace, shape_error as se
from roundedmesh_study.analytic import elliptical_hertz_force, hertz_force, nrmse

MODULUS = 1e6 / (1 - 0.4 ** 2)   # E* of S1's particle on a rigid plane [Pa]
DEEPEST = 5e-4                    # the study's deepest overlap [m]


def grid(half_width, cells):
    """(X, Y) cell centres [m] of the square window and its spacing [m]."""
    spacing = 2 * half_width / cells
    offsets = (np.arange(cells) - (cells - 1) / 2) * spacing
    x, y = np.meshgrid(offsets, offsets, indexing="ij")
    return x, y, spacing


def test_love_influence_matches_its_closed_forms():
    # Centre of a uniformly loaded square of side 2a: pi E* u / p = 8 a ln(1 + sqrt 2) (Johnson Section 3.4), exact.
    assert halfspace.love_influence(0.0, 0.0, 1.0, 1.0) == pytest.approx(8 * math.log(1 + math.sqrt(2)), rel=1e-14)
    # Far away a cell acts as a point load of its area: u = A / (pi E* r); the next term is O((a / r)^2) = 2.5e-3 at
    # r = 20 a, so 1e-3 tells the two apart from any error of order a / r.
    r = 20.0
    assert halfspace.love_influence(r, 0.0, 1.0, 1.0) == pytest.approx(4.0 / r, rel=1e-3)
    assert halfspace.love_influence(0.3, -0.7, 1.0, 2.0) == pytest.approx(halfspace.love_influence(-0.3, 0.7, 1.0, 2.0),
                                                                          rel=1e-14)


def test_a_sphere_on_a_plane_is_hertz():
    # The study's grid: 64 cells over a window whose contact fills 75 % at the deepest overlap (48 cells across).
    # Discretisation error of piecewise-constant pressure: measured 0.006 % NRMSE; 0.3 % is the bound the study's
    # reference needs (an order below the 5 % targets' resolution), and what the module docstring states.
    radius = 0.025
    overlaps = DEEPEST * np.arange(1, 21) / 20
    x, y, spacing = grid(math.sqrt(radius * DEEPEST) / 0.75, 64)
    forces, pressure = halfspace.contact_forces((x ** 2 + y ** 2) / (2 * radius), spacing, MODULUS, overlaps)
    assert nrmse(forces, hertz_force(MODULUS, radius, overlaps)) < 3e-3
    # Hertz's peak pressure 2 E* a / (pi R) at the centre, to the cell's averaging: 1 %.
    a = math.sqrt(radius * DEEPEST)
    assert pressure.max() == pytest.approx(2 * MODULUS * a / (math.pi * radius), rel=1e-2)


def test_an_elliptical_gap_is_hertz_elliptical_contact():
    # Relative radii 80 and 10 mm (ratio 8): the window sized for the major semi-axis; the minor then spans 18 cells
    # on 64, so 0.3 % (as above) is the bound here too.
    r_major, r_minor = 0.08, 0.01
    overlaps = DEEPEST * np.arange(1, 21) / 20
    reference = elliptical_hertz_force(MODULUS, r_major, r_minor, overlaps)
    a = se.hr.contact_semi_axes(MODULUS, r_major, r_minor, DEEPEST)[0]
    x, y, spacing = grid(a / 0.75, 64)
    forces, _ = halfspace.contact_forces(x ** 2 / (2 * r_major) + y ** 2 / (2 * r_minor), spacing, MODULUS, overlaps)
    assert nrmse(forces, reference) < 3e-3


def test_the_solution_closes_the_gap_where_it_presses_and_nowhere_overlaps():
    # A gap that is not a quadric (a quartic bump): p >= 0; where p > 0 the surfaces meet, u = delta - g, to the
    # solver's tolerance (1e-9 relative change, so 1e-6 of delta is loose); elsewhere they do not overlap,
    # u >= delta - g.
    x, y, spacing = grid(0.01, 48)
    gap = (x ** 2 + y ** 2) ** 2 / 1e-6 + 0.3 * x ** 2 / 0.05
    _, pressure = halfspace.contact_forces(gap, spacing, MODULUS, [2e-4])
    displacement = halfspace._Convolution(gap.shape, spacing, MODULUS)(pressure)
    assert pressure.min() >= 0
    pressed = pressure > 0
    assert np.abs(displacement[pressed] - (2e-4 - gap[pressed])).max() < 1e-6 * 2e-4
    assert (displacement[~pressed] - (2e-4 - gap[~pressed])).min() > -1e-6 * 2e-4


def test_the_study_gap_of_a_sphere_is_its_sagitta():
    # The study's gap of the sphere pressed on the plane, from f by Newton steps (shape_error.contact_gap), against
    # R - sqrt(R^2 - rho^2): the steps stop at |f| < 1e-10 m, the bound.
    geometry = se.press_geometry(se.SmoothShape("sphere"), se.Quaternion.Identity)
    gap, spacing = se.contact_gap(geometry, 0.005, cells=16)
    x, y, _ = grid(0.005, 16)
    rho2 = x ** 2 + y ** 2
    assert np.abs(gap - (se.RADIUS - np.sqrt(se.RADIUS ** 2 - rho2))).max() < 1e-10 + 1e-12
