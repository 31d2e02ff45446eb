"""Helpers for the benchmark scripts: a description of the machine, the time per step of blocks of YADE steps,
and the median CPU time of a call."""
import os
import platform
import statistics
import time

import yade.config
from yade import O


def machine():
    """CPU model, cores, kernel and YADE version, for the header of every benchmark's output."""
    with open("/proc/cpuinfo") as cpuinfo:
        model = next((line.split(":", 1)[1].strip() for line in cpuinfo if line.startswith("model name")),
                     platform.processor())
    return f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}, YADE {yade.config.version}"


def step_times_ms(steps, blocks):
    """Runs O for `blocks` blocks of `steps` steps; returns (wall, cpu): the time per step of each block [ms]."""
    wall, cpu = [], []
    for _ in range(blocks):
        start, start_cpu = time.perf_counter(), time.process_time()
        O.run(steps, True)
        wall.append((time.perf_counter() - start) / steps * 1e3)
        cpu.append((time.process_time() - start_cpu) / steps * 1e3)
    return wall, cpu


def median_cpu_ms(call, repetitions):
    """Median CPU time of `call()` over `repetitions` runs [ms]; CPU time is steadier than wall time on a
    shared machine."""
    times = []
    for _ in range(repetitions):
        start = time.process_time()
        call()
        times.append(time.process_time() - start)
    return statistics.median(times) * 1e3
