"""Pictures of the meshed shapes coloured by each triangle's radius of curvature, like the paper's
Figs. 8c and 9b: the pear and the gummy bear of shapes.json (curvature computed from the mesh, Eq. 1),
and for comparison a heavily distorted icosphere (D = 0.7, Fig. 4a/c) whose computed curvature is poor.

    /usr/bin/python3 scripts/validation/plot_reference_shapes.py [--output out/shapes]

Writes, per shape: <shape>.png (three views), <shape>.csv (per triangle: centroid [m], area [m^2],
mean curvature [1/m], radius used in contact [m]), <shape>.vtp (ParaView: cell data radius and curvature,
point data node curvature). Concave triangles (negative curvature) are drawn in red, whatever their radius.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import cm, colors  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_mesh_vtp  # noqa: E402

VIEWS = [("front (+y)", 10, 90), ("side (+x)", 10, 0), ("from above", 55, 60)]  # (title, elevation, azimuth)


def shapes():
    yield "pear", rm.Mesh.reference_shape("pear")
    yield "gummy_bear", rm.Mesh.reference_shape("gummy_bear")
    yield "distorted_icosphere", rm.Mesh.icosphere(0.025, 3, distortion=0.7, seed=1, curvature="computed")


def upright(mesh):
    """Vertices in the frame the shape was defined in (z up), centred on the centre of mass."""
    return mesh.vertices @ np.array(mesh.orientation.toRotationMatrix()).T


def plot(name, mesh, path):
    points = upright(mesh)
    corners = points[mesh.triangles]
    convex = mesh.curvatures > 0
    radii_mm = mesh.radii * 1e3
    scale = colors.LogNorm(vmin=radii_mm[convex].min(), vmax=np.percentile(radii_mm[convex], 99))
    face_colours = cm.Greys_r(scale(np.clip(radii_mm, scale.vmin, scale.vmax)))
    face_colours[~convex] = colors.to_rgba("tab:red")
    figure = plt.figure(figsize=(13, 4.8))
    half = np.abs(points).max() * 1.05
    for i, (view, elevation, azimuth) in enumerate(VIEWS):
        axes = figure.add_subplot(1, 3, i + 1, projection="3d")
        axes.add_collection3d(Poly3DCollection(corners, facecolors=face_colours, edgecolors=(0, 0, 0, 0.15),
                                               linewidths=0.3))
        axes.set(xlim=(-half, half), ylim=(-half, half), zlim=(-half, half), title=view)
        axes.set_box_aspect((1, 1, 1), zoom=1.5)
        axes.view_init(elevation, azimuth)
        axes.set_axis_off()
    figure.subplots_adjust(left=0, right=0.9, bottom=0, top=0.9, wspace=0)
    bar = figure.colorbar(cm.ScalarMappable(norm=scale, cmap="Greys_r"), ax=figure.axes, shrink=0.7, pad=0.02)
    bar.set_label("radius of curvature [mm] (red: concave or flat)")
    figure.suptitle(f"{name}: {len(mesh.vertices)} nodes, D = {mesh.distortion:.2f}, "
                    f"{np.mean(~convex) * 100:.0f} % concave triangles, {mesh.curvature_mode} curvature")
    figure.savefig(path, dpi=110)
    plt.close(figure)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/shapes")
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    print("shape                  nodes  D     concave  radius min / median / max [mm]")
    for name, mesh in shapes():
        base = os.path.join(args.output, name)
        plot(name, mesh, base + ".png")
        centroids = upright(mesh)[mesh.triangles].mean(axis=1)
        np.savetxt(base + ".csv", np.column_stack([centroids, mesh.areas, mesh.curvatures, mesh.radii]),
                   delimiter=",", comments="", header="x,y,z,area,curvature,radius")
        write_mesh_vtp(mesh, base + ".vtp")
        r = mesh.radii * 1e3
        print(f"{name:22s} {len(mesh.vertices):5d}  {mesh.distortion:.2f}  {np.mean(mesh.curvatures <= 0) * 100:5.1f} %"
              f"  {r.min():.2f} / {np.median(r):.1f} / {r.max():.0f}")
    print(f"wrote {args.output}/<shape>.png, .csv and .vtp")


if __name__ == "__main__":
    main(sys.argv[1:])
