"""Gummy bears in YADE's own containers, built as YADE users build them: a `geom.facetBox` open at the top, a
`geom.facetCylinder` drum with four thin-plate lifters (each two Facets forming a radial plate) turning about its
axis, and a hopper read from an STL file with `ymport.stl`. The bears are dropped in from a lattice above, in random
orientations, and fall under gravity; roundedmesh welds each container's Facets into surfaces (doc/physics.md,
"What each partner's surface is").

    yade -n -x scripts/examples/example_containers.py --container box [--bodies 30] [--duration T] [--vtk out/box]
    /usr/bin/python3 scripts/examples/example_containers.py --container drum|hopper [the same options]

O.dt is 0.3 of rm.critical_timestep for impacts at 3 m/s (1.33e-5 s). Default simulated time: box 1 s (75,200 steps),
drum 0.5 s (37,600), hopper 1.5 s (112,800). Prints progress and each 1000 steps' time per step, and at the end how many bears
stayed inside and their highest speed; with --vtk, a ParaView series every 0.02 s of the bears and the container's
Facets (open <vtk>/<container>.pvd).
"""
import argparse
import math
import os
import sys
import time

CONTAINERS = ("box", "drum", "hopper")
DEFAULT_DURATION = {"box": 1.0, "drum": 0.5, "hopper": 1.5}  # [s] simulated
HOPPER_STL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "hopper.stl")
SPACING = 0.1  # [m] between the lattice's nodes: a gummy bear (reference shape, r_eq 25 mm) reaches 48.5 mm from its
               # centre, so bears in any orientation start apart


def lattice(corner, counts, spacing, bodies):
    """The first `bodies` nodes of a lattice of counts[0] x counts[1] x counts[2] nodes `spacing` [m] apart from
    `corner` [m], bottom layer first."""
    nodes = [(corner[0] + i * spacing, corner[1] + j * spacing, corner[2] + k * spacing)
             for k in range(counts[2]) for j in range(counts[1]) for i in range(counts[0])]
    if len(nodes) < bodies:
        raise SystemExit(f"--bodies {bodies}: the lattice above this container holds {len(nodes)}")
    return nodes[:bodies]


def box_container(utils, geom, O):
    """An open-topped facetBox 0.3 m x 0.3 m, 0.5 m high, its floor at z = 0; the lattice inside it."""
    ids = O.bodies.append(geom.facetBox((0, 0, 0.25), (0.15, 0.15, 0.25), wallMask=31, fixed=True))
    return ids, [], lattice((-0.1, -0.1, 0.06), (3, 3, 4), SPACING, 36)


def drum_container(utils, geom, O, Quaternion, Vector3):
    """A facetCylinder drum of radius 0.25 m and length 0.4 m about the y axis (24 panels, both ends closed), with four
    lifters: radial plates 6 cm high of two Facets each, standing on panel edges at 0, 90, 180 and 270 degrees."""
    radius, length, segments, height = 0.25, 0.4, 24, 0.06
    axis_to_y = Quaternion(Vector3(1, 0, 0), math.pi / 2)
    ids = O.bodies.append(geom.facetCylinder((0, 0, 0), radius, length, orientation=axis_to_y,
                                             segmentsNumber=segments, wallMask=7, fixed=True))
    ids += O.bodies.append(lifter_plates(utils, Vector3, radius, length, height))
    return ids, [RotationAbout(ids)], lattice((-0.1, -0.15, -0.1), (3, 4, 3), SPACING, 36)


def lifter_plates(utils, Vector3, radius, length, height):
    """Four radial plates `height` [m] high of two fixed Facets each, along a drum of `radius` and `length` [m] about
    the y axis, at 0, 90, 180 and 270 degrees: where facetCylinder puts its panels' corners (one at angle 0, every
    360 / segments degrees), so that they are welded to the mantle."""
    lifters = []
    for k in range(4):
        angle = k * math.pi / 2
        outer = Vector3(radius * math.cos(angle), 0, radius * math.sin(angle))
        inner = outer * ((radius - height) / radius)
        y0, y1 = Vector3(0, -length / 2, 0), Vector3(0, length / 2, 0)
        lifters += [utils.facet([outer + y0, inner + y0, inner + y1], fixed=True),
                    utils.facet([outer + y0, inner + y1, outer + y1], fixed=True)]
    return lifters


def RotationAbout(ids):
    """The drum's turn: 3 rad/s about the y axis through the origin (the rim moves at 0.75 m/s)."""
    from yade import RotationEngine
    return RotationEngine(ids=ids, rotationAxis=(0, 1, 0), rotateAroundZero=True, zeroPoint=(0, 0, 0),
                          angularVelocity=3.0)


def hopper_triangles():
    """A square hopper: a funnel from 0.4 m x 0.4 m at z = 0.2 m down to an outlet 0.12 m x 0.12 m at z = 0, walls
    0.3 m high above it, and a floor 0.4 m x 0.4 m at z = -0.1 m under the outlet; each quad two triangles, wound
    with their normals toward the inside."""
    top, outlet, rise, floor = 0.2, 0.06, 0.3, -0.1
    ring = lambda h, z: [(-h, -h, z), (h, -h, z), (h, h, z), (-h, h, z)]  # noqa: E731
    quads = []
    for lower, upper in ((ring(outlet, 0.0), ring(top, 0.2)), (ring(top, 0.2), ring(top, 0.2 + rise))):
        for i in range(4):
            quads.append((lower[i], lower[(i + 1) % 4], upper[(i + 1) % 4], upper[i]))
    quads.append(tuple(ring(top, floor)))
    triangles = []
    for a, b, c, d in quads:
        triangles += [(a, b, c), (a, c, d)]
    return triangles


def write_hopper_stl(path):
    """Writes hopper_triangles() as an ASCII STL file (what a CAD program exports), in metres."""
    import numpy as np
    with open(path, "w") as f:
        f.write("solid hopper\n")
        for t in hopper_triangles():
            a, b, c = (np.array(p, float) for p in t)
            n = np.cross(b - a, c - a)
            n /= np.linalg.norm(n)
            f.write(f"  facet normal {n[0]:.9g} {n[1]:.9g} {n[2]:.9g}\n    outer loop\n")
            for p in (a, b, c):
                f.write(f"      vertex {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid hopper\n")


def hopper_container(ymport, O):
    """The hopper of data/hopper.stl, read as YADE reads a CAD part: one Facet per triangle."""
    ids = O.bodies.append(ymport.stl(HOPPER_STL, fixed=True))
    return ids, [], lattice((-0.1, -0.1, 0.27), (3, 3, 4), SPACING, 36)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--container", choices=CONTAINERS, required=True)
    parser.add_argument("--bodies", type=int, default=30, help="gummy bears (default 30)")
    parser.add_argument("--duration", type=float, help="simulated time [s] (default: box 1, drum 0.5, hopper 1.5)")
    parser.add_argument("--seed", type=int, default=1, help="of the bears' orientations (default 1)")
    parser.add_argument("--vtk", help="folder for a ParaView series")
    parser.add_argument("--write-stl", action="store_true", help=f"write {HOPPER_STL} afresh and stop")
    args = parser.parse_args(argv)
    if args.write_stl:
        write_hopper_stl(HOPPER_STL)
        print(f"wrote {HOPPER_STL}")
        return 0
    duration = DEFAULT_DURATION[args.container] if args.duration is None else args.duration
    if not duration > 0 or args.bodies < 1:
        parser.error("--duration and --bodies must be positive")

    import numpy as np
    import roundedmesh as rm
    from yade import ForceResetter, NewtonIntegrator, O, PyRunner, geom, utils, ymport
    from yade.minieigenHP import Quaternion, Vector3

    O.reset()
    bear_material = rm.HertzMaterial(young=1e6, poisson=0.4, density=1200, damping=0.05, friction=0.5,
                                     tangential_damping=0.1)
    wall_material = rm.HertzMaterial(young=1e8, poisson=0.3, density=7800, damping=0.05, friction=0.4,
                                     tangential_damping=0.1)
    if args.container == "box":
        facets, movers, nodes = box_container(utils, geom, O)
    elif args.container == "drum":
        facets, movers, nodes = drum_container(utils, geom, O, Quaternion, Vector3)
    else:
        facets, movers, nodes = hopper_container(ymport, O)
    for facet in facets:
        rm.assign_material(facet, wall_material)
    bear = rm.Mesh.reference_shape("gummy_bear")
    rng = np.random.default_rng(args.seed)
    bears = []
    for node in nodes[:args.bodies]:
        q = rng.normal(size=4)
        bears.append(rm.add_body(bear, pos=node, ori=Quaternion(*(q / np.linalg.norm(q))), material=bear_material))
    O.engines = [ForceResetter()] + movers + [rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = min(1e-4, 0.3 * rm.critical_timestep(impact_speed=3.0))
    steps = math.ceil(duration / O.dt - 1e-9)

    if args.vtk:
        global series  # PyRunner commands run in __main__, this script's namespace
        series = rm.export.VtkSeries(args.vtk, prefix=args.container, partners=True)
        O.engines = O.engines + [PyRunner(command="series.write()", virtPeriod=0.02, initRun=True)]
    print(f"{args.container}: {len(facets)} Facets, {len(bears)} gummy bears, O.dt = {O.dt:.3g} s, {steps} steps")
    progress = rm.progress.Progress(steps, args.container)
    start, done, failure = time.perf_counter(), 0, ""
    try:
        while done < steps:
            chunk = min(1000, steps - done)
            before = time.perf_counter()
            O.run(chunk, True)
            done += chunk
            progress.update(done)
            print(f"  step {done}: {1e3 * (time.perf_counter() - before) / chunk:.2f} ms per step")
    except RuntimeError as error:
        failure = str(error).splitlines()[0][:400]
    seconds = time.perf_counter() - start
    speeds = [O.bodies[b].state.vel.norm() for b in bears]
    inside = sum(1 for b in bears if O.bodies[b].state.pos[2] > -0.5)
    print(f"{args.container}: {'stopped: ' + failure if failure else 'completed'} after {O.iter} steps "
          f"({O.time:.3g} s simulated) in {seconds:.0f} s, {1e3 * seconds / max(O.iter, 1):.2f} ms per step; "
          f"{inside} of {len(bears)} bears inside, highest speed {max(speeds):.3g} m/s")
    return 1 if failure else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
