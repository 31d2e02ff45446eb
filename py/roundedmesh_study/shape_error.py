"""The error axis of the speed-against-error study (issues 14 and 27; doc/speed-vs-error.md): one representation of
a smooth shape (sphere, pear, gummy bear, the grains of grains.py) pressed on a rigid plane or on a copy of itself at
a random orientation, force against overlap, against Hertz's solution at the smooth shape's contact point
(hertz_reference), or the half-space solution of the shapes' gap where the curvature changes over the contact.

    SmoothShape(name, nodes)                the shape f = 0 in the frame of one representation
    press_geometry(shape, upper, lower)     where the bodies touch, the reference radii, and whether Hertz holds
    RoundedMesh(...), Clump(...), LevelSetBody(...), YadeSphere()
                                            the representations: .forces(geometry, overlaps) -> (n, 3) [N]
    pose_errors(representation, geometry)   NRMSE of the force and the angle of its direction

Pressing. The direction of pressing d is the global z axis. Against the plane z = 0 (partner 'plane') the body
is turned by its orientation and lowered onto the plane; on a copy (partner 'self') the lower copy, turned by a
second orientation, stands at the origin and the upper one is lowered onto it, shifted sideways so that the
lower body's support point in +z and the upper body's in -z touch: there both outward normals are parallel to
d, so the contact normal of the smooth shapes is d. The overlap delta is the rigid approach from that touching
position, delta_k = k MAX_OVERLAP / SAMPLES, k = 1..SAMPLES, up to MAX_OVERLAP = 2 % of the volume-equivalent
radius r = 25 mm (0.5 mm). Each representation is placed by the same positions and orientations, in its own
body frame, where its smooth shape is the one it was built from (SmoothShape).

Errors. NRMSE = sqrt(mean_k (F_k . d - F_Hertz(delta_k))^2) / (max_k F_Hertz - min_k F_Hertz) (analytic.nrmse,
as doc/validation.md), F_k the force on the upper body; the reference's range is F_Hertz(MAX_OVERLAP) times
(1 - SAMPLES^-1.5). The normal error is the angle between F and d at the deepest overlap (90 degrees if the
force is zero there).

Materials: both bodies E = 1 MPa, nu = 0.4 (scene S1's particles); the plane E = RIGID_YOUNG, nu = 0.4, so
E* = E / (1 - nu^2) (1 - 1e-6) for the plane and E / (2 (1 - nu^2)) for two bodies. No damping, no friction: the
forces depend on the positions only, so a quasi-static press is one step per overlap.
"""
import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation
from yade import (FrictMat, ForceResetter, InsertionSortCollider, InteractionLoop, NewtonIntegrator, O, utils)
from yade import (Bo1_LevelSet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, Ig2_LevelSet_LevelSet_ScGeom,
                  Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_LevelSet_ScGeom, Ig2_Wall_Sphere_ScGeom,
                  Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin)
from yade.minieigenHP import Quaternion, Vector3

from roundedmesh import HertzMaterial, Mesh, plane_contact, shapes
from roundedmesh.contact import body_contact

from . import grains, halfspace
from . import hertz_reference as hr
from . import peers
from .analytic import effective_modulus, nrmse

RADIUS = 0.025                    # volume-equivalent radius r of every shape [m] (shapes.json)
MAX_OVERLAP = 0.02 * RADIUS       # deepest overlap, 2 % of r [m]
SAMPLES = 20                      # overlaps per curve
YOUNG, POISSON, DENSITY = 1e6, 0.4, 2000.0   # scene S1's particles [Pa], [-], [kg/m^3]
RIGID_YOUNG = 1e12                # the plane [Pa]
PARTNERS = ("plane", "self")

BODY = HertzMaterial(young=YOUNG, poisson=POISSON, density=DENSITY)
RIGID = HertzMaterial(young=RIGID_YOUNG, poisson=POISSON, density=DENSITY)
_Z = np.array([0.0, 0.0, 1.0])


def overlaps():
    """The overlap samples delta_k = k MAX_OVERLAP / SAMPLES [m], k = 1..SAMPLES."""
    return MAX_OVERLAP * np.arange(1, SAMPLES + 1) / SAMPLES


def modulus(partner):
    """E* [Pa] (Eq. 3) of a body on the rigid plane ('plane') or on a copy of itself ('self')."""
    return effective_modulus(BODY, RIGID if partner == "plane" else BODY)


def rotation_matrix(q):
    """(3, 3) rotation of a minieigen Quaternion."""
    return np.array(q.toRotationMatrix())


# --- the smooth shape ---------------------------------------------------------------------------------------

@dataclass(frozen=True)
class SmoothShape:
    """The smooth shape `name` ('sphere', 'pear', 'gummy_bear', or a study grain: grains.NAMES) in the body frame
    of a representation: the sphere |x| - r of radius r = RADIUS about the origin; f = 0 of shapes.json in the frame
    and at the scale of Mesh.reference_shape(name, nodes) (peers.shape_distance; nodes None is the paper's count,
    the frame of the clumps and level sets); a grain's f in its own frame (grains.Grain.distance), which is the
    frame of its clumps and level sets. Optionally seen from a frame turned by `rotation` and moved by `offset`
    from it (a mesh in its principal frame: x_reference = rotation x + offset)."""
    name: str
    nodes: int = None
    rotation: tuple = None
    offset: tuple = None

    def distance(self, points):
        """f [m] at body-frame points (n, 3) [m]."""
        points = np.asarray(points, dtype=float)
        if self.rotation is not None:
            points = points @ np.asarray(self.rotation).T + np.asarray(self.offset)
        if self.name == "sphere":
            return np.linalg.norm(points, axis=1) - RADIUS
        if self.name in grains.NAMES:
            return grains.grain(self.name).distance(points)
        return peers.shape_distance(self.name, points, self.nodes)

    def to_common(self):
        """(3, 3) rotation taking vectors of this body frame to the body frame of Mesh.reference_shape(name) (the
        paper's node count), in which the poses are given: R_common^T R_nodes (rotation), so that one pose turns
        every representation's smooth shape alike. The identity for the sphere."""
        if self.name == "sphere":
            return np.eye(3)
        if self.name in grains.NAMES:   # the grain's own frame is the common one
            return np.eye(3) if self.rotation is None else np.asarray(self.rotation)
        own = peers.body_frame(self.name, self.nodes)[2]
        turn = own if self.rotation is None else own @ np.asarray(self.rotation)
        return peers.body_frame(self.name)[2].T @ turn

    def samples(self):
        """Points on f = 0 [m], body frame, about 2 mm apart: the nodes of a 2562-node icosphere, or of the
        2200-node mesh of the shape mapped to this frame (through shape units for shapes.json's)."""
        return _surface_samples(self)


@functools.lru_cache(maxsize=None)
def _surface_samples(shape):
    if shape.name == "sphere":
        points = np.array(Mesh.icosphere(RADIUS, 4).vertices)
    elif shape.name in grains.NAMES:
        points = grains.grain(shape.name).surface()[0]
    else:
        fine, fine_scale = shapes.mesh_with_scale(shape.name, 2200)
        _, scale, rotation, centroid = peers.body_frame(shape.name, shape.nodes)
        units = (np.array(fine.vertices) @ rotation_matrix(fine.orientation).T + np.array(fine.centroid)) / fine_scale
        points = (scale * units - centroid) @ rotation
    if shape.rotation is not None:
        points = (points - np.asarray(shape.offset)) @ np.asarray(shape.rotation)
    return points


# --- where the bodies touch ---------------------------------------------------------------------------------

# Second contact: another part of the bodies within SECOND_CONTACT_GAP of each other at first touch (where the
# contact at MAX_OVERLAP would reach it), farther than SECOND_CONTACT_REACH contact semi-axes plus 3 mm (the
# sample spacing) from the contact point. The gap is judged at the sample points, which lie on f = 0 but up to
# about 0.1 mm inside the surface between them (2.3 mm apart, radii of curvature >= 5.4 mm: sagitta
# 2.3^2 / (8 5.4) mm), hence the margin of 1.5 MAX_OVERLAP; f underestimates distances in blends, which only
# leaves more poses out.
SECOND_CONTACT_GAP = 1.5 * MAX_OVERLAP
SECOND_CONTACT_REACH = 2.0


@dataclass
class PressGeometry:
    """A body lowered along -z onto the plane or onto a copy (module docstring), all in global coordinates but
    for the points and tensors, which are in each body's frame.
        shape                  the SmoothShape
        partner                'plane' or 'self'
        upper, lower           orientations (Quaternion) of the pressed body's frame and of the copy's (None on
                               a plane)
        upper_point, lower_point   support points in the body frames [m]
        touch_upper            position [m] of the upper body where the bodies touch (delta = 0); the lower
                               copy stands at the origin
        r_major, r_minor       relative principal radii of the smooth shapes [m] (inf, when 'flat')
        principal              the bodies' principal curvatures at their points [1/m]
        reference_kind         'hertz', or 'half-space' where the curvature changes over the contact by more than
                               hertz_reference.CREASE_TOLERANCE (halfspace_forces)
        left_out               None, or why neither reference holds here (hertz_reference.hertz_holds:
                               'concave', 'flat', 'second contact')"""
    shape: SmoothShape
    partner: str
    upper: Quaternion
    lower: Quaternion = None
    upper_point: np.ndarray = None
    lower_point: np.ndarray = None
    touch_upper: np.ndarray = None
    r_major: float = math.nan
    r_minor: float = math.nan
    principal: list = None
    reference_kind: str = "hertz"
    left_out: str = None

    def upper_position(self, overlap):
        """Position [m] of the upper body at approach `overlap` [m]."""
        return self.touch_upper - overlap * _Z

    def reference(self, deltas):
        """The reference force [N] at the overlaps `deltas` [m]: Hertz's, or the half-space solution's."""
        if self.reference_kind == "half-space":
            return halfspace_forces(self, deltas)
        return hr.reference_force(modulus(self.partner), self.r_major, self.r_minor, deltas)


def _quaternion(rotation):
    """The minieigen Quaternion of a rotation matrix (3, 3)."""
    x, y, z, w = Rotation.from_matrix(rotation).as_quat()
    q = Quaternion(w, x, y, z)
    q.normalize()
    return q


def press_geometry(shape, upper, lower=None):
    """PressGeometry of `shape` pressed on the plane z = 0 (lower None) or on a copy at the origin; `upper` and
    `lower` (Quaternion) turn the body frame of Mesh.reference_shape(name) (SmoothShape.to_common), so that the
    geometry's orientations, which turn the shape's own frame, put every representation's smooth shape alike."""
    samples = shape.samples()
    to_common = shape.to_common()
    r_up = rotation_matrix(upper) @ to_common
    upper = _quaternion(r_up)
    up_point = hr.support_point(shape.distance, r_up.T @ -_Z, samples)
    up_tensor = hr.curvature_tensor(shape.distance, up_point)[1]
    bodies = [(shape.distance, up_point, up_tensor, r_up)]
    up_global = samples @ r_up.T                       # sample points turned, the body at the origin
    geometry = PressGeometry(shape, "plane" if lower is None else "self", upper, upper_point=up_point)
    if lower is None:
        height = -(r_up @ up_point)[2]
        geometry.touch_upper = np.array([0.0, 0.0, height])
        gaps = up_global[:, 2] + height                  # heights above the plane
        far = np.linalg.norm(up_global - r_up @ up_point, axis=1)
        tensors = [r_up @ up_tensor @ r_up.T, np.zeros((3, 3))]
    else:
        r_low = rotation_matrix(lower) @ to_common
        geometry.lower = _quaternion(r_low)
        low_point = hr.support_point(shape.distance, r_low.T @ _Z, samples)
        low_tensor = hr.curvature_tensor(shape.distance, low_point)[1]
        bodies.insert(0, (shape.distance, low_point, low_tensor, r_low))
        contact_global = r_low @ low_point
        geometry.lower_point = low_point
        geometry.touch_upper = contact_global - r_up @ up_point
        upper_samples = up_global + geometry.touch_upper
        lower_samples = samples @ r_low.T
        # f of each body at the other's samples: the gap, or less (f <= distance)
        gaps = np.concatenate([shape.distance((lower_samples - geometry.touch_upper) @ r_up),
                               shape.distance(upper_samples @ r_low)])
        far = np.linalg.norm(np.concatenate([lower_samples, upper_samples]) - contact_global, axis=1)
        tensors = [r_low @ low_tensor @ r_low.T, r_up @ up_tensor @ r_up.T]
    geometry.r_major, geometry.r_minor, _ = hr.contact_radii(tensors[0], tensors[1], _Z)
    geometry.principal = [hr.tangent_principal(t, _Z)[0] for t in tensors[:len(bodies)]]
    reach = 3e-3
    if math.isfinite(geometry.r_major):
        reach += SECOND_CONTACT_REACH * hr.contact_semi_axes(modulus(geometry.partner), geometry.r_major,
                                                             geometry.r_minor, MAX_OVERLAP)[0]
    second = bool(np.any((gaps < SECOND_CONTACT_GAP) & (far > reach)))
    geometry.left_out = hr.hertz_holds(modulus(geometry.partner), MAX_OVERLAP, bodies, second)
    if geometry.left_out == "crease":   # the curvature changes over the contact: the half-space solution instead
        geometry.left_out = "second contact" if second else None
        geometry.reference_kind = "half-space"
    return geometry


# --- the half-space reference, where the curvature changes over the contact ----------------------------------

HALFSPACE_CELLS = 64     # grid cells across the window (tests/python/test_halfspace.py: NRMSE < 0.3 % from 40
                         # cells across the deepest contact)
HALFSPACE_FILL = 0.75    # the window is resized until the deepest contact spans this share of it, at most ...
HALFSPACE_PASSES = 4     # ... this many times
# The first window at most 0.6 r wide on either side: near a flat point (a pill's face) Hertz's ellipse at the
# contact point's curvature is unbounded, while the gap's higher orders hold the contact to a part of the body.
HALFSPACE_MAX_HALF_WIDTH = 0.6 * RADIUS


def _surface_heights(distance, to_body, origin, points, below):
    """Heights z [m] of the body surface over (x, y) `points` (n, 2) [m] near the contact point, global frame:
    Newton steps along z on f(to_body(x, y, z)) = 0 from the contact point's height `origin`, for the body's lower
    side (`below` True, f decreasing upward) or its upper side. np.inf (np.-inf for the upper side) where the steps
    do not find that side of the surface (the column misses the body)."""
    z = np.full(len(points), origin, dtype=float)
    step = 1e-7

    def f(heights):
        return distance(to_body(np.column_stack([points, heights])))
    for _ in range(40):
        value = f(z)
        slope = (f(z + step) - f(z - step)) / (2 * step)
        slope = np.where(np.abs(slope) > 1e-6, slope, np.nan)
        z = z - value / slope
    found = np.isfinite(z) & (np.abs(f(np.nan_to_num(z))) < 1e-10)
    slope = (f(np.nan_to_num(z) + step) - f(np.nan_to_num(z) - step)) / (2 * step)
    found &= (slope < 0) if below else (slope > 0)
    return np.where(found, z, np.inf if below else -np.inf)


def contact_gap(geometry, half_width, cells=HALFSPACE_CELLS):
    """(gap (cells, cells) [m], spacing [m]): the distance along z between the undeformed surfaces of `geometry` at
    first touch over a square window of side 2 half_width [m] in the tangent plane, centred on the contact point;
    np.inf where a column misses a body."""
    spacing = 2 * half_width / cells
    offsets = (np.arange(cells) - (cells - 1) / 2) * spacing
    r_up = rotation_matrix(geometry.upper)
    contact = r_up @ geometry.upper_point + geometry.touch_upper
    xy = np.stack(np.meshgrid(offsets, offsets, indexing="ij"), axis=-1).reshape(-1, 2) + contact[:2]
    shape = geometry.shape
    upper = _surface_heights(shape.distance, lambda p: (p - geometry.touch_upper) @ r_up, contact[2], xy, True)
    if geometry.partner == "plane":
        lower = np.zeros(len(xy))
    else:
        r_low = rotation_matrix(geometry.lower)
        lower = _surface_heights(shape.distance, lambda p: p @ r_low, contact[2], xy, False)
    with np.errstate(invalid="ignore"):
        gap = (upper - lower).reshape(cells, cells)
    gap[np.isnan(gap)] = np.inf
    if not np.isfinite(gap).any():
        raise ValueError(f"contact_gap: no column of the {2e3 * half_width:.3g} mm window meets both bodies")
    return np.maximum(gap, 0.0), spacing   # 0 at the contact point, where the bodies touch; round-off below


def halfspace_forces(geometry, deltas):
    """The half-space solution's force [N] at the overlaps `deltas` [m] (halfspace.contact_forces) for the gap of
    `geometry` (contact_gap), on a window first as wide as Hertz's ellipse at the deepest overlap would need, then
    resized until the contact there spans HALFSPACE_FILL of it (it may be larger or smaller than Hertz's where the
    curvature changes)."""
    a, b = hr.contact_semi_axes(modulus(geometry.partner), geometry.r_major, geometry.r_minor, max(deltas))
    half_width = min(max(a, b) / HALFSPACE_FILL, HALFSPACE_MAX_HALF_WIDTH)
    for _ in range(HALFSPACE_PASSES):
        gap, spacing = contact_gap(geometry, half_width)
        forces, pressure = halfspace.contact_forces(gap, spacing, modulus(geometry.partner), deltas)
        rows, columns = np.nonzero(pressure)
        centre = (HALFSPACE_CELLS - 1) / 2
        extent = (np.max(np.abs(np.concatenate([rows, columns]) - centre)) + 1) * spacing if len(rows) else 0
        if extent == 0 or abs(extent / half_width - HALFSPACE_FILL) < 0.15:
            break
        half_width = extent / HALFSPACE_FILL
    return forces


# --- the representations ------------------------------------------------------------------------------------

@dataclass
class RoundedMesh:
    """A roundedmesh body: `mesh` in its principal frame, where its smooth shape is `shape`, with the contact law's
    options `regime` ('auto', 'quadrature', 'direct'), `curvature` ('mean': a contact circle; 'principal': Hertz's
    ellipse) and `normal` ('pressure' or 'energy', rm.engine); forces from rm.plane_contact / rm.body_contact."""
    mesh: Mesh
    shape: SmoothShape
    regime: str = "auto"
    curvature: str = "mean"
    normal: str = "pressure"

    def forces(self, geometry, deltas):
        """Forces [N] on the upper body at the overlaps `deltas` [m], (n, 3)."""
        options = dict(regime=self.regime, curvature=self.curvature, normal=self.normal)
        result = []
        for overlap in deltas:
            position = Vector3(*geometry.upper_position(overlap))
            if geometry.partner == "plane":
                force = plane_contact(self.mesh, position, geometry.upper, Vector3(0, 0, 0), Vector3(0, 0, 1), BODY,
                                      RIGID, **options)[0]
            else:
                force = body_contact(self.mesh, Vector3(0, 0, 0), geometry.lower, self.mesh, position, geometry.upper,
                                     BODY, BODY, **options)[2]
            result.append([force[0], force[1], force[2]])
        return np.array(result)


def rounded_mesh(name, nodes, curvature="computed", regime="auto", law_curvature="mean", normal="pressure"):
    """RoundedMesh of `name` with about `nodes` nodes and the law's options regime, law_curvature (its `curvature`)
    and normal. The mesh's curvature is 'computed' (Eq. 1) or 'prescribed' (the smooth shape's mean and principal
    curvatures under each triangle). For the sphere an icosphere of radius RADIUS (nodes one of 42, 162, 642, 2562);
    for the pear and the gummy bear Mesh.reference_shape(name, nodes, 'computed' or 'exact'); for a grain
    Grain.mesh(nodes, ...), whose principal frame is mapped to the grain's own."""
    exact = "exact" if curvature == "prescribed" else "computed"
    options = dict(regime=regime, curvature=law_curvature, normal=normal)
    if name == "sphere":
        subdivisions = {42: 1, 162: 2, 642: 3, 2562: 4}[nodes]
        return RoundedMesh(Mesh.icosphere(RADIUS, subdivisions, curvature=exact), SmoothShape("sphere"), **options)
    if name in grains.NAMES:
        mesh = grains.grain(name).mesh(nodes, exact)
        frame = SmoothShape(name, nodes, tuple(map(tuple, rotation_matrix(mesh.orientation))), tuple(mesh.centroid))
        return RoundedMesh(mesh, frame, **options)
    return RoundedMesh(shapes.reference_shape(name, nodes, exact), SmoothShape(name, nodes), **options)


def source_mesh(name, nodes=2200):
    """The study's computed-curvature mesh of `name` with about `nodes` nodes (the icosphere of 2562 for the sphere):
    what a mesh to be remeshed (Mesh.remeshed) is made from."""
    if name == "sphere":
        return Mesh.icosphere(RADIUS, 4, curvature="computed")
    return rounded_mesh(name, nodes).mesh


def remeshed_frame(name, mesh, nodes=2200):
    """SmoothShape of `name` in the principal frame of `mesh`, made from source_mesh(name, nodes) in that mesh's
    input frame (Mesh.remeshed keeps it): x_reference = rotation x + offset, the reference being the source's
    principal frame (its own frame for a grain or the sphere)."""
    source = source_mesh(name, nodes)
    own = rotation_matrix(mesh.orientation), np.array(mesh.centroid)
    if name == "sphere" or name in grains.NAMES:
        rotation, offset = own
    else:
        turn = rotation_matrix(source.orientation).T
        rotation, offset = turn @ own[0], turn @ (own[1] - np.array(source.centroid))
    return SmoothShape(name, None if name == "sphere" or name in grains.NAMES else nodes,
                       tuple(map(tuple, rotation)), tuple(offset))


SPEED = 0.01   # the pressed body's speed [m/s]; with no damping and no friction YADE's forces do not depend on it


def _press_in_yade(geometry, deltas, add_body, bounds, functors, verlet_distance):
    """Forces [N] on the upper body (n, 3) at the overlaps `deltas` [m] (evenly spaced), from YADE: O is reset,
    the upper body added by add_body(position, orientation, material) -> (id, ids of the bodies that touch: the
    members of a clump) is moved down kinematically by one overlap step per time step, from two steps before
    touching, onto a fixed Wall or a fixed copy; Hertz-Mindlin without damping or friction. The force on the
    upper body is minus the sum of the forces YADE puts on the lower one, read after each step: they are those of
    the positions at the step's start (InteractionLoop runs before NewtonIntegrator moves the body)."""
    O.reset()
    body = O.materials.append(FrictMat(young=YOUNG, poisson=POISSON, density=DENSITY, frictionAngle=0))
    rigid = O.materials.append(FrictMat(young=RIGID_YOUNG, poisson=POISSON, density=DENSITY, frictionAngle=0))
    step = deltas[1] - deltas[0]
    start = -2 * step
    upper, _ = add_body(Vector3(*geometry.upper_position(start)), geometry.upper, body)
    if geometry.partner == "plane":
        lower = [O.bodies.append(utils.wall(0, axis=2, sense=1, material=rigid))]
    else:
        fixed, lower = add_body(Vector3(0, 0, 0), geometry.lower, body)
        O.bodies[fixed].state.blockedDOFs = "xyzXYZ"
    state = O.bodies[upper].state
    state.blockedDOFs = "xyzXYZ"
    state.vel = Vector3(0, 0, -SPEED)
    O.engines = [ForceResetter(), InsertionSortCollider(bounds, verletDist=verlet_distance),
                 InteractionLoop(functors, [Ip2_FrictMat_FrictMat_MindlinPhys(betan=0, betas=0)],
                                 [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
    O.dt = step / SPEED
    z0 = state.pos[2]
    measured = {}
    for _ in range(len(deltas) + 3):
        overlap = start + (z0 - state.pos[2])
        O.step()
        force = -sum((O.forces.f(i) for i in lower), Vector3(0, 0, 0))
        measured[int(round(overlap / step))] = [force[0], force[1], force[2]]
    return np.array([measured[int(round(d / step))] for d in deltas])


def peer_frame(name):
    """The SmoothShape in the body frame of YADE's clumps and level sets of `name` (peers.clump_spheres,
    peers.level_set_shape): the paper mesh's for the pear and the gummy bear, the reference mesh's
    (grains.REFERENCE_NODES) for a grain."""
    if name in grains.NAMES:
        rotation, centroid = grains.grain(name).frame()
        return SmoothShape(name, grains.REFERENCE_NODES, tuple(map(tuple, rotation)), tuple(centroid))
    return SmoothShape(name)


def _peer_mass(name):
    """(mass [kg], principal inertia (3,) [kg m^2]) the clumps and level sets of `name` are given: those of the
    mesh whose frame they stand in (peers.body_frame), as for the rounded bodies."""
    mesh = peers.body_frame(name)[0]
    return DENSITY * mesh.volume, DENSITY * np.array(mesh.inertia)


@dataclass
class Clump:
    """A YADE clump of `count` spheres (peers.clump_spheres by `method`: None the shape's default, 'primitives' or
    'fill'; for the sphere, one sphere of radius RADIUS), Hertz-Mindlin against a Wall or a copy."""
    name: str
    count: int
    method: str = None

    @property
    def shape(self):
        return peer_frame(self.name)

    def forces(self, geometry, deltas):
        """Forces [N] on the upper body at the overlaps `deltas` [m], (n, 3), from YADE."""
        if self.name == "sphere":
            def add(position, ori, material):
                body = O.bodies.append(utils.sphere(position, RADIUS, material=material))
                return body, [body]
        else:
            centres, radii = peers.clump_spheres(self.name, self.count, self.method)
            mass = _peer_mass(self.name)[0]

            def add(position, ori, material):
                return peers.add_clump(centres, radii, position, ori, material, mass)
        return _press_in_yade(geometry, deltas, add, [Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()],
                              [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], -0.5)


@functools.lru_cache(maxsize=None)
def _level_set(name, spacing, surface_nodes):
    return peers.level_set_shape(name, spacing, surface_nodes)


@dataclass
class LevelSetBody:
    """A YADE level-set body of `name` (peers.level_set_shape: grid `spacing` [m], `surface_nodes` boundary
    nodes), Hertz-Mindlin (Ig2_Wall_LevelSet_ScGeom, Ig2_LevelSet_LevelSet_ScGeom) against a Wall or a copy."""
    name: str
    spacing: float
    surface_nodes: int

    @property
    def shape(self):
        return peer_frame(self.name)

    def forces(self, geometry, deltas):
        """Forces [N] on the upper body at the overlaps `deltas` [m], (n, 3), from YADE."""
        level_set = _level_set(self.name, self.spacing, self.surface_nodes)
        mass, inertia = _peer_mass(self.name)

        def add(position, ori, material):
            body = peers.add_level_set_body(level_set, position, ori, material, mass, inertia)
            return body, [body]
        return _press_in_yade(geometry, deltas, add, [Bo1_LevelSet_Aabb(), Bo1_Wall_Aabb()],
                              [Ig2_LevelSet_LevelSet_ScGeom(), Ig2_Wall_LevelSet_ScGeom()], 0.0)


# --- errors -------------------------------------------------------------------------------------------------

def pose_errors(representation, geometry, deltas=None, reference=None):
    """(NRMSE of the force along d [-], angle between the force and d at the deepest overlap [deg], forces along
    d [N]) of `representation` in the press `geometry` (module docstring), against `reference` (the forces [N] at
    `deltas`; default geometry.reference(deltas), which a caller judging many representations at one pose
    computes once)."""
    deltas = overlaps() if deltas is None else deltas
    forces = representation.forces(geometry, deltas)
    along = forces @ _Z
    error = nrmse(along, geometry.reference(deltas) if reference is None else reference)
    deepest = forces[-1]
    norm = np.linalg.norm(deepest)
    angle = 90.0 if norm == 0 else math.degrees(math.acos(min(1.0, max(-1.0, deepest @ _Z / norm))))
    return error, angle, along
