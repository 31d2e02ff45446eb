"""A mixed scene: rounded bodies (icospheres, a gummy bear, a clump of two icospheres) and YADE spheres (one
clump of two among them) settling in a box. YADE's InsertionSortCollider and InteractionLoop handle the
contacts of the spheres among themselves and with the box; roundedmesh handles every contact of a rounded
body, with the box, with another rounded body or with a sphere.

    yade -n -x scripts/examples/example_mixed_scene.py [--steps 27000] [--vtk out/mixed]
    /usr/bin/python3 scripts/examples/example_mixed_scene.py [--steps 27000] [--vtk out/mixed]

The scene is the one of doc/user-guide.md, "A mixed scene". At the end it prints what the floor carries
against the weight of everything in the box. With --vtk, a ParaView series (rounded bodies and spheres)
every 20 ms of simulated time.
"""
import argparse
import sys


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=27000, help="time steps to run (default 27000: 1.9 s)")
    parser.add_argument("--vtk", help="folder for a ParaView series")
    args = parser.parse_args(argv)
    if args.steps < 1:
        parser.error(f"--steps must be positive, got {args.steps}")

    # --- the scene of doc/user-guide.md, "A mixed scene" ---
    import roundedmesh as rm
    from yade import (O, utils, ForceResetter, InsertionSortCollider, InteractionLoop, NewtonIntegrator,
                      Bo1_Sphere_Aabb, Bo1_Wall_Aabb, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, ViscElMat,
                      Ip2_ViscElMat_ViscElMat_ViscElPhys, Law2_ScGeom_ViscElPhys_Basic)

    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2, friction=0.3,
                              tangential_damping=5)
    steel = rm.HertzMaterial(young=2e11, poisson=0.3, density=7800, damping=1e-2, friction=0.3,
                             tangential_damping=5)
    # YADE's own material for the contacts YADE computes: sphere-sphere and sphere-wall
    grains = O.materials.append(ViscElMat(tc=0.005, en=0.3, et=1.0, density=2000, frictionAngle=0.3))

    # a box of five Walls, 0.2 m x 0.2 m: partners of the rounded bodies, and YADE's walls for the spheres
    walls = [O.bodies.append(utils.wall(0, axis=2, sense=1, material=grains))]
    for axis in (0, 1):
        for side, sense in ((-0.1, 1), (0.1, -1)):
            walls.append(O.bodies.append(utils.wall(side, axis=axis, sense=sense, material=grains)))
    for wall in walls:
        rm.assign_material(wall, steel)

    icosphere = rm.Mesh.icosphere(0.02, 2)                                 # 162 nodes
    bear = rm.Mesh.reference_shape("gummy_bear")                           # 554 nodes, 25 mm equivalent radius
    for i, (x, y) in enumerate([(-0.05, -0.05), (0.05, -0.05), (-0.05, 0.05)]):
        rm.add_body(icosphere, pos=(x, y, 0.03 + 0.01 * i), material=rubber)
    rm.add_body(bear, pos=(0.04, 0.04, 0.05), material=rubber)
    O.bodies.clump([rm.add_body(icosphere, pos=(x, 0, 0.12), material=rubber) for x in (-0.02, 0.02)])

    # YADE spheres: partners of the rounded bodies (assign_material), YADE's own bodies otherwise
    spheres = [O.bodies.append(utils.sphere((x, y, 0.18), 0.015, material=grains))
               for x, y in [(-0.05, -0.05), (0.05, -0.05), (-0.05, 0.05), (0.05, 0.05)]]
    _, members = O.bodies.appendClumped([utils.sphere((-0.02, 0.0, 0.24), 0.015, material=grains),
                                         utils.sphere((0.01, 0.0, 0.24), 0.015, material=grains)])
    for sphere in spheres + list(members):
        rm.assign_material(sphere, rubber)

    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                        [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
        rm.engine(),
        NewtonIntegrator(gravity=(0, 0, -9.81), damping=0),
    ]
    # a fifth of the rounded bodies' stability limit, and at most a tenth of YADE's contact duration tc
    O.dt = min(0.2 * rm.critical_timestep(), 0.1 * 0.005)
    # --- end of the scene ---

    if args.vtk:
        from yade import PyRunner
        global series  # PyRunner commands run in __main__, this script's namespace
        series = rm.export.VtkSeries(args.vtk, prefix="mixed", spheres=True)
        O.engines = O.engines + [PyRunner(command="series.write()", virtPeriod=0.02, initRun=True)]
    rm.progress.Progress(args.steps, "mixed scene").update(0)
    O.run(args.steps, True)
    weight = 9.81 * sum(b.state.mass for b in O.bodies if b.isStandalone or b.isClump)
    print(f"after {O.iter} steps ({O.time:.3f} s, dt = {O.dt:.3g} s): "
          f"the floor carries {0.0 - O.forces.f(walls[0])[2]:.4f} N, "
          f"the side walls {sum(abs(O.forces.f(w)[a]) for w, a in zip(walls[1:], (0, 0, 1, 1))):.4f} N sideways; "
          f"the weight in the box is {weight:.4f} N")
    print("statistics of the last step:", rm.statistics())


if __name__ == "__main__":
    main(sys.argv[1:])
