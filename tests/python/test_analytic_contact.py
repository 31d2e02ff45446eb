"""Analytic references for non-spherical contact (roundedmesh_study.analytic), each checked against a result obtained
another way: the sphere (Eq. 6), Hertz's eccentricity equation in Legendre's elliptic integrals (the module uses
Carlson's), the Boussinesq surface displacement of the ellipsoidal pressure integrated numerically, plane-strain
Hertz for Eq. 27 and finite-difference curvature of the spheroid's surface."""
import math
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipe, ellipk

from roundedmesh_study import analytic

MODULUS = 2.5e6  # E* [Pa]
OVERLAP = 1e-4  # [m]


def legendre_ratio(e):
    """B/A = (E/(1 - e^2) - K) / (K - E), K and E of modulus e (scipy takes the parameter m = e^2)."""
    m = e * e
    k, E = ellipk(m), ellipe(m)
    return (E / (1 - m) - k) / (k - E)


# Equal radii are the sphere of Eq. 6 up to rounding (the solver returns m' = 1 exactly): 1e-12 leaves
# room for a few roundings. A ratio of 1 + 1e-12 must not jump away from it (F varies smoothly, by ~1e-12).
def test_equal_radii_give_the_sphere():
    overlap = np.array([-1e-4, 0.0, 1e-6, 1e-4, 3e-3])
    for radius in (1e-3, 0.02, 5.0):
        sphere = analytic.hertz_force(MODULUS, radius, overlap)
        np.testing.assert_allclose(analytic.elliptical_hertz_force(MODULUS, radius, radius, overlap), sphere,
                                   rtol=1e-12, atol=0)
        np.testing.assert_allclose(analytic.approximate_elliptical_hertz_force(MODULUS, radius, radius, overlap),
                                   sphere, rtol=1e-12, atol=0)
        near = analytic.elliptical_hertz_force(MODULUS, radius * (1 + 1e-12), radius, overlap)
        np.testing.assert_allclose(near, sphere, rtol=1e-11, atol=0)
        force, a, b = analytic.elliptical_hertz_contact(MODULUS, radius, radius, 1e-4)
        assert a == b == pytest.approx(math.sqrt(radius * 1e-4), rel=1e-12)  # Eq. 5
    assert analytic.elliptical_hertz_eccentricity(0.3, 0.3) == 0.0
    assert overlap[0] < 0 and analytic.elliptical_hertz_force(MODULUS, 3.0, 1.0, overlap)[0] == 0.0


# Hertz's equation for e written with scipy's Legendre integrals (the module solves it with Carlson's R_D):
# where it is well conditioned (ratio <= 100: one ulp of e moves B/A by < 1e-13) it holds to 1e-12; beyond,
# one ulp of e moves B/A by 1e-12 (ratio 1e3) to 1e-11 (1e4), so there the root must lie within 4 ulps of e.
@pytest.mark.parametrize("ratio", [1.5, 2.0, 3.0, 9.0, 16.0, 100.0, 1e3, 1e4])
def test_eccentricity_solves_hertz_equation(ratio):
    e = analytic.elliptical_hertz_eccentricity(0.01 * ratio, 0.01)
    assert 0 < e < 1
    if ratio <= 100:
        assert legendre_ratio(e) == pytest.approx(ratio, rel=1e-12)
    else:
        below, above = e - 4 * np.spacing(e), e + 4 * np.spacing(e)
        assert legendre_ratio(below) < ratio < legendre_ratio(above)


def surface_approach(p0, a, b, x0, y0):
    """Sum of the two bodies' surface displacements, (1/(pi E*)) int p/rho dA (Boussinesq), at (x0, y0) inside the
    ellipse under p0 sqrt(1 - x^2/a^2 - y^2/b^2), in polar coordinates about (x0, y0): along each ray the pressure
    is sqrt(g (s1 - s)(s - s0)), integrated by quad with the (s1 - s)^1/2 end weight; quad again over the angle."""
    inside = 1 - x0 ** 2 / a ** 2 - y0 ** 2 / b ** 2

    def ray(angle):
        c, s = math.cos(angle), math.sin(angle)
        g = c * c / a ** 2 + s * s / b ** 2
        beta = x0 * c / a ** 2 + y0 * s / b ** 2
        root = math.sqrt(beta * beta + inside * g)
        s1, s0 = (root - beta) / g, (-root - beta) / g
        return quad(lambda r: math.sqrt(g * (r - s0)), 0, s1, weight="alg", wvar=(0, 0.5), epsabs=0,
                    epsrel=1e-12)[0]

    total = quad(ray, -math.pi / 2, 3 * math.pi / 2, points=[math.pi / 2], epsabs=0, epsrel=1e-11, limit=200)[0]
    return p0 * total / (math.pi * MODULUS)


def exterior_approach(p0, a, b, x0, y0):
    """The same displacement at (x0, y0) outside the ellipse: rays cross the pressure on [s0, s1] or miss it."""
    outside = x0 ** 2 / a ** 2 + y0 ** 2 / b ** 2 - 1

    def ray(angle):
        c, s = math.cos(angle), math.sin(angle)
        g = c * c / a ** 2 + s * s / b ** 2
        beta = x0 * c / a ** 2 + y0 * s / b ** 2
        if beta >= 0 or beta * beta <= outside * g:
            return 0.0
        root = math.sqrt(beta * beta - outside * g)
        return math.pi / 8 * math.sqrt(g) * (2 * root / g) ** 2  # int sqrt(g (s1 - s)(s - s0)) ds, s1 - s0 = 2 root/g

    return p0 * quad(ray, 0, 2 * math.pi, epsabs=0, epsrel=1e-8, limit=400)[0] / (math.pi * MODULUS)


# Independent check of the whole exact solution (F, a, b for a given approach): the Hertz pressure with peak
# p0 = 3F/(2 pi a b) (its integral is F) must, by Boussinesq, bring the surfaces together by exactly
# delta - x^2/(2 r_major) - y^2/(2 r_minor) everywhere inside the contact ellipse. The nested quadratures are
# asked for 1e-11..1e-12 and reach ~1e-15 here; 1e-10 of delta allows for the worst-conditioned ellipses.
# Outside the ellipse the surfaces must stay apart (no interpenetration), checked at 1.1 times each semi-axis;
# for the sphere that separation is known in closed form (Johnson Section 3.4: (a^2/(pi R)) ((2 - r^2/a^2)
# asin(a/r) + sqrt(r^2/a^2 - 1)) - delta + r^2/(2R)), matched to 1e-6 (quad asked for 1e-8 across the kinks
# of the rays tangent to the ellipse).
@pytest.mark.parametrize("ratio", [1.0, 2.5, 16.0, 100.0, 1e4])
def test_ellipsoidal_pressure_closes_the_gap(ratio):
    r_major, r_minor = 0.05 * ratio, 0.05
    force, a, b = analytic.elliptical_hertz_contact(MODULUS, r_major, r_minor, OVERLAP)
    assert force == analytic.elliptical_hertz_force(MODULUS, r_major, r_minor, OVERLAP)
    assert a >= b and math.sqrt(1 - (b / a) ** 2) == pytest.approx(
        analytic.elliptical_hertz_eccentricity(r_major, r_minor), rel=1e-12, abs=1e-7)
    p0 = 3 * force / (2 * math.pi * a * b)
    for fx, fy in [(0, 0), (0.5, 0), (0, 0.99), (0.6, 0.6), (0.3, -0.9)]:
        x, y = fx * a, fy * b
        gap = x * x / (2 * r_major) + y * y / (2 * r_minor)
        assert surface_approach(p0, a, b, x, y) == pytest.approx(OVERLAP - gap, rel=0, abs=1e-10 * OVERLAP)
    for x, y in [(1.1 * a, 0), (0, 1.1 * b)]:
        gap = x * x / (2 * r_major) + y * y / (2 * r_minor)
        separation = gap - OVERLAP + exterior_approach(p0, a, b, x, y)
        assert separation > 1e-3 * OVERLAP
        if ratio == 1:
            r = math.hypot(x, y) / a
            sphere = OVERLAP / math.pi * ((2 - r * r) * math.asin(1 / r) + math.sqrt(r * r - 1)) - OVERLAP + gap
            assert separation == pytest.approx(sphere, rel=1e-6)


# Johnson's equivalent-radius chart fit, measured here within 0.86% of the exact force for ratios 1..100 (the
# docstring's 0.9%): a 1% bound, on a dense logarithmic sweep. It is no reference beyond that (25% at 1000).
def test_approximation_follows_the_exact_force_up_to_ratio_100():
    ratios = np.logspace(0, 2, 81)
    exact = np.array([analytic.elliptical_hertz_force(MODULUS, 0.01 * r, 0.01, OVERLAP) for r in ratios])
    approximate = np.array([analytic.approximate_elliptical_hertz_force(MODULUS, 0.01 * r, 0.01, OVERLAP)
                            for r in ratios])
    np.testing.assert_allclose(approximate, exact, rtol=0.01, atol=0)
    assert abs(approximate[-1] / exact[-1] - 1) > 0.005  # the sweep reaches where the fit departs
    with pytest.raises(ValueError, match="r_minor <= r_major"):
        analytic.approximate_elliptical_hertz_force(MODULUS, 0.01, 0.02, OVERLAP)
    with pytest.raises(ValueError, match="r_minor <= r_major"):
        analytic.elliptical_hertz_force(MODULUS, 0.01, 0.02, OVERLAP)


# The exact force exceeds the sphere of the geometric-mean radius and, more so, the circle of the mean-curvature
# radius that a contact model based on mean curvature uses (values of the report, to 1e-5).
def test_exact_force_against_equivalent_spheres():
    table = {1.5: (1.00342, 1.01372), 2.0: (1.00999, 1.04018), 4.0: (1.03980, 1.16254), 16.0: (1.15761, 1.68750)}
    for ratio, (geometric, mean_curvature) in table.items():
        exact = analytic.elliptical_hertz_force(MODULUS, ratio, 1.0, OVERLAP)
        assert exact / analytic.hertz_force(MODULUS, math.sqrt(ratio), OVERLAP) == pytest.approx(geometric, abs=1e-5)
        circle = analytic.hertz_force(MODULUS, 2 / (1 / ratio + 1), OVERLAP)
        assert exact / circle == pytest.approx(mean_curvature, abs=1e-5)


# Eq. 27 is plane-strain Hertz (Johnson Section 4.3: half-width c^2 = 4 F R/(pi E* L)) with the sphere's
# c^2 = R delta of Eq. 5, whatever R; both sides are a few roundings apart (1e-14). E* is Eq. 3's.
def test_parallel_cylinders_force_is_plane_strain_hertz():
    glass = SimpleNamespace(young=6e7, poisson=0.25)
    rubber = SimpleNamespace(young=2e6, poisson=0.49)
    modulus = analytic.effective_modulus(glass, rubber)
    length, overlap = 0.03, np.array([-1e-4, 0.0, 1e-5, 2e-4])
    force = analytic.parallel_cylinders_force(modulus, length, overlap)
    np.testing.assert_array_equal(force[:2], 0.0)
    for radius in (1e-3, 0.1):
        np.testing.assert_allclose(4 * force[2:] * radius / (math.pi * modulus * length), radius * overlap[2:],
                                   rtol=1e-14)
    assert force[3] / force[2] == pytest.approx(20.0, rel=1e-14)


def principal_radii(surface, u, v, h=1e-4):
    """Principal radii of curvature of the parametric surface at (u, v), from its first and second fundamental
    forms by central differences of step h (error ~h^2 + eps/h^2, ~1e-8 relative)."""
    p = surface(u, v)
    su = (surface(u + h, v) - surface(u - h, v)) / (2 * h)
    sv = (surface(u, v + h) - surface(u, v - h)) / (2 * h)
    suu = (surface(u + h, v) - 2 * p + surface(u - h, v)) / h ** 2
    svv = (surface(u, v + h) - 2 * p + surface(u, v - h)) / h ** 2
    suv = (surface(u + h, v + h) - surface(u + h, v - h) - surface(u - h, v + h) + surface(u - h, v - h)) / (4 * h * h)
    normal = np.cross(su, sv)
    normal /= np.linalg.norm(normal)
    first = np.array([[su @ su, su @ sv], [su @ sv, sv @ sv]])
    second = np.array([[suu @ normal, suv @ normal], [suv @ normal, svv @ normal]])
    return np.sort(1 / np.abs(np.linalg.eigvals(np.linalg.solve(first, second))))[::-1]


# The spheroid's radii against finite-difference curvature of its surface (long axis along x) at two equator
# points; 1e-6 covers the ~1e-8 differencing error. Two equal bodies add their curvatures: r = R/2.
@pytest.mark.parametrize("a, b", [(1.0, 1.0), (0.02, 0.01), (3.0, 1.0), (0.5, 0.05)])
def test_spheroid_radii_by_finite_differences(a, b):
    def spheroid(u, v):
        return np.array([a * math.cos(u), b * math.sin(u) * math.cos(v), b * math.sin(u) * math.sin(v)])

    meridian, around = analytic.spheroid_equator_radii(a, b)
    for v in (0.0, 2.0):
        np.testing.assert_allclose(principal_radii(spheroid, math.pi / 2, v), [meridian, around], rtol=1e-6)
    assert meridian == pytest.approx(a * a / b, rel=1e-15) and around == b
    r_major, r_minor = analytic.spheroid_pair_radii(a, b)
    assert (r_major, r_minor) == pytest.approx((meridian / 2, around / 2), rel=1e-15)
    assert 1 / r_major == pytest.approx(2 * b / a ** 2, rel=1e-14) and 1 / r_minor == pytest.approx(2 / b, rel=1e-14)
    assert r_major / r_minor == pytest.approx((a / b) ** 2, rel=1e-14)
