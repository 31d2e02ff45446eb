"""scripts/examples/example_drum.py, scene S7 of doc/scenes.md (roundedmesh_study.drum): the drum of Facets it makes
(24 panels, two end caps, 4 lifters), the lattice it starts the placement from, the scene it builds for roundedmesh and for YADE's
clumps, the drum turned by RotationEngine in the ParaView export, and a short run from the shipped placement (no pair
deeper than START_OVERLAP at the start): nothing leaves the drum, every output is written and the frames hold the
Facets."""
import csv
import json
import math
import os
import subprocess
import types
import xml.etree.ElementTree as ElementTree

import numpy as np
import pytest
from yade import O, RotationEngine

import roundedmesh as rm
from roundedmesh_study import drum
from test_export import read_piece, rotation

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
SCRIPT = os.path.join(ROOT, "scripts", "examples", "example_drum.py")

RADIUS, LENGTH = 0.15, 0.12  # S7's drum [m]


def test_importing_the_module_does_nothing():
    assert len(O.bodies) == 0 and O.iter == 0 and callable(drum.main)


def triangles():
    return {part: np.array(t) for part, t in drum.drum_triangles().items()}


# S7: 24 flat panels of two Facets at the inner radius 0.15 m, 0.12 m long about y; two end caps; 4 lifters,
# triangular prisms 15 mm high and 10 mm wide at the base, every 90 degrees. Every Facet faces into the drum.
def test_the_drum_is_the_one_s7_asks_for():
    parts = triangles()
    assert {part: len(t) for part, t in parts.items()} == {"mantle": 48, "cap": 48, "lifter": 16}
    mantle = parts["mantle"]
    normals = np.cross(mantle[:, 1] - mantle[:, 0], mantle[:, 2] - mantle[:, 0])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    np.testing.assert_allclose(normals[:, 1], 0, atol=1e-15)  # parallel to the axis
    np.testing.assert_allclose(-np.einsum("ij,ij->i", normals, mantle[:, 0]), RADIUS, rtol=1e-12)  # 0.15 m inside
    angles = np.degrees(np.arctan2(-normals[:, 2], -normals[:, 0])) % 360
    np.testing.assert_allclose(np.sort(angles[::2]), 15 * np.arange(24), atol=1e-9)  # 24 panels
    np.testing.assert_allclose(angles[::2], angles[1::2], atol=1e-9)                   # two Facets each
    assert np.ptp(mantle[:, :, 1]) == pytest.approx(LENGTH) and mantle[:, :, 1].min() == pytest.approx(-LENGTH / 2)
    caps = parts["cap"]
    assert sorted(np.unique(np.round(caps[:, :, 1], 12))) == [-LENGTH / 2, LENGTH / 2]
    cap_normals = np.cross(caps[:, 1] - caps[:, 0], caps[:, 2] - caps[:, 0])
    assert (np.sign(cap_normals[:, 1]) == -np.sign(caps[:, 0, 1])).all()  # into the drum
    area = 0.5 * np.linalg.norm(cap_normals, axis=1).sum() / 2  # one cap: the 24-gon of apothem 0.15 m
    assert area == pytest.approx(24 * RADIUS ** 2 * math.tan(math.pi / 24), rel=1e-12)
    lifters = parts["lifter"]
    radial = np.hypot(lifters[:, :, 0], lifters[:, :, 2])
    assert radial.min() == pytest.approx(RADIUS - 0.015) and radial.max() == pytest.approx(math.hypot(RADIUS, 0.005))
    ridges = lifters[radial == radial.min()]
    np.testing.assert_allclose(sorted(np.degrees(np.arctan2(ridges[:, 2], ridges[:, 0])) % 360 // 1),
                               np.repeat([0, 90, 180, 270], len(ridges) // 4), atol=1)
    for k in range(4):  # the base: 10 mm wide on the panel
        on_panel = lifters[4 * k:4 * k + 4][np.isclose(radial[4 * k:4 * k + 4], math.hypot(RADIUS, 0.005))]
        xz = np.unique(np.round(on_panel[:, [0, 2]], 12), axis=0)
        assert len(xz) == 2 and np.linalg.norm(xz[0] - xz[1]) == pytest.approx(0.010)
    lifter_normals = np.cross(lifters[:, 1] - lifters[:, 0], lifters[:, 2] - lifters[:, 0])
    assert (np.einsum("ij,ij->i", lifter_normals, -lifters.mean(axis=1)) > 0).all()  # away from the mantle


# The lattice: 30 bears, 30 pears and 40 spheres at seeded nodes with seeded orientations, apart at the start size.
def test_the_lattice_holds_the_bodies_apart_at_the_start_size():
    poses = drum.lattice(1)
    kinds = [kind for kind, _, _ in poses]
    assert (kinds.count("gummy_bear"), kinds.count("pear"), kinds.count("sphere")) == (30, 30, 40)
    assert kinds[60:] == ["sphere"] * 40
    centres = np.array([p for _, p, _ in poses])
    reach = np.array([drum.START_SCALE * drum.reach(kind) for kind in kinds])
    gaps = np.linalg.norm(centres[:, None] - centres[None], axis=2) - reach[:, None] - reach[None]
    np.fill_diagonal(gaps, np.inf)
    assert gaps.min() > 0
    assert (np.hypot(centres[:, 0], centres[:, 2]) + reach < RADIUS - 0.015).all()  # clear of the lifters' ridges
    assert (np.abs(centres[:, 1]) + reach < LENGTH / 2).all()
    np.testing.assert_allclose([np.linalg.norm(q) for _, _, q in poses], 1, rtol=1e-14)
    again, other = drum.lattice(1), drum.lattice(2)
    assert all((p == a).all() and (q == b).all() for (_, p, q), (_, a, b) in zip(poses, again))
    assert not all((q == b).all() for (_, _, q), (_, _, b) in zip(poses, other))


def material_record(kind, body_id):
    """The material the scene's tags keep for the body, as values in the order of rm.HertzMaterial.fields."""
    record = json.loads(O.tags[f"roundedmesh.{kind}.{body_id}"])
    record = record["material"] if kind == "body" else record
    assert tuple(record) == rm.HertzMaterial.fields
    return list(record.values())


# S7's scene for roundedmesh: the Facets are partners of E = 5e6 Pa, nu = 0.4, mu = 0.5 turned by RotationEngine at
# 3 rad/s about y through the axis; the bodies E = 1e6 Pa, nu = 0.4, 2000 kg/m^3, A = 0.01 s, mu = 0.5.
def test_the_scene_has_what_s7_asks_for():
    bodies, facets = drum.build_roundedmesh(drum.lattice(1))
    assert len(facets) == 112 and len(bodies) == 100
    meshes = rm.rounded_bodies()
    names = {id(rm.Mesh.reference_shape(name)): name for name in ("gummy_bear", "pear")}
    assert sorted(names[id(mesh)] for mesh in meshes.values()) == ["gummy_bear"] * 30 + ["pear"] * 30
    assert sorted(rm.sphere_bodies().values()) == [0.01] * 40
    assert set(meshes) | set(rm.sphere_bodies()) == set(bodies)
    for body in bodies:
        kind = "body" if body in meshes else "sphere"
        assert material_record(kind, body) == [1e6, 0.4, 2000.0, 0.01, 0.5, 0.0]
    for facet in facets:
        assert material_record("partner", facet) == [5e6, 0.4, 2000.0, 0.01, 0.5, 0.0]
        assert type(O.bodies[facet].shape).__name__ == "Facet"
    engine = next(e for e in O.engines if isinstance(e, RotationEngine))
    assert sorted(engine.ids) == sorted(facets) and engine.angularVelocity == 3 and engine.rotateAroundZero
    assert tuple(engine.rotationAxis) == (0, 1, 0) and tuple(engine.zeroPoint) == (0, 0, 0)
    assert tuple(O.engines[-1].gravity) == (0, 0, -9.81) and O.engines[-1].damping == 0 and O.dt == 1e-4


# The same drum with YADE's own bodies: 40-sphere clumps of the bear, the pear's two spheres, YADE spheres.
def test_the_clumps_scene():
    poses = drum.lattice(1)
    bodies, facets = drum.build_clumps(poses)
    assert len(facets) == 112 and len(bodies) == 100
    members = [len(O.bodies[b].shape.members) if O.bodies[b].isClump else 0 for b in bodies]
    expected = {"gummy_bear": 40, "pear": 2, "sphere": 0}
    assert members == [expected[kind] for kind, _, _ in poses]
    used = {O.bodies[i].material.label for i in facets} | {b.material.label for b in O.bodies if b.isClumpMember}
    assert used == {"particle", "drum"}
    assert {m.label: (m.young, m.poisson, m.frictionAngle) for m in O.materials if m.label in used} == {
        "particle": (1e6, 0.4, math.atan(0.5)), "drum": (5e6, 0.4, math.atan(0.5))}


# The drum turning in the ParaView export: after 0.1 s every Facet is where a turn of 0.3 rad about y puts it.
def test_the_export_has_the_turned_drum(tmp_path):
    _, facets = drum.build_roundedmesh([])
    O.run(1000, True)
    assert drum.drum_angle(facets) == pytest.approx(3 * O.time, rel=1e-9)
    _, arrays = read_piece(rm.export.write_partners_vtp(str(tmp_path / "drum.vtp")))
    start = np.vstack([t.reshape(-1, 3) for t in triangles().values()])
    np.testing.assert_allclose(arrays["Points"], start @ rotation(np.array([0, 1, 0]), 3 * O.time).T, atol=1e-12)
    np.testing.assert_array_equal(arrays["body_id"], facets)
    assert (arrays["partner"] == 1).all() and (arrays["shape"] == 0).all()


# The check before a run: bodies that touch (here the lattice's poses at the bodies' own size, where they overlap
# by centimetres) are refused, unless --start-overlap allows as much.
def test_the_check_refuses_bodies_that_touch():
    poses = drum.lattice(1)
    with pytest.warns(RuntimeWarning, match="start overlapped deeper"):
        with pytest.raises(RuntimeError, match=r"pairs touch at the start, the deepest by \d"):
            drum.check_start(poses)
        assert drum.check_start(poses, allowed=1.0) > 100


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def placement(tmp_path_factory):
    """S7's placement for seed 1, overlaps up to START_OVERLAP (scripts/examples/drum_placements/ if it is there, else
    placed now: minutes)."""
    folder = tmp_path_factory.mktemp("drum")
    poses = drum.initial_poses(1, str(folder), start_overlap=drum.START_OVERLAP)
    drum.write_placement(drum.placement_path(str(folder), 1, drum.START_OVERLAP), 1, poses, drum.START_OVERLAP)
    yield folder, poses
    O.reset()


# 300 steps (0.03 s) of S7 from the placement: at rest, no pair deeper than START_OVERLAP at the start, all inside the drum, every
# output written; the frames at 0, 200 and 300 steps hold the 60 bodies, the 40 spheres and the 112 Facets, which
# are where the engine's turn put them.
@pytest.mark.slow
def test_a_short_run(placement):
    folder, poses = placement
    args = types.SimpleNamespace(steps=300, out=str(folder), seed=1, sample=100, vtk_every=200, threads=None,
                                 run="roundedmesh", start_overlap=drum.START_OVERLAP)
    result = drum.run(args, poses)
    # The placement's pairs overlap by at most START_OVERLAP (checked when it is read); the first step pushes them.
    assert result["touching_at_start"] > 0
    assert result["completed"], result["failure"]
    out = folder / "roundedmesh"
    table = rows(out / "drum.csv")
    assert [int(r["step"]) for r in table] == [0, 100, 200, 300]
    assert all(int(r["outside"]) == 0 for r in table)
    assert float(table[-1]["drum_angle_rad"]) == pytest.approx(3 * 0.03, rel=1e-9)
    assert float(table[-1]["max_speed_m_s"]) < 1.0  # the drum's mantle moves at 0.45 m/s
    for name in ("drum.png", "initial_state.csv", "timing.csv"):
        assert (out / name).stat().st_size > 0
    (timing,) = rows(out / "timing.csv")
    assert (timing["completed"], timing["steps_done"]) == ("True", "300") and float(timing["median_ms_per_step"]) > 0
    datasets = ElementTree.parse(out / "vtk" / "drum.pvd").getroot().findall("Collection/DataSet")
    assert [(d.get("timestep"), d.get("part")) for d in datasets][-3:] == [(repr(O.time), p) for p in "012"]
    assert len(datasets) == 9
    bodies, spheres, partners = (read_piece(out / "vtk" / d.get("file"))[1] for d in datasets[-3:])
    assert len(np.unique(bodies["body_id"])) == 60 and len(spheres["radius"]) == 40
    assert len(partners["body_id"]) == 112
    start = np.vstack([t.reshape(-1, 3) for t in triangles().values()])
    np.testing.assert_allclose(partners["Points"], start @ rotation(np.array([0, 1, 0]), 3 * O.time).T, atol=1e-12)


# The script itself, as users run it, from the placement the fixture left in its --out: a few steps.
@pytest.mark.slow
def test_the_script_runs(placement):
    folder, _ = placement
    out = subprocess.run(["/usr/bin/python3", SCRIPT, "--steps", "20", "--sample", "10", "--vtk-every", "0",
                          "--out", str(folder)], capture_output=True, text=True, env=os.environ)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "placement: read from" in out.stdout and "touching pairs in the first step: " in out.stdout
    assert "20 of 20 steps" in out.stdout, out.stdout
