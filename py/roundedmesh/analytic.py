"""Analytic references for validation, written independently of the compiled contact code.

    effective_modulus(m1, m2)          E* of Eq. 3
    hertz_force(E, R, delta, rate, A)  damped Hertz force of Eq. 7 (never pulling), [N]
    bouncing_sphere(...)               a perfect sphere dropped on a plane under that law (scene S3)
    apex_heights(t, z)                 heights of the maxima of a bouncing trajectory
    nrmse(model, reference)            NRMSE as scenes.md defines it
"""
import math

import numpy as np
from scipy.integrate import solve_ivp


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
