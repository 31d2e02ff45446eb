"""Rounded bodies under YADE's MPI decomposition (yade.mpy, through roundedmesh.mpi): scripts/examples/example_mpi.py
run on the master and two workers (mpiexec -n 3) against the same scene in one process, a stop on one process
ending all of them, the scenes roundedmesh.mpi refuses, and the split of the bodies between the workers."""
import json
import os
import re
import subprocess

import numpy as np
import pytest
from yade import O

import roundedmesh as rm

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
SCRIPT = os.path.join(ROOT, "scripts", "examples", "example_mpi.py")
MPIEXEC = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-n", "3"]
RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01)


def run(command, timeout=300):
    return subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                          env={**os.environ, "OMP_NUM_THREADS": "1"})


def drop(folder, processes, *options):
    command = (MPIEXEC if processes == 3 else []) + ["yade", "-n", "-x", SCRIPT, "--output", str(folder), *options]
    out = run(command)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    with open(folder / "result.json") as f:
        result = json.load(f)
    return result, np.loadtxt(folder / "final_state.csv", delimiter=",", skiprows=1)


# 48 icospheres of 162 nodes fall into S1's box, which shakes (the workers' copies of the master's walls follow it),
# for 0.2 s: the bottom layer lands at about 0.085 s. The workers own slabs across z, so that the upper bodies land
# on the other worker's (15 of the 43 touching pairs at the end cross between the workers). Each process computes a pair from the same states with the
# same operations as the one process does, and YADE sums and integrates per body, so the runs agree bit for bit: a
# pair missed, computed twice into one body or from a stale image would show as a difference.
@pytest.mark.slow
def test_three_processes_move_every_body_as_one_process_does(tmp_path):
    options = ("--steps", "2000", "--shake", "--split-axis", "2")
    one, one_state = drop(tmp_path / "one", 1, *options)
    three, three_state = drop(tmp_path / "three", 3, *options)
    assert three["processes"] == 3 and one["processes"] == 1
    assert three["bodies_merged"] == 48 and len(three_state) == 48
    workers = three["parts"][1:]
    assert [p["bodies"] for p in workers] == [24, 24] and three["parts"][0]["bodies"] == 0
    assert all(p["touching_pairs"] > 0 and p["collisions"] > 0 for p in workers)
    # A pair of two workers' bodies counts on both: some pairs cross between the workers.
    assert sum(p["touching_pairs"] for p in workers) > one["parts"][0]["touching_pairs"] > 0
    np.testing.assert_array_equal(three_state, one_state)
    assert three["mean_height_m"] == one["mean_height_m"]


# O.dt far above the contacts' stability limit: the workers stop at their first step; the master, which holds no
# rounded body, would wait for them forever.
@pytest.mark.slow
def test_a_stop_on_one_process_ends_every_process_with_its_message(tmp_path):
    out = run(MPIEXEC + ["yade", "-n", "-x", SCRIPT, "--output", str(tmp_path), "--steps", "10", "--dt", "0.01"],
              timeout=120)
    assert out.returncode != 0
    # Found anywhere in a line: another process's output may precede it on the same line.
    said = re.findall(r"roundedmesh\.mpi: rank \d+: .*", out.stdout + out.stderr)
    assert said and all("above the stability limit" in line for line in said), out.stdout[-2000:] + out.stderr[-2000:]
    assert not (tmp_path / "result.json").exists()


# Each process writes its copies of the walls to a file of its own: lines printed by three processes through mpiexec
# can interleave (a CI run read "WALLSWALLS" and lost a rank's line).
FOLLOWER = """
import json
import roundedmesh as rm
from roundedmesh_study import mpi_drop
from yade import O
args = mpi_drop.parse(["--shape", "gummy_bear", "--count", "64", "--lattice", "8", "--steps", "1", "--shake"])
bodies, walls = mpi_drop.build(args)
rm.mpi.mpirun(300)
rank = rm.mpi._mpy().rank
with open(f"{folder}/walls_{{rank}}.json", "w") as f:
    json.dump([(w, O.bodies[w].state.pos[2].hex(), O.bodies[w].state.vel[2].hex()) for w in walls
               if O.bodies[w] is not None], f)
"""


# The workers' copies of the master's walls, which neither mpy nor their NewtonIntegrator moves, stand where the
# master's walls stand, bit for bit, at every step of the box's shaking (also the first: a copy one step behind
# would press the bodies by a step's displacement of the box, 62 micrometres here). 64 gummy bears in one layer of
# 8 x 8, some touching the side walls from the start: the walls are shipped at the split.
@pytest.mark.slow
def test_the_workers_copies_of_the_masters_walls_move_with_them(tmp_path):
    script = tmp_path / "follower.py"
    script.write_text(FOLLOWER.format(folder=tmp_path))
    out = run(MPIEXEC + ["yade", "-n", "-x", str(script)], timeout=120)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    walls = {}
    for rank in range(3):
        with open(tmp_path / f"walls_{rank}.json") as f:
            walls[rank] = {w: (z, v) for w, z, v in json.load(f)}
    assert len(walls[0]) == 5
    for rank in (1, 2):
        assert walls[rank], f"no wall was shipped to worker {rank}"
        for wall, state in walls[rank].items():
            assert state == walls[0][wall], (rank, wall)


REFUSED = """
import roundedmesh as rm
from yade import ForceResetter, InsertionSortCollider, NewtonIntegrator, O
rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01)
rm.add_body(rm.Mesh.icosphere(0.01, 1), (0, 0, 0), material=rubber)
{extra}
O.engines = [ForceResetter(), {collider}rm.engine(), NewtonIntegrator()]
try:
    rm.mpi.prepare()
except ValueError as error:
    print("REFUSED:", error, "| shape", type(O.bodies[0].shape).__name__, "bounded", O.bodies[0].bounded)
"""


@pytest.mark.parametrize("extra, collider, message", [
    ("rm.add_sphere((1, 0, 0), 0.01, rubber)", "InsertionSortCollider(), ", "sphere bodies [1]: not supported"),
    ("", "", "holds 0 InsertionSortColliders"),
    ("", "InsertionSortCollider(avoidSelfInteractionMask=2), ", "avoidSelfInteractionMask is 2"),
])
def test_prepare_refuses_what_mpy_cannot_run_and_changes_nothing(tmp_path, extra, collider, message):
    script = tmp_path / "refused.py"
    script.write_text(REFUSED.format(extra=extra, collider=collider))
    out = run(["yade", "-n", "-x", str(script)], timeout=60)
    refused = [line for line in out.stdout.splitlines() if line.startswith("REFUSED:")]
    assert len(refused) == 1 and message in refused[0], out.stdout[-2000:] + out.stderr[-2000:]
    assert "| shape Shape bounded False" in out.stdout


def test_assign_subdomains_gives_the_workers_slabs_of_equal_counts():
    O.reset()
    mesh = rm.Mesh.icosphere(0.01, 0)
    # Spread most along y, in shuffled order of ids.
    ys = [0.5, 0.0, 0.3, 0.1, 0.4, 0.2]
    ids = [rm.add_body(mesh, (0.001 * k, y, 0), material=RUBBER) for k, y in enumerate(ys)]
    rm.mpi.assign_subdomains(3)
    owner = {y: O.bodies[i].subdomain for i, y in zip(ids, ys)}
    assert [owner[y] for y in sorted(ys)] == [1, 1, 2, 2, 3, 3]
    rm.mpi.assign_subdomains(2, axis=0)  # x: the order of the ids
    assert [O.bodies[i].subdomain for i in ids] == [1, 1, 1, 2, 2, 2]
    with pytest.raises(ValueError, match="axis: expected 0, 1 or 2"):
        rm.mpi.assign_subdomains(2, axis=3)
    O.reset()
