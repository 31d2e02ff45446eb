"""Mesh.load with two checks: that the loaded body has the size of a DEM particle, and that its mesh is fine enough for
the curvature it was given.

A mesh file carries no unit. A file in millimetres loaded without scale=0.001 gives a body 1000 times too
large (a 33 mm gummy bear becomes 36,824 m^3), which then runs, slowly and wrongly, with nothing to show for
it; a file scaled twice gives a body 1000 times too small. Mesh.load warns (RuntimeWarning) when the
volume-equivalent radius is outside PLAUSIBLE_RADII: from a micrometre, below which a DEM body of continuum
Hertz contact makes little sense, to 10 m, above any particle (a boulder) that DEM is used for. The body is
loaded all the same: the warning is for the unit, not a refusal.

Each triangle's cap (the part of its sphere beyond its plane) is where the rounded body lies beyond the mesh, and how
far from the mesh it pushes a partner. Where the mesh is too coarse for its curvature (a sharp edge, a sliver, a coarse
scan) the caps grow to half spheres over the triangles: YADE's 12-triangle rod-coarse.stl reaches 1.6 r_eq beyond its
faces, the coarse GTS horse 1.7 r_eq (262 of its 668 triangles beyond the tolerance). Mesh.load warns (RuntimeWarning,
naming the worst triangles, their cap heights and the tolerance) when a cap is taller than COARSE_CAP_TOLERANCE of the
body's volume-equivalent radius: 0.05 r_eq, half the Hertz depth (doc/physics.md), which the meshes the project
validates stay within (tallest caps: the 563-node gummy bear 0.045 r_eq, the 478-node pear 0.016, icospheres of 162
and 642 nodes 0.018 and 0.0045; the 42-node icosphere, 0.069, does not). The body is loaded all the same.
"""
import math
import warnings

from ._core import Mesh

PLAUSIBLE_RADII = (1e-6, 10.0)  # volume-equivalent radius [m]
COARSE_CAP_TOLERANCE = 0.05     # of the volume-equivalent radius

_load = Mesh.load


def load(path, scale=1.0, radius=None, max_radius=None, fill_holes=False):
    mesh = _load(path, scale, radius, max_radius, fill_holes)
    equivalent = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    smallest, largest = PLAUSIBLE_RADII
    if not smallest <= equivalent <= largest:
        warnings.warn(
            f"{path}: with scale={scale:g} the body's volume is {mesh.volume:.6g} m^3, a volume-equivalent radius "
            f"of {equivalent:.3g} m, outside the {smallest:g} m to {largest:g} m of a DEM particle; check the "
            f"file's unit and the scale argument (scale=0.001 for a file in millimetres)", RuntimeWarning,
            stacklevel=2)
    heights = mesh.cap_heights
    tall = heights > COARSE_CAP_TOLERANCE * equivalent
    if tall.any():
        worst = heights.argsort()[::-1][:3]
        named = ", ".join(f"{t} ({heights[t] / equivalent:.2g} r_eq)" for t in worst)
        warnings.warn(
            f"{path}: {tall.sum()} of {len(heights)} triangles have caps taller than the tolerance of "
            f"{COARSE_CAP_TOLERANCE:g} r_eq, up to {heights.max():.3g} m ({heights.max() / equivalent:.2g} r_eq) "
            f"beyond the surface: the mesh is too coarse there for its curvature, and the body pushes partners the "
            f"mesh does not touch; worst triangles {named}. Refine the mesh there (shorter edges, no slivers)",
            RuntimeWarning, stacklevel=2)
    return mesh


# Boost.Python's docstring starts with its own signature line and ends with the C++ one: keep the text between.
load.__doc__ = "\n".join(_load.__doc__.split("C++ signature")[0].strip().splitlines()[1:]).rstrip() + (
    "\n    Warns (RuntimeWarning) when the body's volume-equivalent radius is outside 1 um to 10 m, what a file in\n"
    "    millimetres loaded without scale=0.001 gives (roundedmesh.meshfiles.PLAUSIBLE_RADII), and when a triangle's\n"
    "    cap is taller than 0.05 r_eq (roundedmesh.meshfiles.COARSE_CAP_TOLERANCE; a mesh too coarse for its\n"
    "    curvature), naming the worst triangles (Mesh.cap_heights).\n")
