"""The engine's threads follow YADE's convention (issue 36): one unless the user asks, by `yade -jN` (which sets
OMP_NUM_THREADS), by OMP_NUM_THREADS itself, or by rm.engine(threads=N); a script run by /usr/bin/python3 no longer
takes every core. rm.statistics()['threads'] is what the last step ran on."""
import os
import subprocess

import pytest

SCENE = """
import yade, roundedmesh as rm
from yade import O, ForceResetter, NewtonIntegrator
material = rm.HertzMaterial(young=1e6, poisson=0.4, density=1000, damping=1e-3)
rm.add_body(rm.Mesh.icosphere(0.01, 1), pos=(0, 0, 0), material=material)
rm.add_body(rm.Mesh.icosphere(0.01, 1), pos=(0, 0, 0.0199), material=material)
O.engines = [ForceResetter(), rm.engine({options}), NewtonIntegrator(damping=0)]
O.dt = 1e-6
O.step()
print("THREADS", rm.statistics()["threads"])
"""


def threads(command, options="", environment=None, tmp_path=None):
    script = tmp_path / "scene.py"
    script.write_text(SCENE.format(options=options))
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON") and k != "OMP_NUM_THREADS"}
    out = subprocess.run(command + [str(script)], capture_output=True, text=True, env={**env, **(environment or {})})
    lines = [line for line in out.stdout.splitlines() if line.startswith("THREADS")]
    assert lines, out.stdout + out.stderr
    return int(lines[-1].split()[1])


@pytest.mark.parametrize("command, options, environment, expected", [
    (["/usr/bin/python3"], "", None, 1),                       # as yade without -j: one, not every core
    (["/usr/bin/python3"], "", {"OMP_NUM_THREADS": "2"}, 2),   # the user's environment
    (["yade", "-n", "-x"], "", None, 1),
    (["yade", "-j2", "-n", "-x"], "", None, 2),                # yade -jN
    (["/usr/bin/python3"], "threads=2", {"OMP_NUM_THREADS": "1"}, 2),  # the engine's own option wins
])
def test_threads_as_yade_has_them(tmp_path, command, options, environment, expected):
    assert threads(command, options, environment, tmp_path) == expected
