"""scripts/s1_packing.py, the whole scene S1 (doc/scenes.md), on small runs: it runs end to end and writes every
output, keeps every body in the box, moves the box as z = A sin(2 pi t / T) and stops it after three periods, and
refuses bad input before it runs."""
import csv
import math
import os
import subprocess
import xml.etree.ElementTree as ElementTree

import numpy as np

from test_export import read_piece

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
SCRIPT = os.path.join(ROOT, "scripts", "s1_packing.py")
AMPLITUDE, PERIOD = 0.025, 0.25    # S1's shaking [m], [s]
VOLUME = 4 / 3 * math.pi * 0.025 ** 3  # every body's [m^3]


def run(*arguments):
    return subprocess.run(["/usr/bin/python3", SCRIPT, *arguments], capture_output=True, text=True, timeout=120,
                          env=os.environ)


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


# 100 steps of 8 icospheres (42 nodes): a second of running, the rest is starting YADE.
def test_a_short_run_writes_every_output_and_keeps_the_bodies_in_the_box(tmp_path):
    out = run("--shape", "icosphere42", "--count", "8", "--duration", "0.01", "--output", str(tmp_path))
    assert out.returncode == 0, out.stdout + out.stderr
    assert "Traceback" not in out.stderr, out.stderr
    assert out.stdout.count("machine: ") == 2 and out.stdout.count("command: ") == 2, out.stdout
    for name in ("height.csv", "packing.csv", "timing.csv", "height.png", "vtk/icosphere42.pvd"):
        assert (tmp_path / name).stat().st_size > 0, name

    height = rows(tmp_path / "height.csv")
    assert [int(r["step"]) for r in height] == [100]
    assert all(int(r["bodies"]) == 8 and int(r["outside"]) == 0 for r in height)
    # the box stands where A sin(2 pi t / T) puts it, to rounding
    for r in height:
        assert abs(float(r["box_z_m"]) - AMPLITUDE * math.sin(2 * math.pi * float(r["time_s"]) / PERIOD)) < 1e-12

    # the frame at the end: the 8 bodies, every node inside the box (no contact has begun after 0.01 s)
    datasets = ElementTree.parse(tmp_path / "vtk" / "icosphere42.pvd").getroot().findall("Collection/DataSet")
    assert [d.get("file") for d in datasets] == ["icosphere42_00000100.vtp"]
    _, arrays = read_piece(tmp_path / "vtk" / datasets[0].get("file"))
    assert len(np.unique(arrays["body_id"])) == 8
    points = arrays["Points"]
    assert (np.abs(points[:, :2]) < 0.20).all() and (points[:, 2] > float(height[-1]["box_z_m"])).all()

    # Eq. 28 with the volume of a sphere of radius 0.025 m: the icosphere is scaled to it
    packing = rows(tmp_path / "packing.csv")
    assert [float(r["h_m"]) for r in packing] == [round(0.01 * k, 2) for k in range(1, 31)]
    for r in packing:
        h = float(r["h_m"])
        expected = int(r["bodies_below"]) * VOLUME / (0.4 * 0.4 * h) * 100
        assert math.isclose(float(r["packing_factor_percent"]), expected, rel_tol=1e-9)
    assert int(packing[-1]["bodies_below"]) == 8

    (timing,) = rows(tmp_path / "timing.csv")
    assert (timing["threads"], timing["omp_max_threads"], timing["steps"]) == ("1", "1", "100")
    assert float(timing["median_ms_per_step_shaking"]) > 0 and float(timing["median_cpu_ms_per_step_shaking"]) > 0
    assert timing["median_ms_per_step_settling"] == "nan"


# 1,600 steps of 5e-4 s (a quarter of this scene's stability limit) with one body: past the shaking's end,
# with four frames spread over the run.
def test_the_box_shakes_for_three_periods_then_stands_still(tmp_path):
    out = run("--shape", "icosphere12", "--count", "1", "--duration", "0.8", "--dt", "5e-4", "--sample", "10",
              "--frames", "4", "--output", str(tmp_path))
    assert out.returncode == 0, out.stdout + out.stderr
    height = rows(tmp_path / "height.csv")
    assert [int(r["step"]) for r in height] == list(range(10, 1601, 10))
    for r in height:
        t, z = float(r["time_s"]), float(r["box_z_m"])
        shaking = int(r["step"]) <= 1500
        assert r["phase"] == ("shaking" if shaking else "settling")
        assert abs(z - (AMPLITUDE * math.sin(2 * math.pi * t / PERIOD) if shaking else 0.0)) < 1e-12, (t, z)
        assert int(r["outside"]) == 0 and int(r["bodies"]) == 1
    (timing,) = rows(tmp_path / "timing.csv")
    assert (timing["shaking_windows"], timing["settling_windows"]) == ("150", "10")
    datasets = ElementTree.parse(tmp_path / "vtk" / "icosphere12.pvd").getroot().findall("Collection/DataSet")
    assert [(round(float(d.get("timestep")), 9), d.get("file")) for d in datasets] == \
        [(round(0.2 * k, 9), f"icosphere12_{400 * k:08d}.vtp") for k in (1, 2, 3, 4)]


def test_bad_input_is_refused_before_any_step(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    cases = [(["--shape", "cube"], "unknown shape"),
             (["--shape", "sphere"], "perfect spheres are left out"),
             (["--output", str(blocker / "out")], "cannot write there"),
             (["--dt", "7e-5"], "whole number of steps"),
             (["--shape", "icosphere12", "--count", "2", "--dt", "0.01"], "above the stability limit")]
    for arguments, message in cases:
        output = tmp_path / "out"
        out = run(*arguments, *(["--output", str(output)] if "--output" not in arguments else []))
        assert out.returncode != 0 and message in out.stderr, (arguments, out.stdout + out.stderr)
        assert not (output / "height.csv").exists(), arguments
