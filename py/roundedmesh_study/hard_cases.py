"""Scene S8 of doc/scenes.md: the hard cases every contact change must pass, run and reported pass or fail with
the figure each one is judged by. A feature is done when it survives what users do with it; this suite is what
users do:

    s1          S1 (scripts/s1_packing.py) through the shaking (0.75 s, 7,500 steps) for every shape and seed:
                it must complete, with no pair deeper than --s1-overlap (0.3) of the smaller r_eq at any step
    drum        S7 whole (scripts/examples/example_drum.py, 20,000 steps): it must complete
    newuser     the new user's drum (scripts/validation/newuser_drum.py): YADE's facetCylinder with thin-plate lifters,
                YADE's GTS horses and gummy bears at E = 1 MPa dropped in from a lattice (0.63 s), and the same with
                bears only (1.67 s), with the defaults: each must complete (its deepest pair and fastest body reported)
    pressed     two gummy bears, two pears, and a gummy bear on a Wall, a Facet and a Box, pressed from first touch
                to 0.5 r_eq along a random direction at --orientations random orientations
                (scripts/validation/deep_monotonicity.py, partner_monotonicity.py): the force along the push must
                never fall
    coarse      a 12-triangle bar (2 x 2 x 5 cm), the gummy bear coarsened to 150 nodes and a plate whose sides are
                slivers (1 x 20 x 50 mm, 12 triangles, 50:1), as a user makes them (rm.Mesh of the 12 triangles,
                prepared by its default tolerance; the generator's bear): 1 mm from a Wall, a Box and a Facet they
                feel no force, and dropped 1 mm onto a Wall, a Box and a floor of two Facets they come to rest on it
                (slower than 1 cm/s after 2 s)
    collisions  undamped, frictionless collisions of two gummy bears and of a bear with a pear, head-on and
                off-centre, at the Hertz range (0.05 r_eq) and deep (0.3 r_eq), O.dt = dt_c / 50
                (scripts/validation/energy_conservation.py): the kinetic energy must come back within 0.5 % and 1 %

    /usr/bin/python3 scripts/hard_cases.py [--quick] [--only s1 drum newuser pressed coarse collisions]
        [--shapes gummy_bear pear ...] [--seeds 1 2 3 4 5] [--threads 2] [--orientations 200] [--output out/hard_cases]

--quick is the short form CI runs (tests/python/test_hard_cases.py): S1 of the gummy bears through the shaking,
seed 1, on two threads. The whole suite takes hours (S1 alone is 30 runs of 7,500 steps).

Writes <output>/hard_cases.csv, one row per check (case, check, passed, figure, limit, unit, detail, seconds),
hard_cases.png (each check's figure over its limit, green where it passes, red where it fails), and the run
folders of the cases it runs as subprocesses (<output>/s1/seed<N>/<shape>, <output>/drum). Prints a table, the
machine and the command; exits 1 if any check fails.
"""
import argparse
import csv
import math
import os
import shlex
import subprocess
import sys
import time

from . import SCRIPTS, newuser_drum

CASES = ("s1", "drum", "newuser", "pressed", "coarse", "collisions")
S1_SHAPES = ("sphere", "icosphere12", "icosphere42", "icosphere162", "pear", "gummy_bear")
SHAKING = 0.75              # S1's shaking [s]
S1_OVERLAP = 0.3            # the deepest pair overlap allowed in S1 [r_eq]
PRESS_DEPTH = 0.5           # the pushes go from first touch to this overlap [r_eq]
CLEARANCE = 1e-3            # the coarse meshes' gap to a partner that must give no force [m]
# A dropped body has come to rest when, REST_TIME after the drop, its points move slower than REST_SPEED: the
# 554-node gummy bear of the reference shapes, dropped the same way, moves at 1.8 mm/s on a Wall and a Box and 4e-6 m/s
# on the two Facets after 2 s (tipping over, then rocking), so 1 cm/s separates resting from being pushed about.
REST_SPEED = 1e-2           # [m/s]
REST_TIME = 2.0             # [s]
# ... and rests on it: its lowest corner within half a millimetre of the top (a body resting under its weight
# overlaps about 0.01 r_eq, 0.25 mm; a coarse mesh pushed from a distance floats millimetres above).
REST_GAP = 5e-4             # [m]
ENERGY_LIMITS = {"hertz": 0.005, "deep": 0.01}  # |change of kinetic energy| allowed in a collision
COLLISION_PAIRS = ("bear-bear", "bear-pear")
COLLISION_FRACTION = 50     # O.dt = dt_c / 50


class Report:
    """The checks so far, printed as they come."""

    def __init__(self):
        self.rows = []

    def add(self, case, check, passed, figure, limit, unit, detail, seconds):
        self.rows.append({"case": case, "check": check, "passed": bool(passed), "figure": figure, "limit": limit,
                          "unit": unit, "detail": detail, "seconds": round(seconds, 1)})
        print(f"{'PASS' if passed else 'FAIL'}  {case:10s} {check:42s} {figure:.4g} (limit {limit:.4g} {unit}) "
              f"{detail}  [{seconds:.0f} s]", flush=True)


# --- S1 and S7: whole scenes, each in its own process ----------------------------------------------------------

def s1_checks(args, report):
    for seed in args.seeds:
        for shape in args.shapes:
            output = os.path.join(args.output, "s1", f"seed{seed}")
            command = [sys.executable, os.path.join(SCRIPTS, "s1_packing.py"), "--shape", shape, "--seed",
                       str(seed), "--duration", str(SHAKING), "--threads", str(args.threads), "--frames", "1",
                       "--checkpoint-every", "100000", "--output", output]
            start = time.perf_counter()
            done = subprocess.run(command, capture_output=True, text=True)
            seconds = time.perf_counter() - start
            rows = read_csv(os.path.join(output, shape, "height.csv"))
            steps = int(rows[-1]["step"]) if rows else 0
            deepest = max((float(r["deepest_pair_r"]) for r in rows), default=math.nan)
            stopped = next((line for line in reversed((done.stdout + done.stderr).splitlines())
                            if "stopped" in line), "")
            completed = done.returncode == 0 and steps == round(SHAKING / 1e-4)
            detail = (f"completed {steps} steps" if completed else
                      f"stopped after {steps} steps (exit {done.returncode}): {stopped[:300]}")
            report.add("s1", f"{shape}, seed {seed}: completes", completed, steps, round(SHAKING / 1e-4), "steps",
                       detail, seconds)
            report.add("s1", f"{shape}, seed {seed}: deepest pair", completed and deepest <= S1_OVERLAP, deepest,
                       S1_OVERLAP, "r_eq", "largest over every step of the run (deepest_pair_r of height.csv)", 0)


def drum_check(args, report):
    output = os.path.join(args.output, "drum")
    command = [sys.executable, os.path.join(SCRIPTS, "examples", "example_drum.py"), "--threads",
               str(args.threads), "--out", output, "--vtk-every", "100000"]
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    lines = (done.stdout + done.stderr).strip().splitlines()
    report.add("drum", "S7 whole: completes", done.returncode == 0, done.returncode, 0, "exit status",
               lines[-1][:300] if lines else "", time.perf_counter() - start)


def newuser_checks(args, report):
    for contents in ("mixed", "bears"):
        command = [sys.executable, os.path.join(SCRIPTS, "validation", "newuser_drum.py"), "--contents", contents,
                   "--output", os.path.join(args.output, "newuser_drum")]
        start = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True)
        lines = (done.stdout + done.stderr).strip().splitlines()
        last = next((line for line in reversed(lines) if line.startswith(f"{contents} roundedmesh:")), lines[-1] if lines else "")
        report.add("newuser", f"{contents}: completes {newuser_drum.DURATION[contents]:g} s", done.returncode == 0,
                   done.returncode, 0, "exit status", last[:400], time.perf_counter() - start)


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


# --- Pressed to half a radius ----------------------------------------------------------------------------------

def pressed_checks(args, report):
    import numpy as np
    import roundedmesh as rm
    from . import deep_monotonicity as deep, partner_monotonicity as partner
    for shape in ("gummy_bear", "pear"):
        start = time.perf_counter()
        mesh = rm.Mesh.reference_shape(shape)
        r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
        falls = []
        for q1, q2, u in deep.random_orientations(args.orientations, 1):
            _, rows = deep.sweep(mesh, r_eq, q1, q2, u)
            last = int(round(PRESS_DEPTH / deep.STEP))
            falls.append(deep.worst_fall(rows[:last + 1, 1])[0])
        falling = [f for f in falls if f > 0]
        report.add("pressed", f"two {shape}s: orientations whose force falls", not falling, len(falling), 0,
                   f"of {len(falls)}", f"worst fall {100 * max(falling, default=0):.3g} %", time.perf_counter() - start)
    start = time.perf_counter()
    mesh = rm.Mesh.reference_shape("gummy_bear")
    vertices = np.array(mesh.vertices)
    r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    reach = 2 * np.linalg.norm(vertices, axis=1).max()
    rng = np.random.default_rng(1)
    bodies = partner.partners()
    falls = {name: [] for name in bodies}
    for _ in range(args.orientations):
        ori, u = partner.random_push(rng)
        m = ori.toRotationMatrix()
        rotation = np.array([[m[i][j] for j in range(3)] for i in range(3)])
        lowest = (vertices @ rotation.T)[:, 2].min()
        begin = np.array([0, 0, 0.001 - lowest]) - (reach / 2) * u
        for name, body in bodies.items():
            touch = partner.first_touch(mesh, ori, begin, u, body, reach)
            forces = [partner.push_force(mesh, ori, begin, u, touch + x * r_eq, body) for x in partner.STEPS]
            falls[name].append(partner.worst_fall(forces))
    seconds = (time.perf_counter() - start) / len(bodies)
    for name, worst in falls.items():
        falling = [w for w in worst if w > 0]
        report.add("pressed", f"gummy bear on a {name}: orientations whose force falls", not falling, len(falling), 0,
                   f"of {len(worst)}", f"worst fall {max(falling, default=0):.3g} %", seconds)


# --- Coarse meshes ---------------------------------------------------------------------------------------------

def box_arrays(x, y, z):
    """A closed box of 12 triangles, x by y by z [m], centred on the origin, outward: (vertices, triangles)."""
    import numpy as np
    corners = [(sx * x / 2, sy * y / 2, sz * z / 2) for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return np.array(corners, float), np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])


def coarse_meshes():
    """The coarse meshes as a user makes them: the boxes of 12 triangles through rm.Mesh (prepared to its default
    tolerance, doc/user-guide.md), the coarsened gummy bear from the generator (its exact curvature, never changed)."""
    import roundedmesh as rm
    return {"12-triangle bar 2 x 2 x 5 cm": rm.Mesh(*box_arrays(0.02, 0.02, 0.05)),
            "gummy bear of 150 nodes": rm.Mesh.reference_shape("gummy_bear", nodes=150),
            "sliver plate 1 x 20 x 50 mm": rm.Mesh(*box_arrays(0.001, 0.02, 0.05))}


def lowest_below(mesh, ori):
    """How far the mesh's lowest vertex lies below its centre when turned by ori (a YADE Quaternion) [m]."""
    import numpy as np
    m = ori.toRotationMatrix()
    return -(np.asarray(mesh.vertices) @ np.array([m[2][j] for j in range(3)])).min()


def coarse_checks(args, report):
    import numpy as np
    from yade import ForceResetter, NewtonIntegrator, O, utils
    from yade.minieigenHP import Quaternion, Vector3
    import roundedmesh as rm
    body_material = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0.01, friction=0.5,
                                     tangential_damping=0.1)
    partner_material = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0.01, friction=0.5,
                                        tangential_damping=0.1)
    rng = np.random.default_rng(1)
    for name, mesh in coarse_meshes().items():
        # 1 mm clear of each partner's top at z = 0, in 20 orientations: no force.
        start = time.perf_counter()
        for partner_name, partner in (("Wall", utils.wall(0, axis=2, sense=1)),
                                      ("Box", utils.box((0, 0, -0.05), (1, 1, 0.05))),
                                      ("Facet", utils.facet([(-2, -2, 0), (3, -2, 0), (0, 3, 0)]))):
            largest = 0.0
            for _ in range(20):
                axis = rng.normal(size=3)
                ori = Quaternion(Vector3(*(axis / np.linalg.norm(axis))), rng.uniform(0, 2 * math.pi))
                pos = (0, 0, CLEARANCE + lowest_below(mesh, ori))
                force = rm.partner_contact(mesh, pos, ori, partner, body_material, partner_material)[0]
                largest = max(largest, force.norm())
            report.add("coarse", f"{name}: 1 mm from a {partner_name}", largest == 0, largest, 0, "N",
                       "largest force over 20 orientations", time.perf_counter() - start)
            start = time.perf_counter()
        # Dropped 1 mm onto each partner: at rest after REST_TIME.
        for partner_name in ("Wall", "Box", "two Facets"):
            start = time.perf_counter()
            O.reset()
            if partner_name == "Wall":
                partners = [O.bodies.append(utils.wall(0, axis=2, sense=1))]
            elif partner_name == "Box":
                partners = [O.bodies.append(utils.box((0, 0, -0.05), (0.2, 0.2, 0.05), fixed=True))]
            else:
                corners = [(-0.2, -0.2, 0), (0.2, -0.2, 0), (0.2, 0.2, 0), (-0.2, 0.2, 0)]
                partners = [O.bodies.append(utils.facet([corners[a], corners[b], corners[c]], fixed=True))
                            for a, b, c in ((0, 1, 2), (0, 2, 3))]
            for p in partners:
                rm.assign_material(p, partner_material)
            ori = Quaternion(Vector3(1, 0.3, 0.1).normalized(), 0.4)
            body = rm.add_body(mesh, pos=(0.01, 0.02, CLEARANCE + lowest_below(mesh, ori)), ori=ori,
                               material=body_material)
            O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
            O.dt = 0.2 * rm.critical_timestep()
            failure = ""
            try:
                O.run(int(REST_TIME / O.dt), True)
            except RuntimeError as error:
                failure = str(error)[:300]
            state = O.bodies[body].state
            speed = state.vel.norm() + state.angVel.norm() * np.linalg.norm(np.asarray(mesh.vertices), axis=1).max()
            gap = state.pos[2] - lowest_below(mesh, state.ori)  # the lowest corner's height above the top [m]
            on_top = abs(gap) < REST_GAP
            passed = not failure and on_top and speed < REST_SPEED
            report.add("coarse", f"{name}: dropped onto a {partner_name}, at rest", passed, speed, REST_SPEED, "m/s",
                       failure or (f"after {O.time:.2f} s its lowest corner is {gap * 1e3:+.2f} mm from the top"
                                   + ("" if on_top else " (floating or sunk)")), time.perf_counter() - start)
    O.reset()


# --- Undamped collisions ---------------------------------------------------------------------------------------

def collision_checks(args, report):
    from . import energy_conservation as energy
    for pair in COLLISION_PAIRS:
        for kind in energy.KINDS:
            for depth_name, depth in energy.DEPTHS.items():
                start = time.perf_counter()
                row = energy.collide(pair, kind, depth, COLLISION_FRACTION, 1)
                change = abs(row["change"])
                report.add("collisions", f"{pair} {kind}, {depth_name}: |change of kinetic energy|",
                           change <= ENERGY_LIMITS[depth_name], change, ENERGY_LIMITS[depth_name], "of KE",
                           f"deepest {row['deepest_overlap_req']:.3f} r_eq, O.dt = dt_c/{COLLISION_FRACTION}",
                           time.perf_counter() - start)


# --- The report ------------------------------------------------------------------------------------------------

def write_report(rows, output):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    path = os.path.join(output, "hard_cases.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    # Each check's figure over its limit (a check whose limit is 0 shows 1 for any figure above it).
    ratios = [r["figure"] / r["limit"] if r["limit"] else (1.0 + r["figure"] if r["figure"] else 0.0) for r in rows]
    figure, axes = plt.subplots(figsize=(9, 0.28 * len(rows) + 1.2))
    axes.barh(range(len(rows)), [min(x, 3) if math.isfinite(x) else 3 for x in ratios],
              color=["tab:green" if r["passed"] else "tab:red" for r in rows])
    axes.axvline(1, color="k", lw=0.8)
    axes.set_yticks(range(len(rows)), [f"{r['case']}: {r['check']}" for r in rows], fontsize=7)
    axes.invert_yaxis()
    axes.set_xlabel("figure / limit (cut at 3; a check with limit 0: 1 + figure)")
    axes.set_title(f"scene S8, hard cases: {sum(r['passed'] for r in rows)} of {len(rows)} pass")
    figure.tight_layout()
    figure.savefig(os.path.join(output, "hard_cases.png"), dpi=110)
    plt.close(figure)
    return path


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true",
                        help="the short form CI runs: S1 of the gummy bears through the shaking, seed 1, two threads")
    parser.add_argument("--only", nargs="+", choices=CASES, help="run only these cases (default all)")
    parser.add_argument("--shapes", nargs="+", choices=S1_SHAPES, default=list(S1_SHAPES), help="S1's shapes")
    parser.add_argument("--seeds", nargs="+", type=int, default=[1, 2, 3, 4, 5], help="S1's seeds")
    parser.add_argument("--threads", type=int, default=2, help="OpenMP threads of S1 and S7 (default 2)")
    parser.add_argument("--orientations", type=int, default=200, help="random orientations of the pushes")
    parser.add_argument("--output", default=os.path.join("out", "hard_cases"))
    args = parser.parse_args(argv)
    if args.quick:
        args.only, args.shapes, args.seeds, args.threads = ["s1"], ["gummy_bear"], [1], 2
    if args.orientations < 1 or args.threads < 1:
        parser.error("--orientations and --threads must be positive")
    args.only = args.only or list(CASES)
    return args


def main(argv):
    args = parse(argv)
    os.makedirs(args.output, exist_ok=True)
    from .benchmarking import machine
    command = shlex.join([sys.executable] + sys.argv)
    print(f"machine: {machine()}\ncommand: {command}", flush=True)
    report = Report()
    runners = {"s1": s1_checks, "drum": drum_check, "newuser": newuser_checks, "pressed": pressed_checks,
               "coarse": coarse_checks, "collisions": collision_checks}
    for case in CASES:
        if case in args.only:
            runners[case](args, report)
    path = write_report(report.rows, args.output)
    failed = [r for r in report.rows if not r["passed"]]
    print(f"\n{len(report.rows) - len(failed)} of {len(report.rows)} checks pass; wrote {path} and hard_cases.png")
    for r in failed:
        print(f"  FAIL {r['case']}: {r['check']}: {r['figure']:.4g} (limit {r['limit']:.4g} {r['unit']}) {r['detail']}")
    print(f"machine: {machine()}\ncommand: {command}")
    return 1 if failed else 0

