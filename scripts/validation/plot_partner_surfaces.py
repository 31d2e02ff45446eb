"""doc/figures/partner_surfaces.png: what each flat partner's surface is to a rounded body (doc/physics.md, "What
each partner's surface is"), in a cross-section: a Wall, a Box with its rounded edge, and a ridge of welded Facets.

    /usr/bin/python3 scripts/validation/plot_partner_surfaces.py [--output doc/figures/partner_surfaces.png]

A schematic: the regions are those of pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.cpp (the faces a body meets, by
where its centre lies), the rounding of pkg/geom/TriangleEdgeGeom.hpp, and the sheet rule of
pkg/geom/TrianglePlaneGeom.cpp (faceGeometry) on a surface welded by pkg/shape/FacetSurface.hpp.
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


def rounded_corner(ax, corner, radius, start, colour="k"):
    """The quarter arc of `radius` rounding a 90-degree corner whose arc starts at angle `start` [deg]."""
    centre = np.array(corner) - radius * np.array([np.cos(np.radians(start + 45)), np.sin(np.radians(start + 45))]) * np.sqrt(2)
    angles = np.radians(np.linspace(start, start + 90, 30))
    ax.plot(centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles), colour, lw=2.5)
    return centre


def box(ax):
    r = 0.25
    ax.add_patch(Rectangle((-1, -1), 2, 1, color="0.85"))
    ax.plot([-1, 1 - r], [0, 0], "k", lw=2)
    ax.plot([1, 1, -1, -1], [-r, -1, -1, 0], "k", lw=2)
    centre = rounded_corner(ax, (1, 0), r, 0, "C3")
    ax.plot(*centre, "C3.", ms=4)
    regions = [(Polygon([(-1, 0), (1 - r, 0), (1 - r, 1.4), (-1, 1.4)]), "C0", "top face"),
               (Polygon([(1, -r), (2.2, -r), (2.2, -1), (1, -1)]), "C1", "side face"),
               (Polygon([(1 - r, 0), (1 - r, 1.4), (2.2, 1.4), (2.2, -r), (1, -r)]), "C3", "rounded edge:\na cylinder")]
    for patch, colour, label in regions:
        patch.set_alpha(0.15)
        patch.set_color(colour)
        ax.add_patch(patch)
    for (x, y), label in (((-0.1, 0.7), "top face"), ((1.6, -0.65), "side face"), ((1.65, 0.75), "rounded edge:\na cylinder")):
        ax.text(x, y, label, ha="center", va="center", fontsize=8)
    ax.text(0, -0.55, "centre inside: the face\nit is least deep behind", ha="center", fontsize=8)
    ax.text(-1.9, 2.2, "edges and corners rounded by r\n(rm.set_edge_radius): Hertz's contact\nwith a cylinder, a sphere",
            fontsize=8, color="C3")
    ax.set_title("Box: six faces, twelve rounded edges,\neight rounded corners", fontsize=10)


def ridge(ax):
    apex, left, right = np.array([0, 0.9]), np.array([-0.35, -0.6]), np.array([0.35, -0.6])
    ax.add_patch(Polygon([left, apex, right], color="0.92"))
    half = np.arctan2(0.35, 1.5)  # half the apex angle
    r = 0.12
    centre = apex - np.array([0, r / np.sin(half)])
    trim = r / np.tan(half)
    down_left, down_right = (left - apex) / np.linalg.norm(left - apex), (right - apex) / np.linalg.norm(right - apex)
    ax.plot(*zip(left, apex + trim * down_left), "C0", lw=2.5, label="panel A (two Facets)")
    ax.plot(*zip(apex + trim * down_right, right), "C2", lw=2.5, label="panel B")
    angles = np.linspace(np.pi - half, half, 30)  # the faces' outward normals, left to right
    ax.plot(centre[0] + r * np.cos(angles), centre[1] + r * np.sin(angles), "C3", lw=2.5, label="rounded ridge")
    ax.plot([-1.9, -0.35], [-0.6, -0.6], "k", lw=2.5)
    ax.plot([0.35, 2.2], [-0.6, -0.6], "k", lw=2.5)
    ax.text(-1.9, -0.45, "flat seam: one plane", fontsize=8)
    ax.text(0.55, 2.25, "a convex edge between panels\nis rounded; a concave one (a\ndrum's wall, a hopper's corner)\nis closed: the faces push", fontsize=8, color="C3")
    ax.text(-1.9, -1.05, "zero thickness: the body meets the surface on its side; free edges stay sharp", fontsize=8)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("Facets: welded into surfaces, each touching\na body only where the body reaches it", fontsize=10)


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
