"""A gummy bear at rest on every flat partner (issue 21; doc/validation.md, "Resting on a Wall, a Box and Facets"):
dropped from 5 mm in random orientations onto a fixed YADE Wall, a YADE Box (0.1 m thick) and a floor of two YADE
Facets, all at z = 0, with S1's materials, mu = 0.5 and c = 100 N s/m (the slope scene's,
roundedmesh_study.scenes.SLOPE). It settles for `settle` seconds; then its drift (how far its centre moves) over
`duration` seconds, and the force the partner carries against the bear's weight. A Box used to stop such runs on
phantom overlaps of its far faces.

    /usr/bin/python3 scripts/validation/validate_resting_on_partners.py [--orientations 20] [--settle 2.5]
                                                                        [--duration 2] [--partners wall box facets]
                                                                        [--output out/resting]

Writes resting.csv (one row per partner and orientation) and resting.png (drift per orientation), and prints the
worst drift per partner. About 20 s per orientation and partner on one core.
"""
import argparse
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402

from . import scenes  # noqa: E402
from yade import ForceResetter, NewtonIntegrator, O, utils  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

PARTNERS = ("wall", "box", "facets")
GAP = 0.005  # [m] between the bear's lowest vertex and the partner at the start
G = 9.81


def _materials():
    s = scenes.SLOPE
    return [rm.HertzMaterial(young=m.young, poisson=m.poisson, density=m.density, damping=m.damping,
                             friction=m.friction, tangential_damping=m.tangential_damping) for m in (s.particle, s.floor)]


def random_orientations(count, seed=21):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(count):
        q = rng.normal(size=4)
        out.append(Quaternion(*(q / np.linalg.norm(q))))
    return out


def add_partner(kind, material):
    """The partner's YADE bodies, their top at z = 0: a Wall, a Box 0.1 m thick, or a floor of two Facets."""
    if kind == "wall":
        ids = [O.bodies.append(utils.wall(0, axis=2, sense=1))]
    elif kind == "box":
        ids = [O.bodies.append(utils.box((0, 0, -0.05), (0.3, 0.3, 0.05), fixed=True))]
    elif kind == "facets":
        corners = [(-0.3, -0.3, 0), (0.3, -0.3, 0), (0.3, 0.3, 0), (-0.3, 0.3, 0)]
        ids = [O.bodies.append(utils.facet([corners[i] for i in f], fixed=True)) for f in ((0, 1, 2), (0, 2, 3))]
    else:
        raise ValueError(f"partner: expected one of {PARTNERS}, got {kind!r}")
    for i in ids:
        rm.assign_material(i, material)
    return ids


def build(kind, ori):
    """Resets YADE: the gummy bear GAP above the partner `kind`, turned by `ori`. Returns (bear id, partner ids)."""
    O.reset()
    particle, floor = _materials()
    mesh = rm.Mesh.reference_shape("gummy_bear")
    lowest = min((ori * Vector3(*x))[2] for x in mesh.vertices)
    bear = rm.add_body(mesh, pos=(0, 0, GAP - lowest), ori=ori, material=particle)
    partners = add_partner(kind, floor)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -G), damping=0)]
    O.dt = scenes.SLOPE.timestep_fraction * rm.critical_timestep()
    return bear, partners


def rest(kind, ori, settle, duration):
    """(drift [m], partner force over the bear's weight, steps) after settling."""
    bear, partners = build(kind, ori)
    O.run(max(int(round(settle / O.dt)), 1), True)
    start = Vector3(O.bodies[bear].state.pos)
    steps = max(int(round(duration / O.dt)), 1)
    O.run(steps, True)
    drift = (O.bodies[bear].state.pos - start).norm()
    carried = sum(O.forces.f(i)[2] for i in partners)
    weight = O.bodies[bear].state.mass * G
    return drift, -carried / weight, O.iter


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--orientations", type=int, default=20)
    parser.add_argument("--settle", type=float, default=2.5)
    parser.add_argument("--duration", type=float, default=2.0)
    parser.add_argument("--partners", nargs="+", choices=PARTNERS, default=list(PARTNERS))
    parser.add_argument("--output", default="out/resting")
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    rows = []
    started = time.time()
    orientations = random_orientations(args.orientations)
    total = len(orientations) * len(args.partners)
    for kind in args.partners:
        for i, ori in enumerate(orientations):
            drift, load, steps = rest(kind, ori, args.settle, args.duration)
            rows.append((kind, i, drift, load, steps))
            done = len(rows)
            elapsed = time.time() - started
            print(f"[{done}/{total}] {kind} orientation {i}: drift {drift * 1e6:.3g} um, load {load:.4f} weights, "
                  f"{steps} steps; ETA {elapsed / done * (total - done):.0f} s", flush=True)
    write_csv(os.path.join(args.output, "resting.csv"), ["partner", "orientation", "drift_m", "load_over_weight", "steps"],
              rows)
    fig, ax = plt.subplots(figsize=(6, 3.5))
    for shift, kind in enumerate(args.partners):
        mine = [r for r in rows if r[0] == kind]
        # Side by side; a drift of exactly 0 (the centre did not move by one ulp) drawn at 1e-12 um.
        ax.semilogy([r[1] + 0.2 * (shift - 1) for r in mine], [max(r[2] * 1e6, 1e-12) for r in mine], "o", label=kind)
    ax.axhline(1.0, color="k", lw=0.8, ls="--", label="1 um")
    ax.set_xlabel("orientation")
    ax.set_ylabel(f"drift over {args.duration:g} s [um]")
    ax.set_title("gummy bear at rest on flat partners")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "resting.png"), dpi=120)
    for kind in args.partners:
        mine = [r for r in rows if r[0] == kind]
        print(f"{kind}: worst drift {max(r[2] for r in mine) * 1e6:.3g} um over {args.duration:g} s, load "
              f"{min(r[3] for r in mine):.4f}-{max(r[3] for r in mine):.4f} weights, {len(mine)} orientations")
