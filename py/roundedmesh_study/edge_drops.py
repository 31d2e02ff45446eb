"""A gummy bear dropped onto the top edge of a thin plate (issue 38): is the plate ever passed through?

    /usr/bin/python3 scripts/validation/edge_drops.py [--heights 0.1 0.3 1.0] [--orientations 20] [--seed 1]
        [--output out/edge_drops]

The plate is a lifter as users build one: a vertical rectangle of two Facets (`utils.facet`), 0.2 m long along y and
0.1 m high, in the plane x = 0, its top edge the segment z = 0 (welded into one panel, its rim rounded by the default
edge radius). The bear (rm.Mesh.reference_shape, E = 1 MPa, nu = 0.4, 1200 kg/m^3, A = 0.05 s, mu = 0.5; the plate
E = 100 MPa, nu = 0.3, mu = 0.4) is turned at random (seeded), its centre above the edge's midpoint, 0 to 2 mm to
either side, its lowest point `height` above the edge, and falls under gravity from rest with
O.dt = rm.critical_timestep(impact_speed=v) at the impact speed v = sqrt(2 g height), the step the user guide gives
for impacts. It runs until its centre is 0.15 m below the edge (it has fallen off to one side), at most 1 s.

Outcome of each drop: "off +x" / "off -x" (fell off on that side), "resting" (still on the edge after 1 s), or
"stopped: ..." (the engine's stop rule; a centre through a Facet is a pass-through caught). "Through" counts drops
whose centre ended on the other side of the plate from where it went below the edge's height, which a body that fell
off to one side never does. Also the deepest pair over the drop (rm.statistics()["deepest_pair_fraction"], every
step) and the largest number of touching core spheres. Hertz's own overlap for the impact, of a sphere of the bear's
r_eq on a flat partner, (15 m v^2 / (16 E* sqrt(r_eq)))^(2/5), is printed per height: an edge is sharper, so deeper.
Writes edge_drops.csv (height, orientation, outcome, through, deepest [r_eq], core contacts) and edge_drops.png (each
drop's deepest pair by height and outcome), and prints the table.
"""
import argparse
import csv
import math
import os
import shlex
import sys
import warnings

import numpy as np

GRAVITY = 9.81
LENGTH, HEIGHT = 0.2, 0.1     # [m]
BODY = dict(young=1e6, poisson=0.4, density=1200.0, damping=0.05, friction=0.5, tangential_damping=0.1)
PLATE = dict(young=1e8, poisson=0.3, density=7800.0, damping=0.05, friction=0.4, tangential_damping=0.1)
FALLEN = 0.15                 # [m] below the edge: off the plate
DURATION = 1.0                # [s]


def drop(mesh, height, ori, offset):
    """One drop: (outcome, through, deepest [r_eq], largest number of core contacts)."""
    import roundedmesh as rm
    from yade import ForceResetter, NewtonIntegrator, O, utils
    from yade.minieigenHP import Quaternion, Vector3
    O.reset()
    y0, y1 = -LENGTH / 2, LENGTH / 2
    plate = O.bodies.append([utils.facet([(0, y0, -HEIGHT), (0, y1, -HEIGHT), (0, y1, 0)], fixed=True),
                             utils.facet([(0, y0, -HEIGHT), (0, y1, 0), (0, y0, 0)], fixed=True)])
    for facet in plate:
        rm.assign_material(facet, rm.HertzMaterial(**PLATE))
    rotation = np.array([[ori.toRotationMatrix()[i, j] for j in range(3)] for i in range(3)])
    lowest = (np.asarray(mesh.vertices) @ rotation.T)[:, 2].min()
    body = rm.add_body(mesh, Vector3(offset, 0, height - lowest), ori, rm.HertzMaterial(**BODY))
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -GRAVITY), damping=0)]
    O.dt = rm.critical_timestep(impact_speed=math.sqrt(2 * GRAVITY * height))
    deepest, cores, side_below = 0.0, 0, None
    state = O.bodies[body].state
    try:
        while O.time < DURATION and state.pos[2] > -FALLEN:
            O.run(10, True)
            statistics = rm.statistics()
            deepest = max(deepest, statistics["deepest_pair_fraction"])
            cores = max(cores, statistics["core_contacts"])
            if side_below is None and state.pos[2] < 0:
                side_below = math.copysign(1, state.pos[0])
    except RuntimeError as error:
        lines = str(error).splitlines()
        reason = next((line for line in lines if line.startswith("roundedmesh stopped")), lines[0])
        return "stopped: " + reason[:300], False, deepest, cores
    outcome = "resting" if state.pos[2] > -FALLEN else ("off +x" if state.pos[0] > 0 else "off -x")
    through = side_below is not None and math.copysign(1, state.pos[0]) != side_below
    return outcome, through, deepest, cores


def plot(rows, heights, path):
    """edge_drops.png: each drop's deepest pair by height, marked by its outcome."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(6, 4))
    styles = {"off": ("C0", "o"), "resting": ("C2", "s"), "stopped": ("C3", "x")}
    for kind, (colour, marker) in styles.items():
        points = [(h, d) for h, _, outcome, _, d, _ in rows if outcome.startswith(kind)]
        if points:
            axes.scatter(*zip(*points), color=colour, marker=marker, label=kind)
    through = [(h, d) for h, _, _, t, d, _ in rows if t]
    if through:
        axes.scatter(*zip(*through), color="k", marker="*", s=80, label="through the plate")
    axes.set(xscale="log", xticks=heights, xticklabels=[f"{h:g}" for h in heights], xlabel="drop height [m]",
             ylabel="deepest pair over the drop [r_eq]", title="a gummy bear dropped onto a plate's top edge")
    axes.legend()
    axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--heights", nargs="+", type=float, default=[0.1, 0.3, 1.0])
    parser.add_argument("--orientations", type=int, default=20)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--output", default=os.path.join("out", "edge_drops"))
    args = parser.parse_args(argv)
    import roundedmesh as rm
    from yade.minieigenHP import Quaternion
    from .benchmarking import machine
    os.makedirs(args.output, exist_ok=True)
    command = shlex.join([sys.executable] + sys.argv)
    print(f"machine: {machine()}\ncommand: {command}", flush=True)
    mesh = rm.Mesh.reference_shape("gummy_bear")
    r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    mass = BODY["density"] * mesh.volume
    modulus = 1 / ((1 - BODY["poisson"] ** 2) / BODY["young"] + (1 - PLATE["poisson"] ** 2) / PLATE["young"])
    rng = np.random.default_rng(args.seed)
    rows = []
    for height in args.heights:
        speed = math.sqrt(2 * GRAVITY * height)
        hertz = (15 * mass * speed ** 2 / (16 * modulus * math.sqrt(r_eq))) ** 0.4 / r_eq
        outcomes = []
        for k in range(args.orientations):
            q = rng.normal(size=4)
            ori = Quaternion(*(q / np.linalg.norm(q)))
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                outcome, through, deepest, cores = drop(mesh, height, ori, rng.uniform(-2e-3, 2e-3))
            outcomes.append((outcome, through, deepest, cores))
            rows.append((height, k, outcome, int(through), round(deepest, 4), cores))
        counts = {}
        for outcome, *_ in outcomes:
            key = outcome if not outcome.startswith("stopped") else "stopped"
            counts[key] = counts.get(key, 0) + 1
        print(f"height {height:g} m, {speed:.2f} m/s (Hertz's own overlap on a flat: {hertz:.2f} r_eq): "
              f"{counts}; through {sum(t for _, t, _, _ in outcomes)}; deepest pair "
              f"{max(d for _, _, d, _ in outcomes):.3f} r_eq; core contacts up to {max(c for *_, c in outcomes)}",
              flush=True)
        for outcome, *_ in outcomes:
            if outcome.startswith("stopped"):
                print(f"    {outcome}")
    plot(rows, args.heights, os.path.join(args.output, "edge_drops.png"))
    with open(os.path.join(args.output, "edge_drops.csv"), "w", newline="") as f:
        f.write(f"# {machine()}\n# {command}\n")
        writer = csv.writer(f)
        writer.writerow(["height_m", "orientation", "outcome", "through", "deepest_r_eq", "core_contacts"])
        writer.writerows(rows)
    print(f"machine: {machine()}\ncommand: {command}")
    return 0
