"""Scene S3 (paper Section 3.1.2, Fig. 5): meshed spheres of 42, 162 and 642 nodes dropped on a YADE Wall,
moved by YADE's NewtonIntegrator with the integrated Hertz pressure, against a perfect sphere under the same
damped Hertz law (Eq. 7).

    yade -n -x scripts/examples/demo_bouncing_sphere.py [--output out/demo] [--duration 0.5]

Writes to the output folder:
    bouncing_sphere_height.csv / .png   height of the centre vs time, every mesh and the analytic sphere
    bouncing_sphere_energy.csv          energy dissipated per impact (m g times the loss of apex height)
    vtk/rounded_bodies.pvd              the 642-node sphere for ParaView, every 5 ms
and prints the NRMSE of each mesh against the analytic sphere (height over time, energy per impact).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade import O, PyRunner  # noqa: E402

from roundedmesh.export import VtkSeries  # noqa: E402
from roundedmesh_study.analytic import apex_heights, bouncing_sphere, nrmse  # noqa: E402
from roundedmesh_study.scenes import S3, build_bouncing_sphere, trace_height  # noqa: E402

SUBDIVISIONS = {42: 1, 162: 2, 642: 3}


def energy_per_impact(heights, mass):
    apexes = np.concatenate([[S3.height], heights])
    return mass * S3.gravity * -np.diff(apexes)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/demo")
    parser.add_argument("--duration", type=float, default=0.5, help="simulated time [s]")
    args = parser.parse_args(argv)
    if not args.duration > 0:
        parser.error(f"--duration must be positive, got {args.duration}")
    os.makedirs(args.output, exist_ok=True)

    heights, energies = {}, {}
    for nodes, k in SUBDIVISIONS.items():
        sphere = build_bouncing_sphere(k)
        if nodes == 642:  # PyRunner commands run in __main__, this script's namespace
            global paraview
            paraview = VtkSeries(os.path.join(args.output, "vtk"))
            O.engines = O.engines + [PyRunner(command="paraview.write()", virtPeriod=5e-3, initRun=True)]
        t, z = trace_height(sphere, args.duration, label=f"{nodes}-node sphere")
        heights[nodes] = z
        energies[nodes] = energy_per_impact(apex_heights(t, z), O.bodies[sphere].state.mass)

    exact = bouncing_sphere(S3.radius, S3.particle.density, S3.particle, S3.wall, S3.height, args.duration,
                            S3.gravity)(t)
    mass = S3.particle.density * 4 / 3 * np.pi * S3.radius ** 3
    exact_energy = energy_per_impact(apex_heights(t, exact), mass)

    np.savetxt(os.path.join(args.output, "bouncing_sphere_height.csv"),
               np.column_stack([t, exact] + [heights[n] for n in SUBDIVISIONS]), delimiter=",",
               header="time_s,analytic_m," + ",".join(f"mesh{n}_m" for n in SUBDIVISIONS), comments="")
    impacts = min(len(exact_energy), *(len(e) for e in energies.values()))
    np.savetxt(os.path.join(args.output, "bouncing_sphere_energy.csv"),
               np.column_stack([np.arange(1, impacts + 1), exact_energy[:impacts]] +
                               [energies[n][:impacts] for n in SUBDIVISIONS]), delimiter=",",
               header="impact,analytic_J," + ",".join(f"mesh{n}_J" for n in SUBDIVISIONS), comments="")

    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    left.plot(t, exact * 1e3, "k-", lw=2.5, label="analytic sphere (Eq. 7)")
    right.plot(np.arange(1, impacts + 1), exact_energy[:impacts] * 1e3, "ko-", lw=2, label="analytic sphere")
    print("\nNRMSE against the analytic sphere")
    for n in SUBDIVISIONS:
        height_error = nrmse(heights[n], exact)
        energy = (f"energy per impact {100 * nrmse(energies[n][:impacts], exact_energy[:impacts]):.3f} %"
                  if impacts > 1 else "energy per impact: too few rebounds within --duration")
        print(f"  {n:4d} nodes: height {100 * height_error:.3f} %, {energy}")
        left.plot(t, heights[n] * 1e3, "--", label=f"{n} nodes (NRMSE {100 * height_error:.2f} %)")
        right.plot(np.arange(1, impacts + 1), energies[n][:impacts] * 1e3, "s--", label=f"{n} nodes")
    left.set(xlabel="time [s]", ylabel="height of the centre [mm]", title="Meshed sphere bouncing on a wall (S3)")
    right.set(xlabel="impact", ylabel="energy dissipated [mJ]", title="Energy dissipated per impact")
    left.legend()
    right.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(args.output, "bouncing_sphere_height.png"), dpi=120)
    print(f"\nwrote {args.output}/bouncing_sphere_height.csv, bouncing_sphere_energy.csv, "
          f"bouncing_sphere_height.png, vtk/rounded_bodies.pvd")


if __name__ == "__main__":
    main(sys.argv[1:])
