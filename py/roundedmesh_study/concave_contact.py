"""Analytic spheres pressed into the gummy bear's concave grooves, against Hertz's elliptical solution at the smooth
shape's groove point.

    /usr/bin/python3 scripts/validation/validate_concave_contact.py [--curvature both|mean|principal]
                                                                    [--mesh-curvature both|computed|exact] [--quick]
                                                                    [--output out/concave_contact]

Grooves, found from the implicit function of shapes.json (peers._blended_distance, in shape units; the frame of
shapes.json) and printed:
    neck   the blend of the head capsule with a body capsule (the two nearest primitives; the third farther than
           the blend width k): the surface point of least smaller principal curvature k1 there, from a grid in
           azimuth (about the z axis) and height, refined along the meridian. k1 is constant within 0.1 % along
           the arcs where the head's cap sphere meets a body capsule's cap sphere (a surface of revolution), so
           of the grid points within 0.1 % of the least k1 the frontmost (largest y, then largest x) is taken.
    belly  the blend of the two body capsules on the front (+y): the point of least k1 on the horizontal
           section at the mid-height of the capsules' straight parts (z = -0.075 shape units; x = 0 by the
           mirror symmetry). k1 is the same all along the groove; there k2 = 0 (the capsules are straight).

For each groove point x (shape units) with outward normal n and principal curvatures k1 <= k2, and each mesh of
Mesh.reference_shape("gummy_bear", nodes) (scale s [m per shape unit], orientation R and centroid c: input-frame
point = R body point + c = s x), the groove is moved into the mesh's principal (body) frame, p = R^T (s x - c),
n_b = R^T n, k [1/m] = k [1/unit] / s, and checked there against peers.shape_distance (f(p) = 0, same normal and
curvatures) and against the mesh (distance from p to the nearest triangle, next to that triangle's cap height).
The mesh body is posed at POSITION turned by ORIENTATION (not the identity, so that the frames are exercised); an
analytic sphere of radius r is centred at POSITION + ORIENTATION (p + (r - delta) n_b), delta from 0 to 0.1 r.

Reference: Hertz holds only while both relative curvatures 1/r + k1, 1/r + k2 are positive; where one is not (the
sphere is wider than the groove: it first touches the groove's two flanks, away from the groove point, and no
single Hertz ellipse at the groove point answers) the model is still swept, and only whether its force is finite,
continuous and non-decreasing is reported. Where Hertz holds,
F = analytic.elliptical_hertz_force(E*, r_major, r_minor, delta) with the relative radii of
hertz_reference.relative_principal_radii((k1, k2), (1/r, 1/r), 0). Model: the force on the sphere along the
groove's outward normal, from rm.sphere_contact (frictionless, at rest), both materials E = 1 MPa, nu = 0.4.
Per (model, groove, r, mesh): F_model/F_hertz at delta = 0.1 r and analytic.nrmse over the overlaps, and the
overlap at which the model's force starts ("touch", negative where the mesh's triangles stand outside the smooth
surface: a flat face bridging the groove by about rho^2 |k1| / 2, rho its circumradius).
Continuity (full run only): the force at DENSE overlaps from -0.1 r to 0.1 r, its largest step between neighbours
against its final value ("step", % of F(0.1 r); a smooth F ~ delta^1.5 from 0 gives about 1.5 %) and its least
step ("dip", negative if it ever decreases). At delta = 0.1 r, from rm.triangle_contacts: the share of the force
carried by triangle pairs whose triangle's estimated smaller curvature k makes 1/r + k <= 0 ("saddle": no Hertz
ellipse for that pair; its quadric overlap has a saddle, not a maximum) and the largest effective overlap over its
pair's sphere overlap ("over"; at most 1 in the mean model, and in the principal model without saddle pairs).

Models (--curvature): 'mean' (the engine's default: one radius per triangle from the mean curvature; a concave
triangle is taken as flat, R = max_radius) and 'principal' (both principal curvatures per triangle,
Mesh.principal_curvatures, estimated from the mesh for a reference shape; Hertz's ellipse per triangle pair; a
concave triangle's cap is a quadric below the facet); 'both' (default) runs the two. The estimate at the groove
point is printed: Mesh.principal_curvatures of the triangle nearest the groove point against (k1, k2).

The mesh's curvatures (--mesh-curvature): 'computed' (Mesh.reference_shape(..., curvature='computed'), the paper's:
estimated from the mesh) and 'exact' (curvature='exact': the smooth shape's mean and principal curvatures from the
implicit function, prescribed per triangle); 'both' (default) runs the two. The vertices, scale and frame are the
same for both; only the per-triangle curvatures (and so the caps) differ.

Writes concave_contact.csv (every overlap), concave_contact_summary.csv (a column 'curvature' gives the model,
'mesh_curvature' the mesh's curvature source) and concave_contact.png (F/F_hertz against delta/r in the belly, per
model; the force where Hertz does not hold).
--quick: 6 overlaps and the paper's mesh only, no continuity sweep.
"""
import argparse
import math
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import minimize_scalar  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh import shapes  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402

from . import SCRIPTS, analytic, hertz_reference as hr, peers  # noqa: E402

ROOT = os.path.dirname(SCRIPTS)  # the repository
SHAPE = "gummy_bear"
RADII = (0.002, 0.010, 0.025)               # sphere radii [m]
MAX_OVERLAP = 0.1                           # deepest overlap, as a share of the sphere's radius
FULL_OVERLAPS, QUICK_OVERLAPS = 21, 6       # overlaps from 0 to MAX_OVERLAP r, both ends included
DENSE = 401                                 # overlaps from -MAX_OVERLAP r to MAX_OVERLAP r: the continuity sweep
CURVATURES = ("mean", "principal")          # the models (rm.sphere_contact's curvature=...)
MESH_CURVATURES = ("computed", "exact")     # the mesh's curvature source (Mesh.reference_shape's curvature=...)
TOUCH_REACH = 0.5                           # the touch is looked for from -TOUCH_REACH r
NEAR = 0.003                                # triangles within this of the groove point [m]: the estimate's spread
MESHES = (None, 2000)                       # node counts: the paper's (563 nodes) and a finer one
MATERIAL = {"young": 1e6, "poisson": 0.4, "density": 1000.0}
POSITION = (0.1, -0.05, 0.2)                # pose of the mesh body [m] ...
ORIENTATION_AXIS, ORIENTATION_ANGLE = (1.0, 2.0, 3.0), 0.7   # ... and its rotation (axis, angle [rad])

NECK = (2, (0, 1))                          # head capsule; body capsules (indices into shapes.json's primitives)
BELLY = (0, 1)                              # the two body capsules
BELLY_HEIGHT = -0.075                       # mid-height of the body capsules' straight parts [shape units]
TIE = 1e-3                                  # relative spread of k1 taken as equal when choosing the neck point


def _log(message):
    print(message, flush=True)


# --- the smooth shape, in shape units ----------------------------------------------------------------------

def _definition():
    return shapes.definitions()["shapes"][SHAPE]


def unit_distance(points):
    """f of shapes.json at shape-unit points (n, 3), in shape units (peers' own blend)."""
    return peers._blended_distance(_definition(), np.atleast_2d(np.asarray(points, dtype=float)))


def primitive_distances(points):
    """(primitives, n): each primitive's exact signed distance at shape-unit points (n, 3)."""
    points = np.atleast_2d(np.asarray(points, dtype=float))
    out = []
    for p in _definition()["primitives"]:
        if p["type"] == "sphere":
            out.append(np.linalg.norm(points - p["center"], axis=1) - p["radius"])
        else:
            a, b = np.array(p["a"]), np.array(p["b"])
            t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
            out.append(np.linalg.norm(points - (a + t[:, None] * (b - a)), axis=1) - p["radius"])
    return np.array(out)


def in_blend(point, first, seconds):
    """True if the two nearest primitives at `point` are `first` and one of `seconds` (or two of `seconds` when
    first is None) and the third is farther than the blend width k: a blend of two primitives only."""
    d = primitive_distances(point)[:, 0]
    order = np.argsort(d)
    pair = set(order[:2].tolist())
    wanted = ({first} <= pair and bool(pair & set(seconds))) if first is not None else pair == set(seconds)
    return wanted and d[order[2]] - d[order[0]] > _definition()["blend_k"]


def ray_surface(azimuth, height):
    """Surface points (n, 3) [shape units] reached from (0, 0, height) outwards along (cos az, sin az, 0): the
    outermost root of f on each ray, by bisection, then projected onto f = 0."""
    azimuth, height = np.broadcast_arrays(np.atleast_1d(azimuth).astype(float), np.atleast_1d(height).astype(float))
    direction = np.stack([np.cos(azimuth), np.sin(azimuth), np.zeros_like(azimuth)], axis=1)
    origin = np.stack([np.zeros_like(height), np.zeros_like(height), height], axis=1)
    lo, hi = np.zeros(len(azimuth)), np.full(len(azimuth), 2.0)     # f(origin + 2 d) > 0 everywhere
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        inside = unit_distance(origin + mid[:, None] * direction) < 0
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    return np.array([hr.project_to_surface(unit_distance, o + l * d) for o, l, d in zip(origin, lo, direction)])


def smaller_curvature(point):
    return hr.principal_curvatures(unit_distance, point)[0][0]


def _refine(azimuth, height, bounds, region):
    """Least k1 along the meridian at `azimuth`, heights within `bounds`, inside `region`."""
    def objective(z):
        p = ray_surface(azimuth, z)[0]
        return smaller_curvature(p) if region(p) else 1e6
    z = minimize_scalar(objective, bounds=bounds, method="bounded", options={"xatol": 1e-7}).x
    return z if objective(z) <= objective(height) else height


def groove(point, name):
    """Dict of a groove point (shape units): point, normal, curvatures (k1, k2) [1/unit], directions."""
    point = hr.project_to_surface(unit_distance, point)
    curvatures, directions, normal = hr.principal_curvatures(unit_distance, point)
    return {"name": name, "point": point, "normal": normal, "curvatures": curvatures, "directions": directions}


def find_neck(azimuth_step_deg=2.0, heights=np.arange(0.42, 0.54, 0.0025)):
    """The neck's groove point (module docstring)."""
    region = lambda p: in_blend(p, NECK[0], NECK[1])   # noqa: E731
    azimuths = np.radians(np.arange(0.0, 360.0, azimuth_step_deg))
    az, z = (a.ravel() for a in np.meshgrid(azimuths, heights, indexing="ij"))
    points = ray_surface(az, z)
    keep = np.array([region(p) for p in points])
    k1 = np.full(len(points), np.inf)
    k1[keep] = [smaller_curvature(p) for p in points[keep]]
    least = k1.min()
    near = np.flatnonzero(k1 <= least + TIE * abs(least))
    best = near[np.lexsort((points[near, 0], points[near, 1]))[-1]]      # largest y, then largest x
    height = _refine(az[best], z[best], (z[best] - 0.01, z[best] + 0.01), region)
    return groove(ray_surface(az[best], height)[0], "neck")


def find_belly(azimuths=np.radians(np.arange(45.0, 135.01, 0.5))):
    """The belly groove's point (module docstring)."""
    region = lambda p: in_blend(p, None, BELLY) and p[1] > 0   # noqa: E731
    points = ray_surface(azimuths, np.full(len(azimuths), BELLY_HEIGHT))
    k1 = np.array([smaller_curvature(p) if region(p) else np.inf for p in points])
    best = int(np.argmin(k1))
    step = azimuths[1] - azimuths[0]

    def objective(a):
        p = ray_surface(a, BELLY_HEIGHT)[0]
        return smaller_curvature(p) if region(p) else 1e6
    a = minimize_scalar(objective, bounds=(azimuths[best] - step, azimuths[best] + step), method="bounded",
                        options={"xatol": 1e-9}).x
    return groove(ray_surface(a, BELLY_HEIGHT)[0], "belly")


def find_grooves():
    return [find_neck(), find_belly()]


def belly_spread(point, heights=np.linspace(-0.3, 0.15, 10)):
    """(min, max) of k1 [1/unit] along the belly groove, at the groove point's x, y and `heights`."""
    k1 = [smaller_curvature(hr.project_to_surface(unit_distance, [point[0], point[1], h])) for h in heights]
    return min(k1), max(k1)


# --- the groove in a mesh's body frame ----------------------------------------------------------------------

def _rotation(q):
    m = q.toRotationMatrix()
    return np.array([[m[i, j] for j in range(3)] for i in range(3)])


def pose():
    axis = np.asarray(ORIENTATION_AXIS) / np.linalg.norm(ORIENTATION_AXIS)
    return np.asarray(POSITION, dtype=float), Quaternion(ORIENTATION_ANGLE, Vector3(*axis))


def mesh_surface_distance(mesh, point):
    """(distance [m] from `point` (body frame) to the nearest triangle of `mesh`, that triangle's index, its cap
    height [m]: |R| - sqrt(R^2 - rho^2), R its radius of curvature, rho its circumradius)."""
    v = np.asarray(mesh.vertices)
    a, b, c = (v[np.asarray(mesh.triangles)[:, i]] for i in range(3))
    distance = _point_triangle_distance(point, a, b, c)
    i = int(np.argmin(distance))
    la, lb, lc = np.linalg.norm(b[i] - c[i]), np.linalg.norm(c[i] - a[i]), np.linalg.norm(a[i] - b[i])
    area = 0.5 * np.linalg.norm(np.cross(b[i] - a[i], c[i] - a[i]))
    rho = la * lb * lc / (4 * area)
    radius = abs(float(np.asarray(mesh.radii)[i]))
    cap = radius - math.sqrt(max(radius ** 2 - rho ** 2, 0.0)) if math.isfinite(radius) else 0.0
    return float(distance[i]), i, cap, rho


def _point_triangle_distance(p, a, b, c):
    """Distances (n,) from point p to triangles (a, b, c) (rows), by the closest point of each (Ericson's
    Real-Time Collision Detection, 5.1.5), vectorised."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = np.einsum("ij,ij->i", ab, ap), np.einsum("ij,ij->i", ac, ap)
    bp, cp = p - b, p - c
    d3, d4 = np.einsum("ij,ij->i", ab, bp), np.einsum("ij,ij->i", ac, bp)
    d5, d6 = np.einsum("ij,ij->i", ab, cp), np.einsum("ij,ij->i", ac, cp)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        denom = 1.0 / (va + vb + vc)
        closest = a + ab * (vb * denom)[:, None] + ac * (vc * denom)[:, None]           # inside the face
        t_ab = d1 / (d1 - d3)
        t_ac = d2 / (d2 - d6)
        t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
    cases = [
        ((d1 <= 0) & (d2 <= 0), a),
        ((d3 >= 0) & (d4 <= d3), b),
        ((d6 >= 0) & (d5 <= d6), c),
        ((vc <= 0) & (d1 >= 0) & (d3 <= 0), a + ab * t_ab[:, None]),
        ((vb <= 0) & (d2 >= 0) & (d6 <= 0), a + ac * t_ac[:, None]),
        ((va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0), b + (c - b) * t_bc[:, None]),
    ]
    done = np.zeros(len(a), dtype=bool)
    result = closest.copy()
    for mask, value in cases:
        take = mask & ~done
        result[take] = value[take]
        done |= mask
    return np.linalg.norm(result - p, axis=1)


def in_body_frame(g, nodes, mesh_curvature="computed"):
    """The groove `g` in the body frame of Mesh.reference_shape(SHAPE, nodes, mesh_curvature), checked: a dict with
    the mesh, scale, point p [m], normal n_b, curvatures [1/m], the implicit function's value and curvatures there
    through peers.shape_distance, and the distance to the mesh with the nearest triangle's cap height."""
    mesh, scale, rotation, centroid = peers.body_frame(SHAPE, nodes, mesh_curvature)
    point = rotation.T @ (scale * g["point"] - centroid)
    normal = rotation.T @ g["normal"]
    curvatures = g["curvatures"] / scale
    distance = lambda x: peers.shape_distance(SHAPE, x, nodes)   # noqa: E731
    check_k, _, check_n = hr.principal_curvatures(distance, point)
    mesh_distance, triangle, cap, rho = mesh_surface_distance(mesh, point)
    estimated = np.sort(np.asarray(mesh.principal_curvatures), axis=1)     # (k_small, k_big) per triangle [1/m]
    v = np.asarray(mesh.vertices)
    near = np.linalg.norm(v[np.asarray(mesh.triangles)].mean(axis=1) - point, axis=1) < NEAR
    return {"estimated": tuple(estimated[triangle]),
            "estimated_near": (estimated[near, 0].min(), estimated[near, 0].max(), int(near.sum())),
            "mesh": mesh, "nodes": len(mesh.vertices), "mesh_curvature": mesh_curvature, "scale": scale, "point": point, "normal": normal,
            "curvatures": curvatures, "f": float(distance(point[None])[0]),
            "curvature_check": float(np.max(np.abs(check_k - curvatures) / np.max(np.abs(curvatures)))),
            "normal_check": float(np.linalg.norm(check_n - normal)), "mesh_distance": mesh_distance,
            "triangle": triangle, "cap_height": cap, "triangle_radius": float(np.asarray(mesh.radii)[triangle]),
            "sagitta": rho ** 2 * float(np.max(np.abs(curvatures))) / 2}


# --- pressing a sphere into the groove ----------------------------------------------------------------------

def hertz_radii(curvatures, radius):
    """(r_major, r_minor) [m] of the sphere of `radius` [m] in a groove of principal curvatures [1/m], or None if
    a relative curvature 1/r + k_i is not positive (Hertz does not hold)."""
    if min(1.0 / radius + k for k in curvatures) <= 0:
        return None
    return hr.relative_principal_radii(tuple(curvatures), (1.0 / radius, 1.0 / radius), 0.0)


def press(frame, radius, overlaps, curvature="mean"):
    """Model force [N] on the sphere along the groove's outward normal at each overlap [m]."""
    material = rm.HertzMaterial(**MATERIAL)
    position, orientation = pose()
    rotation = _rotation(orientation)
    normal = rotation @ frame["normal"]
    options = {} if curvature == "mean" else {"curvature": curvature}
    forces = []
    for delta in overlaps:
        centre = position + rotation @ (frame["point"] + (radius - delta) * frame["normal"])
        result = rm.sphere_contact(frame["mesh"], Vector3(*position), orientation, Vector3(*centre), radius,
                                   material, material, **options)
        forces.append(float(np.dot(np.array(result[2]), normal)))
    return np.array(forces)


def pair_check(frame, radius, overlap, curvature="mean"):
    """(share of the normal force carried by triangle pairs whose triangle's estimated smaller principal curvature
    k makes 1/r + k <= 0 (no Hertz ellipse: the quadric overlap has a saddle, not a maximum), the largest
    effective overlap over its pair's sphere overlap) at `overlap`, from rm.triangle_contacts."""
    position, orientation = pose()
    centre = position + _rotation(orientation) @ (frame["point"] + (radius - overlap) * frame["normal"])
    material = rm.HertzMaterial(**MATERIAL)
    options = {} if curvature == "mean" else {"curvature": curvature}
    pairs = rm.triangle_contacts(frame["mesh"], Vector3(*position), orientation, radius, Vector3(*centre),
                                 orientation, material, material, **options)
    force = np.asarray(pairs["normal_force"])
    if force.size == 0:
        return 0.0, 0.0
    smaller = np.min(np.asarray(frame["mesh"].principal_curvatures), axis=1)[np.asarray(pairs["triangle1"])]
    return (float(force[smaller + 1.0 / radius <= 0].sum() / force.sum()),
            float(np.max(np.asarray(pairs["effective_overlap"]) / np.asarray(pairs["sphere_overlap"]))))


def touch_overlap(frame, radius, curvature="mean", iterations=40, reach=TOUCH_REACH):
    """The overlap delta [m] (measured from the smooth surface's groove point) at which the model's force first
    becomes positive, by bisection in [-reach r, MAX_OVERLAP r] (-inf if it is positive already at -reach r):
    negative where the mesh stands outside the smooth groove (its triangles bridge it), or where the sphere is
    wider than the groove and touches its flanks first."""
    lo, hi = -reach * radius, MAX_OVERLAP * radius
    if press(frame, radius, [lo], curvature)[0] > 0:
        return -math.inf
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if press(frame, radius, [mid], curvature)[0] > 0 else (mid, hi)
    return hi


def case(g, frame, radius, count, curvature="mean", dense=0):
    """One (model, groove, radius, mesh) sweep: a dict with the overlaps and model forces, the touch, and where
    Hertz holds the reference forces, F/F_hertz at the deepest overlap and the NRMSE (else 'skipped' says why);
    with dense > 0 also the continuity sweep's largest and least step."""
    k1, k2 = frame["curvatures"]
    out = {"curvature": curvature, "mesh_curvature": frame["mesh_curvature"], "groove": g["name"], "radius": radius,
           "nodes": frame["nodes"], "k1": k1, "k2": k2, "relative": (1.0 / radius + k1, 1.0 / radius + k2)}
    overlaps = np.linspace(0.0, MAX_OVERLAP * radius, count)
    model = press(frame, radius, overlaps, curvature)
    saddle, overshoot = pair_check(frame, radius, overlaps[-1], curvature)
    out.update(overlaps=overlaps, model=model, touch=touch_overlap(frame, radius, curvature), saddle=saddle,
               overshoot=overshoot,
               finite=bool(np.all(np.isfinite(model))), non_decreasing=bool(np.all(np.diff(model) >= 0)))
    if dense:
        forces = press(frame, radius, np.linspace(-MAX_OVERLAP * radius, MAX_OVERLAP * radius, dense), curvature)
        steps = np.diff(forces)
        out.update(step=float(steps.max() / forces[-1]), dip=float(steps.min() / forces[-1]),
                   finite=out["finite"] and bool(np.all(np.isfinite(forces))))
    radii = hertz_radii(frame["curvatures"], radius)
    if radii is None:
        out["skipped"] = f"1/r + k1 = {1.0 / radius + k1:.1f} 1/m <= 0: Hertz does not hold"
        return out
    modulus = analytic.effective_modulus(rm.HertzMaterial(**MATERIAL), rm.HertzMaterial(**MATERIAL))
    reference = hr.reference_force(modulus, radii[0], radii[1], overlaps)
    out.update(r_major=radii[0], r_minor=radii[1], reference=reference, ratio=model[-1] / reference[-1],
               nrmse=analytic.nrmse(model, reference))
    estimated = hertz_radii(frame["estimated"], radius)     # Hertz with the nearest triangle's estimate instead
    if estimated is not None:
        out["estimate_effect"] = hr.reference_force(modulus, *estimated, overlaps[-1:])[0] / reference[-1]
    return out


def run(quick=False, curvature="mean", grooves=None, meshes=None, dense=None, mesh_curvature="computed"):
    """Every case: (grooves, frames {(groove, nodes, mesh_curvature): frame}, cases). `curvature` is a model or a
    sequence of them, `mesh_curvature` a curvature source of the mesh or a sequence of them; meshes defaults to
    MESHES (the paper's only if quick), dense to DENSE (0 if quick)."""
    grooves = find_grooves() if grooves is None else grooves
    models = (curvature,) if isinstance(curvature, str) else tuple(curvature)
    sources = (mesh_curvature,) if isinstance(mesh_curvature, str) else tuple(mesh_curvature)
    count = QUICK_OVERLAPS if quick else FULL_OVERLAPS
    meshes = (MESHES[:1] if quick else MESHES) if meshes is None else meshes
    dense = (0 if quick else DENSE) if dense is None else dense
    frames, cases = {}, []
    for g in grooves:
        for nodes in meshes:
            for source in sources:
                frame = frames[g["name"], nodes, source] = in_body_frame(g, nodes, source)
                for model in models:
                    for radius in RADII:
                        cases.append(case(g, frame, radius, count, model, dense))
    return grooves, frames, cases


# --- output ---------------------------------------------------------------------------------------------------

def report_grooves(grooves, frames):
    for g in grooves:
        k1, k2 = g["curvatures"]
        _log(f"{g['name']}: x = ({', '.join(f'{c:.5f}' for c in g['point'])}) shape units, n = "
             f"({', '.join(f'{c:.4f}' for c in g['normal'])}), k1, k2 = {k1:.4f}, {k2:.4f} 1/unit "
             f"(radii {1 / k1:.4f}, {1 / k2 if k2 else math.inf:.4f} units)")
        if g["name"] == "belly":
            low, high = belly_spread(g["point"])
            _log(f"  k1 along the belly groove (z = -0.3 to 0.15): {low:.5f} to {high:.5f} 1/unit")
        for (name, nodes, source), f in frames.items():
            if name != g["name"]:
                continue
            if source != "computed" and (name, nodes, "computed") in frames:
                _log(f"  {f['nodes']} nodes, mesh curvature {source!r}: Mesh.principal_curvatures there "
                     f"{f['estimated'][0]:.1f}, {f['estimated'][1]:.1f} 1/m "
                     f"(k1 {f['estimated'][0] / f['curvatures'][0]:.0%} of the smooth shape's at the groove point)")
                continue
            _log(f"  {f['nodes']} nodes, mesh curvature {source!r}: s = {f['scale'] * 1e3:.4f} mm/unit, body-frame point "
                 f"({', '.join(f'{c * 1e3:.3f}' for c in f['point'])}) mm, k1, k2 = {f['curvatures'][0]:.1f}, "
                 f"{f['curvatures'][1]:.1f} 1/m; f there {f['f']:.1e} m, curvatures within "
                 f"{f['curvature_check']:.1e}, normal within {f['normal_check']:.1e} of peers.shape_distance's; "
                 f"distance to the mesh {f['mesh_distance'] * 1e3:.3f} mm (nearest triangle {f['triangle']}: "
                 f"R = {f['triangle_radius'] * 1e3:.1f} mm, cap height {f['cap_height'] * 1e3:.3f} mm; a flat face "
                 f"of circumradius rho bridging the groove stands off by up to rho^2 max|k| / 2 = "
                 f"{f['sagitta'] * 1e3:.3f} mm)")
            low, high, count = f["estimated_near"]
            _log(f"    Mesh.principal_curvatures there: {f['estimated'][0]:.1f}, {f['estimated'][1]:.1f} 1/m "
                 f"(k1 {f['estimated'][0] / f['curvatures'][0]:.0%} of the smooth shape's); smaller one "
                 f"{low:.1f} to {high:.1f} 1/m over the {count} triangles within {NEAR * 1e3:g} mm")


def _touch(c):
    return f"{c['touch'] * 1e3:9.4f}" if math.isfinite(c["touch"]) else f"{f'< -{TOUCH_REACH:g}r':>9}"


def report_cases(cases):
    _log(f"{'model':9} {'mesh':8} {'groove':6} {'r[mm]':>5} {'nodes':>5} {'1/r+k1':>8} {'1/r+k2':>8} {'r_maj[mm]':>9} "
         f"{'r_min[mm]':>9} {'F/F_hertz':>9} {'NRMSE[%]':>8} {'touch[mm]':>9} {'F(0.1r)[N]':>10} {'step[%]':>7} "
         f"{'dip[%]':>7} {'saddle':>6} {'over':>5} {'est.':>6}")
    for c in cases:
        head = (f"{c['curvature']:9} {c['mesh_curvature']:8} {c['groove']:6} {c['radius'] * 1e3:5.0f} {c['nodes']:5d} {c['relative'][0]:8.1f} "
                f"{c['relative'][1]:8.1f}")
        tail = (f"{_touch(c)} {c['model'][-1]:10.4g} {100 * c.get('step', math.nan):7.2f} "
                f"{100 * c.get('dip', math.nan):7.2f} {c['saddle']:6.1%} {c['overshoot']:5.2f}")
        if "skipped" in c:
            _log(f"{head} {'':9} {'':9} {'':9} {'':8} {tail}  no Hertz; finite {c['finite']}, non-decreasing "
                 f"{c['non_decreasing']}")
        else:
            _log(f"{head} {c['r_major'] * 1e3:9.3f} {c['r_minor'] * 1e3:9.3f} {c['ratio']:9.4f} "
                 f"{100 * c['nrmse']:8.3f} {tail} {c.get('estimate_effect', math.nan):6.3f}")
    _log("mesh: the mesh's curvature source (computed: estimated from the mesh; exact: the smooth shape's). est.: "
         "F_hertz with the nearest triangle's curvatures over F_hertz, at delta = 0.1 r")


def write_outputs(output, cases):
    os.makedirs(output, exist_ok=True)
    rows, summary = [], []
    for c in cases:
        common = [c["curvature"], c["mesh_curvature"], c["groove"], c["radius"], c["nodes"], c["k1"], c["k2"]]
        checks = [c["touch"], c["model"][-1], c.get("step", ""), c.get("dip", ""), int(c["finite"]),
                  int(c["non_decreasing"]), c["saddle"], c["overshoot"]]
        if "skipped" in c:
            summary.append(common + ["", "", "", ""] + checks + [c["skipped"]])
        else:
            summary.append(common + [c["r_major"], c["r_minor"], c["ratio"], c["nrmse"]] + checks + [""])
        reference = c.get("reference", [math.nan] * len(c["overlaps"]))
        for d, m, r in zip(c["overlaps"], c["model"], reference):
            rows.append(common[:5] + [d, d / c["radius"], m, "" if math.isnan(r) else r, m / r if r > 0 else ""])
    write_csv(os.path.join(output, "concave_contact.csv"),
              ["curvature", "mesh_curvature", "groove", "radius_m", "nodes", "overlap_m", "overlap_over_r", "force_model_N",
               "force_hertz_N", "ratio"], rows)
    write_csv(os.path.join(output, "concave_contact_summary.csv"),
              ["curvature", "mesh_curvature", "groove", "radius_m", "nodes", "k1_per_m", "k2_per_m", "r_major_m", "r_minor_m",
               "ratio_at_deepest", "nrmse", "touch_overlap_m", "force_at_deepest_N", "largest_step_share",
               "least_step_share", "finite", "non_decreasing", "saddle_force_share",
               "largest_effective_over_sphere_overlap", "skipped"], summary)
    models = list(dict.fromkeys(c["curvature"] for c in cases))
    figure, axes = plt.subplots(1, len(models) + 1, figsize=(5.5 * (len(models) + 1), 4.2), squeeze=False)
    colours = {r: f"C{i}" for i, r in enumerate(RADII)}
    markers = {"computed": "o", "exact": "x"}
    for ax, model in zip(axes[0], models):
        for c in cases:
            if c["curvature"] != model or "skipped" in c:
                continue
            d = c["overlaps"][1:]
            ax.plot(d / c["radius"], c["model"][1:] / c["reference"][1:], marker=markers[c["mesh_curvature"]], ms=3,
                    color=colours[c["radius"]], ls="-" if c["nodes"] < 1000 else "--",
                    label=f"{c['groove']}, r = {c['radius'] * 1e3:g} mm, {c['nodes']} nodes, "
                          f"{c['mesh_curvature']} k")
        ax.axhspan(0.9, 1.1, color="0.9", zorder=0)
        ax.set_yscale("log")
        ax.set_xlim(0, MAX_OVERLAP * 1.05)
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set_xlabel("delta / r")
        ax.set_ylabel("F_model / F_hertz")
        ax.set_title(f"where Hertz holds, curvature = '{model}'")
        ax.legend(fontsize=7)
    ax = axes[0][-1]
    for c in cases:
        if "skipped" not in c:
            continue
        ax.plot(c["overlaps"] / c["radius"], c["model"], ls="-" if c["curvature"] == "principal" else ":",
                marker=("s" if c["groove"] == "neck" else "^") if c["mesh_curvature"] == "computed" else
                ("x" if c["groove"] == "neck" else "+"), ms=3, color=colours[c["radius"]],
                alpha=1.0 if c["nodes"] < 1000 else 0.5,
                label=f"{c['curvature']}, {c['groove']}, r = {c['radius'] * 1e3:g} mm, {c['nodes']} nodes, "
                      f"{c['mesh_curvature']} k")
    ax.set_yscale("log")
    ax.set_xlabel("delta / r (from the groove point)")
    ax.set_ylabel("F_model [N]")
    ax.set_title("where Hertz does not hold (1/r + k1 <= 0)")
    ax.legend(fontsize=4, ncol=2)
    figure.tight_layout()
    figure.savefig(os.path.join(output, "concave_contact.png"), dpi=130)
    plt.close(figure)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--curvature", default="both", choices=("both",) + CURVATURES,
                        help="the model(s): rm.sphere_contact's curvature=...; 'both' (default) runs the two")
    parser.add_argument("--mesh-curvature", default="both", choices=("both",) + MESH_CURVATURES,
                        help="the mesh's curvatures: Mesh.reference_shape's curvature=... ('computed': estimated "
                             "from the mesh; 'exact': the smooth shape's); 'both' (default) runs the two")
    parser.add_argument("--quick", action="store_true", help=f"{QUICK_OVERLAPS} overlaps, the paper's mesh only")
    parser.add_argument("--output", default=os.path.join(ROOT, "out", "concave_contact"))
    args = parser.parse_args(argv)
    start = time.time()
    models = CURVATURES if args.curvature == "both" else (args.curvature,)
    sources = MESH_CURVATURES if args.mesh_curvature == "both" else (args.mesh_curvature,)
    grooves, frames, cases = run(args.quick, models, mesh_curvature=sources)
    report_grooves(grooves, frames)
    report_cases(cases)
    write_outputs(args.output, cases)
    _log(f"wrote {args.output}/concave_contact.csv, concave_contact_summary.csv, concave_contact.png "
         f"({time.time() - start:.1f} s)")
    return cases
