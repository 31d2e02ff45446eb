"""YADE's own representations of a reference shape, the peers our engine's speed is stated against in scene S1
(Smeets et al., CMAME 277 (2014) 219-238, Section 3.4): clumps of spheres, level-set bodies and plain spheres,
built with YADE's Hertz-Mindlin contact law at the poses of the rounded bodies.

    clump_spheres(name, count)        centres [m] and radii [m] of a clump, in the shape's body frame
    shape_distance(name, points)      the shape's distance field f [m] at body-frame points [m]
    body_frame(name, nodes, curvature) the mesh, scale and frame of Mesh.reference_shape(name, nodes, curvature)
    mindlin_betan()                   YADE's damping ratio betan matched to the paper's Eq. 7 (dimensionless)
    add_clump(centres, radii, ...)    one clump of clump_spheres at a pose
    level_set_from_distance(distance, low, high, ...)  a YADE LevelSet of any signed distance function
    level_set_shape(name, ...)        the shape's YADE LevelSet (from shape_distance)
    level_set_from_mesh(vertices, triangles, ...)  a YADE LevelSet of any closed triangle mesh
    add_level_set_body(shape, ...)    one level-set body at a pose
    build_clumps(poses, count)        S1's box and one clump per pose (resets O)
    build_level_sets(poses, ...)      S1's box and one level-set body per pose (resets O)
    build_spheres(poses)              S1's box and one sphere of the volume-equivalent radius per pose (resets O)

A pose is (position [m], quaternion (w, x, y, z) body -> global, velocity [m/s], angular velocity [rad/s]) of
the body's principal frame, the frame of Mesh.reference_shape(name), so that every representation stands where
the rounded body stands.

Frames. shapes.json gives the primitives in shape units. mesh_with_scale(name) returns the mesh and the scale s
[m per shape unit]; mesh.centroid [m] and mesh.orientation (a rotation R) give the input frame, the shape's
coordinates times s:  input-frame point = R * body-frame point + centroid = s * shape-unit point. So a shape-unit
point x maps to the body frame as R^T (s x - centroid), and a length as s times it. (tests/python/test_shapes.py
checks the mesh's nodes on f = 0 through this map; tests/python/test_peers.py checks the clumps through it.)

The box (all representations): five YADE Walls, the base z = 0 and the sides x, y = +-0.20 m, as the
roundedmesh scenes have it. Walls are infinite planes; S1's are 2 m high and the packing stays far below, so
the planes stand for them exactly, and a Wall costs one bound for the collider where a facet box costs ten.
YADE's Ig2_Wall_Sphere_ScGeom gives the wall the sphere's radius (refR1 = refR2 = r), so Hertz-Mindlin takes
R* = r/2 against a wall where Hertz against a plane has R* = r: YADE's wall contact is 1/sqrt(2) as stiff as the
paper's (a Box gives r/2 as well, a Facet 2r/3; no YADE choice gives r). For level sets, Ig2_*_LevelSet_ScGeom
set both radii to the distance from a body's centre to the contact point, so R* is half of that (about 12 mm for
the bear), not the local curvature.

Damping. The paper's normal force (Eq. 7) is F = (4/3) E* sqrt(R*) (delta^1.5 + A d(delta)/dt sqrt(delta)), a
damping coefficient c = k0 A sqrt(delta) with k0 = (4/3) E* sqrt(R*). YADE's Law2_ScGeom_MindlinPhys_Mindlin
(2023.02a) has only c = 2 betan sqrt(m* k_n) with k_n = (3/2) k0 sqrt(delta), so c grows as delta^(1/4), not
delta^(1/2); Ip2's en is the same law through Thornton's fit (en -> betan). betan is the damping ratio
c / (2 sqrt(m* k_n)); Eq. 7's ratio at overlap delta is zeta(delta) = A sqrt(k0) delta^(1/4) / sqrt(6 m*). We set
betan = zeta(delta_ref) per material pair, delta_ref the overlap at which a bear's own weight rests on the contact
(k0 delta_ref^1.5 = m g), with the Hertz R* of volume-equivalent spheres (r/2 bear-bear, r bear-wall) and
m* = m/2 bear-bear, m bear-wall. A settled packing's contacts carry from one to a few weights, and zeta varies as
delta^(1/4): ten times the overlap is 1.8 times the ratio. betas = 0: S1 has no friction, and with friction angle
0 YADE's shear force is zero anyway.
"""
import functools
import itertools
import math

import numpy as np
from yade import (Body, FrictMat, ForceResetter, InsertionSortCollider, InteractionLoop, MatchMaker, NewtonIntegrator,
                  O, utils)
from yade import (Bo1_LevelSet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, Ig2_LevelSet_LevelSet_ScGeom,
                  Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_LevelSet_ScGeom, Ig2_Wall_Sphere_ScGeom,
                  Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, LevelSet, RegularGrid)
from yade.minieigenHP import Matrix3, Quaternion, Vector3, Vector3i

from roundedmesh import HertzMaterial, Mesh, scene, shapes

from . import grains
from .mesh_distance import signed_distance
from .sphere_fill import inscribed_spheres

# Scene S1 (doc/scenes.md)
RADIUS = 0.025                 # volume-equivalent radius r [m]
HALF_BASE = 0.20               # the box's inner base is 0.40 m x 0.40 m, centred on the z axis [m]
PARTICLE = {"young": 1e6, "poisson": 0.4, "density": 2000.0}   # [Pa], [-], [kg/m^3]
BOX = {"young": 5e6, "poisson": 0.4, "density": 2000.0}        # density unused: the walls are fixed
DAMPING_CONSTANT = 0.01        # A of Eq. 7 [s]
GRAVITY = 9.81                 # [m/s^2]
TIME_STEP = 1e-4               # [s]
# S1's icospheres: rm.Mesh.icosphere(RADIUS, subdivisions), whatever `nodes` says. Here a body has the mesh's own mass
# (scripts/s1_packing.py gives its icosphere runs the sphere's).
ICOSPHERES = {"icosphere12": 0, "icosphere42": 1, "icosphere162": 2}
CLUMP_COUNTS = (10, 20, 40, 80)  # sphere counts of the speed-against-error study


# --- the shape's primitives and distance, in the body frame ------------------------------------------------

def body_frame(name, nodes=None, curvature="computed"):
    """(mesh, scale [m/unit], R (3, 3), centroid (3,) [m]) of Mesh.reference_shape(name, nodes, curvature): input
    point = R body point + centroid = scale x. curvature only sets the mesh's per-triangle curvatures (as for
    reference_shape); the vertices, scale and frame are the same for both. For a study grain (grains.NAMES) the
    mesh Grain.mesh(nodes, curvature: 'computed' or 'exact'), default grains.REFERENCE_NODES nodes, and the
    grain's own frame as the input frame (scale 1); for an icosphere (ICOSPHERES) its mesh, with scale 1."""
    if name in ICOSPHERES:
        mesh = _icosphere(name)
        return mesh, 1.0, np.array(mesh.orientation.toRotationMatrix()), np.array(mesh.centroid)
    if name in grains.NAMES:
        mesh = grains.grain(name).mesh(grains.REFERENCE_NODES if nodes is None else nodes, curvature)
        return mesh, 1.0, np.array(mesh.orientation.toRotationMatrix()), np.array(mesh.centroid)
    mesh, scale = shapes.mesh_with_scale(name, nodes, curvature)
    return mesh, scale, np.array(mesh.orientation.toRotationMatrix()), np.array(mesh.centroid)


@functools.lru_cache(maxsize=None)
def _icosphere(name):
    return Mesh.icosphere(RADIUS, ICOSPHERES[name])


def _chain_counts(lengths, radii, budget):
    """Spheres per capsule: `budget` in all, at least one each, proportional to segment length as nearly as
    integers allow (least squares), and equal for equal capsules (a bear's left and right arm) so that the
    clump keeps the shape's mirror symmetry."""
    groups = {}
    for i, key in enumerate(zip(np.round(lengths, 9), np.round(radii, 9))):
        groups.setdefault(key, []).append(i)
    members = list(groups.values())
    quota = [budget * lengths[g[0]] / lengths.sum() for g in members]
    choices = [range(max(1, math.floor(q) - 2), math.ceil(q) + 3) for q in quota]
    best = None
    for counts in itertools.product(*choices):
        if sum(n * len(g) for n, g in zip(counts, members)) != budget:
            continue
        error = sum(len(g) * (n - q) ** 2 for n, g, q in zip(counts, members, quota))
        if best is None or error < best[0]:
            best = (error, counts)
    if best is None:
        raise ValueError(f"count: cannot give {budget} spheres to capsules of lengths {lengths} symmetrically")
    per_capsule = np.zeros(len(lengths), dtype=int)
    for n, g in zip(best[1], members):
        per_capsule[g] = n
    return per_capsule


def fill_surface(name, nodes=2200):
    """(vertices (n, 3) [m], triangles (m, 3)) of the shape's `nodes`-node mesh in the body frame of the peers
    (body_frame(name)): what a clump is filled from and a grain's level set is built from."""
    if name in grains.NAMES:
        return grains.grain(name).surface(nodes, frame="reference")
    mesh, scale, rotation, centroid = body_frame(name, nodes)
    _, paper_scale, paper_rotation, paper_centroid = body_frame(name)
    units = (np.array(mesh.vertices) @ rotation.T + centroid) / scale
    return (paper_scale * units - paper_centroid) @ paper_rotation, np.array(mesh.triangles)


CLUMP_METHODS = ("primitives", "fill")


@functools.lru_cache(maxsize=None)
def clump_spheres(name="gummy_bear", count=40, method=None):
    """(centres (n, 3) [m], radii (n,) [m]): a clump of n = `count` spheres standing for the reference shape
    `name`, in the principal (body) frame of Mesh.reference_shape(name).

    Built from the primitives of shapes.json: each sphere stays one sphere; each capsule (segment a-b swept by
    a ball of radius rho) becomes a chain of k equal spheres of radius rho, centred at a + (b - a) j / (k - 1),
    j = 0..k-1 (ends included, so the chain has the capsule's caps; its midpoint if k = 1). The capsules share
    count - (number of spheres) by segment length, at least one each, mirror-image capsules alike
    (_chain_counts). Shape-unit centres x map to the body frame as R^T (s x - centroid) and radii as s rho
    (module docstring). The union of the spheres lacks the shape's blends (smooth minimum) and is scalloped
    between chain spheres; against the smooth surface f = 0 its volume is -1.2 % at 80 spheres, -1.7 % at 40,
    -13 % at 20 and -47 % at 10 (one sphere per capsule). Against the 554-node mesh, inscribed in f = 0 and
    2.4 % smaller, that is +1.2, +0.7, -11 and -46 %.

    method 'fill' (the default, and the only method, for a study grain, which has no primitives): the clump a user
    builds from a mesh, the greedy inscribed-sphere fill of the shape's 2200-node mesh (sphere_fill.inscribed_spheres,
    fill_surface)."""
    method = method or ("fill" if name in grains.NAMES else "primitives")
    if method not in CLUMP_METHODS or (name in grains.NAMES and method != "fill"):
        raise ValueError(f"method: {method!r} for {name!r}; one of {', '.join(CLUMP_METHODS)} ('fill' for a grain)")
    if method == "fill":
        return inscribed_spheres(*fill_surface(name), count)
    definition = shapes.definitions()["shapes"][name]
    _, scale, rotation, centroid = body_frame(name)
    spheres = [p for p in definition["primitives"] if p["type"] == "sphere"]
    capsules = [p for p in definition["primitives"] if p["type"] == "capsule"]
    if count < len(spheres) + len(capsules):
        raise ValueError(f"count: {name} needs at least {len(spheres) + len(capsules)} spheres (one per "
                         f"primitive), got {count}")
    centres = [np.array(p["center"], dtype=float) for p in spheres]
    radii = [p["radius"] for p in spheres]
    ends = [(np.array(p["a"], dtype=float), np.array(p["b"], dtype=float)) for p in capsules]
    lengths = np.array([np.linalg.norm(b - a) for a, b in ends])
    per_capsule = _chain_counts(lengths, np.array([p["radius"] for p in capsules]), count - len(spheres))
    for (a, b), k, capsule in zip(ends, per_capsule, capsules):
        for t in (np.linspace(0, 1, k) if k > 1 else [0.5]):
            centres.append(a + (b - a) * t)
            radii.append(capsule["radius"])
    body = (scale * np.array(centres) - centroid) @ rotation  # rows: R^T (s x - c)
    return body, scale * np.array(radii)


def _blended_distance(definition, points):
    """f of shapes.json (module shapes) at shape-unit points (n, 3): smooth minimum of the primitives' exact
    signed distances, in shape units."""
    def primitive_distance(p):
        if p["type"] == "sphere":
            return np.linalg.norm(points - p["center"], axis=1) - p["radius"]
        a, b = np.array(p["a"]), np.array(p["b"])
        t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
        return np.linalg.norm(points - (a + t[:, None] * (b - a)), axis=1) - p["radius"]

    k = definition["blend_k"]
    primitives = definition["primitives"]
    d = primitive_distance(primitives[0])
    for p in primitives[1:]:
        e = primitive_distance(p)
        h = np.maximum(k - np.abs(d - e), 0) / k
        d = np.minimum(d, e) - h * h * k / 4
    return d


def shape_distance(name, points, nodes=None):
    """f of shape `name` (shapes.json) at body-frame points (n, 3) [m], in metres: negative inside, zero on the
    surface the nodes of Mesh.reference_shape(name, nodes) lie on (each node count has its own scale and frame).
    f is the shape's own distance field: a smooth minimum of the primitives' exact signed distances. Its gradient
    has norm at most 1, so |f| never exceeds the distance to the surface; it equals it outside the primitives away
    from the blends, and inside down to the depth of the nearest buried junction; in the blends (k = 0.06 shape
    units = 2.7 mm wide for the gummy bear) it falls short by up to k/4."""
    definition = shapes.definitions()["shapes"][name]
    _, scale, rotation, centroid = body_frame(name, nodes)
    return scale * _blended_distance(definition, (np.asarray(points, dtype=float) @ rotation.T + centroid) / scale)


# --- damping ----------------------------------------------------------------------------------------------

def effective_young(young1, poisson1, young2, poisson2):
    """E* [Pa] of Eq. 3: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2."""
    return 1 / ((1 - poisson1 ** 2) / young1 + (1 - poisson2 ** 2) / young2)


def eq7_damping_ratio(young, radius, mass, overlap, damping_constant=DAMPING_CONSTANT):
    """Damping ratio c / (2 sqrt(m* k_n)) of Eq. 7 at `overlap` [m], for E* `young` [Pa], R* `radius` [m] and
    m* `mass` [kg]: c = k0 A sqrt(delta), k_n = (3/2) k0 sqrt(delta), k0 = (4/3) E* sqrt(R*)."""
    k0 = 4 / 3 * young * math.sqrt(radius)
    return damping_constant * math.sqrt(k0) * overlap ** 0.25 / math.sqrt(6 * mass)


def resting_overlap(young, radius, load):
    """Hertz overlap [m] under a normal `load` [N]: k0 delta^1.5 = load."""
    return (load / (4 / 3 * young * math.sqrt(radius))) ** (2 / 3)


def mindlin_betan(damping_constant=DAMPING_CONSTANT):
    """{"bear-bear": betan, "bear-wall": betan}: YADE's Hertz-Mindlin damping ratios matched to Eq. 7 at the
    overlap under one bear's weight (module docstring), with their reference overlaps [m] as
    {"bear-bear overlap": ..., "bear-wall overlap": ...}."""
    mass = PARTICLE["density"] * 4 / 3 * math.pi * RADIUS ** 3
    result = {}
    for pair, partner, radius, reduced_mass in (("bear-bear", PARTICLE, RADIUS / 2, mass / 2),
                                                ("bear-wall", BOX, RADIUS, mass)):
        young = effective_young(PARTICLE["young"], PARTICLE["poisson"], partner["young"], partner["poisson"])
        overlap = resting_overlap(young, radius, mass * GRAVITY)
        result[pair] = eq7_damping_ratio(young, radius, reduced_mass, overlap, damping_constant)
        result[pair + " overlap"] = overlap
    return result


# --- scenes -----------------------------------------------------------------------------------------------

def _new_scene():
    """Resets O; the two materials and S1's box. Returns (particle material id, box material id)."""
    O.reset()
    particle = O.materials.append(FrictMat(frictionAngle=0, label="particle", **PARTICLE))
    box = O.materials.append(FrictMat(frictionAngle=0, label="box", **BOX))
    O.bodies.append([utils.wall(0, axis=2, sense=1, material=box),
                     utils.wall(-HALF_BASE, axis=0, sense=1, material=box),
                     utils.wall(HALF_BASE, axis=0, sense=-1, material=box),
                     utils.wall(-HALF_BASE, axis=1, sense=1, material=box),
                     utils.wall(HALF_BASE, axis=1, sense=-1, material=box)])
    O.dt = TIME_STEP
    return particle, box


def _set_engines(bounds, geometries, particle, box, verlet_distance=-0.5):
    """YADE's engines for S1: collider (verlet_distance as InsertionSortCollider.verletDist: negative is a
    fraction of the smallest sphere's radius, YADE's default), Hertz-Mindlin with the damping of mindlin_betan,
    NewtonIntegrator without numerical damping."""
    betan = mindlin_betan()
    physics = Ip2_FrictMat_FrictMat_MindlinPhys(
        betan=MatchMaker(matches=((particle, particle, betan["bear-bear"]), (particle, box, betan["bear-wall"]))),
        betas=0)
    O.engines = [ForceResetter(), InsertionSortCollider(bounds, verletDist=verlet_distance),
                 InteractionLoop(geometries, [physics], [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 NewtonIntegrator(damping=0, gravity=(0, 0, -GRAVITY))]


def _pose(pose):
    """(Vector3 position, Quaternion, Vector3 velocity, Vector3 angular velocity) of a pose."""
    position, (w, x, y, z), velocity, angular = pose
    ori = Quaternion(w, x, y, z)
    ori.normalize()
    return Vector3(*position), ori, Vector3(*velocity), Vector3(*angular)


def build_spheres(poses):
    """S1 with one sphere of radius r per pose (resets O): the sphere has the bear's mass (r is its
    volume-equivalent radius), orientation and velocities. Returns the bodies' ids."""
    particle, box = _new_scene()
    ids = []
    for pose in poses:
        position, ori, velocity, angular = _pose(pose)
        body = utils.sphere(position, RADIUS, material=particle)
        body.state.ori = ori
        ids.append(O.bodies.append(body))
        scene.set_velocity(ids[-1], velocity, angular)
    _set_engines([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()], [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                 particle, box)
    return ids


def build_rounded(poses, name="gummy_bear", nodes=None, **engine_options):
    """S1 with one rounded body of Mesh.reference_shape(name, nodes) per pose (resets O), with S1's HertzMaterials
    (Eq. 7 damping A on both) and the roundedmesh engine (roundedmesh.engine's options, e.g. regime): the
    representation the others are compared with. The poses are of the default mesh's principal frame; a mesh of
    other `nodes` has its own (its axes may even be ordered otherwise), so each body is placed where its smooth
    shape coincides with the default mesh's. name 'sphere': a sphere body of radius RADIUS (scene.add_sphere) per
    pose. Returns the bodies' ids."""
    O.reset()
    particle = HertzMaterial(damping=DAMPING_CONSTANT, **PARTICLE)
    if name == "sphere":
        def add(position, ori):
            return scene.add_sphere(position, RADIUS, particle, ori=ori)
    else:
        mesh, _, own_axes, own_centroid = body_frame(name, nodes)
        _, _, axes, centroid = body_frame(name)
        turn = Quaternion(Matrix3(*(axes.T @ own_axes).flatten()))  # this mesh's frame -> the default mesh's
        shift = axes.T @ (own_centroid - centroid)                  # its origin in the default mesh's frame [m]

        def add(position, ori):
            return scene.add_body(mesh, position + ori * Vector3(*shift), ori * turn, particle)
    ids = []
    for pose in poses:
        position, ori, velocity, angular = _pose(pose)
        body = add(position, ori)
        scene.set_velocity(body, velocity, angular)
        ids.append(body)
    for wall in (utils.wall(0, axis=2, sense=1), utils.wall(-HALF_BASE, axis=0, sense=1),
                 utils.wall(HALF_BASE, axis=0, sense=-1), utils.wall(-HALF_BASE, axis=1, sense=1),
                 utils.wall(HALF_BASE, axis=1, sense=-1)):
        scene.assign_material(O.bodies.append(wall), HertzMaterial(damping=DAMPING_CONSTANT, **BOX))
    O.engines = [ForceResetter(), scene.engine(**engine_options), NewtonIntegrator(damping=0, gravity=(0, 0, -GRAVITY))]
    O.dt = TIME_STEP
    return ids


def add_clump(centres, radii, position, ori, material, mass, discretization=30):
    """Appends to O a clump of spheres of `radii` [m] at body-frame `centres` [m] (clump_spheres) for a body at
    `position` [m] turned by `ori` (Quaternion), of FrictMat id `material`, with mass `mass` [kg] and the principal
    inertia YADE integrates for the union (O.bodies.appendClumped on a grid of `discretization` cells) scaled to
    that mass; every member's own mass is set to the clump's (build_clumps). Returns (clump id, member ids)."""
    rotation = np.array(ori.toRotationMatrix())
    members = [utils.sphere(Vector3(*(np.array(position) + rotation @ c)), float(rho), material=material)
               for c, rho in zip(centres, radii)]
    clump, member_ids = O.bodies.appendClumped(members, discretization=discretization)
    state = O.bodies[clump].state
    state.inertia = state.inertia * (mass / state.mass)
    state.mass = mass
    for member in member_ids:
        O.bodies[member].state.mass = mass
    return clump, member_ids


def build_clumps(poses, count=40, name="gummy_bear", discretization=30, method=None):
    """S1 with one clump of `count` spheres (clump_spheres, by `method`) per pose (resets O); returns the clumps'
    ids.

    The members stand exactly where the pose puts the shape's primitives. YADE puts the clump's own frame at
    the principal axes of the members' union, integrated on a grid of `discretization` cells across the
    clump's smallest extent (O.bodies.appendClumped), so the clump's position and orientation differ slightly
    from the pose's; its velocity is the pose's rigid motion at that position. Mass: the union of spheres is a
    little smaller than the shape (clump_spheres), so the clump's mass is set to the shape's and its principal
    inertia scaled alike: the packing's weight, hence its overlaps, stay those of the rounded bodies. Each
    member's own mass, which YADE's dynamics ignore but Law2_ScGeom_MindlinPhys_Mindlin reads for the damping
    coefficient (2 betan sqrt(m* k_n)), is set to the clump's, so that betan means for the clump what it means
    for the body (module docstring)."""
    particle, box = _new_scene()
    centres, radii = clump_spheres(name, count, method)
    mass = PARTICLE["density"] * body_frame(name)[0].volume
    ids = []
    for pose in poses:
        position, ori, velocity, angular = _pose(pose)
        clump, _ = add_clump(centres, radii, position, ori, particle, mass, discretization)
        scene.set_velocity(clump, velocity + angular.cross(O.bodies[clump].state.pos - position), angular)
        ids.append(clump)
    _set_engines([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()], [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                 particle, box)
    return ids


def level_set_from_distance(distance, low, high, spacing=1e-3, surface_nodes=511):
    """A YADE LevelSet of any shape given by its signed distance: `distance` maps body-frame points (n, 3) [m] to
    (n,) signed distances [m], negative inside, and is sampled once on a regular grid of `spacing` [m] that
    covers the box `low`..`high` (3,) [m] the surface lies in and 3 cells more on every side, so that the grid
    brackets the surface with outside nodes everywhere. YADE ray-traces the boundary nodes from the body-frame
    origin along `surface_nodes` rays on a spiral (nodesPath = 2); a ray keeps every crossing of the surface, so
    a shape that is not star-shaped from the origin gets more nodes than asked for (YADE warns about it)."""
    low = np.asarray(low, dtype=float) - 3 * spacing
    counts = np.ceil((np.asarray(high, dtype=float) + 3 * spacing - low) / spacing).astype(int) + 1
    axes = [low[i] + spacing * np.arange(counts[i]) for i in range(3)]
    points = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    field = np.asarray(distance(points), dtype=float).reshape(*counts)
    grid = RegularGrid(min=Vector3(*low), nGP=Vector3i(*(int(n) for n in counts)), spacing=spacing)
    shape = LevelSet(lsGrid=grid, distField=field.tolist(), nSurfNodes=surface_nodes, nodesPath=2)
    shape.volume()  # LevelSet::init: the surface nodes and the voxel volume, once for every body sharing it
    return shape


def level_set_shape(name="gummy_bear", spacing=1e-3, surface_nodes=511):
    """A YADE LevelSet of shape `name` in its body frame (level_set_from_distance): shape_distance on a regular
    grid of `spacing` [m] covering the mesh's box and 3 cells more, and `surface_nodes` ray-traced boundary
    nodes. The gummy bear, not star-shaped from its centre, gets 527 nodes from 511 rays. At 1 mm the trilinear
    interpolation of f puts the nodes within 0.06 mm of f = 0. A study grain: level_set_from_mesh of its
    2200-node mesh in the body frame of its reference mesh."""
    if name in grains.NAMES:
        return level_set_from_mesh(*fill_surface(name), spacing, surface_nodes)
    vertices = np.array(shapes.mesh_with_scale(name)[0].vertices)
    return level_set_from_distance(lambda points: shape_distance(name, points), vertices.min(axis=0),
                                   vertices.max(axis=0), spacing, surface_nodes)


def level_set_from_mesh(vertices, triangles, spacing=1e-3, surface_nodes=511):
    """A YADE LevelSet of any closed, outward-oriented triangle mesh (`vertices` (v, 3) [m] in the body frame,
    `triangles` (t, 3) int), as a user would build one from a mesh: the mesh's exact signed distance
    (mesh_distance.signed_distance) on a grid of `spacing` [m] over the mesh's box and 3 cells more
    (level_set_from_distance), `surface_nodes` ray-traced boundary nodes. The zero surface is the trilinear
    interpolation of the exact distance, so it departs from the mesh between grid nodes, most where the mesh
    has its edges: for Mesh.icosphere(0.025, 3) (1280 triangles) at 1 mm the boundary nodes lie within 0.04 mm
    of the mesh and LevelSet.volume() is the mesh's to 2e-5 (320 triangles: 0.08 mm, 1.5e-4; at 2 mm, 9e-4).
    Cost: nearly all in the distances, 4.7 s on one core for that 1280-triangle sphere at 1 mm (57^3 nodes)."""
    vertices = np.asarray(vertices, dtype=float)
    return level_set_from_distance(lambda points: signed_distance(vertices, triangles, points),
                                   vertices.min(axis=0), vertices.max(axis=0), spacing, surface_nodes)


def add_level_set_body(shape, position, ori, material, mass, inertia):
    """Appends to O a body of LevelSet `shape` (level_set_shape, may be shared) at `position` [m] turned by `ori`
    (Quaternion), of FrictMat id `material`, mass `mass` [kg] and principal inertia `inertia` (3,) [kg m^2].
    Returns its id."""
    body = Body()
    body.shape = shape
    body.material = O.materials[material]
    body.state = body.material.newAssocState()
    body.state.mass = mass
    body.state.inertia = Vector3(*inertia)
    body.aspherical = True
    body.state.pos = body.state.refPos = position
    body.state.ori = body.state.refOri = ori
    return O.bodies.append(body)


def build_level_sets(poses, name="gummy_bear", spacing=1e-3, surface_nodes=511, verlet_distance=0.0):
    """S1 with one level-set body per pose (resets O), all sharing one LevelSet (level_set_shape): the
    distance field and nodes utils.levelSetBody would build once per body, read-only during the step. Mass
    and principal inertia are the mesh's, as for the rounded bodies (the grid is in the mesh's body frame):
    YADE's voxel sums (LevelSet.volume, inertia) give 2.4 % more volume (f = 0 encloses the inscribed mesh)
    and put the centre half a cell off (a voxel counts by its lowest corner). The collider's verletDist is
    `verlet_distance` [m]; 0 is what YADE falls back to without spheres (given here to skip its warning), and
    the quickest on the settled packing: 0, 1, 2.5 and 5 mm took 47, 51, 60 and 63 CPU ms per step, since
    Ig2_LevelSet_LevelSet_ScGeom visits the nodes inside the overlap of the two bounds, which a larger
    distance inflates. Returns the bodies' ids."""
    particle, box = _new_scene()
    shape = level_set_shape(name, spacing, surface_nodes)
    mesh = body_frame(name)[0]
    density = PARTICLE["density"]
    ids = []
    for pose in poses:
        position, ori, velocity, angular = _pose(pose)
        body = add_level_set_body(shape, position, ori, particle, density * mesh.volume,
                                  density * np.array(mesh.inertia))
        scene.set_velocity(body, velocity, angular)
        ids.append(body)
    _set_engines([Bo1_LevelSet_Aabb(), Bo1_Wall_Aabb()], [Ig2_LevelSet_LevelSet_ScGeom(), Ig2_Wall_LevelSet_ScGeom()],
                 particle, box, verlet_distance)
    return ids
