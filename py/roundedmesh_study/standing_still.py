"""A settled packing standing still (issue 41, item 1): does it stay at rest, and does its energy balance close?

Each shape's settled S1 packing of bench/data (doc/scenes.md) is restarted in S1's standing box at its recorded poses,
velocities and spins (peers.build_rounded: S1's materials, Eq. 7's damping A = 0.01 s, no friction, dt = 1e-4 s).
The packings of bench/data were settled at five times that step and stopped at a mean speed of 1 cm/s or after their
time limit, so they still descend; --settle-damping D first settles each one further at S1's step with NewtonIntegrator's damping
D, which leaves the packing's equilibrium as it is (it acts on the bodies' motion only), until no body moves faster
than --settled-speed (checked every SETTLE_CHECK s, at most --max-settle-time). Then, with NewtonIntegrator's damping
off, it stands for `--time` seconds with YADE's energy tracking on. Sampled at spin_energy.SAMPLES even times:

    translational, rotational kinetic energy [J] and the fastest spin [rad/s] (energy_conservation.kinetic_energies);
    YADE's O.energy: 'kinetic' (NewtonIntegrator's), 'gravWork' (minus gravity's work, m g dz summed: the packing's
    change of potential energy), and the engine's 'rmElastPotential', 'rmNormDamp', 'rmFrictDissip'
    (doc/physics.md, "Energy"); and O.energy.total(), their sum.

With forces that have a potential and dissipations that are all counted, the total stays constant: its drift over the
run, against the energy the damping dissipated in it, is how far the balance fails to close. The first sample is taken
after one step, when the engine has written its terms; the mean descent of the bodies' centres is minus 'gravWork'
over the packing's weight. --lowest N restarts only the N bodies nearest the floor, the rest left out: they are then
released from their pressed state, which tells a body's contacts with the floor from the packing's.

    /usr/bin/python3 scripts/validation/standing_still.py [--shapes sphere icosphere162 pear gummy_bear ...]
        [--normal pressure energy] [--time 0.5] [--lowest N] [--settle-damping 0.3] [--settled-speed 1e-3]
        [--max-settle-time 2] [--output out/standing_still]
    /usr/bin/python3 scripts/validation/standing_still.py --merge FOLDER [FOLDER ...] --output out/standing_still

Writes standing_still.csv (COLUMNS, per shape and law), standing_still_summary.csv (SUMMARY: per run, the settling
it took, the kinetic energy at the start and the end, the fastest spin sampled, the mean descent, the balance's drift
and the energy the damping dissipated) and standing_still.png (kinetic energy and the balance's drift against time).
"""
import argparse
import csv
import os
import shlex

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from yade import O  # noqa: E402

import roundedmesh as rm  # noqa: E402

from . import peers  # noqa: E402
from .bench_s1_peers import default_poses, read_poses  # noqa: E402
from .benchmarking import machine  # noqa: E402
from .energy_conservation import kinetic_energies  # noqa: E402
from .spin_energy import sampled_run, save_time_panels  # noqa: E402

SHAPES = ("sphere", "icosphere162", "pear", "gummy_bear", "spheroid", "pill", "tetra_grain")  # packings of bench/data
SETTLE_CHECK = 0.01  # how often settling checks the bodies' speeds [s]
ENERGY_KEYS = ("kinetic", "gravWork", "rmElastPotential", "rmNormDamp", "rmFrictDissip")
COLUMNS = ["run", "t_s", "translational_J", "rotational_J", "fastest_spin_rad_s", "yade_kinetic_J", "gravity_work_J",
           "elastic_J", "normal_damping_J", "friction_J", "total_J"]
SUMMARY = ["run", "settling_s", "settled_fastest_m_s", "kinetic_start_J", "kinetic_end_J", "fastest_spin_rad_s",
           "descent_mm", "drift_J", "dissipated_J", "drift_over_dissipated"]


def energies(ids):
    """translational, rotational [J], fastest spin [rad/s], then O.energy's ENERGY_KEYS and its total [J]."""
    translational, rotational, _, fastest = kinetic_energies(ids)
    terms = dict(O.energy.items())
    return [translational, rotational, fastest, *(terms.get(key, 0.0) for key in ENERGY_KEYS), O.energy.total()]


def fastest_speed(ids):
    """The fastest body's speed [m/s]."""
    return max(O.bodies[i].state.vel.norm() for i in ids)


def settle(ids, damping, speed, max_time):
    """Runs with NewtonIntegrator's damping `damping` until no body's centre moves faster than `speed` [m/s]
    (checked every SETTLE_CHECK s) or for `max_time` [s]; then turns the damping off. Returns (time taken [s],
    fastest speed [m/s]). The spins are not checked: YADE's damping takes only what the forces and torques do, so a
    frictionless sphere keeps its spin, which nothing can change, whatever the damping."""
    newton, start, first = O.engines[-1], O.time, O.iter
    newton.damping = damping
    steps, last = max(1, int(round(SETTLE_CHECK / O.dt))), first + max(1, int(round(max_time / O.dt)))
    progress = rm.progress.Progress(int(round(max_time / O.dt)), f"settling (at most {max_time:g} s)", interval=10.0)
    checks = 0
    while True:
        O.run(min(steps, last - O.iter), True)
        progress.update(O.iter - first)
        fastest, checks = fastest_speed(ids), checks + 1
        if fastest <= speed or O.iter >= last:
            break
        if checks % 25 == 0:
            print(f"settling: t = {O.time - start:.2f} s, the fastest body at {fastest:.3g} m/s", flush=True)
    newton.damping = 0.0
    return O.time - start, fastest_speed(ids)


def run(shape, poses, duration, normal="pressure", settling=(0.0, 0.0, 0.0)):
    """(rows (COLUMNS), ids, (settling time [s], fastest speed then [m/s])) of one packing standing still for
    `duration` [s] under the normal law `normal`, first settled as settle(ids, *settling) says if its damping is
    positive."""
    ids = peers.build_rounded(poses, shape, normal=normal)
    O.dt = peers.TIME_STEP
    settled = settle(ids, *settling) if settling[0] > 0 else (0.0, fastest_speed(ids))
    O.trackEnergy = True
    O.run(1, True)
    return sampled_run(f"{shape}, {normal}", duration, lambda: energies(ids)), ids, settled


def weight(ids):
    """The bodies' weight [N]."""
    return sum(O.bodies[i].state.mass for i in ids) * 9.81


def summary(rows, weight, settled):
    """SUMMARY's row of one run's rows; `weight` [N] of its bodies, `settled` run's third result."""
    first, last = rows[0], rows[-1]
    kinetic = COLUMNS.index("translational_J")
    drift = last[-1] - first[-1]
    dissipated = sum(last[COLUMNS.index(c)] - first[COLUMNS.index(c)] for c in ("normal_damping_J", "friction_J"))
    return [first[0], *settled, first[kinetic] + first[kinetic + 1], last[kinetic] + last[kinetic + 1],
            max(r[COLUMNS.index("fastest_spin_rad_s")] for r in rows),
            -1e3 * (last[COLUMNS.index("gravity_work_J")] - first[COLUMNS.index("gravity_work_J")]) / weight,
            drift, dissipated, drift / dissipated if dissipated > 0 else float("nan")]


def plot(rows, path):
    """Kinetic energy (left, logarithmic) and the balance's drift from the first sample (right) against the time
    since standing began (after any settling), one line per run: a colour per shape, solid for the paper's law and
    dashed for the energy law."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    names = list(dict.fromkeys(r[0] for r in rows))
    shapes = list(dict.fromkeys(name.split(",")[0] for name in names))
    for name in names:
        mine = [r for r in rows if r[0] == name]
        t = [r[1] - mine[0][1] for r in mine]
        style = {"color": f"C{shapes.index(name.split(',')[0]) % 10}", "ls": "--" if name.endswith("energy") else "-",
                 "marker": "o", "ms": 3, "label": name}
        axes[0].plot(t, [1e3 * (r[2] + r[3]) for r in mine], **style)
        axes[1].plot(t, [1e3 * (r[-1] - mine[0][-1]) for r in mine], **style)
    axes[0].set_yscale("log")
    save_time_panels(fig, axes, ("kinetic energy [mJ]", "drift of O.energy.total() [mJ]"), path)


def write_outputs(folder, rows, summaries):
    """standing_still.csv, standing_still_summary.csv and standing_still.png in `folder`."""
    tables = (("standing_still.csv", COLUMNS, rows), ("standing_still_summary.csv", SUMMARY, summaries))
    for name, header, table in tables:
        with open(os.path.join(folder, name), "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(header)
            writer.writerows(table)
    plot(rows, os.path.join(folder, "standing_still.png"))
    print(f"wrote {folder}/standing_still.csv, standing_still_summary.csv and standing_still.png")


def read_outputs(folder):
    """(rows, summaries) of the tables write_outputs wrote in `folder`, numbers as floats; a table of other columns
    (an older version's) is refused."""
    def table(name, header):
        with open(os.path.join(folder, name), newline="") as f:
            lines = list(csv.reader(f))
        if not lines or lines[0] != header:
            raise SystemExit(f"{os.path.join(folder, name)}: not this script's columns ({', '.join(header)})")
        return [[row[0], *map(float, row[1:])] for row in lines[1:]]
    return table("standing_still.csv", COLUMNS), table("standing_still_summary.csv", SUMMARY)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shapes", nargs="+", default=list(SHAPES), choices=SHAPES)
    parser.add_argument("--normal", nargs="+", default=["pressure"], choices=("pressure", "energy"))
    parser.add_argument("--time", type=float, default=0.5, help="simulated time per run [s]")
    parser.add_argument("--lowest", type=int, default=0, help="restart only this many bodies, the lowest (0: all)")
    parser.add_argument("--settle-damping", type=float, default=0.0,
                        help="NewtonIntegrator's damping while settling first (0: no settling; module docstring)")
    parser.add_argument("--settled-speed", type=float, default=1e-3, help="settle until no body is faster [m/s]")
    parser.add_argument("--max-settle-time", type=float, default=2.0, help="settle at most this long [s]")
    parser.add_argument("--merge", nargs="+", metavar="FOLDER",
                        help="run nothing: join the tables of these earlier outputs (runs split by --shapes) into --output")
    parser.add_argument("--output", default=os.path.join("out", "standing_still"))
    args = parser.parse_args(argv)
    if args.merge:
        os.makedirs(args.output, exist_ok=True)
        parts = [read_outputs(folder) for folder in args.merge]
        write_outputs(args.output, [r for rows, _ in parts for r in rows], [s for _, runs in parts for s in runs])
        return
    if not args.time > 0:
        parser.error(f"--time {args.time:g}: the time to stand must be positive [s]")
    if args.lowest < 0:
        parser.error(f"--lowest {args.lowest}: a number of bodies, 0 for all")
    if not 0 <= args.settle_damping < 1:
        parser.error(f"--settle-damping {args.settle_damping:g}: NewtonIntegrator's damping is in [0, 1)")
    if not (args.settled_speed > 0 and args.max_settle_time > 0):
        parser.error("--settled-speed and --max-settle-time must be positive")
    os.makedirs(args.output, exist_ok=True)
    print(f"# {machine()}\n# /usr/bin/python3 scripts/validation/standing_still.py {shlex.join(argv)}", flush=True)
    rows, summaries = [], []
    for shape in args.shapes:
        poses = read_poses(default_poses(shape), shape)
        if args.lowest:
            poses = sorted(poses, key=lambda pose: pose[0][2])[:args.lowest]
        for normal in args.normal:
            settling = (args.settle_damping, args.settled_speed, args.max_settle_time)
            mine, ids, settled = run(shape, poses, args.time, normal, settling)
            rows += mine
            summaries.append(summary(mine, weight(ids), settled))
            name, settle_time, settle_speed, start, end, spin, descent, drift, dissipated, ratio = summaries[-1]
            print(f"{name}: settled for {settle_time:.2f} s to {settle_speed:.2g} m/s; kinetic {1e3 * start:.3g} -> {1e3 * end:.3g} mJ, fastest spin {spin:.1f} rad/s, descent "
                  f"{descent:.3g} mm, balance drift {1e3 * drift:+.3g} mJ of {1e3 * dissipated:.3g} mJ dissipated "
                  f"({100 * ratio:+.1f} %)", flush=True)
    write_outputs(args.output, rows, summaries)
