"""Body-body validation scenes of doc/scenes.md (paper Sections 3.1.1 and 3.2, Figs. 3, 7 and 8): two
rounded bodies pressed together along the global z axis, force against overlap, compared with Hertz. Values
the scene list leaves open are ours and marked (ours); doc/validation.md lists them.

The pressing geometry, shared by every scene:
    pressed_pair(mesh1, mesh2, overlaps, material, orientation1, orientation2, extents=...) -> forces [N]
    pressed_on_sphere(mesh, radius, overlaps, material, orientation, extent=...) -> forces [N]
    pair_poses(count, seed), axis_poses(count, seed)   the relative mesh poses each error is judged over

S2 pair -- two meshed unit spheres pressed together (the body-body analogue of Fig. 3), and a meshed unit
sphere pressed against an analytic unit sphere; E* = 0.5 Pa, R* = R/2, overlap 0 to 5 % of R:
    PAIR_MATERIAL, PAIR_MODULUS, PAIR_OVERLAPS, SPHERE_RADIUS
    sphere_pair(subdivisions, partner="mesh" | "sphere", poses=6, seed=1) -> PairSweep

S5 -- non-spherical curvature (Section 3.2):
    S5_RATIOS, S5_SEMI_MINOR, S5_MAX_OVERLAP
    spheroid_mesh(ratio, nodes), spheroid_pair(ratio, nodes=2562, poses=3, seed=1) -> SpheroidSweep (Fig. 7)
    spheroid_mean_radius(ratio)
    S5_CROSSING_ANGLES, spheroid_relative_radii(ratio, angle), spheroid_pair(ratio, ..., angle=phi)
                                             crossed spheroids: long axes at phi in the contact plane (issue 13)
    spheroid_pair(ratio, ..., mesh_curvature="computed")   curvatures estimated from the mesh
    engine_options of every sweep go to the contact (gamma, regime, curvature="mean" | "principal")
    CYLINDER_RADIUS, CYLINDER_LENGTH, CYLINDER_OVERLAPS
    cylinder_mesh(nodes), cylinder_pair("crossed" | "parallel", nodes, poses, seed) -> CylinderSweep (Fig. 8)
    linear_fit(overlaps, forces) -> (slope [N/m], intercept [N]), power_law_exponent(overlaps, forces)

Hertz is meant to hold down to an overlap of DEEPEST_OVERLAP times the smaller body's volume-equivalent radius
(kDeepestOverlap, pkg/engine/ContactModel.hpp): search_limit(mesh1, mesh2) [m]. The engine's triangle pair search
once stopped there; it no longer does (doc/physics.md, "Which triangle pairs touch"), but sweeps that go deeper (S5
spheroids of ratio >= 2.5 at 7.5 % of a) still also report their errors over the overlaps within it (`in_range`,
`errors_in_range`), as the tables of doc/validation.md were made.

Every sweep holds the overlaps [m], the model forces per pose [N] (one row per pose) and the analytic
references [N]; NRMSE is analytic.nrmse per pose. Meshes are cached: build them once per process.
"""
import functools
import math
from dataclasses import dataclass, field

import numpy as np
from yade.minieigenHP import Quaternion, Vector3

from roundedmesh import HertzMaterial, Mesh
from roundedmesh._core import DEEPEST_OVERLAP
from roundedmesh.contact import body_contact, sphere_contact

from .analytic import (approximate_elliptical_hertz_force, elliptical_hertz_force, hertz_force, nrmse,
                       parallel_cylinders_force, spheroid_equator_radii)
from .hertz_reference import relative_principal_radii

# --- pressing two bodies together -----------------------------------------------------------------------

_AXES = np.eye(3)

# DEEPEST_OVERLAP (kDeepestOverlap of pkg/engine/ContactModel.hpp): the triangle pair search margin, as a fraction of
# the smaller body's volume-equivalent radius.


def equivalent_radius(mesh):
    """Radius [m] of the sphere with the volume of the closed triangulated surface `mesh`."""
    v = np.asarray(mesh.vertices)[np.asarray(mesh.triangles)]
    volume = np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum() / 6.0
    return (3.0 * volume / (4.0 * math.pi)) ** (1.0 / 3.0)


def search_limit(mesh1, mesh2):
    """Deepest overlap [m] the engine's triangle pair search is sure to find between two rounded bodies:
    DEEPEST_OVERLAP times the smaller volume-equivalent radius. (Against an analytic sphere every triangle is
    tested, without a limit.)"""
    return DEEPEST_OVERLAP * min(equivalent_radius(mesh1), equivalent_radius(mesh2))


def _extent(mesh, orientation, direction):
    """max over the nodes of (orientation * node) . direction [m]: how far the turned mesh reaches along
    `direction` from its position."""
    rotation = np.array([[orientation.toRotationMatrix()[i, j] for j in range(3)] for i in range(3)])
    return float(np.max(np.asarray(mesh.vertices) @ rotation.T @ direction))


def pressed_pair(mesh1, mesh2, overlaps, material, orientation1=Quaternion.Identity,
                 orientation2=Quaternion.Identity, extents=None, material2=None, axis=2, **engine_options):
    """Normal force [N] between two rounded bodies pressed together along the global `axis` (0, 1, 2 = x, y, z)
    by each of `overlaps` [m]: body 1 (`mesh1` turned by `orientation1`) sits at the origin, body 2 at
    (h1 + h2 - delta) along the axis, so that the surfaces just touch at delta = 0. h1, h2 = `extents` [m] are
    how far body 1 reaches towards body 2 and body 2 back towards body 1 (give the analytic ones, e.g. R and
    R for two spheres); by default the mesh nodes' reach. Returns the force on body 2 along +axis, which is
    positive when the bodies repel. material2 defaults to material; engine_options are body_contact's gamma,
    regime and curvature ('mean' or 'principal')."""
    direction = _AXES[axis]
    if extents is None:
        extents = (_extent(mesh1, orientation1, direction), _extent(mesh2, orientation2, -direction))
    material2 = material if material2 is None else material2
    forces = []
    for overlap in overlaps:
        position = Vector3(*(direction * (extents[0] + extents[1] - overlap)))
        force = body_contact(mesh1, Vector3(0, 0, 0), orientation1, mesh2, position, orientation2, material,
                             material2, **engine_options)[2]
        forces.append(force[axis])
    return np.array(forces)


def pressed_on_sphere(mesh, radius, overlaps, material, orientation=Quaternion.Identity, extent=None,
                      sphere_material=None, axis=2, **engine_options):
    """Normal force [N] between a rounded body (`mesh` turned by `orientation`, at the origin) and an analytic
    sphere of `radius` [m] centred at (h + radius - delta) along the global `axis`, for each of `overlaps` [m];
    h = `extent` is the body's analytic reach along the axis [m] (default: its nodes'). Returns the force on
    the sphere along +axis (positive when they repel). sphere_material defaults to material."""
    direction = _AXES[axis]
    if extent is None:
        extent = _extent(mesh, orientation, direction)
    sphere_material = material if sphere_material is None else sphere_material
    forces = []
    for overlap in overlaps:
        centre = Vector3(*(direction * (extent + radius - overlap)))
        force = sphere_contact(mesh, Vector3(0, 0, 0), orientation, centre, radius, material, sphere_material,
                               **engine_options)[2]
        forces.append(force[axis])
    return np.array(forces)


def _random_rotation(rng):
    q = Quaternion(*rng.normal(size=4))
    q.normalize()
    return q


def pair_poses(count=6, seed=1):
    """(orientation1, orientation2) pairs: both bodies in their own frames, then `count` - 1 pairs of
    independent uniformly random rotations (seeded). For bodies whose geometry does not depend on the
    orientation (spheres): the error depends on how the two meshes meet, so it is judged over several poses."""
    rng = np.random.default_rng(seed)
    yield Quaternion.Identity, Quaternion.Identity
    for _ in range(count - 1):
        yield _random_rotation(rng), _random_rotation(rng)


def axis_poses(count=3, seed=1):
    """(angle1, angle2) [rad]: 0, 0, then `count` - 1 pairs of uniformly random angles (seeded), by which each
    body of a spheroid or cylinder pair is turned about its own axis of symmetry -- the geometry stays, the
    way the two meshes meet changes."""
    rng = np.random.default_rng(seed)
    yield 0.0, 0.0
    for _ in range(count - 1):
        yield tuple(rng.uniform(0, 2 * math.pi, size=2))


def _long_axis(mesh):
    """Index (0, 1, 2) of the principal axis along which the mesh is longest."""
    vertices = np.asarray(mesh.vertices)
    return int(np.argmax(vertices.max(axis=0) - vertices.min(axis=0)))


def aligned(mesh, target, angle=0.0):
    """Orientation that turns the mesh's long axis onto the global axis `target` (0, 1, 2), then turns the
    body by `angle` [rad] about that axis."""
    source = _long_axis(mesh)
    base = Quaternion.Identity
    if source != target:
        base = Quaternion(Vector3(*np.cross(_AXES[source], _AXES[target])), math.pi / 2)
    return Quaternion(Vector3(*_AXES[target]), angle) * base


@dataclass
class PairSweep:
    """A force-indentation sweep over several poses: overlaps [m], forces [N] (poses x overlaps), reference
    [N], with the NRMSE of each pose against `reference` (analytic.nrmse), over the whole sweep (`errors`) and
    over the overlaps up to `limit` [m], the engine's search_limit (`in_range`, `errors_in_range`)."""
    overlaps: np.ndarray
    forces: np.ndarray
    reference: np.ndarray
    limit: float = math.inf
    errors: np.ndarray = field(init=False)
    in_range: np.ndarray = field(init=False)
    errors_in_range: np.ndarray = field(init=False)

    def __post_init__(self):
        self.forces = np.atleast_2d(self.forces)
        self.errors = np.array([nrmse(f, self.reference) for f in self.forces])
        self.in_range = self.overlaps <= self.limit
        self.errors_in_range = np.array([nrmse(f[self.in_range], self.reference[self.in_range]) for f in self.forces])

    def increasing(self, in_range_only=False):
        """Per pose: whether the force rises strictly from each overlap to the next (over the whole sweep, or
        only up to the search limit)."""
        keep = self.in_range if in_range_only else np.ones_like(self.in_range)
        return np.array([bool(np.all(np.diff(f[keep]) > 0)) for f in self.forces])

    @property
    def worst(self):
        """Largest NRMSE over the poses, whole sweep [-]."""
        return float(self.errors.max())

    @property
    def mean(self):
        """Mean NRMSE over the poses, whole sweep [-]."""
        return float(self.errors.mean())


# --- S2 pair: two meshed spheres, and a meshed sphere against an analytic one ---------------------------

# Both bodies E = 1 Pa, nu = 0 (the convention of scenes.S2_MATERIAL for each body): E* = 0.5 Pa (Eq. 3).
PAIR_MATERIAL = HertzMaterial(young=1.0, poisson=0.0, density=1.0)
PAIR_MODULUS = 0.5
SPHERE_RADIUS = 1.0
# total overlap delta = 2 R - centre distance, 50 values up to 5 % of R as scenes.S2_OVERLAPS (ours for pairs)
PAIR_OVERLAPS = np.linspace(0, 0.05, 51)[1:] * SPHERE_RADIUS


@functools.lru_cache(maxsize=None)
def icosphere_mesh(subdivisions, curvature="exact"):
    """The unit icosphere of `subdivisions` (1, 2, 3, 4: 42, 162, 642, 2562 nodes), cached."""
    return Mesh.icosphere(SPHERE_RADIUS, subdivisions, curvature=curvature)


def sphere_pair(subdivisions, partner="mesh", poses=6, seed=1, **engine_options):
    """S2 pair: a meshed unit sphere pressed against an identical one (partner="mesh") or against an analytic
    unit sphere (partner="sphere"), at PAIR_OVERLAPS, over `poses` of pair_poses (the analytic sphere has
    no orientation; the mesh takes the first orientation of each pair). Reference: Hertz with E* = 0.5 Pa,
    R* = R/2 (Eq. 6). Returns a PairSweep."""
    mesh = icosphere_mesh(subdivisions)
    forces = []
    for q1, q2 in pair_poses(poses, seed):
        if partner == "mesh":
            forces.append(pressed_pair(mesh, mesh, PAIR_OVERLAPS, PAIR_MATERIAL, q1, q2,
                                       extents=(SPHERE_RADIUS, SPHERE_RADIUS), **engine_options))
        elif partner == "sphere":
            forces.append(pressed_on_sphere(mesh, SPHERE_RADIUS, PAIR_OVERLAPS, PAIR_MATERIAL, q1,
                                            extent=SPHERE_RADIUS, **engine_options))
        else:
            raise ValueError(f"partner must be 'mesh' or 'sphere', got {partner!r}")
    reference = hertz_force(PAIR_MODULUS, SPHERE_RADIUS / 2, PAIR_OVERLAPS)
    return PairSweep(PAIR_OVERLAPS, np.array(forces), reference, 
                     search_limit(mesh, mesh) if partner == "mesh" else math.inf)


# --- S5 spheroids (Fig. 7) ------------------------------------------------------------------------------

# Ratios R_max/R_min of the principal radii of curvature at the contact point (the paper's "a/b" of Fig. 7 are
# radii of curvature). Two identical prolate spheroids with semi-axes a (along the axis) and b, b, long axes
# parallel, touching at their equators: R_max/R_min = (a/b)^2, so a = sqrt(ratio) b. We keep b fixed (ours):
# the smaller radius of curvature, b, and the reach along the pressing axis stay the same for every ratio;
# the volume grows as sqrt(ratio).
S5_RATIOS = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0)
S5_SEMI_MINOR = 1.0                     # b [m]
S5_MAX_OVERLAP = 0.075                  # of the long semi-axis a (scenes.md: 7.5 % of a)
S5_SAMPLES = 50


@functools.lru_cache(maxsize=None)
def spheroid_mesh(ratio, nodes=2562, curvature="exact"):
    """Prolate spheroid with R_max/R_min = `ratio` at the equator: semi-axes a = sqrt(ratio) b along its axis,
    b = S5_SEMI_MINOR across, about `nodes` nodes, curvatures 'exact' or 'computed' (Mesh.spheroid); cached
    (meshing takes 0.4 s at 642 nodes, 2.3 s at 2562)."""
    return Mesh.spheroid(math.sqrt(ratio) * S5_SEMI_MINOR, S5_SEMI_MINOR, nodes, curvature=curvature)


@dataclass
class SpheroidSweep(PairSweep):
    """S5 spheroid pair (long axes at `angle` [rad]): PairSweep against the exact elliptical Hertz force, plus the
    reference the paper's circular model is built to reproduce, circular Hertz with each body's mean radius of
    curvature 1/H at the equator (`circular`, error `circular_errors`), and Hale-type approximation
    (`approximate`)."""
    ratio: float = 1.0
    nodes: int = 0
    angle: float = 0.0
    circular: np.ndarray = None
    approximate: np.ndarray = None
    circular_errors: np.ndarray = field(init=False)

    def __post_init__(self):
        super().__post_init__()
        self.circular_errors = np.array([nrmse(f, self.circular) for f in self.forces])

    @property
    def model_error(self):
        """NRMSE of circular Hertz (mean curvature) against exact elliptical Hertz: the error the circular-
        contact model makes even on a perfect mesh."""
        return nrmse(self.circular, self.reference)


def spheroid_mean_radius(ratio):
    """1/H [m], H the mean curvature at the equator of spheroid_mesh(ratio): (1/R_meridian + 1/R_around)/2."""
    meridian, around = spheroid_equator_radii(math.sqrt(ratio) * S5_SEMI_MINOR, S5_SEMI_MINOR)
    return 2.0 / (1.0 / meridian + 1.0 / around)


# Crossed spheroid pairs (issue 13, ours): the same two spheroids with the long axis of body 2 turned by phi
# about the pressing axis, in the contact plane. phi = 0 is Fig. 7's parallel pair; at phi = 90 deg the relative
# curvature is the same in every direction (a circular contact whatever the ratio).
S5_CROSSING_ANGLES = (math.pi / 4, math.pi / 2)     # [rad]


def spheroid_relative_radii(ratio, angle=0.0):
    """(r_major, r_minor) [m]: relative principal radii of two spheroid_mesh(ratio) bodies touching at their
    equators with long axes at `angle` [rad] in the contact plane (hertz_reference.relative_principal_radii of
    each body's equator curvatures (1/R_meridian, 1/R_around), the meridian direction being the long axis). At
    angle 0 these are analytic.spheroid_pair_radii: (a^2/(2b), b/2)."""
    meridian, around = spheroid_equator_radii(math.sqrt(ratio) * S5_SEMI_MINOR, S5_SEMI_MINOR)
    curvatures = (1.0 / meridian, 1.0 / around)
    return relative_principal_radii(curvatures, curvatures, angle)


def spheroid_pair(ratio, nodes=2562, poses=3, seed=1, angle=0.0, mesh_curvature="exact", max_overlap=None,
                  **engine_options):
    """S5: two identical prolate spheroids (spheroid_mesh(ratio, nodes, mesh_curvature): 'exact', curvatures
    prescribed, or 'computed', both principal curvatures estimated from the mesh), the long axis of body 1 along x
    and that of body 2 at `angle` [rad] from it about z (0: parallel, Fig. 7; S5_CROSSING_ANGLES: crossed), pressed
    together along z at their equators, overlap delta = 2 b - centre distance from 0 to max_overlap [m] (default
    S5_MAX_OVERLAP a) in S5_SAMPLES steps, each body turned about its own axis by the angles of
    axis_poses(poses, seed). engine_options go to body_contact (gamma, regime, curvature). References with
    E* = 0.5 Pa: exact elliptical Hertz with the pair's relative radii (spheroid_relative_radii; (a^2/(2b), b/2)
    parallel); circular Hertz with R* = 1/(2H), whatever the angle. Returns a SpheroidSweep."""
    mesh = spheroid_mesh(ratio, nodes, mesh_curvature)
    a, b = math.sqrt(ratio) * S5_SEMI_MINOR, S5_SEMI_MINOR
    overlaps = np.linspace(0, S5_MAX_OVERLAP * a if max_overlap is None else max_overlap, S5_SAMPLES + 1)[1:]
    crossing = Quaternion(Vector3(0, 0, 1), angle)
    forces = [pressed_pair(mesh, mesh, overlaps, PAIR_MATERIAL, aligned(mesh, 0, angle1),
                           crossing * aligned(mesh, 0, angle2), extents=(b, b), **engine_options)
              for angle1, angle2 in axis_poses(poses, seed)]
    r_major, r_minor = spheroid_relative_radii(ratio, angle)
    return SpheroidSweep(overlaps, np.array(forces), elliptical_hertz_force(PAIR_MODULUS, r_major, r_minor, overlaps),
                         search_limit(mesh, mesh), ratio=ratio, nodes=len(mesh.vertices), angle=angle,
                         circular=hertz_force(PAIR_MODULUS, spheroid_mean_radius(ratio) / 2, overlaps),
                         approximate=approximate_elliptical_hertz_force(PAIR_MODULUS, r_major, r_minor, overlaps))


# --- S5 cylinders (Fig. 8) ------------------------------------------------------------------------------

CYLINDER_RADIUS = 1.0                   # R [m]
CYLINDER_LENGTH = 4.0                   # L [m] (ours: L = 4 R)
# total overlap 2 R - axis distance, 50 values up to 7.5 % of R (ours: S5's 7.5 %, of R here)
CYLINDER_OVERLAPS = np.linspace(0, 0.075, 51)[1:] * CYLINDER_RADIUS


@functools.lru_cache(maxsize=None)
def cylinder_mesh(nodes=2562, curvature="exact"):
    """Closed cylinder of radius CYLINDER_RADIUS and length CYLINDER_LENGTH, about `nodes` nodes; curvature
    prescribed: mean curvature 1/(2R) on the hull (the paper's "mean radius of curvature twice the cylinder
    radius"), flat caps. Cached."""
    return Mesh.cylinder(CYLINDER_RADIUS, CYLINDER_LENGTH, nodes, curvature=curvature)


@dataclass
class CylinderSweep(PairSweep):
    """S5 cylinder pair: PairSweep against the analytic force; for parallel cylinders also the least-squares
    line through the sweep (`slope` [N/m], `intercept` [N]) and the stiffness error slope / slope_ref - 1."""
    arrangement: str = "crossed"
    nodes: int = 0
    reference_slope: float = math.nan

    def slopes(self):
        """Least-squares slope [N/m] of each pose's force-overlap line (linear_fit)."""
        return np.array([linear_fit(self.overlaps, f)[0] for f in self.forces])

    def stiffness_errors(self):
        """slope / reference slope - 1 per pose (parallel cylinders; reference slope pi/4 E* L)."""
        return self.slopes() / self.reference_slope - 1.0


def linear_fit(overlaps, forces):
    """(slope [N/m], intercept [N]) of the least-squares line through (overlaps, forces)."""
    slope, intercept = np.polyfit(overlaps, forces, 1)
    return float(slope), float(intercept)


def power_law_exponent(overlaps, forces):
    """n of the least-squares fit F = k delta^n in log-log over the points with positive force [-]: 1 for a line
    contact (Eq. 27), 3/2 for a point contact (Eq. 6)."""
    overlaps, forces = np.asarray(overlaps), np.asarray(forces)
    keep = forces > 0
    return float(np.polyfit(np.log(overlaps[keep]), np.log(forces[keep]), 1)[0])


def cylinder_pair(arrangement, nodes=2562, poses=3, seed=1, **engine_options):
    """S5: two cylinder_mesh(nodes) pressed together along z at the middle of their hulls, at CYLINDER_OVERLAPS
    (delta = 2 R - axis distance), each turned about its own axis by the angles of axis_poses(poses, seed).
    arrangement "crossed": axes along x and y; reference Hertz sphere-on-plane with R* = R (the relative
    curvature is 1/R in both directions), E* = 0.5 Pa. "parallel": both axes along x; reference Eq. 27,
    F = pi/4 E* L delta. Returns a CylinderSweep."""
    mesh = cylinder_mesh(nodes)
    second_axis = {"crossed": 1, "parallel": 0}.get(arrangement)
    if second_axis is None:
        raise ValueError(f"arrangement must be 'crossed' or 'parallel', got {arrangement!r}")
    forces = [pressed_pair(mesh, mesh, CYLINDER_OVERLAPS, PAIR_MATERIAL, aligned(mesh, 0, angle1),
                           aligned(mesh, second_axis, angle2), extents=(CYLINDER_RADIUS, CYLINDER_RADIUS),
                           **engine_options)
              for angle1, angle2 in axis_poses(poses, seed)]
    if arrangement == "crossed":
        reference = hertz_force(PAIR_MODULUS, CYLINDER_RADIUS, CYLINDER_OVERLAPS)
    else:
        reference = parallel_cylinders_force(PAIR_MODULUS, CYLINDER_LENGTH, CYLINDER_OVERLAPS)
    return CylinderSweep(CYLINDER_OVERLAPS, np.array(forces), reference, search_limit(mesh, mesh),
                         arrangement=arrangement,
                         nodes=len(mesh.vertices), reference_slope=math.pi / 4 * PAIR_MODULUS * CYLINDER_LENGTH)

