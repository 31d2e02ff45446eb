"""The scaling benchmark's scenes and its report (bench/scaling.cpp, scripts/benchmarks/scaling.py): the smallest
lattices and one tile of the settled S1 packing, run for real, checked against what the lattice's geometry says
(no timing is checked: speed is measured by the benchmark, not by tests)."""
import csv
import json
import os
import subprocess
import sys

import pytest

import roundedmesh

BUILD = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(roundedmesh.__file__))))
BENCH = os.path.join(BUILD, "bench", "roundedmesh_scaling_bench")
SCRIPT = os.path.join(os.path.dirname(__file__), os.pardir, os.pardir, "scripts", "benchmarks", "scaling.py")
SIDE = 6  # the smallest lattice: 6^3 = 216 bodies


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    if not os.path.isfile(BENCH):
        pytest.skip(f"{BENCH} is not built (the package is not run from its build tree)")
    folder = tmp_path_factory.mktemp("scaling")
    run = subprocess.run([BENCH, f"--benchmark_filter=BM_Lattice/[01]/{SIDE}/[01]/|BM_TiledS1/1/0/",
                          "--benchmark_format=json"], capture_output=True, text=True, check=True,
                         env={**os.environ, "OMP_NUM_THREADS": "1"})
    path = folder / "scaling.json"
    path.write_text(run.stdout)
    subprocess.run([sys.executable, SCRIPT, "--json", str(path), "--output", str(folder)], check=True,
                   capture_output=True, text=True)
    with open(folder / "scaling.csv") as table:
        rows = list(csv.DictReader(line for line in table if not line.startswith("#")))
    return folder, json.loads(run.stdout), {(row["shape"], row["motion"]): row for row in rows}


def test_the_sphere_lattice_touches_every_neighbour_once(report):
    # A simple cubic lattice of side n has 3 n^2 (n - 1) neighbour pairs, each overlapping by 0.5 % of the radius:
    # one contact each, at rest and rattling (the rattle is a quarter of the overlap each way).
    _, _, rows = report
    for motion in ("at rest", "rattling"):
        row = rows[("spheres", motion)]
        assert int(row["bodies"]) == SIDE ** 3
        assert float(row["contacts"]) == 3 * SIDE ** 2 * (SIDE - 1)


def test_the_icosphere_lattice_pairs_are_its_neighbours(report):
    # The bounding spheres (radius 5 mm) of diagonal neighbours, sqrt(2) * 9.975 mm apart, do not meet: the body
    # pairs are exactly the lattice's 540 neighbour pairs, and each has at least one triangle contact.
    _, _, rows = report
    neighbours = 3 * SIDE ** 2 * (SIDE - 1)
    for motion in ("at rest", "rattling"):
        row = rows[("12-node icospheres", motion)]
        assert int(row["primitives"]) == SIDE ** 3 * 20
        assert float(row["body_pairs"]) == neighbours
        assert float(row["contacts"]) >= neighbours
        assert 0 < float(row["engine_bytes_per_body"]) < 1e6


def test_one_tile_is_the_recorded_packing_without_its_side_walls(report):
    folder, _, rows = report
    row = rows[("gummy bears", "settled")]
    assert int(row["bodies"]) == 250
    assert int(row["primitives"]) == 250 * 1122  # the recorded bear's 563 nodes make 1,122 triangles
    assert float(row["contacts"]) > 20000          # the settled packing's 24,217, less those with the side walls
    assert float(row["mesh_bytes"]) > 0
    for plot in ("scaling_primitives.png", "scaling_bodies.png"):
        assert (folder / plot).stat().st_size > 10000
