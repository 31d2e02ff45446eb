"""YADE's representations of the gummy bear for the S1 speed comparison (roundedmesh_study.peers): the clump's spheres
against the mesh they stand for, the level set's distance field, the damping mapping, and a few steps of each
builder on four hand-made poses."""
import math

import numpy as np
import pytest
from yade import O

import roundedmesh as rm
from roundedmesh_study import peers

MESH = rm.Mesh.reference_shape("gummy_bear")
DENSITY = peers.PARTICLE["density"]


def winding_numbers(points, vertices, triangles):
    """Generalised winding number of the closed mesh about each point (1 inside, 0 outside): the solid angle
    of every triangle seen from the point (Van Oosterom and Strackee), summed over 4 pi. Independent of the
    shape function the clumps are built from."""
    a, b, c = (vertices[triangles[:, i]][None, :, :] - points[:, None, :] for i in range(3))
    la, lb, lc = (np.linalg.norm(v, axis=2) for v in (a, b, c))
    numerator = np.einsum("ptk,ptk->pt", a, np.cross(b, c))
    denominator = (la * lb * lc + np.einsum("ptk,ptk->pt", a, b) * lc + np.einsum("ptk,ptk->pt", b, c) * la
                   + np.einsum("ptk,ptk->pt", c, a) * lb)
    return 2 * np.arctan2(numerator, denominator).sum(axis=1) / (4 * math.pi)


def union_mass_properties(centres, radii, spacing):
    """(volume [m^3], centroid [m], geometric inertia tensor about it [m^5]) of the union of spheres, by
    counting the centres of cubic cells of `spacing` inside any sphere."""
    low, high = (centres - radii[:, None]).min(axis=0), (centres + radii[:, None]).max(axis=0)
    axes = [np.arange(low[i], high[i], spacing) + spacing / 2 for i in range(3)]
    points = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    inside = np.zeros(len(points), dtype=bool)
    for centre, radius in zip(centres, radii):
        inside |= ((points - centre) ** 2).sum(axis=1) < radius ** 2
    cells = points[inside]
    centroid = cells.mean(axis=0)
    d = cells - centroid
    inertia = (np.eye(3) * (d * d).sum() - d.T @ d) * spacing ** 3
    return inside.sum() * spacing ** 3, centroid, inertia


@pytest.mark.parametrize("count", peers.CLUMP_COUNTS)
def test_clump_has_count_spheres_centred_inside_the_mesh_and_mirror_symmetric(count):
    centres, radii = peers.clump_spheres("gummy_bear", count)
    assert centres.shape == (count, 3) and radii.shape == (count,)
    assert np.all(radii > 0)
    winding = winding_numbers(centres, np.array(MESH.vertices), np.array(MESH.triangles))
    np.testing.assert_allclose(winding, 1, atol=1e-6)
    # The bear's mirror plane x = 0 (shape units) is the body's y = 0 plane within 0.03 degrees (its principal
    # axes): reflecting the clump through it gives the clump again, to 0.1 mm.
    mirrored = centres * np.array([1, -1, 1])
    distances = np.linalg.norm(mirrored[:, None, :] - centres[None, :, :], axis=2)
    assert distances.min(axis=1).max() < 1e-4


def test_clump_of_40_spheres_has_the_mass_properties_of_the_mesh():
    centres, radii = peers.clump_spheres("gummy_bear", 40)
    volume, centroid, inertia = union_mass_properties(centres, radii, 0.5e-3)
    # The union of spheres lacks the smooth blends (-) and is scalloped between chain spheres (-), while the
    # mesh is inscribed in the smooth surface and 2.4 % smaller than it (+): +0.7 % measured; 3 % leaves room
    # for the 0.5 mm cells (about 0.2 %).
    assert volume == pytest.approx(MESH.volume, rel=0.03)
    # The centroid is the body frame's origin: within 0.5 mm (measured 0.04 mm), 2 % of the bear's thickness.
    assert np.linalg.norm(centroid) < 0.5e-3
    # Principal moments: the same mass excess lies at the outside, +3 % measured; 6 % allowed.
    np.testing.assert_allclose(np.diag(inertia), MESH.inertia, rtol=0.06)
    # Principal axes: the body axes within 1 degree (measured 0.11): the products of inertia are small
    # against the differences of the moments (they differ by 16 % or more).
    moments, axes = np.linalg.eigh(inertia)
    np.testing.assert_allclose(moments, MESH.inertia, rtol=0.06)
    assert np.degrees(np.arccos(np.abs(np.diag(axes)).min())) < 1.0


def test_clump_counts_follow_the_segment_lengths():
    # 40 spheres: 3 spheres and 37 over the capsules by length (body 0.55, arms 0.375, legs 0.31, head 0.2
    # shape units): 8 + 8 + 3 (head) + 5 + 5 + 4 + 4, mirror pairs alike.
    np.testing.assert_array_equal(peers._chain_counts(np.array([0.55, 0.55, 0.2, 0.375, 0.375, 0.31, 0.31]),
                                                      np.array([0.32, 0.32, 0.3, 0.13, 0.13, 0.17, 0.17]), 37),
                                  [8, 8, 3, 5, 5, 4, 4])
    with pytest.raises(ValueError, match="at least 10"):
        peers.clump_spheres("gummy_bear", 9)


def test_shape_distance_is_zero_on_the_mesh_nodes_and_a_distance_off_them():
    vertices = np.array(MESH.vertices)
    assert np.abs(peers.shape_distance("gummy_bear", vertices)).max() < 1e-12
    # 1 mm off each node along its triangles' mean normal: |f| cannot exceed the distance to the node, which lies
    # on the surface (f is 1-Lipschitz), and has the sign of the side.
    normals = np.zeros_like(vertices)
    for corner in range(3):
        np.add.at(normals, np.array(MESH.triangles)[:, corner], np.array(MESH.normals))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    outside = peers.shape_distance("gummy_bear", vertices + 1e-3 * normals)
    inside = peers.shape_distance("gummy_bear", vertices - 1e-3 * normals)
    assert np.all(outside > 0) and np.all(inside < 0)
    assert np.abs(outside).max() <= 1e-3 * (1 + 1e-9) and np.abs(inside).max() <= 1e-3 * (1 + 1e-9)
    # Away from the blends f is the distance itself: most nodes see 1 mm to 2 %.
    assert np.median(outside) == pytest.approx(1e-3, rel=0.02)


def test_mindlin_damping_ratio_is_eq7s_at_the_resting_overlap():
    betan = peers.mindlin_betan()
    mass = DENSITY * 4 / 3 * math.pi * peers.RADIUS ** 3
    young = 1 / (2 * (1 - 0.4 ** 2) / 1e6)
    k0 = 4 / 3 * young * math.sqrt(peers.RADIUS / 2)
    overlap = betan["bear-bear overlap"]
    assert k0 * overlap ** 1.5 == pytest.approx(mass * peers.GRAVITY, rel=1e-12)  # one bear's weight
    # Eq. 7's damping coefficient against YADE's critical one, 2 sqrt(m* k_n), at that overlap.
    eq7 = k0 * peers.DAMPING_CONSTANT * math.sqrt(overlap)
    critical = 2 * math.sqrt(mass / 2 * 1.5 * k0 * math.sqrt(overlap))
    assert betan["bear-bear"] == pytest.approx(eq7 / critical, rel=1e-12)
    assert 0 < betan["bear-wall"] < 1 and 0 < betan["bear-bear"] < 1


POSES = [((-0.10, 0.00, 0.0145), (1, 0, 0, 0), (0, 0, 0), (0, 0, 0)),              # on the floor, 1.4 mm in
         ((-0.10, 0.00, 0.0460), (1, 0, 0, 0), (0, 0, -0.05), (0, 0, 0)),          # on the first, falling
         ((0.10, 0.10, 0.0500), (math.cos(0.6), math.sin(0.6), 0, 0), (0.1, 0, 0), (0, 0, 2.0)),
         ((0.17, -0.10, 0.0500), (0.5, 0.5, 0.5, 0.5), (0, 0, 0), (1.0, 0, 0))]   # near the wall x = 0.2


@pytest.mark.parametrize("build", [peers.build_spheres, peers.build_clumps,
                                   lambda poses: peers.build_level_sets(poses, spacing=2e-3)],
                         ids=["spheres", "clumps", "level sets"])
def test_builders_run_s1_with_four_bodies(build):
    ids = build(POSES)
    assert len(ids) == 4
    assert sum(type(b.shape).__name__ == "Wall" for b in O.bodies) == 5
    for i in ids:
        assert O.bodies[i].state.mass == pytest.approx(DENSITY * MESH.volume, rel=1e-12)
    O.run(10, True)
    assert all(np.isfinite(tuple(O.bodies[i].state.pos)).all() for i in ids)
    betan = peers.mindlin_betan()
    real = [i for i in O.interactions if i.isReal]
    assert real  # the lowest body rests on the floor
    walls = {b.id for b in O.bodies if type(b.shape).__name__ == "Wall"}
    for interaction in real:
        with_wall = interaction.id1 in walls or interaction.id2 in walls
        assert interaction.phys.betan == pytest.approx(betan["bear-wall" if with_wall else "bear-bear"])
        assert interaction.phys.betas == 0


def test_clumps_members_carry_the_clump_mass_and_the_pose():
    pose = ((0.0, 0.0, 0.1), (math.cos(0.3), 0, math.sin(0.3), 0), (0.1, 0.0, 0.0), (0.0, 0.0, 3.0))
    clump, = peers.build_clumps([pose])
    state = O.bodies[clump].state
    centres, _ = peers.clump_spheres("gummy_bear", 40)
    rotation = np.array(peers._pose(pose)[1].toRotationMatrix())
    members = sorted(O.bodies[clump].shape.members)
    positions = np.array([tuple(O.bodies[m].state.pos) for m in members])
    np.testing.assert_allclose(positions, np.array(pose[0]) + centres @ rotation.T, atol=1e-12)
    assert all(O.bodies[m].state.mass == state.mass for m in members)
    # The clump's own frame, YADE's, is within 0.2 mm of the pose's (the union's centroid, see above) ...
    assert np.linalg.norm(np.array(tuple(state.pos)) - pose[0]) < 2e-4
    # ... and moves with the pose's rigid motion.
    expected = np.array(pose[2]) + np.cross(pose[3], np.array(tuple(state.pos)) - pose[0])
    np.testing.assert_allclose(np.array(tuple(state.vel)), expected, atol=1e-12)
