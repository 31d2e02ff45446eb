"""Analytic references for validation, written independently of the compiled contact code.

    effective_modulus(m1, m2)          E* of Eq. 3
    hertz_force(E, R, delta, rate, A)  damped Hertz force of Eq. 7 (never pulling), [N]
    bouncing_sphere(...)               a perfect sphere dropped on a plane under that law (scene S3)
    apex_heights(t, z)                 heights of the maxima of a bouncing trajectory
    nrmse(model, reference)            NRMSE as scenes.md defines it

Non-spherical contact (r_major >= r_minor are the relative principal radii: 1/r = sum of the two bodies'
curvatures along aligned principal directions, gap A x^2 + B y^2 with A = 1/(2 r_major), B = 1/(2 r_minor)):
    elliptical_hertz_eccentricity(r_major, r_minor)                exact contact-ellipse eccentricity
    elliptical_hertz_contact(E, r_major, r_minor, delta)           exact force and contact semi-axes
    elliptical_hertz_force(E, r_major, r_minor, delta)             exact Hertz force, [N]
    approximate_elliptical_hertz_force(E, r_major, r_minor, delta) equivalent-radius approximation, [N]
    parallel_cylinders_force(E, L, delta)                          Eq. 27, [N]
    spheroid_equator_radii(a, b), spheroid_pair_radii(a, b)        principal / relative radii of spheroids
"""
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import elliprd, elliprf


def effective_modulus(material1, material2):
    """E* = ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)^-1 (Eq. 3) [Pa]; an infinite modulus is a rigid body."""
    return 1.0 / sum((1 - m.poisson ** 2) / m.young for m in (material1, material2))


def hertz_force(modulus, radius, overlap, rate=0.0, damping=0.0):
    """(4/3) E* sqrt(R*) (delta^3/2 + A ddelta/dt delta^1/2) for delta > 0 (Eq. 7), clamped at zero."""
    overlap = np.maximum(overlap, 0.0)
    force = 4.0 / 3.0 * modulus * np.sqrt(radius) * (overlap ** 1.5 + damping * rate * np.sqrt(overlap))
    return np.maximum(force, 0.0)


def bouncing_sphere(radius, density, sphere_material, plane_material, height, duration, gravity=9.81):
    """Height of the centre of a perfect sphere dropped from rest at `height` [m] onto the fixed plane z = 0,
    under gravity and the damped Hertz law of Eq. 7 with A = (A1 + A2) / 2. Returns a function t -> z(t),
    integrated to a relative tolerance of 1e-11."""
    modulus = effective_modulus(sphere_material, plane_material)
    damping = 0.5 * (sphere_material.damping + plane_material.damping)
    mass = density * 4.0 / 3.0 * math.pi * radius ** 3

    def motion(_, y):
        z, v = y
        return [v, -gravity + hertz_force(modulus, radius, radius - z, -v, damping) / mass]

    solution = solve_ivp(motion, (0.0, duration), [height, 0.0], method="DOP853", rtol=1e-11, atol=1e-13,
                         max_step=radius * 1e-3, dense_output=True)
    return lambda t: solution.sol(t)[0]


def apex_heights(t, z):
    """Heights of the local maxima of z(t) after its first minimum, by parabolic interpolation of the
    samples around each maximum."""
    z = np.asarray(z)
    first_minimum = int(np.argmax(np.diff(z) > 0))
    apexes = []
    for i in range(max(first_minimum, 1), len(z) - 1):
        if z[i] >= z[i - 1] and z[i] > z[i + 1]:
            curvature = z[i - 1] - 2 * z[i] + z[i + 1]
            apexes.append(z[i] - (z[i + 1] - z[i - 1]) ** 2 / (8 * curvature))
    return np.array(apexes)


def nrmse(model, reference):
    """sqrt(mean((model - reference)^2)) / (max(reference) - min(reference))."""
    model, reference = np.asarray(model), np.asarray(reference)
    return math.sqrt(np.mean((model - reference) ** 2)) / (reference.max() - reference.min())


# Exact elliptical Hertz contact (Hertz 1881; Johnson, Contact Mechanics, 1985, Section 4.2). The pressure
# p0 sqrt(1 - x^2/a^2 - y^2/b^2) on the ellipse with semi-axes a >= b (a along the direction of r_major),
# e^2 = 1 - b^2/a^2 = m, makes the two surfaces approach by
#     delta - A x^2 - B y^2,   delta = 3 F K / (2 pi a E*),
#     A = 3 F (K - E) / (2 pi E* a^3 e^2),   B = 3 F (E / (1 - e^2) - K) / (2 pi E* a^3 e^2),
# K, E complete elliptic integrals of parameter m. Written with Carlson's integrals, free of the cancellation
# in K - E and of the loss of 1 - m near m = 1 (m' = 1 - m = b^2/a^2):
#     K = R_F(0, m', 1),   (K - E)/m = R_D(0, m', 1)/3,   (E/m' - K)/m = R_D(0, 1, m')/3,
# so B/A = R_D(0, 1, m') / R_D(0, m', 1), a^2 = 2 r_major delta (K - E)/(m K), and
#     F = (2 pi / 3) E* sqrt(2 r_major (K - E)/m) K^-3/2 delta^3/2,
# which is (4/3) E* sqrt(R) delta^3/2 for m = 0 ((K - E)/m = pi/4, K = pi/2).

def _axis_ratio_squared(r_major, r_minor):
    """m' = b^2/a^2 of the exact contact ellipse: the root of R_D(0, 1, m')/R_D(0, m', 1) = r_major/r_minor,
    by brentq on ln m' (1 for a circle)."""
    if not 0 < r_minor <= r_major < math.inf:
        raise ValueError(f"need 0 < r_minor <= r_major < inf, got r_major={r_major!r}, r_minor={r_minor!r}")
    target = math.log(r_major / r_minor)
    if target == 0.0:
        return 1.0

    def residual(log_m):
        m1 = math.exp(log_m)
        return math.log(elliprd(0.0, 1.0, m1) / elliprd(0.0, m1, 1.0)) - target

    # a/b < B/A (a/b grows about as (B/A)^2/3), so m' > (A/B)^2 brackets the root; ln m' to full precision
    return math.exp(brentq(residual, 2.0 * math.log(r_minor / r_major) - 1.0, 0.0, xtol=1e-300, maxiter=400))


def elliptical_hertz_eccentricity(r_major, r_minor):
    """Eccentricity e = sqrt(1 - b^2/a^2) of the exact Hertz contact ellipse: the root of
    B/A = r_major/r_minor = (E(e)/(1 - e^2) - K(e)) / (K(e) - E(e)); 0 for r_major = r_minor. [-]"""
    return math.sqrt(max(0.0, -math.expm1(math.log(_axis_ratio_squared(r_major, r_minor)))))


def elliptical_hertz_contact(modulus, r_major, r_minor, overlap):
    """Exact Hertz contact of relative principal radii r_major >= r_minor [m], modulus E* of Eq. 3 [Pa],
    approach delta [m] (scalar radii, delta scalar or array; Johnson Section 4.2): returns (F [N], a [m], b [m])
    with the contact semi-axes a = sqrt(2 r_major delta (K - E)/(m K)) along r_major and b = a sqrt(1 - e^2);
    zero for delta <= 0."""
    m1 = _axis_ratio_squared(r_major, r_minor)
    k, d = elliprf(0.0, m1, 1.0), elliprd(0.0, m1, 1.0) / 3.0  # K and (K - E)/m
    overlap = np.maximum(overlap, 0.0)
    force = 2.0 * math.pi / 3.0 * modulus * math.sqrt(2.0 * r_major * d) * k ** -1.5 * overlap ** 1.5
    a = np.sqrt(2.0 * r_major * d / k * overlap)
    return force, a, a * math.sqrt(m1)


def elliptical_hertz_force(modulus, r_major, r_minor, overlap):
    """Exact Hertz force F = (2 pi/3) E* sqrt(2 r_major (K - E)/e^2) K^-3/2 delta^3/2 [N] for relative principal
    radii r_major >= r_minor [m], E* of Eq. 3 [Pa], approach delta [m] (zero for delta <= 0); K, E of the
    eccentricity e of elliptical_hertz_eccentricity. Equals (4/3) E* sqrt(R) delta^3/2 when both radii are R."""
    return elliptical_hertz_contact(modulus, r_major, r_minor, overlap)[0]


def approximate_elliptical_hertz_force(modulus, r_major, r_minor, overlap):
    """Equivalent-radius approximation (4/3) E* sqrt(Re) (delta/F2)^3/2 [N], Re = sqrt(r_major r_minor): Johnson's
    delta = (9 F^2/(16 Re E*^2))^1/3 F2(e) (Contact Mechanics Section 4.2, Fig. 4.4) with the power-law fit
    F2 = 1 - ((r_major/r_minor)^0.0684 - 1)^1.531 of his chart, the kind of approximation the paper takes from
    Hale [34] (coefficients as quoted in secondary sources; no accuracy is stated with them). Measured against
    elliptical_hertz_force: within 0.9% for r_major/r_minor <= 100, 4% at 200, 25% at 1000."""
    if not 0 < r_minor <= r_major < math.inf:
        raise ValueError(f"need 0 < r_minor <= r_major < inf, got r_major={r_major!r}, r_minor={r_minor!r}")
    f2 = 1.0 - ((r_major / r_minor) ** 0.0684 - 1.0) ** 1.531
    return 4.0 / 3.0 * modulus * math.sqrt(math.sqrt(r_major * r_minor)) * (np.maximum(overlap, 0.0) / f2) ** 1.5


def parallel_cylinders_force(modulus, length, overlap):
    """F = (pi/4) E* L delta (Eq. 27) [N] for two parallel cylinders of length L [m] with the combined modulus
    E* of Eq. 3 [Pa] and overlap delta [m]; zero for delta <= 0."""
    return math.pi / 4.0 * modulus * length * np.maximum(overlap, 0.0)


def spheroid_equator_radii(a, b):
    """Principal radii of curvature [m] at an equator point of the spheroid with semi-axis a along its axis and
    b, b across it: (a^2/b in the meridian plane, along the axis; b around the axis)."""
    return a * a / b, b


def spheroid_pair_radii(a, b):
    """Relative principal radii (r_major, r_minor) [m] of two identical spheroids (semi-axes a; b, b) touching at
    their equators with parallel axes: half each body's radius (1/r' = 2 b/a^2, 1/r'' = 2/b), so
    r_major/r_minor = (a/b)^2 for a prolate spheroid (a >= b)."""
    meridian, around = spheroid_equator_radii(a, b)
    return np.maximum(meridian, around) / 2.0, np.minimum(meridian, around) / 2.0
