"""scripts/hard_cases.py, scene S8 of doc/scenes.md (roundedmesh_study.hard_cases): its short form, which CI runs (S1
of the gummy bears through the shaking, seed 1, two threads), and its coarse-mesh and report machinery on a small
case.

The short form fails today: S1 of the gummy bears completes the shaking (it stopped at step 4494 on a false deep
triangle pair until the deep-contact criterion followed the whole segment), but its deepest pair reaches 0.35 r_eq, a
foot 8.8 mm into another bear at step 5080 (vertices 8.6 mm inside), above the suite's 0.3 (issue 23, "Bodies never
pass through each other"). It is kept as an expected failure, strict: the day it passes, this test fails until the
mark is removed."""
import csv
import math
import os
import subprocess

import pytest

from roundedmesh_study import hard_cases

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
SCRIPT = os.path.join(ROOT, "scripts", "hard_cases.py")


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="issue 23: S1 of the gummy bears completes, its deepest pair at 0.35 r_eq")
def test_the_short_form_passes(tmp_path):
    out = subprocess.run(["/usr/bin/python3", SCRIPT, "--quick", "--output", str(tmp_path)], capture_output=True,
                         text=True, env={**os.environ, "OMP_NUM_THREADS": "2"})
    checks = rows(tmp_path / "hard_cases.csv")
    assert [c["check"] for c in checks] == ["gummy_bear, seed 1: completes", "gummy_bear, seed 1: deepest pair"]
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    assert all(c["passed"] == "True" for c in checks), checks


def test_the_coarse_meshes_and_the_report(tmp_path):
    """The coarse meshes are what S8 says: the bar and the plate are given as 12 triangles and made as rm.Mesh makes
    them, within its tolerance of 0.05 r_eq, the coarsened bear has about 150 nodes; the report writes one row per
    check and its picture, and names the failures."""
    meshes = hard_cases.coarse_meshes()
    sizes = {name: (len(m.vertices), len(m.triangles)) for name, m in meshes.items()}
    for size in ((0.02, 0.02, 0.05), (0.001, 0.02, 0.05)):
        vertices, triangles = hard_cases.box_arrays(*size)
        assert vertices.shape == (8, 3) and triangles.shape == (12, 3)
    for name in ("12-triangle bar 2 x 2 x 5 cm", "sliver plate 1 x 20 x 50 mm"):
        mesh = meshes[name]
        assert mesh.deviation <= 0.05 * (3 * mesh.volume / (4 * math.pi)) ** (1 / 3) * (1 + 1e-12)
    assert 140 <= sizes["gummy bear of 150 nodes"][0] <= 160
    report = hard_cases.Report()
    report.add("coarse", "a check that passes", True, 0.0, 1.0, "N", "", 0.1)
    report.add("coarse", "a check that fails", False, 2.0, 1.0, "N", "why", 0.2)
    path = hard_cases.write_report(report.rows, str(tmp_path))
    written = rows(path)
    assert [r["passed"] for r in written] == ["True", "False"] and written[1]["detail"] == "why"
    assert os.path.getsize(tmp_path / "hard_cases.png") > 1000
    args = hard_cases.parse(["--quick"])
    assert (args.only, args.shapes, args.seeds, args.threads) == (["s1"], ["gummy_bear"], [1], 2)


def test_the_reference_gummy_bear_passes_the_coarse_mesh_checks(tmp_path, monkeypatch):
    """The coarse-mesh checks can be passed: the 554-node gummy bear of the reference shapes feels no force 1 mm from
    a Wall, a Box and a Facet, and dropped 1 mm onto each comes to rest on it (0.23 mm deep, 1.8 mm/s on a Wall after
    2 s)."""
    import argparse
    import roundedmesh as rm
    monkeypatch.setattr(hard_cases, "coarse_meshes", lambda: {"bear": rm.Mesh.reference_shape("gummy_bear")})
    report = hard_cases.Report()
    hard_cases.coarse_checks(argparse.Namespace(), report)
    assert len(report.rows) == 6 and all(r["passed"] for r in report.rows), report.rows
