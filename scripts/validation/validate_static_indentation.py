"""Scene S2 (paper Section 3.1.1, Figs. 3 and 4): a meshed unit sphere pressed into a rigid plane, overlap
0 to 5 % of R, against Hertz, with curvature prescribed (1/R on every triangle), and on distorted meshes
with curvature prescribed or computed from the mesh (Eq. 1).

    /usr/bin/python3 scripts/validation/validate_static_indentation.py [--output out/validation]

Writes:
    static_indentation_force.csv   Fig. 3: force vs overlap for 42, 162, 642, 2562 nodes and Hertz
    static_indentation_nrmse.csv   Fig. 4b: NRMSE vs nodes, icosphere frame and worst of 12 poses, for the
                                   automatic regime choice and for each regime alone
    static_indentation_distortion.csv  Figs. 4b, 4c: NRMSE (worst of 4 poses) vs nodes for distortions
                                   D = 0.3, 0.5, 0.7, curvature prescribed and computed from the mesh
    static_indentation.png         the figures
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh_study.analytic import hertz_force, nrmse  # noqa: E402
from roundedmesh_study.scenes import S2_MATERIAL as MATERIAL, S2_OVERLAPS as OVERLAPS, s2_poses  # noqa: E402
from roundedmesh_study.scenes import static_indentation  # noqa: E402

NODES = {42: 1, 162: 2, 642: 3, 2562: 4}
DISTORTIONS = (0.3, 0.5, 0.7)


def distortion_sweep(hertz):
    """Rows (nodes, D, NRMSE prescribed, NRMSE computed, fraction of triangles whose computed curvature is
    off by more than 10 %): Fig. 4b and 4c. Worst of 4 poses; distorted meshes from seed 1."""
    poses = list(s2_poses(4))
    rows = []
    for n, k in NODES.items():
        for distortion in DISTORTIONS:
            row = [n, distortion]
            for curvature in ("exact", "computed"):
                mesh = rm.Mesh.icosphere(1.0, k, distortion=distortion, seed=1, curvature=curvature)
                row.append(max(nrmse(static_indentation(mesh, OVERLAPS, MATERIAL, q), hertz) for q in poses))
            row.append(np.mean(np.abs(mesh.curvatures - 1) > 0.1))
            rows.append(row)
    return np.array(rows)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/validation")
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    hertz = hertz_force(1.0, 1.0, OVERLAPS)

    forces = {n: static_indentation(rm.Mesh.icosphere(1.0, k), OVERLAPS, MATERIAL) for n, k in NODES.items()}
    np.savetxt(os.path.join(args.output, "static_indentation_force.csv"),
               np.column_stack([OVERLAPS, hertz] + [forces[n] for n in NODES]), delimiter=",",
               header="overlap_over_R,hertz_over_ER2," + ",".join(f"mesh{n}" for n in NODES), comments="")

    rows = []
    for n, k in NODES.items():
        mesh = rm.Mesh.icosphere(1.0, k)
        row = [n]
        for regime in ("auto", "quadrature", "direct"):
            errors = [nrmse(static_indentation(mesh, OVERLAPS, MATERIAL, q, regime=regime), hertz) for q in s2_poses()]
            row += [errors[0], max(errors)]
        rows.append(row)
    rows = np.array(rows)
    np.savetxt(os.path.join(args.output, "static_indentation_nrmse.csv"), rows, delimiter=",", comments="",
               header="nodes,auto_frame,auto_worst,quadrature_frame,quadrature_worst,direct_frame,direct_worst")

    sweep = distortion_sweep(hertz)
    np.savetxt(os.path.join(args.output, "static_indentation_distortion.csv"), sweep, delimiter=",", comments="",
               header="nodes,distortion,nrmse_prescribed,nrmse_computed,fraction_curvature_off_10pct")

    figure, (left, right, distorted) = plt.subplots(1, 3, figsize=(17, 4.5))
    left.plot(OVERLAPS * 100, hertz, "k-", lw=2.5, label="Hertz (Eq. 6)")
    for n in (42, 162, 642):
        left.plot(OVERLAPS * 100, forces[n], "--", label=f"{n} nodes")
    left.set(xlabel="overlap [% of R]", ylabel="F / (E* R^2)", title="Meshed sphere on a rigid plane (Fig. 3)")
    left.legend()
    for column, label, style in ((1, "auto, icosphere frame", "o-"), (2, "auto, worst of 12 poses", "s-"),
                                 (4, "quadrature only, worst", "^--")):
        right.loglog(rows[:, 0], rows[:, column] * 100, style, label=label)
    right.set(xlabel="nodes", ylabel="NRMSE [%]", title="Convergence, prescribed curvature (Fig. 4b)")
    right.legend()
    right.grid(True, which="both", alpha=0.3)
    for distortion, colour in zip(DISTORTIONS, ("tab:green", "tab:orange", "tab:red")):
        rows_d = sweep[sweep[:, 1] == distortion]
        distorted.loglog(rows_d[:, 0], rows_d[:, 2] * 100, "o--", color=colour, label=f"D = {distortion}, prescribed")
        distorted.loglog(rows_d[:, 0], rows_d[:, 3] * 100, "s-", color=colour, label=f"D = {distortion}, computed (Eq. 1)")
    distorted.set(xlabel="nodes", ylabel="NRMSE [%]", title="Distorted meshes, worst of 4 poses (Figs. 4b, 4c)")
    distorted.legend(fontsize=8)
    distorted.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(args.output, "static_indentation.png"), dpi=120)

    print("nodes   NRMSE % (auto: frame / worst of 12)   quadrature only   direct only")
    for r in rows:
        print(f"{int(r[0]):5d}   {100 * r[1]:8.3f} / {100 * r[2]:.3f}            {100 * r[4]:8.3f}        {100 * r[6]:.1e}")
    print("\nnodes   D     NRMSE % prescribed / computed   triangles with curvature off > 10 %")
    for r in sweep:
        print(f"{int(r[0]):5d}   {r[1]:.1f}   {100 * r[2]:8.3f} / {100 * r[3]:8.3f}        {100 * r[4]:5.1f} %")
    print(f"wrote {args.output}/static_indentation_force.csv, static_indentation_nrmse.csv, "
          "static_indentation_distortion.csv, static_indentation.png")


if __name__ == "__main__":
    main(sys.argv[1:])
