"""Checkpoints for long runs: the scene saved every N steps or seconds, so that a run killed at any moment
(a power cut, an out-of-memory kill, a full disk) resumes from the last complete checkpoint and goes on bit for
bit as if it had never stopped.

    import roundedmesh as rm
    checkpoints = rm.checkpoint.Checkpointer("run.yade.gz", every_steps=10000, every_seconds=600)
    O.engines = [checkpoints.engine()] + O.engines     # first: a checkpoint is taken between two steps
    ...
    # after a kill, in a new process:
    rm.checkpoint.resume("run.yade.gz")                 # the scene as it was at the last checkpoint
    O.run(steps_wanted - O.iter, True)

A checkpoint is the scene as O.save writes it (path; its extension picks YADE's format, .yade.gz for the usual
compressed binary) and a sidecar, path + ".checkpoint.json", with the SHA-256, size, iteration and time of the
saved file. Saving writes the scene to a temporary file in the same folder, lists its checksum in the sidecar
beside the previous one's, renames it over path (atomic), then drops the previous checksum: at every moment,
path is a complete checkpoint that the sidecar vouches for, the new one or the previous one.

resume verifies before it loads: that the file is there, that the sidecar lists its size and checksum, that a
compressed file decompresses whole, and that it holds a YADE scene (with or without roundedmesh bodies). Anything else raises
CheckpointError naming the file and what is wrong, and leaves the current scene as it was: YADE's own O.load is
never given a file that failed these checks (on a truncated file it may throw or leave a partial scene,
doc/reliability.md).
"""
import bz2
import gzip
import hashlib
import json
import os
import time
import zlib

from yade import O, PyRunner

_FORMAT = 1
_COMMAND = "__import__('roundedmesh').checkpoint._engine_save"
# Every scene YADE saves is a Boost serialization archive naming YADE's classes (yade::Body, yade::Sphere, ...);
# a roundedmesh scene is one too, its meshes and materials in O.tags (scene.py).
_ARCHIVE, _YADE_CLASS = b"serialization::archive", b"yade::"


class CheckpointError(RuntimeError):
    """A checkpoint that cannot be resumed from; the message starts with the file's path."""


def sidecar_path(path):
    """The sidecar that vouches for the checkpoint at path."""
    return path + ".checkpoint.json"


def _partial_path(path):
    # In path's folder, so that the rename is atomic; with path's extension, which O.save reads the format from.
    folder, name = os.path.split(path)
    return os.path.join(folder, ".partial-" + name)


def _sha256(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _fsync(path):
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _write_sidecar(path, scenes):
    sidecar = sidecar_path(path)
    partial = _partial_path(sidecar)
    with open(partial, "w") as f:
        json.dump({"format": _FORMAT, "file": os.path.basename(path), "scenes": scenes}, f, indent=1)
        f.flush()
        os.fsync(f.fileno())
    os.replace(partial, sidecar)


def _read_sidecar(path):
    """The sidecar's list of scene records, or CheckpointError."""
    sidecar = sidecar_path(path)
    try:
        with open(sidecar) as f:
            content = json.load(f)
    except FileNotFoundError:
        raise CheckpointError(f"{path}: no sidecar {sidecar}: not a checkpoint saved by roundedmesh.checkpoint") from None
    except (OSError, ValueError) as e:
        raise CheckpointError(f"{path}: its sidecar {sidecar} cannot be read: {e}") from None
    if not isinstance(content, dict) or content.get("format") != _FORMAT or not isinstance(content.get("scenes"), list):
        raise CheckpointError(f"{path}: its sidecar {sidecar} is not a checkpoint record of format {_FORMAT}")
    return content["scenes"]


def save(path):
    """Saves O's scene as a checkpoint at path, atomically (see the module's documentation). Returns the record
    written to the sidecar: sha256, size, iteration, time, saved (wall-clock time.time())."""
    partial = _partial_path(path)
    O.save(partial)
    _fsync(partial)
    record = {"sha256": _sha256(partial), "size": os.path.getsize(partial), "iteration": O.iter, "time": O.time,
              "saved": time.time()}
    # Until the rename, path is still the previous checkpoint: the sidecar keeps vouching for it.
    try:
        previous = _read_sidecar(path)[-1:] if os.path.isfile(path) else []
    except CheckpointError:
        previous = []
    _write_sidecar(path, previous + [record])
    os.replace(partial, path)
    _fsync(os.path.dirname(os.path.abspath(path)))
    _write_sidecar(path, [record])
    return record


def _decompressed(path, data):
    """The bytes of a compressed scene (by its extension, as YADE does), or CheckpointError."""
    try:
        if path.endswith(".gz"):
            return gzip.decompress(data)
        if path.endswith(".bz2"):
            return bz2.decompress(data)
    except (OSError, EOFError, ValueError, zlib.error) as e:
        raise CheckpointError(f"{path}: the compressed scene is damaged: {e}") from None
    return data


def _verified_record(path):
    """The sidecar's record of the file at path, after every check; CheckpointError otherwise."""
    if not os.path.isfile(path):
        raise CheckpointError(f"{path}: no such checkpoint file")
    scenes = _read_sidecar(path)
    size = os.path.getsize(path)
    checksum = _sha256(path)
    matching = [r for r in scenes if isinstance(r, dict) and r.get("sha256") == checksum and r.get("size") == size]
    if not matching:
        sizes = sorted({r.get("size") for r in scenes if isinstance(r, dict)}, key=str)
        if size not in sizes:
            raise CheckpointError(f"{path}: the file has {size} bytes, the checkpoint saved had "
                                  f"{' or '.join(map(str, sizes))}: truncated, extended or replaced")
        raise CheckpointError(f"{path}: its SHA-256 {checksum} is not the checkpoint's: the file was altered "
                              "or replaced after it was saved")
    with open(path, "rb") as f:
        scene = _decompressed(path, f.read())
    if _ARCHIVE not in scene[:64] or _YADE_CLASS not in scene:
        raise CheckpointError(f"{path}: the file holds no YADE scene (no serialization archive of YADE's classes)")
    return matching[-1]


def verify(path):
    """Checks the checkpoint at path without loading it; returns its record (sha256, size, iteration, time,
    saved) or raises CheckpointError naming the file and what is wrong."""
    return _verified_record(path)


def resume(path):
    """Loads the checkpoint at path into O after verify(path); returns its record. On any error, raises
    CheckpointError and leaves the current scene as it was."""
    record = _verified_record(path)
    O.load(path)
    if O.iter != record["iteration"]:
        raise CheckpointError(f"{path}: loaded at iteration {O.iter}, the checkpoint was saved at "
                              f"{record['iteration']}")
    return record


def _engine_save(path):
    """The checkpoint engine's command: saves between two steps, so the engine must run first."""
    engines = O.engines
    ours = [i for i, e in enumerate(engines) if isinstance(e, PyRunner) and e.command.startswith(_COMMAND + "(" + repr(path))]
    if ours != [0]:
        raise ValueError(f"O.engines: the checkpoint engine of {path} must be the first engine: a checkpoint taken "
                         "within a step would be resumed by doing the step's first engines twice")
    save(path)


class Checkpointer:
    """Saves O's scene at path every every_steps steps and/or every every_seconds seconds of wall-clock time,
    whichever comes first (at least one must be given)."""

    def __init__(self, path, every_steps=None, every_seconds=None):
        if every_steps is None and every_seconds is None:
            raise ValueError("Checkpointer: give every_steps, every_seconds or both")
        if every_steps is not None and not (isinstance(every_steps, int) and every_steps > 0):
            raise ValueError(f"Checkpointer: every_steps must be a positive integer, got {every_steps!r}")
        if every_seconds is not None and not every_seconds > 0:
            raise ValueError(f"Checkpointer: every_seconds must be positive, got {every_seconds!r}")
        self.path = os.path.abspath(path)
        self.every_steps = every_steps
        self.every_seconds = every_seconds
        self._last_iteration = O.iter
        self._last_clock = time.monotonic()

    def engine(self, label="checkpoint"):
        """A PyRunner that saves when due, to be put first in O.engines. It is saved with the scene, so a resumed
        scene goes on checkpointing to the same path."""
        return PyRunner(command=f"{_COMMAND}({self.path!r})", iterPeriod=self.every_steps or 0,
                        realPeriod=self.every_seconds or 0, label=label)

    def __call__(self):
        """For a script that runs O.run(n, True) in a loop: saves if due (between two runs is between two steps).
        Returns the sidecar's record when it saved, else None."""
        due = (self.every_steps is not None and O.iter - self._last_iteration >= self.every_steps) or \
              (self.every_seconds is not None and time.monotonic() - self._last_clock >= self.every_seconds)
        if not due:
            return None
        record = save(self.path)
        self._last_iteration = O.iter
        self._last_clock = time.monotonic()
        return record
