"""scripts/validation/newuser_drum.py, the new user's drum of scene S8 (roundedmesh_study.newuser_drum): it runs for a
simulated time at the step rm.critical_timestep(impact_speed=3) gives, samples inside one O.run, and checkpoints a
run that can be resumed. Whether the whole drums complete is measured in doc/validation.md ("Hard cases"): 31 min
for the horses."""
import csv
import os
import subprocess
import sys

import pytest

from roundedmesh_study import newuser_drum

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "validation", "newuser_drum.py")


def test_each_drum_runs_for_its_simulated_time():
    assert newuser_drum.parse(["--contents", "mixed"]).duration == 0.63
    assert newuser_drum.parse(["--contents", "bears"]).duration == 1.67
    assert newuser_drum.parse(["--duration", "0.1"]).duration == 0.1
    for bad in (["--duration", "0"], ["--threads", "0"], ["--checkpoint-every", "-1"]):
        with pytest.raises(SystemExit):
            newuser_drum.parse(bad)


# 3 ms of the bears' drum (68 steps at 44 us): the bodies are still falling from the lattice, but the run goes through
# the sampling (every 10 steps) and a checkpoint (every 20 steps) to its end.
def test_a_short_run_samples_and_checkpoints(tmp_path):
    out = subprocess.run([sys.executable, SCRIPT, "--contents", "bears", "--duration", "0.003", "--checkpoint-every",
                          "20", "--output", str(tmp_path)], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stdout + out.stderr
    steps = next(int(line.split(", ")[-1].split()[0]) for line in out.stdout.splitlines() if "O.dt =" in line)
    assert abs(steps * float(out.stdout.split("O.dt = ")[1].split()[0]) - 0.003) < 1e-4
    assert f"bears roundedmesh: completed after {steps} steps" in out.stdout
    with open(tmp_path / "bears_roundedmesh.csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    assert [int(r["step"]) for r in rows] == list(range(10, steps + 1, 10))
    assert all(float(r["ms_per_step"]) > 0 for r in rows)
    assert os.path.getsize(tmp_path / "bears_roundedmesh.yade.gz") > 1000
    assert os.path.getsize(tmp_path / "newuser_drum_bears.png") > 1000
