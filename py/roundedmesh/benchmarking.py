"""Helpers for the benchmark scripts: a description of the machine, and the median CPU time of a call."""
import os
import platform
import statistics
import time

import yade.config


def machine():
    """CPU model, cores, kernel and YADE version, for the header of every benchmark's output."""
    with open("/proc/cpuinfo") as cpuinfo:
        model = next((line.split(":", 1)[1].strip() for line in cpuinfo if line.startswith("model name")),
                     platform.processor())
    return f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}, YADE {yade.config.version}"


def median_cpu_ms(call, repetitions):
    """Median CPU time of `call()` over `repetitions` runs [ms]; CPU time is steadier than wall time on a
    shared machine."""
    times = []
    for _ in range(repetitions):
        start = time.process_time()
        call()
        times.append(time.process_time() - start)
    return statistics.median(times) * 1e3
