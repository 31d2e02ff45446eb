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


# YADE's own engines beside ours, on another thread count than the engine's: YADE sizes a scene's per-thread force
# buffers by the OpenMP default of the thread that makes the scene, and its InteractionLoop runs on that default.
# The engine once set that default to its own count at each step, so a YADE contact law wrote past its buffers (a
# segmentation fault) on the next O.step or after O.load. The spheres rest in contact with each other and the
# floor, so YADE's law writes forces at every step.
MIXED_SCENE = """
import sys
import roundedmesh as rm
from yade import (O, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                  InsertionSortCollider, InteractionLoop, Ip2_ViscElMat_ViscElMat_ViscElPhys,
                  Law2_ScGeom_ViscElPhys_Basic, NewtonIntegrator, ViscElMat, utils)
viscel = O.materials.append(ViscElMat(tc=0.01, en=0.3, et=1.0, density=2000, frictionAngle=0.3))
rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=1000, damping=1e-3)
rm.add_body(rm.Mesh.icosphere(0.01, 1), pos=(0, 0, 0.0099), material=rubber)
rm.add_body(rm.Mesh.icosphere(0.01, 1), pos=(0.0199, 0, 0.0099), material=rubber)  # two pairs at least: a parallel loop
floor = O.bodies.append(utils.wall(0, axis=2, sense=1, material=viscel))
rm.assign_material(floor, rubber)
for i in range(40):
    O.bodies.append(utils.sphere((0.1 + 0.0199 * (i % 10), 0.0199 * (i // 10), 0.0099), 0.01, material=viscel))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                             [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
             rm.engine(threads={threads}), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
O.dt = 1e-5
for _ in range(20):
    O.step()
if "{then}" == "load":
    O.save(sys.argv[1])
    O.load(sys.argv[1])
    O.run(200, True)
else:
    for _ in range(200):
        O.step()
print("DONE", rm.statistics()["threads"], sum(1 for i in O.interactions if i.isReal), rm.statistics()["body_pairs"])
"""


@pytest.mark.parametrize("environment, threads, then", [
    ("2", 1, "load"),   # crashed: O.load made the scene's buffers for the engine's one thread
    ("1", 2, "step"),   # crashed: YADE's loop in O.step ran on the engine's two threads, the buffers one
    ("1", 2, "load"),
])
def test_yade_engines_beside_ours_on_another_thread_count(tmp_path, environment, threads, then):
    script = tmp_path / "mixed.py"
    script.write_text(MIXED_SCENE.format(threads=threads, then=then))
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    out = subprocess.run(["/usr/bin/python3", str(script), str(tmp_path / "mixed.yade.gz")], capture_output=True,
                         text=True, env={**env, "OMP_NUM_THREADS": environment}, timeout=300)
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
    done = [line.split() for line in out.stdout.splitlines() if line.startswith("DONE")]
    assert done, out.stdout + out.stderr
    assert int(done[-1][1]) == threads
    assert int(done[-1][2]) >= 40  # YADE's law had contacts to write forces for
    assert int(done[-1][3]) >= 3   # and the engine's loop more than one pair to share out
