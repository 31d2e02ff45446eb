"""Shapes not made of spheres for the speed-against-error study (issue 27; doc/speed-vs-error.md): smooth convex
solids {f < 0} with a known implicit function, each scaled to the volume of a sphere of radius RADIUS = 25 mm, as
the pear and the gummy bear are.

    GRAINS                   name -> Grain: 'spheroid' (2:1, prolate), 'pill' (superellipsoid 2 : 1.5 : 1,
                             exponent 4, a rounded box), 'tetra_grain' (rounded tetrahedron, rounding 0.3 of its
                             inradius)
    Grain.distance(points)   f [m] at points (n, 3) of the shape's own frame: negative inside, 1-Lipschitz
    Grain.mesh(nodes, curvature='computed' | 'exact')   the C++ generator's Mesh (Mesh.spheroid, .superellipsoid,
                             .rounded_tetrahedron), in its principal frame; Mesh.centroid and Mesh.orientation
                             map it back to the shape's own frame (input point = R body point + centroid)

f is written as a distance-like function, |grad f| <= 1, because the study's second-contact check reads f of one
body at points of the other as a lower bound of their gap (shape_error.press_geometry): for the spheroid and the
superellipsoid f = r_in (g(x) - 1), g the gauge of the solid (the norm whose unit ball it is), which is
1/r_in-Lipschitz for a convex solid holding the ball of radius r_in = its smallest semi-axis about its centre; for
the rounded tetrahedron f = s ln sum_i exp(n_i . x / s) - h itself, whose gradient is a weighted mean of unit
normals. Hertz's reference needs only the zero level set and its curvature, which do not depend on that choice.
"""
import functools
import math
from dataclasses import dataclass

import numpy as np

from roundedmesh import Mesh

RADIUS = 0.025                      # volume-equivalent radius of every study shape [m]
REFERENCE_NODES = 600               # the node count of a grain's body frame and of its S1 packing
VOLUME = 4 / 3 * math.pi * RADIUS ** 3
TETRA_ROUNDING = 0.3                # s / h of the tetrahedral grain
# Volume of the solid of h = 1, s = 0.3 (no closed form): the inscribed meshes of N = 3988 and 7993 nodes fall short
# of it by C / N (10.06470, 10.07414), extrapolated; tests/python/test_grains.py recomputes it.
TETRA_UNIT_VOLUME = 10.08354
PILL_AXES = (2.0, 1.5, 1.0)         # a : b : c of the pill
PILL_EXPONENT = 4.0
# Outward unit face normals of the regular tetrahedron (pkg/meshing/RoundedTetrahedron.hpp).
TETRA_NORMALS = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float) / math.sqrt(3)


@dataclass(frozen=True)
class Grain:
    """One study shape: `kind` 'spheroid' (semi-axis a = parameters[0] along z, b = parameters[1] across),
    'superellipsoid' (semi-axes a, b, c along x, y, z and exponent p) or 'tetrahedron' (inradius h, rounding s);
    lengths in m."""
    name: str
    kind: str
    parameters: tuple
    description: str

    def distance(self, points):
        """f [m] at points (n, 3) [m] of the shape's own frame (module docstring)."""
        x = np.asarray(points, dtype=float)
        if self.kind == "spheroid":
            a, b = self.parameters
            gauge = np.sqrt((x[:, 0] ** 2 + x[:, 1] ** 2) / b ** 2 + x[:, 2] ** 2 / a ** 2)
            return min(a, b) * (gauge - 1)
        if self.kind == "superellipsoid":
            a, b, c, p = self.parameters
            gauge = (np.abs(x[:, 0] / a) ** p + np.abs(x[:, 1] / b) ** p + np.abs(x[:, 2] / c) ** p) ** (1 / p)
            return min(a, b, c) * (gauge - 1)
        h, s = self.parameters
        heights = x @ TETRA_NORMALS.T / s
        top = heights.max(axis=1)
        return s * (top + np.log(np.exp(heights - top[:, None]).sum(axis=1))) - h

    def mesh(self, nodes, curvature="computed"):
        """Mesh of about `nodes` nodes with the curvature 'computed' from it (Eq. 1) or 'exact' (the smooth
        shape's mean and principal curvatures under each triangle); cached."""
        return _mesh(self, int(nodes), curvature)

    def frame(self, nodes=REFERENCE_NODES):
        """(R (3, 3), centroid (3,) [m]) of mesh(nodes): a point of its principal (body) frame x is R x + centroid
        in the shape's own frame. The frame of mesh(REFERENCE_NODES) is the grain's body frame in S1 and the frame
        of its clumps and level sets, as the paper mesh's is for the pear and the gummy bear."""
        mesh = self.mesh(nodes)
        return np.array(mesh.orientation.toRotationMatrix()), np.array(mesh.centroid)

    def surface(self, nodes=2200, frame="own"):
        """(vertices (n, 3) [m], triangles (m, 3)) of mesh(nodes) in the shape's own frame (`frame` 'own') or in the
        body frame of mesh(REFERENCE_NODES) ('reference'): what the study samples f = 0 at, and what YADE's clumps
        and level sets of the grain are built from."""
        rotation, centroid = self.frame(nodes)
        own = np.array(self.mesh(nodes).vertices) @ rotation.T + centroid
        if frame == "reference":
            rotation, centroid = self.frame()
            return (own - centroid) @ rotation, np.array(self.mesh(nodes).triangles)
        return own, np.array(self.mesh(nodes).triangles)


@functools.lru_cache(maxsize=None)
def _mesh(grain, nodes, curvature):
    if grain.kind == "spheroid":
        return Mesh.spheroid(*grain.parameters, nodes, curvature=curvature)
    if grain.kind == "superellipsoid":
        return Mesh.superellipsoid(*grain.parameters, nodes, curvature=curvature)
    return Mesh.rounded_tetrahedron(*grain.parameters, nodes, curvature=curvature)


def _tetra_grain():
    """The rounded tetrahedron of rounding 0.3 h whose solid has VOLUME: f scales with h (f_h(x) = h f_1(x / h)),
    so h = (VOLUME / TETRA_UNIT_VOLUME)^(1/3)."""
    h = (VOLUME / TETRA_UNIT_VOLUME) ** (1 / 3)
    return Grain("tetra_grain", "tetrahedron", (h, TETRA_ROUNDING * h),
                 f"rounded tetrahedron, inradius {h * 1e3:.2f} mm, rounding {TETRA_ROUNDING * h * 1e3:.2f} mm")


def _pill():
    """Semi-axes 2k, 1.5k, k with 8 a b c Gamma(1 + 1/p)^3 / Gamma(1 + 3/p) = VOLUME."""
    gamma = math.gamma(1 + 1 / PILL_EXPONENT) ** 3 / math.gamma(1 + 3 / PILL_EXPONENT)
    k = (VOLUME / (8 * math.prod(PILL_AXES) * gamma)) ** (1 / 3)
    a, b, c = (k * v for v in PILL_AXES)
    return Grain("pill", "superellipsoid", (a, b, c, PILL_EXPONENT),
                 f"superellipsoid, semi-axes {a * 1e3:.2f} x {b * 1e3:.2f} x {c * 1e3:.2f} mm, exponent 4")


def _spheroid():
    """Prolate 2:1: a = 2 b, (4/3) pi a b^2 = VOLUME."""
    b = RADIUS / 2 ** (1 / 3)
    return Grain("spheroid", "spheroid", (2 * b, b), f"spheroid 2:1, semi-axes {2 * b * 1e3:.2f} and {b * 1e3:.2f} mm")


NAMES = ("spheroid", "pill", "tetra_grain")


@functools.lru_cache(maxsize=None)
def grain(name):
    """The study shape `name` (one of NAMES)."""
    makers = {"spheroid": _spheroid, "pill": _pill, "tetra_grain": _tetra_grain}
    if name not in makers:
        raise ValueError(f"name: {name!r} is not a study grain; known: {', '.join(NAMES)}")
    return makers[name]()
