"""Where does a settled packing's spin come from? Issue 41, item 1: an analysis, the model is not changed.

The spheroid's S1 packing as settled while Eq. 7's damping was taken at the contact circle's centre
(bench/data/s1_spinning_spheroid.csv, before issue 41's repair) holds 38 bodies spinning faster than 10 rad/s about
their long axes, up to 478 rad/s. This restarts it (peers.build_rounded: S1's box, materials and engine, each
body at its recorded pose, velocity and spin) under a set of cases that each change one thing, and follows the
bodies' kinetic energy for `--time` seconds of simulated time:

    default            the engine's defaults (the paper's normal law, Eq. 7's damping A = 0.01 s), dt = 1e-4 s
    dt/4               the same at dt = 2.5e-5 s: what changes with the step is the integration's
    undamped           the bodies' A = 0 (the box keeps its 0.01 s, so a contact with a wall is damped at 0.005 s)
    energy             normal='energy', the exact gradient of one energy, damped
    energy, undamped   normal='energy', the bodies' A = 0 (the box's as above)
    ... at rest        the same, every spin set to zero first

With --pair, the same question on one contact: two of the shape's bodies, long axes crossed or parallel, pressed
`--overlap` into each other, no gravity; body 2 held, body 1 held in place and turning only about its long axis, which
spins at `--spin`; under each of the normal laws with and without damping, and at dt/4. A surface of revolution
turning about its axis moves along itself: a contact that is the gradient of an energy and a damping that
dissipates leave the spin as it is or slow it.

Rotational energy per body: sum over principal axes of I_k w_k^2 / 2, w in the principal frame; "axial" is the part
about the axis of least inertia (a prolate spheroid's long axis). Gravity's work and the elastic energy are of the
order of the packing's weight times its overlaps (mJ): a gain of joules in the spin is work the contacts do.

    /usr/bin/python3 scripts/validation/spin_energy.py [--shape spheroid] [--poses CSV] [--time 0.125]
        [--cases default dt/4 undamped energy "energy, undamped"] [--output out/spin_energy]
    /usr/bin/python3 scripts/validation/spin_energy.py --pair [--spin 400] [--overlap 0.5e-3] [--time 0.1]

With --pair it writes spin_pair.csv (law, damping A [s], axes, dt [s], spin [rad/s], rotational energy at the start
and the end [J], its mean rate of change [W]). Else it writes spin_energy.csv (case, t [s], translational,
rotational and axial rotational energy [J], the fastest spin [rad/s]) and spin_energy.png (rotational energy against
time: the cases with the packing's spins and those at rest).
"""
import argparse
import csv
import os
import shlex
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade import ForceResetter, NewtonIntegrator, O  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402

from . import peers  # noqa: E402
from .benchmarking import machine  # noqa: E402
from .energy_conservation import kinetic_energies  # noqa: E402
from .bench_s1_peers import DATA, read_poses  # noqa: E402

TIME_STEP = peers.TIME_STEP  # S1's [s]
CASES = {
    "default": {},
    "dt/4": {"dt": TIME_STEP / 4},
    "undamped": {"damping": 0.0},
    "energy": {"normal": "energy"},
    "energy, undamped": {"normal": "energy", "damping": 0.0},
}
CASES.update({f"{name}, at rest": {**case, "at_rest": True} for name, case in list(CASES.items())})
SPINNING = os.path.join(DATA, "s1_spinning_spheroid.csv")  # the default --poses
SAMPLES = 10  # per run, besides its start
COLUMNS = ["case", "t_s", "translational_J", "rotational_J", "axial_rotational_J", "fastest_spin_rad_s"]


def run_case(name, poses, shape, duration, normal="pressure", dt=TIME_STEP, damping=None, at_rest=False):
    """Rows (COLUMNS) of one case: S1 rebuilt at `poses`, run for `duration` [s] at `dt` [s]."""
    if at_rest:
        poses = [(position, ori, velocity, (0.0, 0.0, 0.0)) for position, ori, velocity, _ in poses]
    ids = peers.build_rounded(poses, shape, normal=normal)
    if damping is not None:
        for i in ids:
            rm.set_material(i, rm.HertzMaterial(damping=damping, **peers.PARTICLE))
    O.dt = dt
    return sampled_run(name, duration, lambda: kinetic_energies(ids))


def sampled_run(name, duration, sample):
    """Runs the scene for `duration` [s] of simulated time at O.dt; rows [name, O.time, *sample()] at the start and
    at SAMPLES even steps, with progress printed."""
    steps, start = int(round(duration / O.dt)), O.iter
    rows = [[name, O.time, *sample()]]
    progress = rm.progress.Progress(steps, name)
    for k in range(1, SAMPLES + 1):
        O.run(start + steps * k // SAMPLES - O.iter, True)
        rows.append([name, O.time, *sample()])
        progress.update(O.iter - start)
    return rows


def principal_axis_along(mesh, axis, direction):
    """The orientation that turns principal axis `axis` of `mesh`'s frame onto the unit vector `direction`."""
    turn = Quaternion()
    turn.setFromTwoVectors(Vector3(*np.eye(3)[axis]), Vector3(*direction))
    return turn


def spinning_pair(shape, normal, damping, spin, crossed, overlap, duration, dt=TIME_STEP):
    """(rotational energy of body 1 at the start, at the end [J]) of --pair's contact (module docstring)."""
    O.reset()
    mesh = peers.body_frame(shape)[0]
    material = rm.HertzMaterial(damping=damping, **peers.PARTICLE)
    long_axis = int(np.argmin(np.array(mesh.inertia)))
    half_width = np.ptp(np.array(mesh.vertices)[:, (long_axis + 1) % 3]) / 2  # across the long axis [m]
    first = rm.add_body(mesh, (0, 0, 0), principal_axis_along(mesh, long_axis, (1, 0, 0)), material)
    second = rm.add_body(mesh, (0, 0, 2 * half_width - overlap),
                         principal_axis_along(mesh, long_axis, (0, 1, 0) if crossed else (1, 0, 0)), material)
    O.bodies[first].state.blockedDOFs = "xyzYZ"
    O.bodies[second].state.blockedDOFs = "xyzXYZ"
    O.engines = [ForceResetter(), rm.engine(normal=normal), NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
    O.dt = dt
    rm.set_velocity(first, angVel=(spin, 0, 0))
    start = kinetic_energies([first])[1]
    O.run(int(round(duration / dt)), True)
    return start, kinetic_energies([first])[1]


def pair_cases(args):
    """Rows of spin_pair.csv: both laws with and without damping for crossed and parallel axes, then dt/4."""
    damping = peers.DAMPING_CONSTANT
    cases = [(normal, a, crossed, TIME_STEP) for crossed in (True, False) for normal in ("pressure", "energy")
             for a in (damping, 0.0)] + [("pressure", damping, True, TIME_STEP / 4)]
    rows = []
    for normal, a, crossed, dt in cases:
        start, end = spinning_pair(args.shape, normal, a, args.spin, crossed, args.overlap, args.time, dt)
        rows.append([normal, a, "crossed" if crossed else "parallel", dt, args.spin, start, end,
                     (end - start) / args.time])
        print(f"{normal}, A = {a:g} s, {rows[-1][2]}, dt = {dt:g} s: {start:.5g} -> {end:.5g} J "
              f"({rows[-1][-1]:+.3g} W)", flush=True)
    return rows


def plot(rows, path):
    """Rotational energy against time: the cases restarted with their spins (left, J) and at rest (right, mJ)."""
    names = list(dict.fromkeys(r[0] for r in rows))
    panels = [(n for n in names if not n.endswith("at rest")), (n for n in names if n.endswith("at rest"))]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    titles = ("with the packing's spins [J]", "spins set to zero [mJ]")
    for ax, chosen, scale in zip(axes, panels, (1.0, 1e3)):
        for name in chosen:
            mine = [r for r in rows if r[0] == name]
            ax.plot([r[1] for r in mine], [scale * r[3] for r in mine], marker="o", ms=3, label=name)
    save_time_panels(fig, axes, [f"rotational kinetic energy, {title}" for title in titles], path)


def save_time_panels(fig, axes, titles, path):
    """Labels panels plotted against simulated time, one title each, and writes the figure to `path`."""
    for ax, title in zip(axes, titles):
        ax.set_xlabel("simulated time [s]")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shape", default="spheroid")
    parser.add_argument("--poses", default=SPINNING, help="packing to restart (CSV; default the spinning spheroids)")
    parser.add_argument("--time", type=float, default=0.125, help="simulated time per case [s]")
    parser.add_argument("--pair", action="store_true", help="one contact of two bodies, one spinning (docstring)")
    parser.add_argument("--spin", type=float, default=400.0, help="--pair: body 1's spin [rad/s]")
    parser.add_argument("--overlap", type=float, default=0.5e-3, help="--pair: the bodies' overlap [m]")
    parser.add_argument("--cases", nargs="+", default=list(CASES), choices=list(CASES))
    parser.add_argument("--output", default=os.path.join("out", "spin_energy"))
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    print(f"# {machine()}\n# /usr/bin/python3 scripts/validation/spin_energy.py {shlex.join(argv)}", flush=True)
    if args.pair:
        with open(os.path.join(args.output, "spin_pair.csv"), "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["normal", "damping_s", "axes", "dt_s", "spin_rad_s", "start_J", "end_J", "rate_W"])
            writer.writerows(pair_cases(args))
        print(f"wrote {args.output}/spin_pair.csv")
        return
    poses = read_poses(args.poses, args.shape)
    rows, start = [], time.perf_counter()
    for name in args.cases:
        rows += run_case(name, poses, args.shape, args.time, **CASES[name])
        first, last = next(r for r in rows if r[0] == name), rows[-1]
        gain = last[3] - first[3]
        print(f"{name}: rotational {first[3]:.4g} -> {last[3]:.4g} J ({gain:+.3g} J, {gain / args.time:+.3g} W; "
              f"about the long axes {last[4] - first[4]:+.3g} J), translational {first[2]:.3g} -> {last[2]:.3g} J, "
              f"fastest spin {first[5]:.1f} -> {last[5]:.1f} rad/s", flush=True)
    with open(os.path.join(args.output, "spin_energy.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(COLUMNS)
        writer.writerows(rows)
    plot(rows, os.path.join(args.output, "spin_energy.png"))
    print(f"wrote {args.output}/spin_energy.csv and spin_energy.png ({time.perf_counter() - start:.0f} s)")
