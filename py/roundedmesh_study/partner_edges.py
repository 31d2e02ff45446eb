"""Seams, edges and corners of partners (issue 37; doc/physics.md, "What each partner's surface is"): a 642-node ball
(R = 25 mm, E = 1 MPa against 5 MPa, nu = 0.4) against YADE Facets and Boxes, through rm.partner_contact (the engine's
own pipeline), with the edge radius rho at its default, a tenth of the ball's r_eq.

    /usr/bin/python3 scripts/validation/partner_edges.py [--output out/partner_edges]

  seam    the ball held 1 mm deep and moved across the diagonal seam of a square of two coplanar Facets: the welded
          surface, each Facet alone with sharp edges (as before the surfaces: their forces summed), and a Wall.
  edge    the ball pushed along the bisector onto a Box's 90-degree edge and onto a drum lifter's 37-degree ridge of
          Facets, from first touch to 0.3 r_eq: the force, and Hertz's for a sphere of R on a cylinder of rho (Johnson
          1985, Section 4.2; solved here with scipy's elliptic integrals, independently of the engine).
  slide   the ball held 0.5 mm into the rounded Box and moved from its top face round the edge onto its side (its
          centre on the offset surface): the force passes from the plane's Hertz force to the cylinder's and back.

Prints the machine, the command and a summary; writes partner_edges.csv (panel, x, series, force [N]) and
doc/figures/partner_edges.png's data as partner_edges.png. About 20 s.
"""
import argparse
import math
import os
import shlex
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from scipy.special import ellipe, ellipk  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402

from .benchmarking import machine  # noqa: E402
from yade import utils  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

BALL_MATERIAL = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)
PARTNER_MATERIAL = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000)
MODULUS = 1 / ((1 - 0.4 ** 2) / 1e6 + (1 - 0.4 ** 2) / 5e6)  # E*, Eq. 3
R = 0.025
TURN = Quaternion(Vector3(1, 2, 3).normalized(), 0.4)  # off every symmetry of the partners


def hertz_force(delta, lambda_a, lambda_b):
    """Hertz's force [N] for relative principal curvatures lambda_a <= lambda_b [1/m] at approach delta [m]."""
    if math.isclose(lambda_a, lambda_b):
        return 4 / 3 * MODULUS * math.sqrt(1 / lambda_a) * delta ** 1.5

    def ratio(e2):
        k, e = ellipk(e2), ellipe(e2)
        return (e / (1 - e2) - k) / (k - e) - lambda_b / lambda_a
    e2 = brentq(ratio, 1e-12, 1 - 1e-15)
    k, e = ellipk(e2), ellipe(e2)
    a = math.sqrt(2 * delta * (k - e) / (k * e2 * lambda_a))
    b = a * math.sqrt(1 - e2)
    return 2 * math.pi / 3 * a * b * MODULUS * delta / (b * k)


def force(ball, pos, partners, **named):
    return rm.partner_contact(ball, Vector3(*pos), TURN, partners, BALL_MATERIAL, PARTNER_MATERIAL, **named)[0]


def square_of_two_facets():
    corners = [(-0.2, -0.2, 0), (0.2, -0.2, 0), (0.2, 0.2, 0), (-0.2, 0.2, 0)]
    return [utils.facet([corners[a], corners[b], corners[c]]) for a, b, c in ((0, 1, 2), (0, 2, 3))]


def ridge(apex):
    """A lifter's ridge: two faces of two Facets each meeting at `apex` [rad] along y through the origin."""
    side = 0.15
    sx, sz = side * math.sin(apex / 2), -side * math.cos(apex / 2)
    a0, a1, r0, r1 = (0, -0.1, 0), (0, 0.1, 0), (sx, -0.1, sz), (sx, 0.1, sz)
    l0, l1 = (-sx, -0.1, sz), (-sx, 0.1, sz)
    return [utils.facet(c) for c in ((a0, a1, r1), (a0, r1, r0), (a0, l1, a1), (a0, l0, l1))]


def seam_panel(ball, rows):
    facets, wall = square_of_two_facets(), utils.wall(0, axis=2, sense=1)
    xs = np.linspace(-0.015, 0.015, 121)
    series = {"welded surface": [], "each Facet alone, sharp (before)": [], "Wall": []}
    for x in xs:
        pos = (x, -x, R - 0.001)  # across the seam x = y
        series["welded surface"].append(force(ball, pos, facets)[2])
        series["each Facet alone, sharp (before)"].append(sum(force(ball, pos, f, edge_radius=0)[2] for f in facets))
        series["Wall"].append(force(ball, pos, wall)[2])
    for name, values in series.items():
        rows += [("seam", x, name, f) for x, f in zip(xs, values)]
    wall_force = np.array(series["Wall"])
    worst = np.max(np.abs(np.array(series["welded surface"]) - wall_force) / wall_force)
    lost = np.max(1 - np.array(series["each Facet alone, sharp (before)"]) / wall_force)
    return xs, series, f"seam: welded surface within {worst:.1e} of the Wall's force; each Facet alone lost up to " \
                       f"{100 * lost:.0f} %"


def edge_panel(ball, rho, r_eq, rows):
    h = 0.1
    apex = math.radians(37)
    cases = {"Box, 90-degree edge": ([utils.box((0, 0, 0), (h, h, h))], np.array([h - rho, 0, h - rho]),
                                     np.array([1, 0, 1]) / math.sqrt(2)),
             "lifter ridge of Facets, 37 degrees": (ridge(apex), np.array([0, 0, -rho / math.sin(apex / 2)]),
                                                    np.array([0, 0, 1.0]))}
    deltas = np.linspace(0.002, 0.3, 60) * r_eq
    curves, summary = {}, []
    for name, (partners, axis, direction) in cases.items():
        values = [force(ball, axis + (rho + R - d) * direction, partners).dot(Vector3(*direction)) for d in deltas]
        curves[name] = values
        rows += [("edge", d, name, f) for d, f in zip(deltas, values)]
        hertz_range = [i for i, d in enumerate(deltas) if d <= 0.1 * rho]
        error = max(abs(values[i] / hertz_force(deltas[i], 1 / R, 1 / R + 1 / rho) - 1) for i in hertz_range)
        rising = all(b > a for a, b in zip(values, values[1:]))
        summary.append(f"{name}: within {100 * error:.1f} % of Hertz up to 0.1 rho, force rising to 0.3 r_eq: {rising}")
    hertz = [hertz_force(d, 1 / R, 1 / R + 1 / rho) for d in deltas]
    rows += [("edge", d, "Hertz, sphere on a cylinder of rho", f) for d, f in zip(deltas, hertz)]
    return deltas, curves, hertz, "; ".join(summary)


def slide_panel(ball, rho, rows):
    """The ball's centre moved along the rounded Box's surface offset by R - 0.5 mm: over the top face, round the
    edge (an arc of radius rho + R - 0.5 mm about the rounding's axis), down the side; x is its path [m]."""
    h, delta = 0.1, 0.0005
    box = utils.box((0, 0, 0), (h, h, h))
    lever = rho + R - delta
    arc = math.pi / 2 * lever

    def centre(s):
        if s < 0:
            return (h - rho + s, 0, h + R - delta)
        if s > arc:
            return (h + R - delta, 0, h - rho - (s - arc))
        return np.array([h - rho, 0, h - rho]) + lever * np.array([math.sin(s / lever), 0, math.cos(s / lever)])
    path = np.linspace(-0.02, arc + 0.02, 801)
    values = [force(ball, centre(s), box).norm() for s in path]
    rows += [("slide", s, "force", f) for s, f in zip(path, values)]
    changes = np.abs(np.diff(values)) / max(values)
    return path, arc, values, f"slide: largest change between poses {1e6 * (path[1] - path[0]):.0f} um apart " \
                              f"{100 * changes.max():.2f} % of the largest force"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output", default=os.path.join("out", "partner_edges"))
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    print(f"machine: {machine()}")
    print(f"command: {shlex.join([sys.executable] + sys.argv)}")
    ball = rm.Mesh.icosphere(R, 3)
    r_eq = (3 * ball.volume / (4 * math.pi)) ** (1 / 3)
    rho = 0.1 * r_eq
    rows = []
    xs, seam, seam_text = seam_panel(ball, rows)
    deltas, edges, hertz, edge_text = edge_panel(ball, rho, r_eq, rows)
    path, arc, slide, slide_text = slide_panel(ball, rho, rows)
    for text in (seam_text, edge_text, slide_text):
        print(text)
    write_csv(os.path.join(args.output, "partner_edges.csv"), ["panel", "x", "series", "force_N"], rows)

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for (name, values), style in zip(seam.items(), ("C0-", "C3--", "k:")):
        axes[0].plot(1e3 * xs, values, style, label=name)
    axes[0].set(xlabel="position across the seam [mm]", ylabel="force on the ball [N]",
                title="1 mm deep across the seam of two Facets")
    for (name, values), colour in zip(edges.items(), ("C0", "C2")):
        axes[1].plot(deltas / rho, values, colour, label=name)
    axes[1].plot(deltas / rho, hertz, "k:", label="Hertz, sphere on a cylinder of rho")
    axes[1].set(xscale="log", yscale="log", xlabel="push / rho", ylabel="force [N]",
                title=f"pushed onto an edge (rho = {1e3 * rho:.2f} mm)")
    axes[2].plot(1e3 * path, slide, "C0")
    for x in (0, 1e3 * arc):
        axes[2].axvline(x, color="0.6", lw=0.8)
    axes[2].set(xlabel="the ball's path [mm] (between the lines: round the edge)", ylabel="force [N]",
                title="0.5 mm deep, slid from a Box's top over its edge")
    for ax in axes[:2]:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "partner_edges.png"), dpi=120)
    print(f"wrote {args.output}/partner_edges.csv, partner_edges.png")
    return 0
