"""doc/figures/partner_surfaces.png: what each flat partner's surface is to a rounded body (doc/physics.md, "What
each partner's surface is"), in a cross-section: a Wall, a Box and a ridge of two Facets.

    /usr/bin/python3 scripts/validation/plot_partner_surfaces.py [--output doc/figures/partner_surfaces.png]

A schematic: the regions are those of pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.cpp (the faces a body meets, by
where its centre lies) and the sheet rule of pkg/geom/TrianglePlaneGeom.cpp (faceGeometry).
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle, Polygon, Rectangle  # noqa: E402


def wall(ax):
    ax.add_patch(Rectangle((-2, -1.2), 4, 1.2, color="0.85"))
    ax.plot([-2, 2], [0, 0], "k", lw=2)
    ax.add_patch(Circle((0, 0.85), 0.9, fill=False, lw=1.5))
    ax.annotate("", (0, 0.7), (0, -0.05), arrowprops=dict(arrowstyle="->", color="C3", lw=1.5))
    ax.text(-1.9, -0.6, "solid half-space\n(sense 0: the side of\nthe body's centre)", fontsize=8)
    ax.set_title("Wall: an infinite plane", fontsize=10)


def box(ax):
    ax.add_patch(Rectangle((-1, -1), 2, 1, color="0.85"))
    ax.plot([-1, 1, 1, -1, -1], [0, 0, -1, -1, 0], "k", lw=2)
    regions = [(Polygon([(-1, 0), (1, 0), (1, 1.4), (-1, 1.4)]), "C0", "top face"),
               (Polygon([(1, 0), (2.2, 0), (2.2, -1), (1, -1)]), "C1", "side face"),
               (Polygon([(1, 0), (2.2, 0), (2.2, 1.4), (1, 1.4)]), "C2", "top and side\n(beyond the edge)")]
    for patch, colour, label in regions:
        patch.set_alpha(0.18)
        patch.set_color(colour)
        ax.add_patch(patch)
        x, y = np.mean(patch.get_xy()[:-1], axis=0)
        ax.text(x, y, label, ha="center", va="center", fontsize=8)
    ax.add_patch(Circle((1.45, 0.42), 0.55, fill=False, lw=1.5))
    ax.plot(1.45, 0.42, "k.", ms=4)
    ax.text(0, -0.55, "centre inside: the face\nit is least deep behind", ha="center", fontsize=8)
    ax.set_title("Box: six finite faces; the faces whose\nouter side holds the body's centre", fontsize=10)


def ridge(ax):
    apex, left, right = (0, 0.9), (-0.35, -0.6), (0.35, -0.6)
    ax.add_patch(Polygon([left, apex, right], color="0.92"))
    ax.plot(*zip(left, apex), "C3", lw=2.5, label="Facet A")
    ax.plot(*zip(apex, right), "C0", lw=2.5, label="Facet B")
    a = np.array(apex) - np.array(left)
    ax.plot(*zip(apex, np.array(apex) + 0.9 * a), "C3", lw=1, ls=":")
    ax.text(0.55, 2.25, "A's plane: a cap behind it,\nover A, that does not hold\nA inside the body is not A's",
            fontsize=8, color="C3")
    touch = np.array(apex) + 0.3 * (np.array(right) - np.array(apex)) / np.linalg.norm(np.subtract(right, apex))
    normal = np.array([1.5, 0.35]) / np.hypot(1.5, 0.35)
    ax.add_patch(Circle(touch + 0.6 * normal, 0.62, fill=False, lw=1.5))
    ax.annotate("", touch + 0.45 * normal, touch, arrowprops=dict(arrowstyle="->", color="C0", lw=1.5))
    ax.text(-1.9, -1.05, "zero thickness: the body meets a facet's side where its centre is;\n"
            "edges and corners are sharp (a face pushes once its contact circle reaches it)", fontsize=8)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("Facets: sheets, each touching a body\nonly where the body reaches it", fontsize=10)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output", default="doc/figures/partner_surfaces.png")
    args = parser.parse_args()
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    for draw, ax in zip((wall, box, ridge), axes):
        draw(ax)
        ax.set_xlim(-2, 2.3)
        ax.set_ylim(-1.2, 3.0)
        ax.set_aspect("equal")
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
