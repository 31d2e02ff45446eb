"""Body-body contact against Hertz (paper Sections 3.1.1 and 3.2): two rounded bodies pressed together along z,
force against overlap, with the scenes of roundedmesh_study.validation (E* = 0.5 Pa: both bodies E = 1 Pa, nu = 0;
curvature prescribed unless said).

    /usr/bin/python3 scripts/validation/validate_body_contact.py [--output out/body_contact] [--only fig3 fig7 ...]

Figures (each a function of FIGURES; each writes its CSVs and PNG and prints its table):
    fig3  two meshed unit spheres, and a meshed unit sphere against an analytic one, overlap 0 to 5 % of R,
          42 to 2562 nodes, 6 poses (icosphere frames, then 5 random pairs), against Hertz with R* = R/2:
              body_contact_fig3_force.csv   force vs overlap, icosphere frames and first random pose
              body_contact_fig3_nrmse.csv   NRMSE per node count and pose
              body_contact_fig3.png
    fig6  S4 friction ramp, 162 and 642 nodes, spring and viscous friction, friction force against applied force with
          the Coulomb law:
              body_contact_fig6.csv, body_contact_fig6.png
    fig7  pairs of identical prolate spheroids pressed at their equators, long axes parallel, R_max/R_min = 1 to 4
          and 16, 2562 nodes (642 for every ratio and 10242 for ratio 2 as convergence checks), 3 poses, the paper's
          circular contact (curvature='mean') and Hertz's ellipse (curvature='principal'), against the exact
          elliptical Hertz force:
              body_contact_fig7_force.csv   force vs overlap per ratio, node count and model, with the references
              body_contact_fig7_nrmse.csv   NRMSE per ratio, node count and model
              body_contact_fig7.png
    fig7crossed  the same spheroids with long axes crossed at 45 and 90 deg, ratios 2, 4, 16, 2562 nodes, both
          models, to 7.5 % of b, against exact elliptical Hertz with the relative radii at that angle:
              body_contact_fig7crossed_force.csv, body_contact_fig7crossed_nrmse.csv, body_contact_fig7crossed.png
    fig7computed  parallel spheroids with curvatures estimated from the mesh (curvature='computed'), ratios 4 and
          16, 642 and 2562 nodes, both models, and the principal model on exact curvatures alongside:
              body_contact_fig7computed_force.csv, body_contact_fig7computed_nrmse.csv, body_contact_fig7computed.png
    fig8  crossed and parallel cylinders (R = 1 m, L = 4 m), 642, 2562, 10242 nodes (the principal model 642 and
          2562), 3 poses, both models, against Hertz sphere-on-plane (crossed) and Eq. 27 (parallel):
              body_contact_fig8_force.csv, body_contact_fig8_summary.csv, body_contact_fig8.png
Runs in about 180 s on two cores with a second job running (fig7 50 s, fig7crossed 12 s, fig7computed 24 s, fig8
88 s, most of it the 10242-node parallel cylinders of the mean model, 68 s).
"""
import argparse
import csv
import os
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from roundedmesh.export import write_csv  # noqa: E402
from roundedmesh_study import validation as v  # noqa: E402
from roundedmesh_study.analytic import nrmse  # noqa: E402

SPHERE_NODES = {42: 1, 162: 2, 642: 3, 2562: 4}
SPHERE_POSES = 6
MODELS = ("mean", "principal")      # engine option curvature: the paper's contact circle, Hertz's ellipse
SPHEROID_RATIOS = v.S5_RATIOS + (16.0,)
SPHEROID_NODES = 2562
SPHEROID_CHECK_NODES = 642          # every ratio, to show mesh convergence
SPHEROID_FINE = (2.0, 10242)        # one ratio at a finer mesh
CROSSING_ANGLES = tuple(round(float(np.degrees(angle))) for angle in v.S5_CROSSING_ANGLES)   # [deg]
CROSSED_RATIOS = (2.0, 4.0, 16.0)
COMPUTED_RATIOS = (4.0, 16.0)
COMPUTED_NODES = (642, 2562)
AXIS_POSES = 3
CYLINDER_NODES = (642, 2562, 10242)
# The principal model's parallel cylinders at 10242 nodes take 210 s (the mean model's 58 s, loaded machine): left
# out of the script; doc/validation.md gives that run's numbers.
CYLINDER_NODES_BY_MODEL = {"mean": CYLINDER_NODES, "principal": CYLINDER_NODES[:2]}


def _log(message):
    print(message, flush=True)


def _save(figure, output, name):
    """Writes `figure` to body_contact_{name}.png in `output` and closes it."""
    figure.tight_layout()
    figure.savefig(os.path.join(output, f"body_contact_{name}.png"), dpi=120)
    plt.close(figure)


# --- Fig. 3: spheres ------------------------------------------------------------------------------------

def figure_3(output):
    """Fig. 3 for body-body contact: meshed sphere against a meshed sphere and against an analytic sphere."""
    sweeps = {}
    for partner in ("mesh", "sphere"):
        for n, k in SPHERE_NODES.items():
            start = time.monotonic()
            sweeps[partner, n] = v.sphere_pair(k, partner, poses=SPHERE_POSES)
            _log(f"fig3: {n:4d} nodes against {'a meshed' if partner == 'mesh' else 'an analytic'} sphere, "
                 f"{SPHERE_POSES} poses, {time.monotonic() - start:.1f} s")
    overlaps, hertz = v.PAIR_OVERLAPS, sweeps["mesh", 42].reference

    columns, header = [overlaps, hertz], ["overlap_over_R", "hertz"]
    for (partner, n), sweep in sweeps.items():
        columns += [sweep.forces[0], sweep.forces[1]]
        header += [f"{partner}{n}_frame", f"{partner}{n}_random1"]
    write_csv(os.path.join(output, "body_contact_fig3_force.csv"), header, np.column_stack(columns))
    rows = [[partner, n, pose, sweep.errors[pose]] for (partner, n), sweep in sweeps.items()
            for pose in range(len(sweep.errors))]
    write_csv(os.path.join(output, "body_contact_fig3_nrmse.csv"),
               ["partner", "nodes", "pose (0 = icosphere frames)", "nrmse"], rows)

    figure, axes = plt.subplots(1, 3, figsize=(17, 4.5))
    for ax, partner, title in ((axes[0], "mesh", "Two meshed spheres"),
                               (axes[1], "sphere", "Meshed sphere on an analytic sphere")):
        ax.plot(overlaps * 100, hertz, "k-", lw=2.5, label="Hertz, R* = R/2 (Eq. 6)")
        for n, colour in zip((42, 162, 642), ("tab:blue", "tab:orange", "tab:green")):
            ax.plot(overlaps * 100, sweeps[partner, n].forces[0], "--", color=colour, label=f"{n} nodes, frames")
            ax.plot(overlaps * 100, sweeps[partner, n].forces[1], ":", color=colour, label=f"{n} nodes, random pose")
        ax.set(xlabel="overlap [% of R]", ylabel="F [N] (E* = 0.5 Pa, R = 1 m)", title=f"{title} (Fig. 3)")
        ax.legend(fontsize=8)
    nodes = np.array(list(SPHERE_NODES))
    floor = 1e-3  # [%]: NRMSE below it (round-off, when every triangle pair takes the direct regime) drawn on it
    for partner, colour in (("mesh", "tab:blue"), ("sphere", "tab:red")):
        worst = [max(sweeps[partner, n].worst * 100, floor) for n in nodes]
        mean = [max(sweeps[partner, n].mean * 100, floor) for n in nodes]
        frame = [max(sweeps[partner, n].errors[0] * 100, floor) for n in nodes]
        axes[2].loglog(nodes, worst, "s-", color=colour, label=f"{partner} partner, worst of {SPHERE_POSES}")
        axes[2].loglog(nodes, mean, "o--", color=colour, label=f"{partner} partner, mean")
        axes[2].loglog(nodes, frame, "^:", color=colour, label=f"{partner} partner, icosphere frames")
    axes[2].set(xlabel="nodes", ylabel=f"NRMSE [%] (round-off drawn at {floor:g})",
                title="Convergence, prescribed curvature", ylim=(0.5 * floor, 20))
    axes[2].legend(fontsize=8)
    axes[2].grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(output, "body_contact_fig3.png"), dpi=120)
    plt.close(figure)

    lines = [f"S2 pair: NRMSE against Hertz (R* = R/2), overlap to 5 % of R, {SPHERE_POSES} poses "
             "(pose 0: icosphere frames, vertex on vertex; then random)",
             "partner   nodes   frames    worst     mean      per pose [%]"]
    for (partner, n), sweep in sweeps.items():
        lines.append(f"{partner:8s} {n:6d}   {100 * sweep.errors[0]:6.3f}   {100 * sweep.worst:6.3f}   "
                     f"{100 * sweep.mean:6.3f}    " + " ".join(f"{100 * e:.3f}" for e in sweep.errors))
    return lines


# --- Fig. 7: spheroid pairs -----------------------------------------------------------------------------

def _spheroid_sweeps(figure, runs, max_overlap=None):
    """{(ratio, nodes, angle [deg], mesh curvature, model): SpheroidSweep} for `runs` of such tuples (nodes asked),
    each over AXIS_POSES poses up to max_overlap [m] (default spheroid_pair's); logs each run's time under
    `figure`."""
    sweeps = {}
    for ratio, nodes, angle, mesh_curvature, model in runs:
        start = time.monotonic()
        s = v.spheroid_pair(ratio, nodes, poses=AXIS_POSES, angle=np.radians(angle), mesh_curvature=mesh_curvature,
                            max_overlap=max_overlap, curvature=model)
        sweeps[ratio, nodes, angle, mesh_curvature, model] = s
        _log(f"{figure}: ratio {ratio:g}, {nodes} nodes ({s.nodes} meshed), axes at {angle:g} deg, curvature "
             f"{mesh_curvature}, model {model}, {AXIS_POSES} poses, {time.monotonic() - start:.1f} s")
    return sweeps


def _spheroid_outputs(output, name, title, sweeps):
    """Writes body_contact_{name}_force.csv and body_contact_{name}_nrmse.csv for spheroid `sweeps` (keys of
    _spheroid_sweeps) and returns the printed table's lines, headed by `title`."""
    keys = ["ratio", "angle_deg", "mesh_curvature", "model", "nodes"]
    rows = []
    for (ratio, _, angle, curvature, model), s in sweeps.items():
        for pose, force in enumerate(s.forces):
            rows += [[ratio, angle, curvature, model, s.nodes, pose, d, f, e, c, h, int(i)]
                     for d, f, e, c, h, i in zip(s.overlaps, force, s.reference, s.circular, s.approximate, s.in_range)]
    write_csv(os.path.join(output, f"body_contact_{name}_force.csv"),
              keys + ["pose", "overlap", "force", "exact_elliptical_hertz", "circular_hertz_mean_curvature",
                      "approximate_elliptical_hertz", "within_search_limit"], rows)

    header = keys + ["a", "b", "r_major", "r_minor", "max_overlap", "search_limit", "nrmse_worst", "nrmse_mean",
                     "nrmse_in_range_worst", "nrmse_in_range_mean", "force_over_exact_at_limit",
                     "force_over_exact_at_max", "nrmse_vs_circular_worst", "circular_vs_exact", "approximate_vs_exact",
                     "increasing_all_poses"]
    table = []
    for (ratio, _, angle, curvature, model), s in sweeps.items():
        last = np.flatnonzero(s.in_range)[-1]
        table.append([ratio, angle, curvature, model, s.nodes, np.sqrt(ratio) * v.S5_SEMI_MINOR, v.S5_SEMI_MINOR,
                      *v.spheroid_relative_radii(ratio, np.radians(angle)), s.overlaps[-1], s.limit, s.worst, s.mean,
                      s.errors_in_range.max(), s.errors_in_range.mean(),
                      float(np.mean(s.forces[:, last]) / s.reference[last]),
                      float(np.mean(s.forces[:, -1]) / s.reference[-1]), s.circular_errors.max(), s.model_error,
                      nrmse(s.approximate, s.reference), bool(s.increasing().all())])
    write_csv(os.path.join(output, f"body_contact_{name}_nrmse.csv"), header, table)

    lines = [title, "ratio  angle  curvature  model      nodes  max ovl  limit   worst   mean  | in range: worst   "
             "mean  F/F_ex | F/F_ex at max | circ vs exact  approx vs exact  increasing"]
    for row in table:
        (ratio, angle, curvature, model, n, _, _, _, _, dmax, limit, worst, mean, worst_in, mean_in, at_limit, at_max,
         _, circ, approx, up) = row
        lines.append(f"{ratio:5.1f}  {angle:5g}  {curvature:9s}  {model:9s}  {n:5d}  {dmax:.4f}  {limit:.4f}  "
                     f"{100 * worst:5.2f}  {100 * mean:5.2f} |          {100 * worst_in:5.2f}  {100 * mean_in:5.2f}  "
                     f"{at_limit:5.3f} |     {at_max:5.3f}     |   {100 * circ:6.2f}          {100 * approx:6.3f}"
                     f"       {up}")
    return lines


def figure_7(output):
    """Fig. 7: NRMSE against the exact elliptical Hertz force vs R_max/R_min for pairs of prolate spheroids with
    parallel axes, the paper's circular contact (curvature='mean') and Hertz's ellipse (curvature='principal')."""
    runs = [(r, nodes, 0, "exact", model) for nodes in (SPHEROID_NODES, SPHEROID_CHECK_NODES)
            for r in SPHEROID_RATIOS for model in MODELS]
    runs += [(SPHEROID_FINE[0], SPHEROID_FINE[1], 0, "exact", model) for model in MODELS]
    sweeps = _spheroid_sweeps("fig7", runs)

    def sweep(ratio, nodes, model):
        return sweeps[ratio, nodes, 0, "exact", model]

    figure, (left, right) = plt.subplots(1, 2, figsize=(13, 4.5))
    ratios = np.array(SPHEROID_RATIOS)
    for model, marker in (("mean", "s"), ("principal", "o")):
        primary = [sweep(r, SPHEROID_NODES, model) for r in ratios]
        check = [sweep(r, SPHEROID_CHECK_NODES, model) for r in ratios]
        left.plot(ratios, [100 * s.worst for s in primary], marker + "-",
                  label=f"{model}, {SPHEROID_NODES} nodes, worst")
        left.plot(ratios, [100 * s.mean for s in primary], marker + "--",
                  label=f"{model}, {SPHEROID_NODES} nodes, mean")
        left.plot(ratios, [100 * s.worst for s in check], marker + ":",
                  label=f"{model}, {SPHEROID_CHECK_NODES} nodes, worst")
        fine = sweep(*SPHEROID_FINE, model)
        left.plot([SPHEROID_FINE[0]], [100 * fine.worst], "k" + marker, ms=9, mfc="none",
                  label=f"{model}, {fine.nodes} nodes")
    primary = [sweep(r, SPHEROID_NODES, "mean") for r in ratios]
    left.plot(ratios, [100 * s.model_error for s in primary], "d-.", label="circular Hertz, mean curvature")
    left.plot(ratios, [100 * nrmse(s.approximate, s.reference) for s in primary], "x:",
              label="equivalent-radius approx.")
    left.set(xlabel="R_max / R_min", ylabel="NRMSE vs exact elliptical Hertz [%] (below 0.01 not drawn)",
             xscale="log", yscale="log", ylim=(0.01, 50), xticks=ratios, xticklabels=[f"{r:g}" for r in ratios],
             title="Spheroid pairs, parallel axes, overlap to 7.5 % of a (Fig. 7a)")
    left.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    left.legend(fontsize=7)
    left.grid(True, which="both", alpha=0.3)
    for r, colour in zip(ratios, plt.cm.viridis(np.linspace(0, 0.9, len(ratios)))):
        for model, style in (("mean", "-"), ("principal", "--")):
            s = sweep(r, SPHEROID_NODES, model)
            right.plot(s.overlaps / s.overlaps[-1], s.forces.mean(axis=0) / s.reference, style, color=colour,
                       label=f"ratio {r:g}, {model}")
    right.axhline(1, color="k", lw=1)
    right.set(xlabel="overlap / max overlap", ylabel="F / F_exact",
              title="mean (solid) and principal (dashed), mean of poses", ylim=(0.9, 1.45))
    right.legend(fontsize=7, ncol=2)
    _save(figure, output, "fig7")
    return _spheroid_outputs(output, "fig7", "S5 spheroid pairs, parallel axes: NRMSE [%] against exact elliptical "
                             f"Hertz, b = 1 m fixed, a = sqrt(ratio) b, overlap to 7.5 % of a, {AXIS_POSES} poses; "
                             "'in range': overlaps <= the engine's search limit", sweeps)


def figure_7_crossed(output):
    """Crossed spheroid pairs (issue 13): long axes at 45 and 90 deg, both models, against exact elliptical Hertz
    with the relative radii at that angle, to 7.5 % of b: the crossed contact spreads across both bodies' short
    axes, and over Fig. 7's 7.5 % of a it would grow to half of b in radius, where Hertz's quadratic gap no longer
    describes the bodies."""
    runs = [(r, SPHEROID_NODES, angle, "exact", model) for angle in CROSSING_ANGLES for r in CROSSED_RATIOS
            for model in MODELS]
    sweeps = _spheroid_sweeps("fig7crossed", runs, max_overlap=v.S5_MAX_OVERLAP * v.S5_SEMI_MINOR)
    figure, (left, right) = plt.subplots(1, 2, figsize=(13, 4.5))
    ratios = np.array(CROSSED_RATIOS)
    for angle, colour in zip(CROSSING_ANGLES, ("tab:blue", "tab:red")):
        for model, style in (("mean", "s-"), ("principal", "o--")):
            chosen = [sweeps[r, SPHEROID_NODES, angle, "exact", model] for r in ratios]
            left.plot(ratios, [100 * s.worst for s in chosen], style, color=colour, label=f"{angle} deg, {model}")
            for s, shade in zip(chosen, (0.4, 0.7, 1.0)):
                right.plot(s.overlaps / v.S5_SEMI_MINOR, s.forces.mean(axis=0) / s.reference, style[1:], color=colour,
                           alpha=shade, label=f"{angle} deg, ratio {s.ratio:g}, {model}")
    left.set(xlabel="R_max / R_min of each body", ylabel="NRMSE vs exact elliptical Hertz [%] (worst of poses)",
             xscale="log", xticks=ratios, xticklabels=[f"{r:g}" for r in ratios],
             title=f"Crossed spheroid pairs, {SPHEROID_NODES} nodes, overlap to 7.5 % of a")
    left.minorticks_off()
    left.legend(fontsize=8)
    left.grid(True, which="both", alpha=0.3)
    right.axhline(1, color="k", lw=1)
    right.set(xlabel="overlap / b", ylabel="F / F_exact (mean of poses)", title="Force against exact Hertz")
    right.legend(fontsize=6, ncol=2)
    _save(figure, output, "fig7crossed")
    return _spheroid_outputs(output, "fig7crossed", "Crossed spheroid pairs (long axes at 45, 90 deg): NRMSE [%] "
                             f"against exact elliptical Hertz at that angle, {AXIS_POSES} poses", sweeps)


def figure_7_computed(output):
    """Spheroid pairs (parallel axes) whose curvatures are estimated from the mesh (curvature='computed'), both
    models, with the principal model on prescribed curvatures alongside."""
    runs = [(r, nodes, 0, curvature, model) for r in COMPUTED_RATIOS for nodes in COMPUTED_NODES
            for curvature, model in (("computed", "mean"), ("computed", "principal"), ("exact", "principal"))]
    sweeps = _spheroid_sweeps("fig7computed", runs)
    figure, axis = plt.subplots(figsize=(7, 4.5))
    labels = [f"ratio {r:g}\n{n} nodes" for r in COMPUTED_RATIOS for n in COMPUTED_NODES]
    x = np.arange(len(labels))
    for offset, (curvature, model) in zip((-0.25, 0, 0.25), (("computed", "mean"), ("computed", "principal"),
                                                              ("exact", "principal"))):
        errors = [100 * sweeps[r, n, 0, curvature, model].worst for r in COMPUTED_RATIOS for n in COMPUTED_NODES]
        axis.bar(x + offset, errors, width=0.25, label=f"{model}, curvature {curvature}")
    axis.set(xticks=x, xticklabels=labels, yscale="log", ylabel="NRMSE vs exact elliptical Hertz [%] (worst of poses)",
             title="Spheroid pairs, curvatures estimated from the mesh")
    axis.legend(fontsize=8)
    axis.grid(True, which="both", axis="y", alpha=0.3)
    _save(figure, output, "fig7computed")
    return _spheroid_outputs(output, "fig7computed", "Spheroid pairs, parallel axes, curvatures computed from the "
                             f"mesh (Rusinkiewicz) or exact: NRMSE [%] against exact elliptical Hertz, {AXIS_POSES} "
                             "poses", sweeps)


# --- Fig. 8: cylinders ----------------------------------------------------------------------------------

def figure_8(output):
    """Fig. 8: crossed and parallel cylinders, force against overlap with the analytic solutions, the paper's circular
    contact (curvature='mean') and Hertz's ellipse (curvature='principal')."""
    sweeps = {}
    for model in MODELS:
        for arrangement in ("crossed", "parallel"):
            for nodes in CYLINDER_NODES_BY_MODEL[model]:
                start = time.monotonic()
                sweeps[model, arrangement, nodes] = v.cylinder_pair(arrangement, nodes, poses=AXIS_POSES,
                                                                    curvature=model)
                _log(f"fig8: {arrangement} cylinders, {nodes} nodes, model {model}, {AXIS_POSES} poses, "
                     f"{time.monotonic() - start:.1f} s")
    overlaps = v.CYLINDER_OVERLAPS

    columns = [overlaps, sweeps["mean", "crossed", 642].reference, sweeps["mean", "parallel", 642].reference]
    header = ["overlap_over_R", "crossed_hertz_R", "parallel_eq27"]
    for (model, arrangement, nodes), s in sweeps.items():
        for pose, force in enumerate(s.forces):
            columns.append(force)
            header.append(f"{model}_{arrangement}{s.nodes}_pose{pose}")
    write_csv(os.path.join(output, "body_contact_fig8_force.csv"), header, np.column_stack(columns))

    table = []
    for (model, arrangement, nodes), s in sweeps.items():
        stiffness = s.stiffness_errors() if arrangement == "parallel" else np.full(len(s.forces), np.nan)
        exponents = [v.power_law_exponent(s.overlaps, f) for f in s.forces]
        table.append([model, arrangement, s.nodes, s.worst, s.mean, float(np.mean(s.forces[:, -1]) / s.reference[-1]),
                      float(np.mean(stiffness)), float(np.min(stiffness)), float(np.max(stiffness)),
                      float(np.mean(exponents)), bool(s.increasing().all())])
    write_csv(os.path.join(output, "body_contact_fig8_summary.csv"),
              ["model", "arrangement", "nodes", "nrmse_worst", "nrmse_mean", "force_over_reference_at_max",
               "stiffness_error_mean", "stiffness_error_min", "stiffness_error_max", "power_law_exponent_mean",
               "increasing_all_poses"], table)

    figure, axes = plt.subplots(2, 2, figsize=(13, 9))
    for row, model in zip(axes, MODELS):
        for ax, arrangement, label in ((row[0], "crossed", "Hertz sphere on plane, R* = R (Eq. 6)"),
                                       (row[1], "parallel", "line contact, pi/4 E* L delta (Eq. 27)")):
            ax.plot(overlaps * 100, sweeps[model, arrangement, 642].reference, "k-", lw=2.5, label=label)
            for nodes, colour in zip(CYLINDER_NODES_BY_MODEL[model], ("tab:blue", "tab:orange", "tab:green")):
                s = sweeps[model, arrangement, nodes]
                ax.plot(overlaps * 100, s.forces[0], "--", color=colour, label=f"{s.nodes} nodes")
                for force in s.forces[1:]:
                    ax.plot(overlaps * 100, force, ":", color=colour, lw=0.8)
            ax.set(xlabel="overlap [% of R]", ylabel="F [N] (E* = 0.5 Pa, R = 1 m, L = 4 m)",
                   title=f"{arrangement.capitalize()} cylinders, curvature='{model}' "
                         f"(Fig. 8{'a' if arrangement == 'crossed' else 'b'})")
            ax.legend(fontsize=8)
    _save(figure, output, "fig8")

    lines = [f"S5 cylinders (R = {v.CYLINDER_RADIUS:g} m, L = {v.CYLINDER_LENGTH:g} m), overlap to 7.5 % of R, "
             f"{AXIS_POSES} poses about the axes",
             "model      arrangement  nodes  NRMSE worst  mean [%]  F/F_ref at max  "
             "stiffness error mean (min..max) [%]  exponent n (F ~ delta^n)  increasing"]
    for model, arrangement, n, worst, mean, at_max, stiff, stiff_min, stiff_max, exponent, up in table:
        stiffness = (f"{100 * stiff:6.1f} ({100 * stiff_min:.1f}..{100 * stiff_max:.1f})" if arrangement == "parallel"
                     else "     -")
        lines.append(f"{model:9s}  {arrangement:11s}  {n:5d}    {100 * worst:6.2f}   {100 * mean:6.2f}      "
                     f"{at_max:6.3f}        {stiffness:24s}            {exponent:5.3f}          {up}")
    return lines


def figure_6(output):
    """S4 friction ramp (scenes.friction_ramp), 162 and 642 nodes, under the tangential spring (the default) and the
    paper's viscous law, against the Coulomb law F_t = min(F_A, mu m g)."""
    from roundedmesh_study import scenes
    figure, axis = plt.subplots(figsize=(6, 4.5))
    lines = ["S4 friction ramp: applied force F_A / F_max at which sliding starts; largest |F_t - F_A| / F_max before "
             "F_A = 0.9 F_max (the ramp's inertia)", "nodes  law      F_A/F_max  before 0.9"]
    with open(os.path.join(output, "body_contact_fig6.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["nodes", "law", "time_s", "applied_over_fmax", "friction_over_fmax", "displacement_m",
                         "sliding"])
        for law, style in (("spring", "-"), ("viscous", "--")):
            for subdivisions, nodes in ((2, 162), (3, 642)):
                r = scenes.friction_ramp(subdivisions, label=f"S4 {nodes} nodes, {law}", law=law)
                applied, friction = r["applied"] / r["f_max"], -r["friction"] / r["f_max"]
                for row in zip(r["time"], applied, friction, r["displacement"], r["sliding"]):
                    writer.writerow([nodes, law, *row])
                axis.plot(applied, friction, style, label=f"{nodes} nodes, {law}")
                before = applied < 0.9
                lines.append(f"{nodes:5d}  {law:7s}  {applied[np.argmax(r['sliding'] > 0)]:9.3f}  "
                             f"{np.abs(friction[before] - applied[before]).max():10.4f}")
    x = np.linspace(0, 1.5, 100)
    axis.plot(x, np.minimum(x, 1), "k:", label="Coulomb, analytic sphere")
    axis.set_xlabel("applied force F_A / (mu m g)")
    axis.set_ylabel("friction force F_t / (mu m g)")
    axis.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(output, "body_contact_fig6.png"), dpi=120)
    plt.close(figure)
    return lines


# --- the figures, in order.
FIGURES = {
    "fig3": figure_3,
    "fig6": figure_6,
    "fig7": figure_7,
    "fig7crossed": figure_7_crossed,
    "fig7computed": figure_7_computed,
    "fig8": figure_8,
}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/body_contact")
    parser.add_argument("--only", nargs="+", choices=sorted(FIGURES), help="run only these figures")
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    start = time.monotonic()
    tables = []
    for name, make in FIGURES.items():
        if args.only and name not in args.only:
            continue
        figure_start = time.monotonic()
        tables.append(make(args.output))
        _log(f"{name}: done in {time.monotonic() - figure_start:.1f} s")
    for lines in tables:
        print()
        print("\n".join(lines))
    print(f"\nwrote {args.output}/body_contact_fig*.csv and .png in {time.monotonic() - start:.1f} s")


if __name__ == "__main__":
    main(sys.argv[1:])
