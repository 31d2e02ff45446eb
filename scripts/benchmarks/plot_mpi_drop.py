"""Plots doc/figures/mpi_drop.csv (rounded bodies under YADE's MPI decomposition, doc/scaling.md): time per step on
one process and on three (the master and two workers), beside the model's estimate for the workers, and whether the
final positions agree.

    /usr/bin/python3 scripts/benchmarks/plot_mpi_drop.py [--csv doc/figures/mpi_drop.csv] [--output doc/figures/mpi_drop.png]

The model (doc/scaling.md): t(P workers) = T / P x (1 + d) + mpy's own cost per step, with T the one process's time on
one thread (its time times its threads: 1 -> 2 threads scale 1.9-2.1x on S1), d the measured share of pairs computed
twice and mpy's cost measured on the small scene (its 3-process time less its 1-process time).
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
FIGURES = os.path.join(HERE, "..", "..", "doc", "figures")


def read(path):
    scenes = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            scenes.setdefault(row["scene"], {})[int(row["processes"])] = row
    return scenes


def model_ms(rows, workers, mpy_ms):
    """The model's time per step on `workers` workers from the one-process run (one row per process count)."""
    one, split = rows[1], rows[workers + 1]
    pairs_one = float(one["touching_pairs_all_processes"])
    duplicated = (float(split["touching_pairs_all_processes"]) - pairs_one) / pairs_one
    one_thread = float(one["ms_per_step"]) * int(one["threads_per_process"])
    return one_thread / workers * (1 + duplicated) + mpy_ms


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--csv", default=os.path.join(FIGURES, "mpi_drop.csv"))
    parser.add_argument("--output", default=os.path.join(FIGURES, "mpi_drop.png"))
    args = parser.parse_args()
    scenes = read(args.csv)
    small = min(scenes.values(), key=lambda rows: float(rows[1]["ms_per_step"]))
    mpy_ms = float(small[3]["ms_per_step"]) - float(small[1]["ms_per_step"])
    figure, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4))
    for ax, (scene, rows) in zip(axes, scenes.items()):
        labels = [f"1 process, {rows[1]['threads_per_process']} thr.", "3 processes, 1 thr.", "model, 3"]
        values = [float(rows[1]["ms_per_step"]), float(rows[3]["ms_per_step"]), model_ms(rows, 2, mpy_ms)]
        bars = ax.bar(labels, values, color=["tab:blue", "tab:orange", "none"], edgecolor="k",
                      hatch=["", "", "//"])
        for bar, value in zip(bars, values):
            ax.annotate(f"{value:.3g}", (bar.get_x() + bar.get_width() / 2, value), ha="center", va="bottom")
        same = all(rows[3][key] == rows[1][key] for key in ("mean_height_m", "packing_factor_10cm_percent"))
        ax.set_title(f"{scene}\nmean height {1000 * float(rows[1]['mean_height_m']):.3f} mm"
                     f"{', equal on 3' if same else ', differs on 3'}", fontsize=9)
        ax.set_ylim(0, 1.15 * max(values))
        ax.set_ylabel("wall ms per step (2 cores)")
    figure.suptitle("Rounded bodies under yade.mpy: one process against the master and two workers")
    figure.tight_layout()
    figure.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
