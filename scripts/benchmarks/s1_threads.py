"""Milliseconds per step of the settled S1 packing on 1 and 2 threads, for every run of scripts/s1_packing.py:
each run's last checkpoint (step 13,000 of 13,500 with the defaults, 0.55 s into the settling) is resumed to the
end once per thread count, in a copy of its folder, and the medians of the resumed windows are tabulated. Every
figure comes from one machine in one session, the runs one after the other.

    /usr/bin/python3 scripts/benchmarks/s1_threads.py [--output out/s1] [--threads 1 2]

Writes <output>/threads.csv (run, threads, steps timed, median wall and CPU ms per step, median contacts, machine,
command) and prints it. The copies go to <output>/threads/<n>/<run>; the runs' own folders are left as they are.
OMP_NUM_THREADS is set for the whole process, so YADE's own OpenMP loops (Debian's YADE is built with OpenMP)
use the threads as well as roundedmesh's engine. Run it on an otherwise idle machine: OpenMP threads that wait
for a busy core at every barrier make a step many times slower.
"""
import argparse
import csv
import os
import shlex
import shutil
import subprocess
import sys

from roundedmesh_study import SCRIPTS
from roundedmesh_study.s1_figures import ORDER, read_csv

CHECKPOINT = "checkpoint.yade.gz"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default=os.path.join("out", "s1"), help="the runs' folder (default out/s1)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2], help="thread counts (default 1 2)")
    parser.add_argument("--seed", type=int, default=1, help="the runs' seed (default 1)")
    args = parser.parse_args()
    runs = [run for run in ORDER if os.path.isfile(os.path.join(args.output, run, CHECKPOINT))
            and os.path.isfile(os.path.join(args.output, run, "timing.csv"))]
    if not runs:
        raise SystemExit(f"s1_threads.py: no complete run with a checkpoint in {args.output}")
    command = shlex.join([sys.executable] + sys.argv)
    table = []
    for run in runs:
        (timing,) = read_csv(os.path.join(args.output, run, "timing.csv"))
        for threads in args.threads:
            root = os.path.join(args.output, "threads", str(threads))
            folder = os.path.join(root, run)
            shutil.rmtree(folder, ignore_errors=True)
            os.makedirs(folder)
            for name in (CHECKPOINT, CHECKPOINT + ".checkpoint.json", "height.csv"):
                shutil.copy2(os.path.join(args.output, run, name), folder)
            scene = ["--seed", str(args.seed), "--count", timing["count"], "--dt", timing["dt_s"], "--duration",
                     repr(round(float(timing["dt_s"]) * int(timing["steps"]), 12))]
            resumed = subprocess.run([sys.executable, os.path.join(SCRIPTS, "s1_packing.py")] + run_arguments(run)
                                     + scene + ["--resume", "--frames", "1", "--threads", str(threads), "--output",
                                                root], capture_output=True, text=True)
            if resumed.returncode:
                raise SystemExit(f"s1_threads.py: {run} on {threads} threads failed:\n{resumed.stdout[-2000:]}"
                                 f"{resumed.stderr[-2000:]}")
            (measured,) = read_csv(os.path.join(folder, "timing.csv"))
            phase = "settling" if int(measured["settling_windows"]) else "shaking"
            table.append([run, threads, int(measured["steps"]) - int(measured["resumed_at"]),
                          float(measured[f"{phase}_median_ms_per_step"]),
                          float(measured[f"{phase}_median_cpu_ms_per_step"]),
                          float(measured[f"{phase}_median_contacts"] or "nan"), measured["machine"], command])
            print("{}: {} thread(s), {} steps from step {}: {:.2f} ms/step wall, {:.2f} CPU, {:.0f} contacts"
                  .format(run, threads, table[-1][2], measured["resumed_at"], *table[-1][3:6]), flush=True)
    with open(os.path.join(args.output, "threads.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "threads", "steps", "median_ms_per_step", "median_cpu_ms_per_step", "median_contacts",
                         "machine", "command"])
        writer.writerows(table)
    print(f"wrote {os.path.join(args.output, 'threads.csv')}")


def run_arguments(run):
    """The arguments of scripts/s1_packing.py that select `run`."""
    for peer in ("clumps", "level_sets"):
        if run.endswith("_" + peer):
            return ["--peers", peer, "--peers-only"]
    return ["--shape", run]


if __name__ == "__main__":
    main()
