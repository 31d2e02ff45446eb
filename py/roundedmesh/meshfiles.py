"""Mesh.load with a check that the loaded body has the size of a DEM particle.

A mesh file carries no unit. A file in millimetres loaded without scale=0.001 gives a body 1000 times too
large (a 33 mm gummy bear becomes 36,824 m^3), which then runs, slowly and wrongly, with nothing to show for
it; a file scaled twice gives a body 1000 times too small. Mesh.load warns (RuntimeWarning) when the
volume-equivalent radius is outside PLAUSIBLE_RADII: from a micrometre, below which a DEM body of continuum
Hertz contact makes little sense, to 10 m, above any particle (a boulder) that DEM is used for. The body is
loaded all the same: the warning is for the unit, not a refusal.
"""
import math
import warnings

from ._core import Mesh

PLAUSIBLE_RADII = (1e-6, 10.0)  # volume-equivalent radius [m]

_load = Mesh.load


def load(path, scale=1.0, radius=None, max_radius=None):
    mesh = _load(path, scale, radius, max_radius)
    equivalent = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    smallest, largest = PLAUSIBLE_RADII
    if not smallest <= equivalent <= largest:
        warnings.warn(
            f"{path}: with scale={scale:g} the body's volume is {mesh.volume:.6g} m^3, a volume-equivalent radius "
            f"of {equivalent:.3g} m, outside the {smallest:g} m to {largest:g} m of a DEM particle; check the "
            f"file's unit and the scale argument (scale=0.001 for a file in millimetres)", RuntimeWarning,
            stacklevel=2)
    return mesh


# Boost.Python's docstring starts with its own signature line and ends with the C++ one: keep the text between.
load.__doc__ = "\n".join(_load.__doc__.split("C++ signature")[0].strip().splitlines()[1:]).rstrip() + (
    "\n    Warns (RuntimeWarning) when the body's volume-equivalent radius is outside 1 um to 10 m, what a file in\n"
    "    millimetres loaded without scale=0.001 gives (roundedmesh.meshfiles.PLAUSIBLE_RADII).\n")
