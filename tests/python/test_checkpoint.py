"""roundedmesh.checkpoint: a run killed at any moment, also in the middle of a save, resumes from its last
complete checkpoint and ends bit for bit where the uninterrupted run ends; a damaged or foreign checkpoint
is refused with an error naming the file and the defect, and the scene is left as it was.
Tolerance: none. Resuming must reproduce the run exactly (float.hex of every state), because the same
steps on the same states give the same bits: anything else means the checkpoint lost state."""
import gzip
import hashlib
import json
import os
import random
import signal
import subprocess
import time

import pytest

import roundedmesh as rm
from yade import ForceResetter, NewtonIntegrator, O, utils

CHILD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "checkpoint_child.py")
STEPS, EVERY = 400, 40  # ten checkpoints


def child(path, mode, kill_at=None):
    args = ["/usr/bin/python3", CHILD, str(path), str(STEPS), str(EVERY), mode] + ([kill_at] if kill_at else [])
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=os.environ)


def finished(process):
    out, err = process.communicate()
    assert process.returncode == 0, err
    return json.loads(out.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def uninterrupted(tmp_path_factory):
    return finished(child(tmp_path_factory.mktemp("reference") / "run.yade.gz", "fresh"))


# Each save renames three times: the sidecar listing both checkpoints (call 3k + 1), the scene over the old
# one (3k + 2), the sidecar listing the new one alone (3k + 3). Killed before or after each, in the second save.
@pytest.mark.parametrize("kill_at", ["4:before", "5:before", "5:after", "6:after"])
def test_a_run_killed_within_a_save_resumes_bit_for_bit(tmp_path, uninterrupted, kill_at):
    path = tmp_path / "run.yade.gz"
    killed = child(path, "fresh", kill_at)
    killed.communicate()
    assert killed.returncode == -signal.SIGKILL
    assert rm.checkpoint.verify(str(path))["iteration"] in (EVERY, 2 * EVERY)
    assert finished(child(path, "resume")) == uninterrupted


# Killed by another process at a random moment after the first checkpoint: often while O.save writes (the
# partial file is then left behind, and must not matter).
@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_run_killed_at_a_random_moment_resumes_bit_for_bit(tmp_path, uninterrupted, seed):
    path = tmp_path / "run.yade.gz"
    running = child(path, "fresh")
    while not os.path.exists(rm.checkpoint.sidecar_path(str(path))):
        assert running.poll() is None
        time.sleep(0.01)
    time.sleep(random.Random(seed).uniform(0, 1.5))
    running.send_signal(signal.SIGKILL)
    running.communicate()
    resumed = finished(child(path, "resume"))
    assert resumed == uninterrupted


# --- damaged and foreign checkpoints ----------------------------------------------------------------------

@pytest.fixture
def saved(tmp_path):
    """A checkpoint of a small scene at iteration 20, then the scene moved on to iteration 30."""
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
    rm.add_body(rm.Mesh.icosphere(0.025, 2), pos=(0, 0, 0.0249), material=rubber)
    rm.assign_material(O.bodies.append(utils.wall(0, axis=2, sense=1)), rubber)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-5
    O.run(20, True)
    path = str(tmp_path / "scene.yade.gz")
    rm.checkpoint.save(path)
    O.run(10, True)
    return path


def scene_now():
    return O.iter, len(O.bodies), O.bodies[0].state.pos, O.tags["roundedmesh.revision"]


def refused(path):
    before = scene_now()
    with pytest.raises(rm.checkpoint.CheckpointError) as error:
        rm.checkpoint.resume(path)
    assert scene_now() == before
    message = str(error.value)
    assert message.startswith(path + ": ")
    return message


def test_a_good_checkpoint_resumes(saved):
    record = rm.checkpoint.resume(saved)
    assert O.iter == record["iteration"] == 20 and len(O.bodies) == 2


def test_a_truncated_checkpoint_is_refused(saved):
    with open(saved, "rb") as f:
        data = f.read()
    with open(saved, "wb") as f:
        f.write(data[:len(data) // 2])
    assert "truncated, extended or replaced" in refused(saved)


def test_a_checkpoint_with_flipped_bytes_is_refused(saved):
    with open(saved, "r+b") as f:
        f.seek(os.path.getsize(saved) // 2)
        byte = f.read(1)
        f.seek(-1, os.SEEK_CUR)
        f.write(bytes([byte[0] ^ 0xFF]))
    assert "the file was altered or replaced" in refused(saved)


def write_sidecar(path):
    """A sidecar vouching for whatever is at path now: what a careless copy or a tool could leave."""
    with open(path, "rb") as f:
        data = f.read()
    record = {"sha256": hashlib.sha256(data).hexdigest(), "size": len(data), "iteration": 0, "time": 0, "saved": 0}
    with open(rm.checkpoint.sidecar_path(path), "w") as f:
        json.dump({"format": 1, "file": os.path.basename(path), "scenes": [record]}, f)


def test_a_scene_of_another_program_is_refused(saved, tmp_path):
    other = str(tmp_path / "other.yade.gz")
    with gzip.open(other, "wb") as f:
        f.write(b"serialization::archive of some other program's scene")
    write_sidecar(other)
    assert "holds no YADE scene" in refused(other)
    os.replace(other, saved)  # over the checkpoint, its sidecar left as it was
    assert "truncated, extended or replaced" in refused(saved)


def test_a_damaged_gzip_stream_is_refused_even_when_its_checksum_is_listed(saved):
    with open(saved, "rb") as f:
        data = f.read()
    with open(saved, "wb") as f:
        f.write(data[:-8])  # the gzip trailer (CRC and length) cut off
    write_sidecar(saved)
    assert "the compressed scene is damaged" in refused(saved)


def test_a_missing_checkpoint_or_sidecar_is_refused(saved, tmp_path):
    assert "no such checkpoint file" in refused(str(tmp_path / "never_saved.yade.gz"))
    os.remove(rm.checkpoint.sidecar_path(saved))
    assert "not a checkpoint saved by roundedmesh.checkpoint" in refused(saved)
    with open(rm.checkpoint.sidecar_path(saved), "w") as f:
        f.write("{not json")
    assert "cannot be read" in refused(saved)


def test_the_checkpoint_engine_must_come_first(tmp_path):
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
    rm.add_body(rm.Mesh.icosphere(0.025, 1), pos=(0, 0, 0.1), material=rubber)
    checkpoints = rm.checkpoint.Checkpointer(str(tmp_path / "c.yade.gz"), every_steps=1)
    O.engines = [ForceResetter(), checkpoints.engine(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-5
    with pytest.raises(Exception, match="must be the first engine"):
        O.run(2, True)


def test_a_checkpointer_in_a_loop_saves_when_due(tmp_path):
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
    rm.add_body(rm.Mesh.icosphere(0.025, 1), pos=(0, 0, 0.1), material=rubber)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-5
    checkpoints = rm.checkpoint.Checkpointer(str(tmp_path / "c.yade.gz"), every_steps=10)
    saved_at = []
    for _ in range(7):
        O.run(4, True)
        record = checkpoints()
        if record:
            saved_at.append(record["iteration"])
    assert saved_at == [12, 24] and rm.checkpoint.verify(checkpoints.path)["iteration"] == 24
    with pytest.raises(ValueError, match="give every_steps, every_seconds or both"):
        rm.checkpoint.Checkpointer("x.yade.gz")


def test_a_checkpointer_by_wall_clock_time_saves_from_the_engine(tmp_path):
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
    rm.add_body(rm.Mesh.icosphere(0.025, 1), pos=(0, 0, 0.1), material=rubber)
    checkpoints = rm.checkpoint.Checkpointer(str(tmp_path / "c.yade.gz"), every_seconds=1e-6)
    O.engines = [checkpoints.engine(), ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-5
    O.run(5, True)
    # Due at every step: the last save is the one at the start of the fifth step.
    assert rm.checkpoint.verify(checkpoints.path)["iteration"] == 4
