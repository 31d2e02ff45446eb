"""Hertz's solution at the contact point of a smooth shape: the reference every representation of the shape is
judged against in the speed-against-error study (issue 14; doc/speed-vs-error.md). All lengths in metres,
curvatures in 1/m, forces in newtons.

A smooth shape is given by its implicit function f (negative inside, zero on the surface, |grad f| > 0 there):
peers.shape_distance for the pear and the gummy bear of shapes.json, |x| - r for the sphere.

    derivatives(f, x)                    f, grad f and the Hessian by central differences
    curvature_tensor(f, x)               outward normal and shape operator P H P / |grad f| at a surface point
    tangent_principal(K, n)              principal curvatures and directions of a shape operator
    principal_curvatures(f, x)           (k_min, k_max), their directions, the normal
    project_to_surface(f, x)             the point of f = 0 reached from x along grad f
    support_point(f, d, samples)         the surface point farthest along d (where the normal is d)
    relative_principal_radii(...)        Johnson's relative radii of two bodies from their principal curvatures
                                         and the angle between their principal directions
    contact_radii(K1, K2, n)             the same from the two curvature tensors in a common frame
    reference_force(E, r_major, r_minor, delta)   exact elliptical Hertz force (analytic.elliptical_hertz_force)
    contact_semi_axes(E, r_major, r_minor, delta) semi-axes of Hertz's contact ellipse
    crease_ratio(f, x, tangents, reach)  how much the curvatures change over a contact's reach
    hertz_holds(...)                     None, or why the pose is left out: 'concave', 'flat', 'crease',
                                         'second contact'

Curvature (a). For a surface f = 0 with outward normal n = grad f / |grad f| the shape operator (Weingarten map)
is K = P H P / |grad f|, with H the Hessian of f and P = I - n n^T the projection on the tangent plane (e.g.
Goldman, "Curvature formulas for implicit curves and surfaces", Comput. Aided Geom. Des. 22 (2005) 632-658).
Its two non-zero eigenvalues are the principal curvatures, positive where the surface is convex (the sphere
|x| - r gives 1/r twice). The gradient and Hessian are central differences with step FD_STEP.

Contact law (b): two bodies touching at a point where their outward normals are opposite have, in the common
tangent plane, the gap h = x^T (K1 + K2) x / 2 (each K in the tangent plane, in the same axes). Its eigenvalues
1/r_major <= 1/r_minor are the relative curvatures (Johnson, Contact Mechanics, Cambridge University Press
1985, Section 4.1, where A = 1/(2 r_major), B = 1/(2 r_minor)), and the force against the
approach delta is Hertz's elliptical solution (Johnson Section 4.2):
analytic.elliptical_hertz_force(E*, r_major, r_minor, delta), with the eccentricity from the ratio of the
complete elliptic integrals. For a rigid plane K2 = 0. For r_major = r_minor = R it is (4/3) E* sqrt(R)
delta^3/2, the paper's Eq. 6 with R* = R.
"""
import math

import numpy as np

from .analytic import elliptical_hertz_contact, elliptical_hertz_force

# Central differences of f, whose values near the surface are O(1e-2 m) and exact to about 1e-17 m (double
# precision): the truncation error of the second difference is h^2 f''''/12, relative (h k)^2/12, below 1e-5 for
# radii of curvature above 1 mm (the gummy bear's smallest primitive is 5.4 mm); the round-off error is about
# 1e-17 m / h^2 = 1e-7 1/m, 1e-9 of the curvatures here (~ 100 1/m). Near a blend's edge f is only C1 (the
# polynomial smooth minimum), and a stencil that straddles it mixes both sides: hertz_holds leaves such points
# out by comparing with neighbours a contact width away, far beyond h.
FD_STEP = 1e-5

# Curvatures at the rim of the contact ellipse (at the deepest overlap) may differ from the contact point's by at
# most this share of the larger principal curvature there; more is a crease (a blend's or capsule's edge) for
# Hertz, whose gap is quadratic over the whole contact. Even if it held over the whole contact, a 10 % change of
# curvature would change Hertz's force (growing as the square root of the radius) by at most 5 %; it holds only
# at the rim, where the pressure falls to zero.
CREASE_TOLERANCE = 0.10

_UNIT = np.eye(3)


def _stencil(step):
    """Offsets (19, 3) for the value, gradient and Hessian by central differences: 0, +-h e_i, and
    (+-h, +-h) in each coordinate plane."""
    offsets = [np.zeros(3)]
    for i in range(3):
        offsets += [step * _UNIT[i], -step * _UNIT[i]]
    for i in range(3):
        for j in range(i + 1, 3):
            for si in (1, -1):
                for sj in (1, -1):
                    offsets.append(step * (si * _UNIT[i] + sj * _UNIT[j]))
    return np.array(offsets)


_OFFSETS = _stencil(FD_STEP)


def derivatives(distance, point, step=FD_STEP):
    """(f, grad f (3,), Hessian (3, 3)) of the implicit function `distance` (points (n, 3) -> (n,)) at `point`,
    by central differences of step `step` [m]."""
    offsets = _OFFSETS if step == FD_STEP else _stencil(step)
    values = np.asarray(distance(np.asarray(point, dtype=float) + offsets), dtype=float)
    f0 = values[0]
    gradient = np.array([(values[1 + 2 * i] - values[2 + 2 * i]) / (2 * step) for i in range(3)])
    hessian = np.empty((3, 3))
    for i in range(3):
        hessian[i, i] = (values[1 + 2 * i] - 2 * f0 + values[2 + 2 * i]) / step ** 2
    k = 7
    for i in range(3):
        for j in range(i + 1, 3):
            pp, pm, mp, mm = values[k:k + 4]
            hessian[i, j] = hessian[j, i] = (pp - pm - mp + mm) / (4 * step ** 2)
            k += 4
    return f0, gradient, hessian


def curvature_tensor(distance, point):
    """(n, K): the outward unit normal (3,) and the shape operator K = P H P / |grad f| (3, 3) [1/m] of the
    surface f = 0 at `point` (on or very near it), P = I - n n^T. Convex surfaces have K >= 0."""
    _, gradient, hessian = derivatives(distance, point)
    norm = np.linalg.norm(gradient)
    normal = gradient / norm
    projection = np.eye(3) - np.outer(normal, normal)
    tensor = projection @ hessian @ projection / norm
    return normal, 0.5 * (tensor + tensor.T)


def tangent_principal(tensor, normal):
    """(curvatures (2,) ascending [1/m], directions (2, 3)) of a shape operator in the tangent plane of
    `normal`: the eigenpairs of K other than the normal's."""
    values, vectors = np.linalg.eigh(tensor)
    tangent = np.argsort(np.abs(vectors.T @ normal))[:2]       # the two eigenvectors farthest from n
    order = tangent[np.argsort(values[tangent])]
    return values[order], vectors[:, order].T


def principal_curvatures(distance, point):
    """(curvatures (k_min, k_max) [1/m], directions (2, 3), outward normal (3,)) at a point of f = 0."""
    normal, tensor = curvature_tensor(distance, point)
    curvatures, directions = tangent_principal(tensor, normal)
    return curvatures, directions, normal


def project_to_surface(distance, point, iterations=20):
    """The point of f = 0 reached from `point` by Newton steps along grad f (f is a distance near the surface,
    so a few steps reach it to round-off)."""
    x = np.asarray(point, dtype=float).copy()
    for _ in range(iterations):
        f0, gradient, _ = derivatives(distance, x)
        x -= f0 * gradient / (gradient @ gradient)
        if abs(f0) < 1e-15:
            break
    return x


def support_point(distance, direction, samples, iterations=50):
    """The point of f = 0 farthest along the unit vector `direction`, where the outward normal is `direction`:
    Newton's method on grad f = lambda d, f = 0 from the sample point (points on the surface, (n, 3)) farthest
    along d. Raises RuntimeError if the normal misses d by more than 1e-8 rad."""
    d = np.asarray(direction, dtype=float)
    d = d / np.linalg.norm(d)
    samples = np.asarray(samples, dtype=float)
    x = project_to_surface(distance, samples[np.argmax(samples @ d)])
    lam = np.linalg.norm(derivatives(distance, x)[1])
    for _ in range(iterations):
        f0, gradient, hessian = derivatives(distance, x)
        residual = np.concatenate([gradient - lam * d, [f0]])
        jacobian = np.zeros((4, 4))
        jacobian[:3, :3], jacobian[:3, 3], jacobian[3, :3] = hessian, -d, gradient
        step = np.linalg.lstsq(jacobian, -residual, rcond=None)[0]
        # keep each step within a millimetre: Newton on a surface whose curvature jumps (blends) may overshoot
        scale = min(1.0, 1e-3 / max(np.linalg.norm(step[:3]), 1e-300))
        x, lam = x + scale * step[:3], lam + scale * step[3]
        if np.linalg.norm(step[:3]) < 1e-13:
            break
    x = project_to_surface(distance, x)
    normal = curvature_tensor(distance, x)[0]
    if normal @ d < 0 or np.linalg.norm(np.cross(normal, d)) > 1e-8:
        raise RuntimeError(f"support_point: no point with normal {d} found (reached normal {normal})")
    if np.max(samples @ d) > x @ d + 1e-9:
        raise RuntimeError("support_point: Newton's method stopped at a local, not the global, extreme point")
    return x


def relative_principal_radii(curvatures1, curvatures2, angle):
    """(r_major, r_minor) [m], r_major >= r_minor: the relative radii of two bodies touching with principal
    curvatures curvatures1 = (1/R1', 1/R1''), curvatures2 = (1/R2', 1/R2'') [1/m] and `angle` [rad] between the
    directions of 1/R1' and 1/R2' (Johnson 1985, Section 4.1):
        A + B = (1/R1' + 1/R1'' + 1/R2' + 1/R2'') / 2,
        |B - A| = sqrt((1/R1' - 1/R1'')^2 + (1/R2' - 1/R2'')^2 + 2 (1/R1' - 1/R1'')(1/R2' - 1/R2'') cos 2 angle) / 2,
    r_major = 1/(2A), r_minor = 1/(2B). A plane has curvatures (0, 0)."""
    (a1, b1), (a2, b2) = curvatures1, curvatures2
    total = 0.5 * (a1 + b1 + a2 + b2)
    difference = 0.5 * math.sqrt(max(0.0, (a1 - b1) ** 2 + (a2 - b2) ** 2
                                     + 2 * (a1 - b1) * (a2 - b2) * math.cos(2 * angle)))
    small, large = (total - difference) / 2, (total + difference) / 2
    return (math.inf if small <= 0 else 1 / (2 * small)), 1 / (2 * large)


def contact_radii(tensor1, tensor2, normal):
    """(r_major, r_minor, major direction (3,)) [m]: relative radii from the two bodies' shape operators (3, 3),
    written in one frame, at a contact of normal `normal` (body 1's outward normal; body 2's is -normal):
    1/r are the tangent eigenvalues of K1 + K2. r_major is inf when K1 + K2 is not positive definite."""
    curvatures, directions = tangent_principal(tensor1 + tensor2, normal)
    r_major = math.inf if curvatures[0] <= 0 else 1 / curvatures[0]
    return r_major, 1 / curvatures[1], directions[0]


def reference_force(modulus, r_major, r_minor, overlaps):
    """Hertz's force [N] at approach `overlaps` [m] for relative radii r_major >= r_minor [m] and E* `modulus`
    [Pa]: analytic.elliptical_hertz_force (Johnson Section 4.2)."""
    return elliptical_hertz_force(modulus, r_major, r_minor, np.asarray(overlaps, dtype=float))


def contact_semi_axes(modulus, r_major, r_minor, overlap):
    """(a, b) [m]: the semi-axes of Hertz's contact ellipse at approach `overlap`, a along r_major."""
    _, a, b = elliptical_hertz_contact(modulus, r_major, r_minor, overlap)
    return float(a), float(b)


def crease_ratio(distance, point, tangents, reach):
    """Largest change of either principal curvature between `point` (on f = 0) and the surface points
    reached by `reach` [m] along +-each of the tangent directions `tangents` (rows), as a share of the larger
    principal curvature at `point`. Large where the surface is not one quadric over that reach: a crease."""
    curvatures = principal_curvatures(distance, point)[0]
    scale = max(abs(curvatures[1]), abs(curvatures[0]), 1e-300)
    worst = 0.0
    for tangent, length in zip(tangents, reach):
        for sign in (1, -1):
            neighbour = project_to_surface(distance, point + sign * length * np.asarray(tangent))
            worst = max(worst, float(np.max(np.abs(principal_curvatures(distance, neighbour)[0] - curvatures))))
    return worst / scale


def hertz_holds(modulus, overlap, bodies, second_contact, flat_ratio=1e-3):
    """None if Hertz's solution is a fair reference for a contact pressed to `overlap` [m], else the reason:
        'concave'         a principal curvature of a body at its contact point is negative;
        'flat'            the relative curvature 1/r_major is below `flat_ratio` of 1/r_minor (a line contact,
                          whose length Hertz does not bound);
        'crease'          a body's curvature changes by more than CREASE_TOLERANCE over the contact ellipse at
                          `overlap` (crease_ratio at the semi-axes);
        'second contact'  the bodies come within reach of each other elsewhere (`second_contact` is True).
    `bodies` is a list of (distance, point, tensor, body_to_common) per body (one for a plane partner): its
    implicit function, contact point and shape operator in its own frame, and the rotation (3, 3) from its
    frame to the common one, where the contact normal is +z for the first body."""
    tensors = []
    for distance, point, tensor, rotation in bodies:
        normal = curvature_tensor(distance, point)[0]
        if tangent_principal(tensor, normal)[0][0] < -1e-9 * np.max(np.abs(tensor)):
            return "concave"
        tensors.append(rotation @ tensor @ rotation.T)
    r_major, r_minor, major = contact_radii(tensors[0], tensors[1] if len(tensors) > 1 else 0 * tensors[0],
                                            _UNIT[2])
    if r_minor < flat_ratio * r_major:          # 1/r_major below flat_ratio of 1/r_minor (or r_major inf)
        return "flat"
    a, b = contact_semi_axes(modulus, r_major, r_minor, overlap)
    directions = np.array([major, np.cross(_UNIT[2], major)])
    for distance, point, _, rotation in bodies:
        if crease_ratio(distance, point, directions @ rotation, (a, b)) > CREASE_TOLERANCE:
            return "crease"
    if second_contact:
        return "second contact"
    return None
