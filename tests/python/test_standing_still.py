"""roundedmesh_study.standing_still (issue 41): its energy columns against the bodies' own motion, and its summary."""
import csv
import os

import pytest
from yade import O

from roundedmesh_study import spin_energy, standing_still
from roundedmesh_study.bench_s1_peers import default_poses, read_poses

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COLUMN = {name: k for k, name in enumerate(standing_still.COLUMNS)}


def potential(ids):
    """sum m g z of the bodies [J], from their positions."""
    return sum(O.bodies[i].state.mass * 9.81 * O.bodies[i].state.pos[2] for i in ids)


def momentum(ids):
    """sum m v_z of the bodies [kg m/s]."""
    return sum(O.bodies[i].state.mass * O.bodies[i].state.vel[2] for i in ids)


@pytest.fixture
def few_spheroids():
    """Six spheroids of the settled packing, the rest left out: they fall onto what is below them."""
    poses = read_poses(os.path.join(ROOT, default_poses("spheroid")), "spheroid")[:6]
    rows, ids, _ = standing_still.run("spheroid", poses, 0.01)
    return rows, ids


def test_rows_sample_the_run(few_spheroids):
    rows, ids = few_spheroids
    assert len(rows) == spin_energy.SAMPLES + 1 and rows[0][0] == "spheroid, pressure"
    assert rows[-1][COLUMN["t_s"]] - rows[0][COLUMN["t_s"]] == pytest.approx(0.01, rel=1e-9)
    for row in rows:  # the total is the sum of O.energy's terms
        terms = [row[COLUMN[c]] for c in ("yade_kinetic_J", "gravity_work_J", "elastic_J", "normal_damping_J",
                                          "friction_J")]
        assert row[COLUMN["total_J"]] == pytest.approx(sum(terms), rel=1e-12, abs=1e-15)


def test_gravity_work_is_the_change_of_potential_energy(few_spheroids):
    """'gravWork', which the summary's descent reads, against m g dz from the bodies' positions over 200 more steps of
    moving bodies, the one term by which the two sums differ taken out: equal to 1e-12 here (measured); 1e-9 leaves
    room for the rounding of 1,200 terms summed in another order."""
    _, ids = few_spheroids
    before_work, before_potential, before_momentum = dict(O.energy.items())["gravWork"], potential(ids), momentum(ids)
    O.run(200, True)
    change = potential(ids) - before_potential
    assert abs(change) > 1e-5  # they move [J]
    # YADE sums m g v dt with each step's velocity before its update, leap-frog moves by the one after: the two sums
    # differ by g dt times the change of the vertical momentum.
    expected = change - 9.81 * O.dt * (momentum(ids) - before_momentum)
    assert dict(O.energy.items())["gravWork"] - before_work == pytest.approx(expected, rel=1e-9)


def test_summary_of_the_rows():
    rows = [["r", 0.0, 1.0, 2.0, 3.0, 9.0, 0.0, 5.0, 0.0, 0.0, 20.0],
            ["r", 0.1, 0.5, 0.5, 7.0, 9.0, -1.0, 5.0, 4.0, 1.0, 23.0]]
    summary = dict(zip(standing_still.SUMMARY, standing_still.summary(rows, 2.0, (0.25, 1e-4))))
    assert summary["settling_s"] == 0.25 and summary["settled_fastest_m_s"] == 1e-4
    assert summary["kinetic_start_J"] == 3.0 and summary["kinetic_end_J"] == 1.0
    assert summary["fastest_spin_rad_s"] == 7.0
    assert summary["drift_J"] == 3.0 and summary["dissipated_J"] == 5.0
    assert summary["drift_over_dissipated"] == pytest.approx(0.6, rel=1e-15)
    assert summary["descent_mm"] == pytest.approx(500.0, rel=1e-15)  # 1 J of potential over 2 N: 0.5 m


def test_settling_first_stops_below_the_speed_and_turns_the_damping_off():
    """The lowest pear of its packing away from the side walls, alone, dropped from 1 mm at rest and settled with
    NewtonIntegrator's damping 0.5: it stops below 1 mm/s within the time given, checked every SETTLE_CHECK, and
    stands undamped afterwards; a settling cut short by its time limit says so by its speed. (Bodies pushed along
    the floor would not do: a frictionless body that slides feels no force along it, which YADE's damping needs.)"""
    poses = [pose for pose in read_poses(os.path.join(ROOT, default_poses("pear")), "pear")
             if max(abs(pose[0][0]), abs(pose[0][1])) < 0.15]
    (x, y, z), ori, _, _ = min(poses, key=lambda pose: pose[0][2])
    poses = [((x, y, z + 1e-3), ori, (0, 0, 0), (0, 0, 0))]
    rows, ids, (took, fastest) = standing_still.run("pear", poses, 0.001, settling=(0.5, 1e-3, 1.0))
    assert 0 < took < 1.0 and fastest <= 1e-3
    assert took / standing_still.SETTLE_CHECK == pytest.approx(round(took / standing_still.SETTLE_CHECK), abs=1e-6)
    assert O.engines[-1].damping == 0
    ids = standing_still.peers.build_rounded(poses, "pear")
    O.dt = standing_still.peers.TIME_STEP
    took, fastest = standing_still.settle(ids, 0.5, 1e-9, 0.025)  # not a whole number of checks: stops at 0.025 s
    assert took == pytest.approx(0.025, abs=1e-9) and fastest > 1e-9


def test_main_writes_its_tables_and_figure(tmp_path, monkeypatch):
    """The script end to end on the lowest spheroid alone, both laws, 20 steps: a row per sample and a summary per run."""
    monkeypatch.chdir(ROOT)  # bench/data is read relative to the repository's root
    standing_still.main(["--shapes", "spheroid", "--lowest", "1", "--time", "0.002", "--normal", "pressure", "energy",
                         "--output", str(tmp_path)])
    with open(tmp_path / "standing_still.csv") as f:
        assert len(f.read().splitlines()) == 1 + 2 * (spin_energy.SAMPLES + 1)
    with open(tmp_path / "standing_still_summary.csv", newline="") as f:
        runs = [row["run"] for row in csv.DictReader(f)]
    assert runs == ["spheroid, pressure", "spheroid, energy"]
    assert (tmp_path / "standing_still.png").stat().st_size > 0
    assert len(O.bodies) == 1 + 5  # the lowest body and S1's five walls
    # two outputs merged: the first's rows, then the second's, every number as written
    merged = tmp_path / "merged"
    standing_still.main(["--merge", str(tmp_path), str(tmp_path), "--output", str(merged)])
    rows, summaries = standing_still.read_outputs(tmp_path)
    assert standing_still.read_outputs(merged) == (rows + rows, summaries + summaries)
    assert (merged / "standing_still.png").stat().st_size > 0
    (tmp_path / "standing_still_summary.csv").write_text("run,kinetic_start_J\nr,1.0\n")  # an older version's
    with pytest.raises(SystemExit, match="not this script's columns"):
        standing_still.main(["--merge", str(tmp_path), "--output", str(tmp_path / "again")])


@pytest.mark.parametrize("bad", [["--time", "0"], ["--time", "nan"], ["--lowest", "-1"], ["--settle-damping", "1"],
                                 ["--settle-damping", "-0.1"], ["--settled-speed", "0"], ["--max-settle-time", "0"]])
def test_main_refuses_bad_arguments(bad, tmp_path, capsys):
    with pytest.raises(SystemExit):
        standing_still.main(bad + ["--output", str(tmp_path / "out")])
    assert bad[0] in capsys.readouterr().err
    assert not (tmp_path / "out").exists()  # refused before anything is written
