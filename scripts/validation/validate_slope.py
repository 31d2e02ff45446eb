"""Friction that holds (doc/validation.md, "Friction on a slope"): the gummy bear and the pear on a slope
(roundedmesh_study.scenes.build_slope: S1's materials, mu = 0.5, c = 100 N s/m, gravity tilted), under the default
tangential spring and under the paper's viscous law.

    /usr/bin/python3 scripts/validation/validate_slope.py [--output out/slope] [--only drift slide damping timestep]
                                                          [--duration 10]

Parts (each writes its CSV, prints its table):
    drift     5 degrees: the body's displacement over `duration` seconds after settling for 1 s, per law
              (slope_drift.csv, slope_drift.png)
    slide     30 to 45 degrees, above the friction angle (26.6): the acceleration fitted over 0.1-0.4 s against
              Coulomb's g (sin a - mu cos a) (slope_slide.csv, slope_slide.png)
    damping   the gummy bear pressed 0.5 mm into a plane in 12 random poses and moved along it: the no-slip force
              over c v (slope_damping.csv)
    timestep  rm.critical_timestep() of the bear on the floor against c, per law (slope_timestep.csv)
About 8 minutes on two cores. The "before" columns of doc/validation.md (the paper's law as it was, before the
spring) came from this script as of commit 44593e1, which also ran on a build without the friction option (main at
93c580d).
"""
import argparse
import math
import os
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import roundedmesh as rm  # noqa: E402
from roundedmesh.export import write_csv  # noqa: E402
from roundedmesh_study import scenes  # noqa: E402
from yade import O  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

LAWS = ["spring", "viscous"]
SHAPES = ("gummy_bear", "pear")
G = 9.81


def _log(message):
    print(message, flush=True)


def build(shape, angle, law, blocked=None, **changes):
    return scenes.build_slope(shape, angle, law=law, blocked=blocked, **changes)


def trace(body, duration, samples):
    steps = max(int(round(duration / O.dt / samples)), 1)
    times, positions = [O.time], [tuple(O.bodies[body].state.pos)]
    for _ in range(samples):
        O.run(steps, True)
        times.append(O.time)
        positions.append(tuple(O.bodies[body].state.pos))
    return np.array(times), np.array(positions)


def drift(output, duration):
    rows, lines, curves = [], [], {}
    lines.append(f"Drift on a 5 degree slope (mu = 0.5, c = 100 N s/m), over {duration:g} s after settling for 1 s")
    lines.append("shape       law       dt [s]     along the slope [um]  per second [um/s]  |total| [um]  sliding")
    for shape in SHAPES:
        for law in LAWS:
            start = time.monotonic()
            body = build(shape, 5.0, law)
            O.run(int(round(1.0 / O.dt)), True)
            times, positions = trace(body, duration, 100)
            d = positions - positions[0]
            curves[shape, law] = (times - times[0], d[:, 0])
            total = np.linalg.norm(d[-1])
            sliding = rm.statistics()["sliding_contacts"]
            rows.append([shape, law, O.dt, duration, d[-1][0], d[-1][0] / duration, total, sliding])
            lines.append(f"{shape:10s}  {law:8s}  {O.dt:.3g}  {1e6 * d[-1][0]:20.6g}  {1e6 * d[-1][0] / duration:17.6g}"
                         f"  {1e6 * total:12.6g}  {sliding}")
            _log(f"drift: {shape} {law}: {time.monotonic() - start:.1f} s")
    write_csv(os.path.join(output, "slope_drift.csv"),
               ["shape", "law", "dt_s", "duration_s", "along_slope_m", "per_second_m_s", "total_m", "sliding_contacts"],
               rows)
    figure, axes = plt.subplots(1, len(SHAPES), figsize=(12, 4.5))
    for axis, shape in zip(axes, SHAPES):
        for law in LAWS:
            t, x = curves[shape, law]
            axis.plot(t, 1e6 * x, label=law)
        axis.set(xlabel="time after settling [s]", ylabel="displacement down the slope [um]",
                 title=f"{shape}, 5 degrees, mu = 0.5, c = 100 N s/m")
        axis.set_yscale("symlog", linthresh=1e-3)
        axis.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(output, "slope_drift.png"), dpi=120)
    plt.close(figure)
    return lines


def slide(output):
    rows, lines = [], ["Sliding above the friction angle: acceleration fitted over 0.1-0.4 s, against Coulomb's "
                       "g (sin a - mu cos a); the pear's rotations blocked",
                       "shape       law       angle  a [m/s^2]  Coulomb   error [%]"]
    angles = (30.0, 35.0, 40.0, 45.0)
    for shape in SHAPES:
        for law in LAWS:
            for angle in angles:
                body = build(shape, angle, law, blocked="" if shape == "gummy_bear" else "XYZ")
                O.run(int(round(0.1 / O.dt)), True)
                times, positions = trace(body, 0.3, 30)
                a = 2 * np.polyfit(times, positions[:, 0], 2)[0]
                r = math.radians(angle)
                coulomb = G * (math.sin(r) - 0.5 * math.cos(r))
                rows.append([shape, law, angle, a, coulomb])
                lines.append(f"{shape:10s}  {law:8s}  {angle:5.1f}  {a:9.4f}  {coulomb:7.4f}  "
                             f"{100 * (a / coulomb - 1):8.3f}")
            _log(f"slide: {shape} {law} done")
    write_csv(os.path.join(output, "slope_slide.csv"), ["shape", "law", "angle_deg", "acceleration", "coulomb"], rows)
    figure, axis = plt.subplots(figsize=(6, 4.5))
    x = np.linspace(26.57, 46, 50)
    axis.plot(x, G * (np.sin(np.radians(x)) - 0.5 * np.cos(np.radians(x))), "k-", label="Coulomb, mu = 0.5")
    for (shape, law), marker in zip([(s, l) for s in SHAPES for l in LAWS], "osd^"):
        chosen = [r for r in rows if r[0] == shape and r[1] == law]
        axis.plot([r[2] for r in chosen], [r[3] for r in chosen], marker, mfc="none", label=f"{shape}, {law}")
    axis.set(xlabel="slope [degrees]", ylabel="acceleration down the slope [m/s^2]")
    axis.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(output, "slope_slide.png"), dpi=120)
    plt.close(figure)
    return lines


def damping(output):
    bear = rm.Mesh.reference_shape("gummy_bear")
    material = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, friction=0.5, tangential_damping=100.0)
    floor = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, friction=0.5, tangential_damping=100.0)
    rng = np.random.default_rng(3)
    rows = []
    for pose in range(12):
        ori = Quaternion(*rng.normal(size=4))
        ori.normalize()
        lowest = min((ori * Vector3(*x))[2] for x in bear.vertices)
        v = Vector3(*rng.normal(size=2), 0).normalized() * 1e-5
        row = [pose]
        for law in LAWS:
            force, _ = rm.plane_contact(bear, (0, 0, -5e-4 - lowest), ori, (0, 0, 0), (0, 0, 1), material, floor,
                                        vel=v, friction=law)
            row.append(-Vector3(force[0], force[1], 0).dot(v) / (100.0 * v.squaredNorm()))
        rows.append(row)
    write_csv(os.path.join(output, "slope_damping.csv"), ["pose"] + [f"{law}_over_c" for law in LAWS], rows)
    lines = ["No-slip force of the gummy bear over c v, 12 random poses (0.5 mm deep, v = 10 um/s along the plane)"]
    for k, law in enumerate(LAWS):
        values = np.array([r[k + 1] for r in rows])
        lines.append(f"{law:8s}  min {values.min():.4f}  max {values.max():.4f}  mean {values.mean():.4f}")
    return lines


def timestep(output):
    rows, lines = [], ["rm.critical_timestep() of the gummy bear on the floor (S1's materials, A = 0.01 s) against c [s]",
                       "c [N s/m]  " + "  ".join(f"{law:>10s}" for law in LAWS)]
    for c in (0.0, 1.0, 10.0, 100.0, 1000.0):
        row = [c]
        for law in LAWS:
            build("gummy_bear", 0.0, law, tangential_damping=c)
            row.append(rm.critical_timestep())
        rows.append(row)
        lines.append(f"{c:9g}  " + "  ".join(f"{v:10.3g}" for v in row[1:]))
    write_csv(os.path.join(output, "slope_timestep.csv"), ["c"] + [f"{law}_s" for law in LAWS], rows)
    return lines


PARTS = {"drift": drift, "slide": slide, "damping": damping, "timestep": timestep}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/slope")
    parser.add_argument("--only", nargs="+", choices=sorted(PARTS))
    parser.add_argument("--duration", type=float, default=10.0, help="drift window [s] (default 10)")
    args = parser.parse_args(argv)
    os.makedirs(args.output, exist_ok=True)
    tables = []
    for name, part in PARTS.items():
        if args.only and name not in args.only:
            continue
        start = time.monotonic()
        tables.append(part(args.output, args.duration) if name == "drift" else part(args.output))
        _log(f"{name}: done in {time.monotonic() - start:.1f} s")
    for lines in tables:
        print()
        print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
