"""The reference scenes of doc/scenes.md that this package can build so far, shared by the tests, the
demo and the benchmarks. Values the scene list leaves open are ours and documented in doc/validation.md.

S2 -- static indentation of a meshed sphere against a rigid plane:
    S2_MATERIAL, S2_OVERLAPS, s2_poses() (the parameters),
    static_indentation(mesh, overlaps, material, orientation) -> forces [N]
S3 -- a meshed sphere dropped on a YADE Wall under gravity with normal damping:
    S3 (the parameters), build_bouncing_sphere(subdivisions) -> body id, trace_height(...)
S4 -- a meshed sphere resting on a YADE Wall, pushed sideways by a force rising past mu m g:
    S4 (the parameters), friction_ramp(subdivisions) -> applied and friction forces over time
Slope (ours, doc/validation.md) -- the gummy bear or the pear resting on a Wall under gravity tilted by an angle:
    SLOPE (the parameters), SLOPE_POSES, build_slope(shape, angle) -> body id, trace_slope(...) -> its motion
"""
import math
from dataclasses import dataclass

import numpy as np
from yade import ForceResetter, NewtonIntegrator, O, PyRunner, utils
from yade.minieigenHP import Quaternion, Vector3

from roundedmesh import HertzMaterial, Mesh, plane_contact, progress
from roundedmesh.scene import add_body, assign_material, critical_timestep, engine, statistics
from roundedmesh.shapes import reference_shape

RIGID = HertzMaterial(young=math.inf, poisson=0.0, density=1.0)

# S2: a unit sphere with E* = 1 Pa against the rigid plane, 50 overlaps up to 5 % of R.
S2_MATERIAL = HertzMaterial(young=1.0, poisson=0.0, density=1.0)
S2_OVERLAPS = np.linspace(0, 0.05, 51)[1:]


def s2_poses(count=12, seed=1):
    """The icosphere's own frame, then `count` - 1 random rotations: the error depends on how the mesh meets
    the plane, so S2 is judged over several poses, not one."""
    rng = np.random.default_rng(seed)
    yield Quaternion.Identity
    for _ in range(count - 1):
        q = Quaternion(*rng.normal(size=4))
        q.normalize()
        yield q


def static_indentation(mesh, overlaps, material, orientation=Quaternion.Identity, **engine_options):
    """Normal force [N] on `mesh` (a sphere of radius R centred at the origin of its frame) pressed by each
    of `overlaps` [m] into the rigid plane z = 0, body turned by `orientation`."""
    radius = float(np.max(np.linalg.norm(mesh.vertices, axis=1)))
    forces = [plane_contact(mesh, (0, 0, radius - d), orientation, (0, 0, 0), (0, 0, 1), material, RIGID,
                            **engine_options)[0][2] for d in overlaps]
    return np.array(forces)


@dataclass(frozen=True)
class BouncingSphere:
    """Scene S3 (ours where scenes.md is silent): S1's particle and box materials, a damping constant that
    dissipates about half the energy of the first impact, and a drop that reaches about 10 % overlap."""
    radius: float = 0.025                       # [m]
    height: float = 0.05                        # initial height of the centre above the wall [m]
    gravity: float = 9.81                       # [m/s^2]
    timestep: float = 2e-5                      # [s], about 600 steps per impact
    particle: HertzMaterial = HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
    wall: HertzMaterial = HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-3)


S3 = BouncingSphere()


def build_bouncing_sphere(subdivisions, scene=S3, **engine_options):
    """Resets YADE and builds S3 with an icosphere of `subdivisions` (1, 2, 3: 42, 162, 642 nodes).
    Returns the sphere's body id."""
    O.reset()
    sphere = add_body(Mesh.icosphere(scene.radius, subdivisions), pos=(0, 0, scene.height), material=scene.particle)
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    assign_material(wall, scene.wall)
    O.engines = [ForceResetter(), engine(**engine_options),
                 NewtonIntegrator(gravity=(0, 0, -scene.gravity), damping=0)]
    O.dt = scene.timestep
    return sphere


def trace_height(body_id, duration, label=None):
    """Runs the current scene for `duration` [s], sampling the body's height every step.
    Returns (times, heights); with a label, prints progress."""
    steps = int(round(duration / O.dt))
    times, heights = np.empty(steps + 1), np.empty(steps + 1)
    state = O.bodies[body_id].state
    times[0], heights[0] = O.time, state.pos[2]
    reporter = progress.Progress(steps, label) if label else None
    for i in range(1, steps + 1):
        O.step()
        times[i], heights[i] = O.time, state.pos[2]
        if reporter:
            reporter.update(i)
    return times, heights


@dataclass(frozen=True)
class FrictionRamp:
    """Scene S4 (ours where scenes.md is silent): S1's particle resting on a Wall under gravity, its rotations
    blocked so that it can only slide (the Coulomb law of Eq. 18 is the one of a sliding block), pushed along
    x at its centre by a force rising linearly from 0 to 1.5 mu m g. With the default tangential spring the
    sphere stands until the push reaches mu m g (its spring stretching by 0.13 mm), then slides; c damps the
    spring. Under the paper's viscous law (engine(friction='viscous')) c makes the slip at the onset of sliding
    mu m g / c = 6 mm/s. The ramp is slow enough that inertia (m dv/dt) stays below 1 % of mu m g before sliding."""
    radius: float = 0.025           # [m]
    gravity: float = 9.81           # [m/s^2]
    friction: float = 0.5
    ramp_time: float = 0.3          # [s] to reach 1.5 mu m g
    settle_time: float = 0.1        # [s] at rest before the ramp (10 decay times of the bounce)
    timestep: float = 2e-4          # [s]: omega dt = 0.04 for the resting contact, c dt / m = 0.15
    particle: HertzMaterial = HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2, friction=0.5,
                                            tangential_damping=100.0)
    wall: HertzMaterial = HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-2, friction=0.5,
                                        tangential_damping=100.0)


S4 = FrictionRamp()


def friction_ramp(subdivisions, scene=S4, label=None, law="spring"):
    """Runs S4 with an icosphere of `subdivisions` (2, 3: 162, 642 nodes) under the friction law `law` ('spring' or
    'viscous'). Returns a dict of arrays over the ramp's steps: time [s], applied force F_A [N], friction force F_t
    on the sphere (x component of the contact force, opposing F_A) [N], sphere displacement along x [m], sliding
    triangle contacts, and f_max = mu m g [N]."""
    O.reset()
    mesh = Mesh.icosphere(scene.radius, subdivisions)
    mass = scene.particle.density * mesh.volume
    modulus = 1 / sum((1 - m.poisson ** 2) / m.young for m in (scene.particle, scene.wall))
    rest = (3 * mass * scene.gravity / (4 * modulus * math.sqrt(scene.radius))) ** (2 / 3)  # Hertz, Eq. 6
    sphere = add_body(mesh, pos=(0, 0, scene.radius - rest), material=scene.particle)
    O.bodies[sphere].state.blockedDOFs = "XYZ"
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    assign_material(wall, scene.wall)
    f_max = scene.friction * mass * scene.gravity
    rate = 1.5 * f_max / scene.ramp_time
    push = f"max(O.time - {scene.settle_time!r}, 0.0) * {rate!r}"  # F_A(t) [N], evaluated by YADE each step
    O.engines = [ForceResetter(), engine(friction=law),
                 PyRunner(command=f"O.forces.addF({sphere}, ({push}, 0, 0))", iterPeriod=1, initRun=True),
                 NewtonIntegrator(gravity=(0, 0, -scene.gravity), damping=0)]
    O.dt = scene.timestep
    settle = int(round(scene.settle_time / O.dt))
    O.run(settle, True)
    steps = int(round(scene.ramp_time / O.dt))
    out = {k: np.empty(steps) for k in ("time", "applied", "friction", "displacement", "sliding")}
    reporter = progress.Progress(steps, label) if label else None
    x0 = O.bodies[sphere].state.pos[0]
    for i in range(steps):
        applied = eval(push)
        O.step()
        out["time"][i] = O.time
        out["applied"][i] = applied
        out["friction"][i] = -O.forces.f(wall)[0]  # on the sphere: the opposite of what the wall receives
        out["displacement"][i] = O.bodies[sphere].state.pos[0] - x0
        out["sliding"][i] = statistics()["sliding_contacts"]
        if reporter:
            reporter.update(i + 1)
    out["f_max"] = f_max
    return out


@dataclass(frozen=True)
class SlopeScene:
    """A body resting on a slope (ours, for the friction law; doc/validation.md): S1's particle and box materials with
    S1's normal damping A = 0.01 s, mu = 0.5 and the tangential damping c = 100 N s/m of S4, a Wall for the floor and
    gravity tilted by `angle` about y (a tilted Wall is not possible), so that +x points down the slope. The body
    starts at rest, its lowest node `gap` above the floor, and the time step is `timestep_fraction` of
    rm.critical_timestep()."""
    angle: float = 5.0              # [degrees]; the friction angle of mu = 0.5 is 26.57
    gravity: float = 9.81           # [m/s^2]
    gap: float = 1e-4               # [m]
    timestep_fraction: float = 0.5
    particle: HertzMaterial = HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-2, friction=0.5,
                                            tangential_damping=100.0)
    floor: HertzMaterial = HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-2, friction=0.5,
                                         tangential_damping=100.0)


SLOPE = SlopeScene()

# How each shape lies on the slope (orientation of its principal frame, YADE's blockedDOFs). The gummy bear lies on
# its back (its thinnest principal axis normal to the floor). The pear has no pose in which it stands still on a
# slope by itself: upright it topples, and on its side (its axis, x, along the fall line, the narrow end up the
# slope) it rolls about its own axis, which no friction law resists (the model, like the paper's, has no rolling
# resistance); its rotation about the fall line (global x) is blocked, which leaves it free to rock and turn on
# its side.
SLOPE_POSES = {"gummy_bear": (Quaternion.Identity, ""), "pear": (Quaternion((0, 0, 1), math.pi), "X")}


def build_slope(shape, angle=None, scene=SLOPE, law="spring", blocked=None, **material_changes):
    """Resets YADE and builds the slope scene with `shape` ('gummy_bear' or 'pear', in its SLOPE_POSES pose) at
    `angle` [degrees] (default scene.angle) under the engine's friction law `law` ('spring' or 'viscous').
    `blocked`: YADE's blockedDOFs of the body, if not the pose's. material_changes (friction, tangential_damping, ...)
    replace those of both materials. Returns the body's id."""
    O.reset()
    angle = scene.angle if angle is None else angle
    materials = []
    for m in (scene.particle, scene.floor):
        values = dict(young=m.young, poisson=m.poisson, density=m.density, damping=m.damping, friction=m.friction,
                      tangential_damping=m.tangential_damping)
        values.update(material_changes)
        materials.append(HertzMaterial(**values))
    ori, pose_blocked = SLOPE_POSES[shape]
    mesh = reference_shape(shape)
    lowest = min((ori * Vector3(*x))[2] for x in mesh.vertices)
    body = add_body(mesh, pos=(0, 0, scene.gap - lowest), ori=ori, material=materials[0])
    O.bodies[body].state.blockedDOFs = pose_blocked if blocked is None else blocked
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    assign_material(floor, materials[1])
    a = math.radians(angle)
    O.engines = [ForceResetter(), engine(friction=law),
                 NewtonIntegrator(gravity=(scene.gravity * math.sin(a), 0, -scene.gravity * math.cos(a)), damping=0)]
    O.dt = scene.timestep_fraction * critical_timestep()
    return body


def trace_slope(body_id, duration, samples=100, label=None):
    """Runs the current scene for `duration` [s]; returns (times [s], positions [m], shape (samples + 1, 3)) of the
    body, sampled evenly."""
    steps = max(int(round(duration / O.dt / samples)), 1)
    times, positions = [O.time], [tuple(O.bodies[body_id].state.pos)]
    reporter = progress.Progress(samples, label) if label else None
    for i in range(samples):
        O.run(steps, True)
        times.append(O.time)
        positions.append(tuple(O.bodies[body_id].state.pos))
        if reporter:
            reporter.update(i + 1)
    return np.array(times), np.array(positions)
