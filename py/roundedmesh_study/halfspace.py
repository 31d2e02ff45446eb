"""Frictionless normal contact of two elastic bodies of any smooth shape, each taken as a half-space (Johnson,
Contact Mechanics, 1985, Sections 3.2 and 4.1, whose Hertz solution is the case of a quadratic gap): the reference of
the speed-against-error study where the curvature changes over the contact and Hertz at the contact point's
curvatures no longer holds (shape_error.PressGeometry).

    contact_forces(gap, spacing, modulus, overlaps) -> forces [N] at each approach, pressures [Pa] at the deepest

Problem. On a square grid of cells of side `spacing` [m] in the common tangent plane, `gap` g >= 0 [m] is the
distance between the undeformed surfaces along the normal (0 where they first touch). Pressed together by the
rigid approach delta, the surfaces' combined normal displacement u (Boussinesq, Johnson Eq. 3.20)
    u(x) = 1 / (pi E*) integral p(s) / |x - s| dA(s),   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Eq. 3 of the paper)
must close the gap where they touch and nowhere overlap them:
    p >= 0,   u - (delta - g) >= 0,   p (u - (delta - g)) = 0.
Pressure is constant on each cell; u at a cell's centre from a unit pressure on another cell is Love's (1929)
closed form for a uniformly loaded rectangle (Johnson Eq. 3.25), summed by FFT over the zero-padded grid (discrete
convolution, Liu, Wang and Liu, Wear 243 (2000) 101-111). The inequality problem is solved by Polonsky and Keer's
conjugate gradients (Wear 231 (1999) 206-219) with the approach prescribed instead of the load, so without their
load-balancing step. The force is sum p spacing^2.

Accuracy: tests/python/test_halfspace.py presses a sphere and a spheroid onto a plane on the grid the study uses and
compares with Hertz's circular and elliptical solutions (analytic.py): the NRMSE over the study's overlaps is below
0.3 % when the contact at the deepest overlap spans at least 40 cells.
"""
import numpy as np

_TOLERANCE = 1e-9      # relative change of the pressure between iterations at which an approach is converged
_MAX_ITERATIONS = 2000


def love_influence(x, y, half_x, half_y):
    """pi E* u [m * Pa / Pa = m] at (x, y) [m] from a unit pressure [Pa] on the rectangle |x| <= half_x,
    |y| <= half_y (Love 1929; Johnson Eq. 3.25): u = love_influence / (pi E*) for a unit pressure."""
    def log_sum(a, b, r):  # ln(a + r), r = hypot(a, b), without cancellation where a < 0
        with np.errstate(divide="ignore"):
            return np.log(np.where(a >= 0, a + r, b * b / (r - a)))

    def term(p, q):  # the antiderivative p ln(q + r) + q ln(p + r) of 1/r over a quadrant; 0 ln 0 = 0
        r = np.hypot(p, q)
        with np.errstate(invalid="ignore"):
            return np.where(p == 0, 0.0, p * log_sum(q, p, r)) + np.where(q == 0, 0.0, q * log_sum(p, q, r))
    xp, xm, yp, ym = x + half_x, x - half_x, y + half_y, y - half_y
    return term(xp, yp) - term(xp, ym) - term(xm, yp) + term(xm, ym)


class _Convolution:
    """u = K p on an n x m grid by FFT of the zero-padded (2n x 2m) grid: K the cell-to-cell influence, each cell
    a square of side `spacing`."""

    def __init__(self, shape, spacing, modulus):
        n, m = shape
        i = np.concatenate([np.arange(n), np.arange(-n, 0)]) * spacing
        j = np.concatenate([np.arange(m), np.arange(-m, 0)]) * spacing
        kernel = love_influence(i[:, None], j[None, :], spacing / 2, spacing / 2) / (np.pi * modulus)
        kernel[n, :] = 0.0   # the padding's middle row and column: offsets of n and m cells never occur
        kernel[:, m] = 0.0
        self._spectrum = np.fft.rfft2(kernel)
        self._shape = shape

    def __call__(self, pressure):
        n, m = self._shape
        padded = np.zeros((2 * n, 2 * m))
        padded[:n, :m] = pressure
        return np.fft.irfft2(np.fft.rfft2(padded) * self._spectrum, s=(2 * n, 2 * m))[:n, :m]


def _solve(convolve, target, pressure):
    """Polonsky and Keer's conjugate gradients for p >= 0 with K p = target where p > 0 and K p >= target where
    p = 0, from the starting `pressure` (n, m) [Pa]; returns p."""
    direction = np.zeros_like(pressure)
    previous = 1.0
    conjugate = False
    for _ in range(_MAX_ITERATIONS):
        residual = convolve(pressure) - target
        active = pressure > 0
        if not active.any():
            pressure = np.where(target > 0, target.max() * 1e-3, 0.0)   # restart from where the gap closes
            continue
        norm = float(np.sum(residual[active] ** 2))
        direction = np.where(active, residual + (norm / previous if conjugate else 0.0) * direction, 0.0)
        previous = norm
        response = convolve(direction)
        curvature = float(np.sum(response[active] * direction[active]))
        if curvature <= 0:
            break
        step = float(np.sum(residual[active] * direction[active])) / curvature
        updated = np.maximum(pressure - step * direction, 0.0)
        penetrating = (updated == 0) & (residual < 0)       # out of contact, yet overlapping: let them in
        conjugate = not penetrating.any()
        updated[penetrating] -= step * residual[penetrating]
        change = np.sum(np.abs(updated - pressure)) / max(np.sum(updated), 1e-300)
        pressure = updated
        if change < _TOLERANCE:
            break
    return pressure


def contact_forces(gap, spacing, modulus, overlaps):
    """(forces (k,) [N], pressure (n, m) [Pa] at the deepest overlap) of the half-space contact of the gap
    `gap` (n, m) [m] (>= 0, np.inf where the bodies do not face each other) on cells of side `spacing` [m], with
    E* = `modulus` [Pa], at each rigid approach of `overlaps` (k,) [m], in increasing order (each solution starts
    from the previous one, scaled)."""
    gap = np.asarray(gap, dtype=float)
    convolve = _Convolution(gap.shape, spacing, modulus)
    forces = []
    pressure = np.zeros_like(gap)
    previous = None
    for overlap in overlaps:
        target = overlap - gap
        if previous is None or not pressure.any():   # a first guess of the right order: E* delta / contact size
            size = spacing * max(np.sqrt(np.count_nonzero(target > 0)), 1.0)
            pressure = modulus * np.clip(target, 0, None) / size
        else:
            pressure = pressure * np.sqrt(overlap / previous)   # Hertz: p scales as delta^(1/2) at a fixed point
        pressure = _solve(convolve, np.where(np.isfinite(target), target, -1.0), pressure)
        forces.append(float(np.sum(pressure)) * spacing ** 2)
        previous = overlap
    return np.array(forces), pressure
