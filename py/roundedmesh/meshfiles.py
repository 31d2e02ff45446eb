"""Mesh.load with what a mesh file cannot say for itself: its unit, and whether it is fine enough for the curvature
computed from it; and a load report of what was made of it.

A mesh file carries no unit. A file in millimetres loaded without scale=0.001 gives a body 1000 times too
large (a 33 mm gummy bear becomes 36,824 m^3), which then runs, slowly and wrongly, with nothing to show for
it; a file scaled twice gives a body 1000 times too small. Mesh.load warns (RuntimeWarning) when the
volume-equivalent radius is outside PLAUSIBLE_RADII: from half a millimetre (a body under about 1 mm across, what a
file in metres scaled by 0.001, or a scale applied twice, gives; powders of finer grains are loaded all the same and
the warning can be ignored or filtered), to 10 m, above any particle (a boulder) that DEM is used for. The body is
loaded all the same: the warning is for the unit, not a refusal.

Each triangle's cap (the part of its sphere beyond its plane) is where the rounded body lies beyond the mesh, and how
far from the mesh it pushes a partner. Where the mesh is too coarse for its curvature (a sharp edge, a sliver, a coarse
scan) the caps grow to half spheres over the triangles: YADE's 12-triangle rod-coarse.stl would reach 1.6 r_eq beyond
its faces, the coarse GTS horse 0.42 r_eq (239 of its 668 triangles beyond 0.05 r_eq). With the curvature computed from the mesh,
Mesh.load (like Mesh.from_arrays) keeps every cap within `tolerance` of r_eq (default DEFAULT_TOLERANCE, 0.05: half
the Hertz depth, doc/physics.md) by raising the radius of the triangles beyond it (Mesh.bounded_caps), and says so in
one line (a RuntimeWarning). tolerance=None takes the mesh as it is and warns, naming the worst triangles, when a cap
is taller than that. Prescribed radii are the caller's: never raised, warned about likewise.

Every loaded mesh carries `mesh.load_report` (a dict: file, nodes, triangles, curvature source, tolerance, bounded
caps, deviation in m and r_eq).
"""
import math
import warnings

from ._core import DEFAULT_MESH_TOLERANCE, Mesh

PLAUSIBLE_RADII = (5e-4, 10.0)  # volume-equivalent radius [m]
DEFAULT_TOLERANCE = DEFAULT_MESH_TOLERANCE  # the tallest cap allowed, of the volume-equivalent radius (0.05)

_load = Mesh.load


def equivalent_radius(mesh):
    return (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)


def load_report(mesh, path, tolerance):
    equivalent = equivalent_radius(mesh)
    return {"file": str(path), "nodes": len(mesh.vertices), "triangles": len(mesh.triangles),
            "curvature": mesh.curvature_mode, "tolerance": tolerance, "remesh_passes": mesh.remesh_passes,
            "remesh_edge_length": mesh.remesh_edge_length, "bounded_caps": mesh.bounded_caps,
            "deviation": mesh.deviation, "deviation_req": mesh.deviation / equivalent}


def load(path, scale=1.0, radius=None, max_radius=None, fill_holes=False, tolerance=DEFAULT_TOLERANCE, remesh=True):
    mesh = _load(path, scale, radius, max_radius, fill_holes, tolerance, remesh)
    equivalent = equivalent_radius(mesh)
    smallest, largest = PLAUSIBLE_RADII
    if not smallest <= equivalent <= largest:
        warnings.warn(
            f"{path}: with scale={scale:g} the body's volume is {mesh.volume:.6g} m^3, a volume-equivalent radius "
            f"of {equivalent:.3g} m, outside the {smallest:g} m to {largest:g} m of a DEM particle; check the "
            f"file's unit and the scale argument (scale=0.001 for a file in millimetres)", RuntimeWarning,
            stacklevel=2)
    mesh.load_report = load_report(mesh, path, tolerance)
    heights = mesh.cap_heights
    if mesh.remesh_passes or mesh.bounded_caps:
        remeshed = (f"remeshed to edges of {mesh.remesh_edge_length:.3g} m ({len(mesh.vertices)} nodes, "
                    f"{len(heights)} triangles)" if mesh.remesh_passes else "")
        bounded = (f"{mesh.bounded_caps} triangles' radii raised" if mesh.bounded_caps else "")
        warnings.warn(
            f"{path}: too coarse for the curvature computed from it; {' and '.join(filter(None, (remeshed, bounded)))} "
            f"to keep the rounded body within {tolerance:g} r_eq ({tolerance * equivalent:.3g} m) of the surface "
            f"(now {mesh.deviation:.3g} m); pass tolerance=None to take the mesh as it is",
            RuntimeWarning, stacklevel=2)
        return mesh
    limit = DEFAULT_TOLERANCE if tolerance is None else tolerance
    tall = heights > limit * equivalent
    if tall.any():
        worst = heights.argsort()[::-1][:3]
        named = ", ".join(f"{t} ({heights[t] / equivalent:.2g} r_eq)" for t in worst)
        warnings.warn(
            f"{path}: {tall.sum()} of {len(heights)} triangles have caps taller than the tolerance of "
            f"{limit:g} r_eq, up to {heights.max():.3g} m ({heights.max() / equivalent:.2g} r_eq) "
            f"beyond the surface: the mesh is too coarse there for its curvature, and the body pushes partners the "
            f"mesh does not touch; worst triangles {named}. Refine the mesh there (shorter edges, no slivers)",
            RuntimeWarning, stacklevel=2)
    return mesh


# Boost.Python's docstring starts with its own signature line and ends with the C++ one: keep the text between.
load.__doc__ = "\n".join(_load.__doc__.split("C++ signature")[0].strip().splitlines()[1:]).rstrip() + (
    "\n    Warns (RuntimeWarning) when the body's volume-equivalent radius is outside 0.5 mm to 10 m, what a file in\n"
    "    millimetres loaded without scale=0.001 (or a scale applied twice) gives (roundedmesh.meshfiles.PLAUSIBLE_RADII);\n"
    "    in one line when the mesh was remeshed or its caps bounded to the tolerance; and, where the caps were not\n"
    "    prepared (tolerance=None, prescribed radius), when a triangle's cap is taller than 0.05 r_eq, naming the worst\n"
    "    triangles (Mesh.cap_heights). mesh.load_report says what was made: nodes, triangles, curvature source,\n"
    "    tolerance, remeshing passes and edge length, bounded caps, deviation.\n")
