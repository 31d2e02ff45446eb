"""Progress of long runs: steps done, simulated time, wall time and estimated time left.

    run(duration, label="shaking")   runs O for `duration` simulated seconds, reporting as it goes
    Progress(total, label)           the reporter, for loops that step YADE themselves
"""
import sys
import time

from yade import O


class Progress:
    """Prints `label: step i/N (p %), t = ... s, wall ... s, ETA ... s` about every `interval` wall seconds
    and at the end."""

    def __init__(self, total_steps, label, interval=2.0, stream=sys.stdout):
        self.total = total_steps
        self.label = label
        self.interval = interval
        self.stream = stream
        self.start = time.monotonic()
        self.last = self.start

    def update(self, done):
        now = time.monotonic()
        if now - self.last < self.interval and done < self.total:
            return
        self.last = now
        elapsed = now - self.start
        eta = elapsed / done * (self.total - done) if done else float("nan")
        print(f"{self.label}: step {done}/{self.total} ({100.0 * done / self.total:.0f} %), t = {O.time:.4f} s, "
              f"wall {elapsed:.1f} s, ETA {eta:.1f} s", file=self.stream, flush=True)


def run(duration, label="run", chunks=50):
    """Runs the current scene for `duration` simulated seconds in `chunks` pieces, printing progress."""
    steps = int(round(duration / O.dt))
    reporter = Progress(steps, label)
    done = 0
    for k in range(1, chunks + 1):
        target = steps * k // chunks
        if target > done:
            O.run(target - done, True)
            done = target
            reporter.update(done)
