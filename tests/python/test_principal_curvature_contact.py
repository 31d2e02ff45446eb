"""Principal curvatures and Hertz's contact ellipse (issue 13): Mesh.principal_curvatures / principal_directions
and the contact option curvature='principal' (engine, body_contact, sphere_contact, plane_contact), against
exact elliptical Hertz on the S5 scenes of roundedmesh_study.validation (E* = 0.5 Pa, curvature prescribed unless
said). NRMSE is over the whole S5 sweep (overlap to 7.5 % of a, resp. of R), worst of the 3 axis poses
(validation.axis_poses, seed 1). The full tables come from scripts/validation/validate_body_contact.py."""
import math
import pickle

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh_study import hertz_reference as hr
from roundedmesh_study import validation as v
from roundedmesh_study.analytic import elliptical_hertz_force, nrmse, spheroid_pair_radii

PRINCIPAL = {"curvature": "principal"}

# --- the principal curvatures of the generators ------------------------------------------------------------


def test_icosphere_principal_curvatures_are_one_over_r():
    mesh = rm.Mesh.icosphere(0.5, 3)
    np.testing.assert_allclose(mesh.principal_curvatures, 2.0, rtol=1e-12)


def test_cylinder_principal_curvatures_hull_and_caps():
    mesh = rm.Mesh.cylinder(v.CYLINDER_RADIUS, v.CYLINDER_LENGTH, 642)
    k = np.asarray(mesh.principal_curvatures)
    normals = np.asarray(mesh.normals)
    # the mesh is in its principal frame (L = 4 R): the axis is the one of the largest extent
    vertices = np.asarray(mesh.vertices)
    axis = int(np.argmax(vertices.max(axis=0) - vertices.min(axis=0)))
    cap = np.abs(normals[:, axis]) > 1 - 1e-9
    assert cap.any() and (~cap).any()
    np.testing.assert_allclose(k[~cap], np.tile([1 / v.CYLINDER_RADIUS, 0.0], ((~cap).sum(), 1)), atol=1e-12)
    np.testing.assert_array_equal(k[cap], 0.0)
    # k1 runs around the axis on the hull
    assert np.abs(np.asarray(mesh.principal_directions)[~cap, axis]).max() < 1e-9


def _principal_of_quadric(f, point, step=1e-2):
    """(k_max, k_min) [1/m] of the quadric f = 0 at `point`, as hertz_reference.principal_curvatures computes them
    (shape operator P H P / |grad f|, tangent eigenvalues) but with central differences of step 1e-2 m: exact for
    a quadratic f (no truncation error), and the round-off, ~1e-16 / step^2 = 1e-12 relative, is far below the
    1e-9 asked -- the default step 1e-5 would leave 1e-6."""
    _, gradient, hessian = hr.derivatives(f, point, step)
    normal = gradient / np.linalg.norm(gradient)
    projection = np.eye(3) - np.outer(normal, normal)
    tensor = projection @ hessian @ projection / np.linalg.norm(gradient)
    curvatures, _ = hr.tangent_principal(0.5 * (tensor + tensor.T), normal)
    return curvatures[::-1]


def test_spheroid_principal_curvatures_are_the_implicit_surfaces():
    # Mesh.spheroid(a, b) is generated with its axis along z, then stored in its principal frame: a generator
    # point is orientation * x + centroid. Its exact curvatures are those of the surface point under each
    # triangle's centroid (Newton along grad f, hertz_reference.project_to_surface, as the generator does).
    a, b = 2.0, 1.0
    mesh = rm.Mesh.spheroid(a, b, 642)

    def f(x):
        x = np.atleast_2d(x)
        return (x[:, 0] ** 2 + x[:, 1] ** 2) / b ** 2 + x[:, 2] ** 2 / a ** 2 - 1

    matrix = mesh.orientation.toRotationMatrix()
    rotation = np.array([[matrix[i, j] for j in range(3)] for i in range(3)])
    vertices = np.asarray(mesh.vertices) @ rotation.T + np.array(mesh.centroid)
    centroids = vertices[np.asarray(mesh.triangles)].mean(axis=1)
    k = np.asarray(mesh.principal_curvatures)
    for t in range(0, len(centroids), 7):
        expected = _principal_of_quadric(f, hr.project_to_surface(f, centroids[t]))
        np.testing.assert_allclose(k[t], expected, rtol=1e-9)


# Estimated from the mesh (Rusinkiewicz's per-face fit of the normals' differences along the edges): on an icosphere
# every node lies on the sphere and the vertex normals (Max's weights, exact for nodes on a sphere) are radial, so
# the normal changes along each edge by exactly edge / R and the fit returns 1/R to round-off -- measured largest
# error 2.4e-15 (162 nodes), 7.1e-15 (642), 3.3e-14 (2562), and 3.7e-14 at 642 nodes with distortion 0.3 (Eq. 1's
# mean curvature on the same meshes: 1.4e-4, 2.4e-5, 6.0e-6). The issue asks for 1 %; 1e-10 keeps four orders
# of magnitude for round-off and would catch any departure from that exactness.
@pytest.mark.parametrize("distortion", [0.0, 0.3])
def test_computed_principal_curvatures_of_an_icosphere(distortion):
    mesh = rm.Mesh.icosphere(1.0, 3, distortion=distortion, curvature="computed")
    assert np.abs(np.asarray(mesh.principal_curvatures) - 1.0).max() <= 1e-10
    assert np.abs(np.asarray(mesh.principal_curvatures) - 1.0).max() <= 0.01   # the bound


def test_pickle_keeps_principal_curvatures_and_directions():
    for mesh in (rm.Mesh.spheroid(2.0, 1.0, 642), rm.Mesh.icosphere(1.0, 2, curvature="computed")):
        copy = pickle.loads(pickle.dumps(mesh))
        np.testing.assert_array_equal(copy.principal_curvatures, mesh.principal_curvatures)
        np.testing.assert_array_equal(copy.principal_directions, mesh.principal_directions)


def test_a_bad_curvature_option_is_refused():
    mesh = v.icosphere_mesh(2)
    with pytest.raises(ValueError, match="curvature"):
        rm.body_contact(mesh, Vector3(0, 0, 0), Quaternion.Identity, mesh, Vector3(0, 0, 1.9), Quaternion.Identity,
                        v.PAIR_MATERIAL, v.PAIR_MATERIAL, curvature="bad")
    with pytest.raises(ValueError, match="curvature"):
        rm.engine(curvature="bad")


# --- the crossed spheroids' reference ---------------------------------------------------------------------

# spheroid_relative_radii (Johnson's relative radii at the crossing angle) is Fig. 7's analytic pair at 0 deg,
# and a circle of radius 1/(1/b + b/a^2) at 90 deg, where each body's large curvature meets the other's small one.
@pytest.mark.parametrize("ratio", [1.0, 2.0, 4.0, 16.0])
def test_crossed_reference_radii(ratio):
    a, b = math.sqrt(ratio) * v.S5_SEMI_MINOR, v.S5_SEMI_MINOR
    np.testing.assert_allclose(v.spheroid_relative_radii(ratio, 0.0), spheroid_pair_radii(a, b), rtol=1e-14)
    np.testing.assert_allclose(v.spheroid_relative_radii(ratio, math.pi / 2), [1 / (1 / b + b / a ** 2)] * 2,
                               rtol=1e-12)
    r45 = v.spheroid_relative_radii(ratio, math.pi / 4)
    assert r45[0] >= r45[1]
    assert 1 / r45[0] + 1 / r45[1] == pytest.approx(2 * (1 / b + b / a ** 2), rel=1e-14)  # the trace: any angle


# --- contacts against Hertz --------------------------------------------------------------------------------

# On a sphere (prescribed curvature) both principal curvatures are 1/R: the ellipse is the circle and the
# principal model must give the mean model's forces, up to round-off (measured 1.3e-15 relative at most).
@pytest.mark.parametrize("partner", ["mesh", "sphere"])
def test_spheres_give_the_same_forces_as_the_mean_model(partner):
    mean = v.sphere_pair(3, partner, poses=3)
    principal = v.sphere_pair(3, partner, poses=3, **PRINCIPAL)
    np.testing.assert_allclose(principal.forces, mean.forces, rtol=1e-12, atol=1e-12 * np.abs(mean.forces).max())


# Parallel long axes (Fig. 7 with the ellipse). 642 nodes hold the bounds: measured worst of 3 poses
# 0.66 % (ratio 4) and 0.93 % (ratio 16) at 642 nodes, 0.14 % and 0.14 % at 2562 -- the mean model 6.1 % and
# 20 % (its circle cannot follow the ellipse). The bounds are the issue's: 1 % at ratio 4, 2 % at ratio 16.
@pytest.mark.parametrize("ratio, bound", [(4.0, 0.01), (16.0, 0.02)])
def test_parallel_spheroids_follow_elliptical_hertz(ratio, bound):
    s = v.spheroid_pair(ratio, 642, **PRINCIPAL)
    assert s.worst <= bound, s.errors
    assert s.increasing().all()


# Crossed long axes (spheroid_pair(angle=...)), 2562 nodes, pressed to 7.5 % of b, the semi-axis both bodies share
# across the contact. Over Fig. 7's range, 7.5 % of a, the crossed contact grows to 0.35 b (ratio 4) and 0.53 b
# (ratio 16) in radius, far outside the small-contact range of Hertz's quadratic gap (the parallel pair's ellipse
# stays within 0.30 b across): there both models fall below the reference alike (ratio 16 at 90 deg, where the
# ellipse is the mean model's circle: principal 3.76 %, mean 3.50 %; F/F_exact 0.91 at 30 % of b). Over 7.5 % of b
# (contact radius at most 0.27 b) the bounds hold: measured worst of 3 poses 0.49 % (45 deg) and 0.68 %
# (90 deg) at ratio 4, 1.28 % and 1.20 % at ratio 16; the mean model 2.55 / 0.76 / 6.09 / 1.31 %. 642 nodes are too
# coarse across a ratio-16 spheroid (4.8 %).
@pytest.mark.parametrize("ratio, angle, bound", [(4.0, 45, 0.01), (4.0, 90, 0.01), (16.0, 45, 0.02), (16.0, 90, 0.02)])
def test_crossed_spheroids_follow_elliptical_hertz(ratio, angle, bound):
    s = v.spheroid_pair(ratio, 2562, poses=2, angle=math.radians(angle), max_overlap=v.S5_MAX_OVERLAP * v.S5_SEMI_MINOR,
                        **PRINCIPAL)
    assert s.worst <= bound, s.errors


# At 90 deg the ellipse is the circle of the mean model (both relative radii 1/(1/b + b/a^2)), so whatever
# falls short of Hertz there is not the ellipse's: the principal model stays within 0.5 percentage points of the
# mean model (measured 642 nodes, worst: ratio 4 1.24 against 1.17 %, ratio 16 4.19 against 3.92 %).
@pytest.mark.parametrize("ratio", [4.0, 16.0])
def test_crossed_at_90_degrees_principal_matches_mean(ratio):
    mean = v.spheroid_pair(ratio, 642, angle=math.pi / 2)
    principal = v.spheroid_pair(ratio, 642, angle=math.pi / 2, **PRINCIPAL)
    assert principal.worst <= mean.worst + 0.005


# Against a plane (rm.plane_contact, curvature='principal'): a spheroid of ratio 4 lying on its side, pressed to 5 %
# of b; reference elliptical Hertz with the body's own radii (a^2/b, b) (the plane adds no curvature), E* = 0.5 Pa.
# Measured worst of 3 poses: principal 0.40 % at 2562 nodes (1.9 % at 642 nodes, hence the finer mesh), mean
# 6.6 %. Bound: the 1 % for ratio 4.
def test_spheroid_on_a_plane_follows_elliptical_hertz():
    ratio = 4.0
    mesh = v.spheroid_mesh(ratio, 2562)
    a, b = math.sqrt(ratio) * v.S5_SEMI_MINOR, v.S5_SEMI_MINOR
    overlaps = np.linspace(0, 0.05 * b, 26)[1:]
    reference = elliptical_hertz_force(v.PAIR_MODULUS, a * a / b, b, overlaps)
    for angle, _ in v.axis_poses(3):
        ori = v.aligned(mesh, 0, angle)
        forces = [rm.plane_contact(mesh, Vector3(0, 0, b - d), ori, Vector3(0, 0, 0), Vector3(0, 0, 1), v.PAIR_MATERIAL,
                                   v.PAIR_MATERIAL, **PRINCIPAL)[0][2] for d in overlaps]
        assert nrmse(forces, reference) <= 0.01, angle


@pytest.fixture(scope="module")
def cylinders():
    return {(arrangement, curvature): v.cylinder_pair(arrangement, 642, curvature=curvature)
            for arrangement in ("crossed", "parallel") for curvature in ("mean", "principal")}


# Parallel cylinders: the ellipse's long axis follows the hull (k2 = 0), so the stiffness comes close to Eq. 27
# (measured per pose -2.4, +3.3, +2.4 % at 642 nodes, -0.1..+3.6 % at 2562, -2.0..+1.4 % at 10284; an earlier
# build of the feature gave +3.2..+4.0 % at 642 and up to +5.3 % at 2562 and 10284; the mean model's circle gives
# -24 %, the paper's "about 23 %"). The bound: 5 %.
def test_parallel_cylinders_stiffness_within_5_percent(cylinders):
    errors = cylinders["parallel", "principal"].stiffness_errors()
    assert np.abs(errors).max() <= 0.05, errors


# Crossed cylinders: the relative curvature is 1/R in every direction, a circle; the ellipse must not make it
# worse than the mean model by more than 0.5 percentage points of NRMSE against sphere-on-plane Hertz (measured
# worst at 642 nodes: principal 0.90 %, mean 1.35 %; 2562 nodes 1.61 against 1.70 %).
def test_crossed_cylinders_unchanged(cylinders):
    assert cylinders["crossed", "principal"].worst <= cylinders["crossed", "mean"].worst + 0.005


# --- in a YADE scene ---------------------------------------------------------------------------------------

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2)
STIFF = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-2)
GRAVITY = 9.81


# A 642-node prolate spheroid (a = 2 cm, b = 1 cm) dropped from 0.1 mm onto a Wall, lying on its side (its long
# axis is x in its principal frame), with NewtonIntegrator damping 0.3 and the contacts' normal damping, free to
# rock and slide: the ellipse under it must carry its weight once settled. Step by step the floor's force keeps a
# jitter of a few 1e-4 m g after settling, with either curvature model (measured: up to 5e-4 principal, 7e-4 mean,
# over 6000 steps), so the force is averaged over 200 steps (measured deviation of the average ~1e-5); bound 1e-3.
@pytest.mark.slow
def test_spheroid_resting_on_a_wall_carries_its_weight():
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(floor, STIFF)
    mesh = rm.Mesh.spheroid(0.02, 0.01, 642)
    body = rm.add_body(mesh, pos=(0, 0, 0.0101), material=RUBBER)
    O.engines = [ForceResetter(), rm.engine(curvature="principal"),
                 NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0.3)]
    O.dt = 0.2 * rm.critical_timestep()
    O.run(2300, True)
    floor_force = []
    for _ in range(200):
        O.run(1, True)
        floor_force.append(O.forces.f(floor)[2])
    weight = O.bodies[body].state.mass * GRAVITY
    found = rm.contacts()
    assert len(found["id1"]) == 1
    # the contact list and the floor's force are the same numbers
    assert abs(found["force1"][:, 2].sum() + found["force2"][:, 2].sum()) <= 1e-12 * weight
    assert abs(abs(found["force1"][0, 2]) - abs(floor_force[-1])) <= 1e-9 * weight
    assert -np.mean(floor_force) == pytest.approx(weight, rel=1e-3)


# Two spheroids crossed at 90 deg, one resting on the other on a Wall: the engine runs the principal model between
# rounded bodies in a scene, and the stack settles with the weight of both on the floor.
def test_two_crossed_spheroids_settle_on_a_wall():
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(floor, STIFF)
    mesh = rm.Mesh.spheroid(0.02, 0.01, 642)
    lower = rm.add_body(mesh, pos=(0, 0, 0.0101), material=RUBBER)
    upper = rm.add_body(mesh, pos=(0, 0, 0.0302), ori=Quaternion(Vector3(0, 0, 1), math.pi / 2), material=RUBBER)
    O.engines = [ForceResetter(), rm.engine(curvature="principal"),
                 NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0.3)]
    O.dt = 0.2 * rm.critical_timestep()
    for b in (lower, upper):
        O.bodies[b].state.blockedDOFs = "xyXYZ"     # keep the stack upright: the test is about the contacts
    O.run(3000, True)
    weight = (O.bodies[lower].state.mass + O.bodies[upper].state.mass) * GRAVITY
    pairs = {tuple(sorted((int(i), int(j)))) for i, j in zip(rm.contacts()["id1"], rm.contacts()["id2"])}
    assert pairs == {tuple(sorted((lower, upper))), tuple(sorted((lower, floor)))}
    assert abs(O.forces.f(floor)[2]) == pytest.approx(weight, rel=1e-3)


# Mesh.reference_shape(curvature='exact'): each triangle's principal curvatures are the smooth shape's at the point
# of f = 0 under its centroid (pkg/meshing/ImplicitCurvature.cpp, central differences of step 1e-4 of the thinnest
# primitive), against hertz_reference's own central differences of the same function (peers.shape_distance, in
# metres) at 40 triangles. Measured: median 2.5e-7, 90 % below 2.4e-6, worst 6.2e-6 of 1/r_eq; bounds 1e-5 and
# 1e-4 leave room for the blend's polynomial smooth minimum, whose second derivatives jump at the edges of its
# 2.7 mm band, where either step can straddle an edge.
def test_exact_reference_shape_curvatures_are_the_implicit_functions():
    from roundedmesh_study import hertz_reference as hr, peers
    mesh = rm.Mesh.reference_shape("gummy_bear", curvature="exact")
    assert mesh.curvature_mode == "prescribed"
    np.testing.assert_allclose(mesh.curvatures, mesh.principal_curvatures.mean(axis=1), rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(mesh.vertices, rm.Mesh.reference_shape("gummy_bear").vertices)  # the same mesh
    distance = lambda points: peers.shape_distance("gummy_bear", points)  # noqa: E731  body frame, metres
    errors = []
    for t in np.linspace(0, len(mesh.triangles) - 1, 40).astype(int):
        point = hr.project_to_surface(distance, mesh.vertices[mesh.triangles[t]].mean(axis=0))
        (k_min, k_max), _, _ = hr.principal_curvatures(distance, point)
        k1, k2 = mesh.principal_curvatures[t]
        errors.append(max(abs(k1 - k_max), abs(k2 - k_min)) * 0.025)  # in units of 1/r_eq, r_eq = 25 mm
    errors = np.array(errors)
    assert np.median(errors) < 1e-5, errors
    assert errors.max() < 1e-4, errors


def test_a_bad_reference_curvature_is_refused():
    with pytest.raises(ValueError, match="curvature"):
        rm.Mesh.reference_shape("gummy_bear", curvature="smooth")
