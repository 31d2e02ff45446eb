"""The figures of scene S1 (doc/s1-packing.md) from the run folders scripts/s1_packing.py writes: every run
found in the output folder goes on one figure, as in Smeets et al., CMAME 277 (2014) 219-238, Section 3.4.

    fig11a_mean_height.png/.csv   mean height of the centres vs time (the paper's Fig. 11a)
    fig11b_packing.png/.csv       packing factor P(h) of Eq. 28 vs h at the end (Fig. 11b)
    fig10_packings.png            each final packing seen from the side (Fig. 10), drawn with matplotlib
    summary.csv                   one row per run: final mean and max height, P at a submerged height, median
                                  ms per step (wall and CPU) while shaking and settling, whole-run wall time

    /usr/bin/python3 scripts/s1_packing.py --plot-only [--output out/s1]   remakes them
"""
import csv
import math
import os

import numpy as np

ORDER = ("sphere", "icosphere12", "icosphere42", "icosphere162", "pear", "gummy_bear", "gummy_bear_clumps",
         "gummy_bear_level_sets", "spheroid", "pill", "tetra_grain")
LABELS = {"sphere": "perfect spheres", "icosphere12": "icospheres, 12 nodes", "icosphere42": "icospheres, 42 nodes",
          "icosphere162": "icospheres, 162 nodes", "pear": "pears", "gummy_bear": "gummy bears",
          "gummy_bear_clumps": "gummy bears, YADE 40-sphere clumps",
          "gummy_bear_level_sets": "gummy bears, YADE level sets", "spheroid": "spheroids", "pill": "pills",
          "tetra_grain": "rounded tetrahedral grains"}
STYLES = {"sphere": ("k", "-"), "icosphere12": ("C0", "--"), "icosphere42": ("C1", "--"),
          "icosphere162": ("C2", "--"), "pear": ("C3", "-"), "gummy_bear": ("C4", "-"),
          "gummy_bear_clumps": ("C4", ":"), "gummy_bear_level_sets": ("C4", "-."), "spheroid": ("C5", "-"),
          "pill": ("C6", "-"), "tetra_grain": ("C7", "-")}
HALF_BASE = 0.20  # the box's half width [m]


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def runs_in(root):
    """The runs of scripts/s1_packing.py that root holds complete (with packing.csv), in the paper's order."""
    return [name for name in ORDER if os.path.isfile(os.path.join(root, name, "packing.csv"))]


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(plt, figure, root, name, header, rows):
    """Writes the figure as root/name.png and the table behind it as root/name.csv."""
    figure.tight_layout()
    figure.savefig(os.path.join(root, name + ".png"), dpi=120)
    plt.close(figure)
    with open(os.path.join(root, name + ".csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)


def mean_height_figure(root, runs):
    """Fig. 11a, whole run on the left; on the right the end of the shaking and the settling, where the shapes
    part."""
    plt = _pyplot()
    figure, (whole, end) = plt.subplots(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": (1, 1.2)})
    table = []
    for run in runs:
        rows = read_csv(os.path.join(root, run, "height.csv"))
        t = np.array([float(r["time_s"]) for r in rows])
        h = np.array([float(r["mean_height_m"]) for r in rows])
        colour, line = STYLES.get(run, ("0.5", "-"))
        for axes in (whole, end):
            axes.plot(t, h * 1e3, color=colour, ls=line, label=LABELS.get(run, run))
        table += [(run, ti, hi) for ti, hi in zip(t, h)]
    for axes in (whole, end):
        axes.axvspan(0, 0.75, color="C0", alpha=0.06, label="box shaking")
        axes.set(xlabel="time [s]", ylabel="mean height of the centres [mm]")
        axes.grid(alpha=0.3)
    lows = [float(r[2]) for r in table if r[1] >= 0.45]
    if lows:  # a run as long as S1's
        end.set(xlim=(0.45, t[-1]), ylim=(1e3 * min(lows) - 5, 1e3 * max(lows) + 5), title="from t = 0.45 s")
    whole.set_title("S1: mean height (Fig. 11a)")
    end.legend(fontsize=8)
    save(plt, figure, root, "fig11a_mean_height", ["run", "time_s", "mean_height_m"], table)


def packing_figure(root, runs):
    plt = _pyplot()
    figure, axes = plt.subplots(figsize=(7.5, 4.8))
    columns = {}
    for run in runs:
        rows = read_csv(os.path.join(root, run, "packing.csv"))
        h = [float(r["h_m"]) for r in rows]
        columns[run] = [float(r["packing_factor_percent"]) for r in rows]
        colour, line = STYLES.get(run, ("0.5", "-"))
        axes.plot(np.array(h) * 1e3, columns[run], color=colour, ls=line, marker=".", label=LABELS.get(run, run))
    axes.set(xlabel="h [mm]", ylabel="packing factor P(h) [%]", title="S1: packing factor at the end (Fig. 11b, Eq. 28)")
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8)
    save(plt, figure, root, "fig11b_packing", ["h_m"] + [f"P_percent_{run}" for run in runs],
         [[h_k] + [columns[run][k] for run in runs] for k, h_k in enumerate(h)])


def drawn_mesh(run, radius):
    """(vertices (n, 3) [m], triangles (m, 3)) drawn for a body of `run`, in its principal frame: the run's own
    mesh; for perfect spheres a 642-node icosphere; for YADE's gummy bears the bear's mesh at the body's pose."""
    import roundedmesh as rm
    from . import grains, peers
    if run == "sphere":
        mesh = rm.Mesh.icosphere(radius, 3)
    elif run in peers.ICOSPHERES:
        mesh = rm.Mesh.icosphere(radius, peers.ICOSPHERES[run])
    elif run in grains.NAMES:
        mesh = grains.grain(run).mesh(grains.REFERENCE_NODES)
    else:
        mesh = rm.Mesh.reference_shape("gummy_bear" if run.startswith("gummy_bear") else run)
    return np.asarray(mesh.vertices), np.asarray(mesh.triangles)


def rotation_matrices(q):
    """Rotation matrices (n, 3, 3) of unit quaternions q (n, 4) given as (w, x, y, z)."""
    w, x, y, z = q.T
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
                     np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
                     np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


def packing_picture(axes, root, run, radius, colour, view=(12, -60)):
    """Draws the final packing of `run` on 3D axes: every body's surface, lit from the viewer's side, the
    triangles facing away from the viewer left out; `colour` one colour or a list cycled over the bodies, `view`
    (elevation, azimuth) [degrees]."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    state = read_csv(os.path.join(root, run, "final_state.csv"))
    positions = np.array([[float(r[k]) for k in ("x_m", "y_m", "z_m")] for r in state])
    rotations = rotation_matrices(np.array([[float(r[k]) for k in ("qw", "qx", "qy", "qz")] for r in state]))
    vertices, triangles = drawn_mesh(run, radius)
    world = np.einsum("bij,vj->bvi", rotations, vertices) + positions[:, None, :]
    faces = world[:, triangles].reshape(-1, 3, 3)
    normals = np.cross(faces[:, 1] - faces[:, 0], faces[:, 2] - faces[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    elevation, azimuth = np.radians(view)
    viewer = np.array([np.cos(elevation) * np.cos(azimuth), np.cos(elevation) * np.sin(azimuth), np.sin(elevation)])
    facing = normals @ viewer > 0
    light = normals[facing] @ (viewer + np.array([0, 0, 0.6])) / np.linalg.norm(viewer + np.array([0, 0, 0.6]))
    import matplotlib.colors
    colours = [colour] if isinstance(colour, str) else colour
    base = np.array([matplotlib.colors.to_rgb(colours[b % len(colours)]) for b in range(len(positions))])
    base = np.repeat(base, len(triangles), axis=0)[facing]
    shade = np.clip(0.35 + 0.65 * light, 0, 1)[:, None] * base
    axes.add_collection3d(Poly3DCollection(faces[facing] * 1e3, facecolors=shade, edgecolors="none"))
    axes.set(xlim=(-200, 200), ylim=(-200, 200), zlim=(0, 300), xticks=[-200, 0, 200], yticks=[-200, 0, 200],
             zticks=[0, 100, 200, 300])
    axes.set_box_aspect((1, 1, 0.75))
    axes.view_init(np.degrees(elevation), np.degrees(azimuth))
    axes.set_title(LABELS.get(run, run), fontsize=9)
    axes.tick_params(labelsize=6)


def packings_figure(root, runs, radius):
    plt = _pyplot()
    if len(runs) == 1:  # one run (tools/setup demo): a picture large and close enough to tell the bodies apart
        return packing_closeup(plt, root, runs[0], radius)
    columns = min(4, len(runs))
    rows = math.ceil(len(runs) / columns)
    figure = plt.figure(figsize=(3.2 * columns, 3.4 * rows))
    for k, run in enumerate(runs):
        axes = figure.add_subplot(rows, columns, k + 1, projection="3d")
        packing_picture(axes, root, run, radius, "0.75" if run == "sphere" else STYLES.get(run, ("C7",))[0])
    figure.suptitle("S1, the packings at the end (Fig. 10)\nside view, box 400 mm wide [mm]", fontsize=10)
    figure.tight_layout()
    figure.savefig(os.path.join(root, "fig10_packings.png"), dpi=110)
    plt.close(figure)


GUMMY_COLOURS = ("#d62728", "#ff7f0e", "#f2c500", "#2ca02c", "#f7f2e0", "#9467bd")  # a bag's red ... white


def packing_closeup(plt, root, run, radius):
    """fig10_packings.png of a single run: 1440 x 1080 pixels, seen from 40 degrees above the box's edge, each body
    in one of six colours."""
    figure = plt.figure(figsize=(12, 9))
    axes = figure.add_axes((0, 0, 1, 0.95), projection="3d")
    packing_picture(axes, root, run, radius, GUMMY_COLOURS if run.startswith("gummy_bear") else
                    "0.75" if run == "sphere" else STYLES.get(run, ("C7",))[0], view=(40, -60))
    axes.collections[-1].set_clip_on(False)  # the zoomed box reaches past the axes' square
    heights = [float(r["z_m"]) for r in read_csv(os.path.join(root, run, "final_state.csv"))]
    top = 1e3 * (max(heights) + 2 * radius)
    axes.set(zlim=(0, top), zticks=[0, 50, 100] if top > 100 else [0, 50])
    axes.set_box_aspect((1, 1, top / 400), zoom=1.2)
    axes.set_title("")
    figure.suptitle(f"S1: {len(heights)} {LABELS.get(run, run)} at the end of the run, box 400 mm wide [mm]",
                    fontsize=13)
    figure.savefig(os.path.join(root, "fig10_packings.png"), dpi=120)
    plt.close(figure)


def summary_table(root, runs, submerged):
    header = ["run", "bodies", "final_mean_height_m", "final_max_height_m", f"P_at_{submerged:.2f}_m_percent",
              "threads", "median_ms_per_step_shaking", "median_cpu_ms_per_step_shaking", "median_ms_per_step_settling",
              "median_cpu_ms_per_step_settling", "median_contacts_settling", "largest_pair_overlap_r", "run_wall_s",
              "resumed_at"]
    table = []
    for run in runs:
        height = read_csv(os.path.join(root, run, "height.csv"))[-1]
        packing = {round(float(r["h_m"]), 2): r for r in read_csv(os.path.join(root, run, "packing.csv"))}
        timing = read_csv(os.path.join(root, run, "timing.csv"))[0]
        floor = float(height["box_z_m"])
        table.append([run, height["bodies"], float(height["mean_height_m"]) - floor,
                      float(height["max_height_m"]) - floor, packing[round(submerged, 2)]["packing_factor_percent"],
                      timing["threads"], timing["shaking_median_ms_per_step"], timing["shaking_median_cpu_ms_per_step"],
                      timing["settling_median_ms_per_step"], timing["settling_median_cpu_ms_per_step"],
                      timing["settling_median_contacts"], timing.get("largest_pair_overlap_r", ""), timing["run_wall_s"],
                      timing["resumed_at"]])
    with open(os.path.join(root, "summary.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(table)
    return header, table


def make_all(root, radius, submerged):
    """Every figure and the summary of the runs in root; prints the summary."""
    runs = runs_in(root)
    if not runs:
        raise SystemExit(f"s1_packing.py: no complete run in {root} to plot")
    mean_height_figure(root, runs)
    packing_figure(root, runs)
    packings_figure(root, runs, radius)
    header, table = summary_table(root, runs, submerged)
    print(f"figures of {len(runs)} runs ({', '.join(runs)}) in {root}: fig11a_mean_height.png, fig11b_packing.png, "
          "fig10_packings.png, summary.csv")
    for row in table:
        print("  " + ", ".join(f"{name}={value:.4g}" if isinstance(value, float) else f"{name}={value}"
                               for name, value in zip(header, row)))
