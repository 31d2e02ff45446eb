"""A settled packing standing still (issue 41, item 1): does it stay at rest, and does its energy balance close?

Each shape's settled S1 packing of bench/data (doc/scenes.md) is restarted in S1's standing box at its recorded poses,
velocities and spins (peers.build_rounded: S1's materials, Eq. 7's damping A = 0.01 s, no friction, dt = 1e-4 s) and
run for `--time` seconds with YADE's energy tracking on. Sampled at spin_energy.SAMPLES even times:

    translational, rotational kinetic energy [J] and the fastest spin [rad/s] (energy_conservation.kinetic_energies);
    YADE's O.energy: 'kinetic' (NewtonIntegrator's), 'gravWork' (minus gravity's work, m g dz summed: the packing's
    change of potential energy), and the engine's 'rmElastPotential', 'rmNormDamp', 'rmFrictDissip'
    (doc/physics.md, "Energy"); and O.energy.total(), their sum.

With forces that have a potential and dissipations that are all counted, the total stays constant: its drift over the
run, against the energy the damping dissipated in it, is how far the balance fails to close. The first sample is taken
after one step, when the engine has written its terms; the mean descent of the bodies' centres is minus 'gravWork'
over the packing's weight. --lowest N restarts only the N bodies nearest the floor, the rest left out: they are then
released from their pressed state, which tells a body's contacts with the floor from the packing's.

    /usr/bin/python3 scripts/validation/standing_still.py [--shapes gummy_bear spheroid pill tetra_grain]
        [--normal pressure energy] [--time 0.5] [--lowest N] [--output out/standing_still]

Writes standing_still.csv (COLUMNS, per shape and law), standing_still_summary.csv (SUMMARY: per run, the kinetic
energy at the start and the end, the fastest spin sampled, the mean descent, the balance's drift and the energy the
damping dissipated) and standing_still.png (kinetic energy and the balance's drift against time).
"""
import argparse
import csv
import os
import shlex

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from yade import O  # noqa: E402

from . import peers  # noqa: E402
from .bench_s1_peers import default_poses, read_poses  # noqa: E402
from .benchmarking import machine  # noqa: E402
from .energy_conservation import kinetic_energies  # noqa: E402
from .spin_energy import sampled_run, save_time_panels  # noqa: E402

SHAPES = ("gummy_bear", "spheroid", "pill", "tetra_grain")  # the settled packings of bench/data
ENERGY_KEYS = ("kinetic", "gravWork", "rmElastPotential", "rmNormDamp", "rmFrictDissip")
COLUMNS = ["run", "t_s", "translational_J", "rotational_J", "fastest_spin_rad_s", "yade_kinetic_J", "gravity_work_J",
           "elastic_J", "normal_damping_J", "friction_J", "total_J"]
SUMMARY = ["run", "kinetic_start_J", "kinetic_end_J", "fastest_spin_rad_s", "descent_mm", "drift_J", "dissipated_J",
           "drift_over_dissipated"]


def energies(ids):
    """translational, rotational [J], fastest spin [rad/s], then O.energy's ENERGY_KEYS and its total [J]."""
    translational, rotational, _, fastest = kinetic_energies(ids)
    terms = dict(O.energy.items())
    return [translational, rotational, fastest, *(terms.get(key, 0.0) for key in ENERGY_KEYS), O.energy.total()]


def run(shape, poses, duration, normal="pressure"):
    """Rows (COLUMNS) of one packing standing still for `duration` [s] under the normal law `normal`."""
    ids = peers.build_rounded(poses, shape, normal=normal)
    O.dt = peers.TIME_STEP
    O.trackEnergy = True
    O.run(1, True)
    return sampled_run(f"{shape}, {normal}", duration, lambda: energies(ids)), ids


def weight(ids):
    """The bodies' weight [N]."""
    return sum(O.bodies[i].state.mass for i in ids) * 9.81


def summary(rows, weight):
    """SUMMARY's row of one run's rows; `weight` [N] of its bodies."""
    first, last = rows[0], rows[-1]
    kinetic = COLUMNS.index("translational_J")
    drift = last[-1] - first[-1]
    dissipated = sum(last[COLUMNS.index(c)] - first[COLUMNS.index(c)] for c in ("normal_damping_J", "friction_J"))
    return [first[0], first[kinetic] + first[kinetic + 1], last[kinetic] + last[kinetic + 1],
            max(r[COLUMNS.index("fastest_spin_rad_s")] for r in rows),
            -1e3 * (last[COLUMNS.index("gravity_work_J")] - first[COLUMNS.index("gravity_work_J")]) / weight,
            drift, dissipated, drift / dissipated if dissipated > 0 else float("nan")]


def plot(rows, path):
    """Kinetic energy (left) and the balance's drift from the first sample (right) against time, one line per run."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for name in dict.fromkeys(r[0] for r in rows):
        mine = [r for r in rows if r[0] == name]
        t = [r[1] for r in mine]
        axes[0].plot(t, [1e3 * (r[2] + r[3]) for r in mine], marker="o", ms=3, label=name)
        axes[1].plot(t, [1e3 * (r[-1] - mine[0][-1]) for r in mine], marker="o", ms=3, label=name)
    save_time_panels(fig, axes, ("kinetic energy [mJ]", "drift of O.energy.total() [mJ]"), path)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shapes", nargs="+", default=list(SHAPES), choices=SHAPES)
    parser.add_argument("--normal", nargs="+", default=["pressure"], choices=("pressure", "energy"))
    parser.add_argument("--time", type=float, default=0.5, help="simulated time per run [s]")
    parser.add_argument("--lowest", type=int, default=0, help="restart only this many bodies, the lowest (0: all)")
    parser.add_argument("--output", default=os.path.join("out", "standing_still"))
    args = parser.parse_args(argv)
    if not args.time > 0:
        parser.error(f"--time {args.time:g}: the time to stand must be positive [s]")
    if args.lowest < 0:
        parser.error(f"--lowest {args.lowest}: a number of bodies, 0 for all")
    os.makedirs(args.output, exist_ok=True)
    print(f"# {machine()}\n# /usr/bin/python3 scripts/validation/standing_still.py {shlex.join(argv)}", flush=True)
    rows, summaries = [], []
    for shape in args.shapes:
        poses = read_poses(default_poses(shape), shape)
        if args.lowest:
            poses = sorted(poses, key=lambda pose: pose[0][2])[:args.lowest]
        for normal in args.normal:
            mine, ids = run(shape, poses, args.time, normal)
            rows += mine
            summaries.append(summary(mine, weight(ids)))
            name, start, end, spin, descent, drift, dissipated, ratio = summaries[-1]
            print(f"{name}: kinetic {1e3 * start:.3g} -> {1e3 * end:.3g} mJ, fastest spin {spin:.1f} rad/s, descent "
                  f"{descent:.3g} mm, balance drift {1e3 * drift:+.3g} mJ of {1e3 * dissipated:.3g} mJ dissipated "
                  f"({100 * ratio:+.1f} %)", flush=True)
    tables = (("standing_still.csv", COLUMNS, rows), ("standing_still_summary.csv", SUMMARY, summaries))
    for name, header, table in tables:
        with open(os.path.join(args.output, name), "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(header)
            writer.writerows(table)
    plot(rows, os.path.join(args.output, "standing_still.png"))
    print(f"wrote {args.output}/standing_still.csv, standing_still_summary.csv and standing_still.png")
