"""Records scene S1 (doc/scenes.md) with 250 gummy bears for the C++ benchmark of the whole contact step
(bench/s1_step.cpp) and the engine's tests, so that they run on a real packing without YADE:

    bench/data/gummy_bear.mesh    the bears' mesh in its principal frame: vertices [m], triangles and the
                                  radius of curvature each triangle uses in contact [m], as Mesh.reference_shape
                                  ("gummy_bear", 554) makes it (563 nodes)
    bench/data/s1_settled.csv     the settled packing: every bear's and wall's state (full double precision)
    bench/data/s1_shaking.bin     the first `--steps` steps of S1's shaking started from the settled packing:
                                  every bear's and the floor's state at every step (float32, see below)
    bench/data/s1_resting.bin     the same number of steps of the settled packing in the standing box: the bears
                                  still rattle and spin (up to 3 rad/s), as they do in YADE after settling
    bench/data/s1_landing.bin     with --landing: the same number of steps of a whole S1 run continued from its
                                  checkpoint in the landing window (the falling bears meeting the shaken pile, the
                                  costliest part of the run: doc/benchmarks.md, "Speed III"), written alone

The settled packing comes from scripts/benchmarks/bench_shaken_bears.py, which lets the bears fall from S1's
lattice into the standing box and saves the settled scene; this script loads it, writes the packing, then moves the
floor as S1 shakes the box, z = A sin(2 pi t / T) (A = 0.025 m, T = 0.25 s), and records the states at every step:

    /usr/bin/python3 scripts/benchmarks/bench_shaken_bears.py --rebuild --settle-dt 5e-4 --settle-damping 0.3
    /usr/bin/python3 scripts/benchmarks/record_s1_scene.py [--settled out/bench_shaken_bears/settled.yade.gz]
                                                           [--steps 200]

The landing window comes from a checkpoint of scripts/s1_packing.py (seed 1, the bears' run) at t = 0.45 s:

    /usr/bin/python3 scripts/s1_packing.py --threads 2 --duration 0.4501 --checkpoint-every 500 --output out/s1_landing
    /usr/bin/python3 scripts/benchmarks/record_s1_scene.py --landing out/s1_landing/gummy_bear/checkpoint.yade.gz

A packing of a study grain (roundedmesh_study.grains.NAMES) or of S1's other shapes (pear, icosphere162, sphere),
settled by bench_shaken_bears.py --shape <name>, is written alone, as bench/data/s1_settled_<name>.csv (its 'shape'
column the shape's name): the speed-against-error study times YADE's peers at a grain's poses
(scripts/benchmarks/bench_s1_peers.py --shape <name>), and scripts/validation/standing_still.py restarts every
shape's packing; the mesh file and the trajectories are the C++ benchmark's, which runs the bear only.

    OMP_NUM_THREADS=2 /usr/bin/python3 scripts/benchmarks/bench_shaken_bears.py --shape spheroid --rebuild \
        --settle-dt 5e-4 --settle-damping 0.3 --settle-only
    /usr/bin/python3 scripts/benchmarks/record_s1_scene.py --settled out/bench_shaken_bears_spheroid/settled.yade.gz

The shape is the one bench_shaken_bears.py recorded in the saved scene (O.tags), gummy_bear for a scene saved
before it did; the CSV's header keeps the settling command and this one.

s1_shaking.bin and s1_resting.bin: the ASCII line "roundedmesh trajectory 1\n", then int32 body count n, int32 step count m,
float64 dt, int32 ids[n], then m frames of n x 13 float32: position (3) [m], orientation quaternion
(w, x, y, z), velocity (3) [m/s], angular velocity (3) [rad/s], bodies in the order of ids. float32 keeps
positions to about 2e-8 m, far below the overlaps of the packing (1e-4 m): the benchmark evaluates contacts at
the recorded states, it does not integrate them.
"""
import argparse
import json
import math
import os
import shlex
import struct
import sys

import numpy as np
from yade import O, PyRunner

import roundedmesh as rm
from roundedmesh.progress import Progress
from roundedmesh_study import grains

AMPLITUDE, PERIOD = 0.025, 0.25  # S1's shaking [m], [s]
HEADER = b"roundedmesh trajectory 1\n"
STATE_COLUMNS = ["x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"]
SETTLED_TAG = "bench_shaken_bears.settled"  # bench_shaken_bears.py's settling record in the saved scene (JSON)


def state_row(state):
    x, y, z, w = state.ori  # YADE's Quaternion iterates as x, y, z, w
    return [*state.pos, w, x, y, z, *state.vel, *state.angVel]


def write_mesh(mesh, path):
    with open(path, "w") as f:
        f.write("# roundedmesh mesh: Mesh.reference_shape('gummy_bear', 554) in its principal frame; units m\n")
        f.write(f"vertices {len(mesh.vertices)}\n")
        for v in mesh.vertices:
            f.write(" ".join(f"{c:.17g}" for c in v) + "\n")
        f.write(f"triangles {len(mesh.triangles)}\n")
        for t in mesh.triangles:
            f.write(" ".join(str(int(i)) for i in t) + "\n")
        f.write(f"radii {len(mesh.radii)}\n")
        for r in mesh.radii:
            f.write(f"{r:.17g}\n")


def walls():
    """[(id, axis, sense)] of the scene's YADE Walls."""
    return [(b.id, b.shape.axis, b.shape.sense) for b in O.bodies
            if b is not None and type(b.shape).__name__ == "Wall"]


def settling_record():
    """bench_shaken_bears.py's record of how the loaded scene was settled ({} for a scene saved before it kept
    one): shape, seed, settling dt [s] and damping, whether it settled, the command."""
    return json.loads(O.tags[SETTLED_TAG]) if O.tags.has_key(SETTLED_TAG) else {}


def settled_name(shape):
    """The packing's file name: s1_settled.csv for the bear (the C++ benchmark's), s1_settled_<shape>.csv else."""
    return "s1_settled.csv" if shape == "gummy_bear" else f"s1_settled_{shape}.csv"


def write_settled(bears, path, shape="gummy_bear", made_by=()):
    """The packing as bench_s1_peers.read_poses reads it: '#' comment lines (`made_by`: lines of provenance, e.g.
    the commands), a header, one row per body (`shape` its shape column) and per wall, states at full double
    precision."""
    with open(path, "w") as f:
        plural = "gummy bears" if shape == "gummy_bear" else f"{shape} bodies"
        f.write(f"# S1 settled packing of {len(bears)} {plural} (doc/scenes.md), t = {O.time:.6g} s, "
                f"dt = {O.dt:g} s; written by scripts/benchmarks/record_s1_scene.py\n")
        mesh = {"gummy_bear": "bench/data/gummy_bear.mesh", "pear": "Mesh.reference_shape('pear'), 486 nodes asked",
                "icosphere162": "Mesh.icosphere(0.025, 2), the mesh's own mass",
                "sphere": "a sphere body of radius 0.025 m, rm.add_sphere"}.get(
                    shape, f"roundedmesh_study.grains.grain({shape!r}).mesh({grains.REFERENCE_NODES}), curvature computed")
        f.write(f"# shape: {shape} ({mesh}) or wall<axis><sense> (a YADE Wall); quaternion body -> global, of the "
                "mesh's principal frame\n")
        for line in made_by:
            f.write(f"# {line}\n")
        f.write(",".join(["id", "shape"] + STATE_COLUMNS) + "\n")
        for i in bears:
            f.write(",".join([str(i), shape] + [f"{c:.17g}" for c in state_row(O.bodies[i].state)]) + "\n")
        for i, axis, sense in walls():
            shape = f"wall{'xyz'[axis]}{'+' if sense > 0 else '-'}"
            f.write(",".join([str(i), shape] + [f"{c:.17g}" for c in state_row(O.bodies[i].state)]) + "\n")


def floor_id():
    floors = [i for i, axis, sense in walls() if axis == 2 and sense > 0]
    if len(floors) != 1:
        raise SystemExit(f"expected one floor (a Wall with axis 2, sense 1), found {len(floors)}")
    return floors[0]


def shake(amplitude):
    """Moves the floor of the loaded scene as S1 shakes the box, with `amplitude` [m] (0: standing), from now on."""
    floor = floor_id()
    start = O.time
    omega = 2 * math.pi / PERIOD

    def drive():  # the box's velocity for the step about to be integrated
        O.bodies[floor].state.vel = (0, 0, amplitude * omega * math.cos(omega * (O.time - start + 0.5 * O.dt)))

    O.engines = O.engines[:-1] + [PyRunner(command="drive()", iterPeriod=1, initRun=True)] + O.engines[-1:]
    sys.modules["__main__"].drive = drive  # PyRunner commands run in __main__'s namespace


def record(bears, steps, path):
    """Records `steps` steps of the loaded scene as its engines run it."""
    ids = list(bears) + [floor_id()]
    frames = np.empty((steps, len(ids), 13), dtype="<f4")
    reporter = Progress(steps, os.path.basename(path))
    for k in range(steps):
        O.run(1, True)
        frames[k] = [state_row(O.bodies[i].state) for i in ids]
        reporter.update(k + 1)
    with open(path, "wb") as f:
        f.write(HEADER)
        f.write(struct.pack("<iid", len(ids), steps, O.dt))
        f.write(np.asarray(ids, dtype="<i4").tobytes())
        f.write(frames.tobytes())


def record_landing(checkpoint, steps, output):
    """s1_landing.bin: `steps` steps of S1 continued from `checkpoint`, its box moved by its own
    HarmonicMotionEngine; s1_packing.py's recorder and frames, which the checkpoint names, left out."""
    if not os.path.exists(checkpoint):
        raise SystemExit(f"{checkpoint} does not exist: run scripts/s1_packing.py with --checkpoint-every first")
    main_module = sys.modules["__main__"]
    main_module.s1_record = main_module.s1_last_step_ends = lambda *arguments: None
    O.load(checkpoint)
    for engine in O.engines:
        if isinstance(engine, PyRunner) and "roundedmesh" not in engine.command:
            engine.dead = True
    bears = sorted(rm.rounded_bodies())
    if len(bears) != 250:
        raise SystemExit(f"{checkpoint}: {len(bears)} rounded bodies, not S1's 250 gummy bears")
    print(f"{checkpoint}: t = {O.time:.4f} s, step {O.iter}")
    record(bears, steps, os.path.join(output, "s1_landing.bin"))
    print(f"wrote s1_landing.bin ({steps} steps from t = {O.time - steps * O.dt:.4f} s) to {output}")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--settled", default="out/bench_shaken_bears/settled.yade.gz")
    parser.add_argument("--output", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir,
                                                         os.pardir, "bench", "data"))
    parser.add_argument("--steps", type=int, default=200, help="steps of each trajectory to record")
    parser.add_argument("--landing", metavar="CHECKPOINT",
                        help="record s1_landing.bin only, from this checkpoint of scripts/s1_packing.py")
    args = parser.parse_args(argv)
    command = " ".join(shlex.quote(a) for a in [sys.executable, sys.argv[0]] + list(argv))
    if args.steps < 1:
        parser.error("--steps must be positive")
    if args.landing:
        record_landing(args.landing, args.steps, args.output)
        return
    if not os.path.exists(args.settled):
        raise SystemExit(f"{args.settled} does not exist: run scripts/benchmarks/bench_shaken_bears.py first")
    os.makedirs(args.output, exist_ok=True)
    O.load(args.settled)
    meshes = rm.rounded_bodies()
    bears = sorted([*meshes, *rm.sphere_bodies()])
    record = settling_record()
    shape = record.get("shape", "gummy_bear")
    made_by = [f"settled by: {record['command']}" if "command" in record else
               "settled by: scripts/benchmarks/bench_shaken_bears.py (command not recorded)",
               f"settling: seed {record.get('seed', '?')}, dt {record.get('dt', '?')} s, NewtonIntegrator damping "
               f"{record.get('damping', '?')}, {record.get('steps', '?')} steps, "
               f"{'settled' if record.get('settled') else 'max time reached'}" if record else "settling: not recorded",
               f"written by: {command}"]
    settled = os.path.join(args.output, settled_name(shape))
    if shape != "gummy_bear":
        write_settled(bears, settled, shape, made_by)
        print(f"wrote {settled} ({len(bears)} {shape} bodies)")
        return
    write_mesh(meshes[bears[0]], os.path.join(args.output, "gummy_bear.mesh"))
    write_settled(bears, settled, shape, made_by)
    shake(AMPLITUDE)
    record(bears, args.steps, os.path.join(args.output, "s1_shaking.bin"))
    O.load(args.settled)
    shake(0.0)
    record(bears, args.steps, os.path.join(args.output, "s1_resting.bin"))
    print(f"wrote gummy_bear.mesh, s1_settled.csv, s1_shaking.bin and s1_resting.bin ({args.steps} steps each) to "
          f"{args.output}")


if __name__ == "__main__":
    main(sys.argv[1:])
