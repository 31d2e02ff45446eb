"""Which curvature estimate should a mesh without a known shape get? Every estimate the project has, and the usual
neighbourhood fits, against the exact mean curvature under each triangle of the paper's pear and gummy bear and of a
2:1 spheroid (doc/validation.md, "Curvature from the mesh"; issue 24, item 2).

    /usr/bin/python3 scripts/validation/curvature_estimates.py [--nodes 300 554 1000 2200] [--output out/curvature_estimates]

Estimates, per triangle [1/m]:
    eq1          Eq. 1 (Meyer et al.'s cotangent Laplacian at the nodes, area-weighted to the triangle): Mesh.curvatures
                 of a mesh whose curvature is computed, what Mesh.load gives
    principal    the mean of Rusinkiewicz's two principal curvatures (Mesh.principal_curvatures)
    smooth1/2    Eq. 1 at the nodes averaged over their 1- and 2-ring neighbourhoods, then over the triangle's nodes
    quadric2/3   a quadric z = a x^2 + b x y + c y^2 + d x + e y fitted in least squares over each node's 2- and 3-ring
                 (in the frame of its area-weighted normal), its mean curvature at the node, averaged over the triangle
Reference: the shapes' exact mean curvature under each triangle (the generators' curvature='exact': the implicit
surface's for the pear and the bear, the spheroid's own). Error: |H - H_exact| / |H_exact| per triangle; the table
gives its median and 75th percentile over the triangles.

Prints the machine, the command and the table; writes curvature_estimates.csv and curvature_estimates.png.
"""
import argparse
import os
import shlex
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sparse  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402
from roundedmesh_study.benchmarking import machine  # noqa: E402

ESTIMATES = ("eq1", "principal", "smooth1", "smooth2", "quadric2", "quadric3")


def shapes(nodes):
    """{name: (exact mesh, computed mesh)}: the same nodes, the curvature exact and computed."""
    return {"pear": tuple(rm.Mesh.reference_shape("pear", nodes=nodes, curvature=c) for c in ("exact", "computed")),
            "gummy bear": tuple(rm.Mesh.reference_shape("gummy_bear", nodes=nodes, curvature=c)
                                for c in ("exact", "computed")),
            "spheroid 2:1": tuple(rm.Mesh.spheroid(0.02, 0.01, nodes, curvature=c) for c in ("exact", "computed"))}


def ring_matrix(count, triangles, k):
    """(n, n) 0/1: node j within k edges of node i (itself included)."""
    rows = np.concatenate([triangles[:, a] for a in (0, 1, 2, 1, 2, 0)])
    cols = np.concatenate([triangles[:, b] for b in (1, 2, 0, 0, 1, 2)])
    adjacency = sparse.coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(count, count)).tocsr()
    step = ((adjacency + sparse.identity(count)) > 0).astype(float)
    reach = step
    for _ in range(k - 1):
        reach = ((reach @ step) > 0).astype(float)
    return reach.tocsr()


def node_normals(vertices, triangles):
    face = np.cross(vertices[triangles[:, 1]] - vertices[triangles[:, 0]], vertices[triangles[:, 2]] - vertices[triangles[:, 0]])
    normals = np.zeros_like(vertices)
    for k in range(3):
        np.add.at(normals, triangles[:, k], face)
    return normals / np.linalg.norm(normals, axis=1)[:, None]


def quadric_curvature(vertices, triangles, k):
    """Mean curvature at each node of the quadric fitted over its k-ring (> 0 convex) [1/m]."""
    reach = ring_matrix(len(vertices), triangles, k)
    normals = node_normals(vertices, triangles)
    out = np.zeros(len(vertices))
    for i, n in enumerate(normals):
        ring = reach.indices[reach.indptr[i]:reach.indptr[i + 1]]
        e1 = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        d = vertices[ring] - vertices[i]
        x, y, z = d @ e1, d @ e2, d @ n
        (a, b, c, zx, zy), *_ = np.linalg.lstsq(np.stack([x * x, x * y, y * y, x, y], 1), z, rcond=None)
        # Mean curvature of the graph z(x, y) at the node; z points outward, so a convex surface bends to -z.
        out[i] = -((1 + zy * zy) * 2 * a - 2 * zx * zy * b + (1 + zx * zx) * 2 * c) / (2 * (1 + zx * zx + zy * zy) ** 1.5)
    return out


def estimates(mesh):
    """{estimate: (m,) mean curvature per triangle} of a mesh whose curvature is computed."""
    vertices, triangles = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    nodes = np.asarray(mesh.node_curvatures)
    out = {"eq1": np.asarray(mesh.curvatures), "principal": np.asarray(mesh.principal_curvatures).mean(axis=1)}
    for k in (1, 2):
        reach = ring_matrix(len(vertices), triangles, k)
        out[f"smooth{k}"] = ((reach @ nodes) / np.asarray(reach.sum(axis=1)).ravel())[triangles].mean(axis=1)
    for k in (2, 3):
        out[f"quadric{k}"] = quadric_curvature(vertices, triangles, k)[triangles].mean(axis=1)
    return out


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--nodes", type=int, nargs="+", default=[300, 554, 1000, 2200])
    parser.add_argument("--output", default="out/curvature_estimates")
    return parser.parse_args(argv)


def main(argv):
    args = parse(argv)
    os.makedirs(args.output, exist_ok=True)
    rows = []
    for nodes in args.nodes:
        for name, (exact, computed) in shapes(nodes).items():
            assert np.allclose(exact.vertices, computed.vertices)
            reference = np.asarray(exact.curvatures)
            for estimate, values in estimates(computed).items():
                error = np.abs(values - reference) / np.abs(reference)
                rows.append({"shape": name, "nodes": len(computed.vertices), "estimate": estimate,
                             "median_error": float(np.median(error)), "p75_error": float(np.quantile(error, 0.75))})
    write_csv(os.path.join(args.output, "curvature_estimates.csv"), list(rows[0]), [list(r.values()) for r in rows])
    print(machine())
    print("command: /usr/bin/python3 scripts/validation/curvature_estimates.py " + shlex.join(argv))
    print("median (75th percentile) of |H - H_exact| / |H_exact| over the triangles")
    print(f"{'shape':14s} {'nodes':>6s} " + " ".join(f"{e:>14s}" for e in ESTIMATES))
    for name in dict.fromkeys(r["shape"] for r in rows):
        for nodes in dict.fromkeys(r["nodes"] for r in rows if r["shape"] == name):
            cells = {r["estimate"]: r for r in rows if r["shape"] == name and r["nodes"] == nodes}
            print(f"{name:14s} {nodes:6d} " + " ".join(
                f"{cells[e]['median_error']:6.3f} ({cells[e]['p75_error']:5.3f})" for e in ESTIMATES))
    figure, axes = plt.subplots(1, 3, figsize=(13, 4), sharey=True)
    for ax, name in zip(axes, dict.fromkeys(r["shape"] for r in rows)):
        for estimate in ESTIMATES:
            chosen = [r for r in rows if r["shape"] == name and r["estimate"] == estimate]
            ax.plot([r["nodes"] for r in chosen], [r["median_error"] for r in chosen], "o-", label=estimate)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(name)
        ax.set_xlabel("nodes")
    axes[0].set_ylabel("median |H - H_exact| / |H_exact|")
    axes[0].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(args.output, "curvature_estimates.png"), dpi=120)
    print(f"wrote {args.output}/curvature_estimates.csv and curvature_estimates.png")


if __name__ == "__main__":
    main(sys.argv[1:])
