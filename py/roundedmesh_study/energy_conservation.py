"""Is the contact force conservative? Issue 12, group 1: the measurements (the model is not changed here).

Materials of scene S1 (doc/scenes.md), with damping 0 and friction 0: particles E = 1 MPa, nu = 0.4,
2000 kg/m^3; the wall E = 5 MPa, nu = 0.4. Bodies: the 642-node icosphere of radius 25 mm, the pear and the
gummy bear (rm.Mesh.reference_shape), all of volume-equivalent radius r_eq = 25 mm.

    /usr/bin/python3 scripts/validation/energy_conservation.py [--quick] [--output out/energy] [--only loops collisions facing]

loops       Body 1 is fixed (at the origin, turned at random; or the plane z = 0 of a Wall, rm.plane_contact);
            body 2 goes quasi-statically (velocities zero) round a closed loop of poses: its centre orbits body 1
            on a cone of half-angle 15 degrees about a random axis while it turns by up to 12 degrees about two
            random axes out of phase (on the wall: 40 degrees, the loop is in its orientation alone), and at every
            pose it sits `overlap` (0.6 or 1.5 mm) closer than the touching boundary along the line from body 1's
            centre (the wall's normal). The boundary is followed from pose to pose, the steps halved where it moves
            by more than 50 um, so that the path is continuous; the loop ends exactly where it began. Work done on
            body 2 by the contact [J]:
                W = sum over the path's steps of trapezoids of F2 . dx2 + T2 . dtheta2,
            each step halved, recursively, where halving changes its work by more than its share of 1e-4 E (the
            force can change steeply within a step: a triangle pair's S grows fast where two projected edges cross
            at a small angle),
            F2, T2 the force and torque (about body 2's centre) of rm.body_contact / rm.plane_contact, dtheta2
            the rotation vector of each step. A potential force gives W = 0 on every closed loop. Reported:
            W / E, E the work of pressing body 2 from first touch to the start pose along the start direction
            [J] (the elastic energy stored there), and W / E_peak, E_peak the same at the loop's pose of largest
            force (the start pose of a bear can be a light touch). W is computed twice, the second time with half
            the segments and twice the step of the boundary: the difference bounds the quadrature's error.
                energy_loops.csv, energy_loops.png
collisions  The two bodies in a YADE scene (ForceResetter, rm.engine(), NewtonIntegrator(damping=0), no
            gravity; rounded bodies have no bounds, so there is nothing for a collider to do), 3 mm apart
            along a random direction, random orientations, approaching at the speed that would press two
            spheres of radius r_eq to 0.05 r_eq (the Hertz range) or 0.3 r_eq (deep); "head-on": along the line
            of centres, no spin; "off-centre": a tangential relative velocity of half the normal one and both
            bodies spinning (rim speed half the normal speed). O.dt = dt_c / 50 and dt_c / 200, dt_c =
            rm.critical_timestep(). Reported: the relative change of the kinetic energy, translational plus
            rotational (0.5 m v^2 + 0.5 sum I_i w_i^2, w in the body's principal frame), from before contact to
            after separation; the deepest overlap reached (rm.contacts()); the largest drift of the kinetic
            energy in free flight before the contact (the integrator's own share).
                energy_collisions.csv, energy_collisions.png
facing      How near Eq. B.5's facing test the contacts come: 40 random poses per pair and overlap, body 2
            pressed `overlap` past first touch along a random direction; each contact's facing cosine
            min(n1 . n12, -n2 . n12), and the energy held by contacts on the energy law's facing ramp (cosine
            below rm.FACING_RAMP, pkg/law/FacingRamp.hpp).
                energy_facing.csv
Each part prints a markdown table (worst and median per case). --quick: one loop per case with a quarter of the
segments, one seed of collisions (a check that the script runs, about 4 min). The full tables in doc/validation.md
took 18 min (loops) and 14 min (collisions), run side by side with --only on a busy two-core machine.
"""
import argparse
import csv
import functools
import math
import os
import shlex
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from yade import ForceResetter, NewtonIntegrator, O, PyRunner  # noqa: E402
from yade.minieigenHP import Quaternion, Vector3  # noqa: E402

import roundedmesh as rm  # noqa: E402

from .analytic import effective_modulus  # noqa: E402
from .benchmarking import machine  # noqa: E402

PARTICLE = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=0, friction=0)
WALL = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=0, friction=0)
R_EQ = 0.025                        # volume-equivalent radius of every shape [m]
PAIRS = ("sphere-sphere", "pear-pear", "bear-bear", "bear-pear")
LOOP_CASES = PAIRS + ("bear-wall",)
OVERLAPS = (0.6e-3, 1.5e-3)         # [m]
TOUCH_TOLERANCE = 1e-11             # first-touch distance found to this [m]
CONE_ANGLE = math.radians(15)       # half-angle of the cone body 2's centre orbits on
TURN = math.radians(12)             # amplitude of each of the two turns of body 2
WALL_TURN = math.radians(40)        # the same on the wall, where the loop is in the orientation alone
JUMP = 50e-6                        # largest move of the touching boundary in one step of a loop's walk [m]
GAP = 3e-3                          # starting gap of a collision [m]
DEPTHS = {"hertz": 0.05, "deep": 0.3}   # sphere-equivalent deepest overlap of a collision [r_eq]
# Segments per loop, so that the quadrature's error is far below the work measured (the table shows by how much W / E
# changes when they are halved). The force has steep stretches and small jumps along a loop, where the regime of
# Eq. 14 switches and triangle pairs come and go; the plane's cheap evaluations buy more segments.
SEGMENTS = {"sphere-sphere": 720, "pear-pear": 720, "bear-bear": 720, "bear-pear": 720, "bear-wall": 2880}
# Each step of a walk is then halved where halving changes its work by more than its share of LOOP_TOLERANCE E, at
# most REFINEMENTS times (Walk.cumulative_work): the loop's quadrature error stays two orders below the 1 %.
LOOP_TOLERANCE = 1e-4
REFINEMENTS = 10
FRACTIONS = (50, 200)               # O.dt = dt_c / fraction
KINDS = ("head-on", "off-centre")


@functools.lru_cache(maxsize=None)
def mesh(shape):
    return rm.Mesh.icosphere(R_EQ, 3) if shape == "sphere" else rm.Mesh.reference_shape(
        "gummy_bear" if shape == "bear" else shape)


def reach(shape):
    """Largest distance of the mesh's nodes from its centre [m]."""
    return float(np.linalg.norm(np.asarray(mesh(shape).vertices), axis=1).max())


def random_rotation(rng):
    q = Quaternion(*rng.normal(size=4))
    q.normalize()
    return q


def random_unit(rng):
    u = rng.normal(size=3)
    return u / np.linalg.norm(u)


def rotation_vector(q_from, q_to):
    """Rotation vector [rad] of the turn taking orientation q_from to q_to (global frame)."""
    axis, angle = (q_to * q_from.conjugate()).toAxisAngle()
    if angle > math.pi:
        angle -= 2 * math.pi
    return np.array(axis) * angle


# --- quasi-static closed loops -----------------------------------------------------------------------------

# The contact law's options (rm.engine's normal and regime; --normal, --regime): every loop and collision uses them.
CONTACT_OPTIONS = {}


class Contact:
    """Body 2 (`shape2`) against body 1 (`shape1` fixed at the origin, turned by q1; or shape1 = 'wall': the
    plane z = 0 of a Wall, normal +z). wrench(x, q) is the (force, torque about x) on body 2 at x turned by q."""

    def __init__(self, shape1, shape2, q1=Quaternion.Identity):
        self.shape1, self.shape2, self.q1 = shape1, shape2, q1
        self.far = reach(shape2) + (0.0 if shape1 == "wall" else reach(shape1)) + 5e-3

    def wrench(self, x, q):
        if self.shape1 == "wall":
            f, t = rm.plane_contact(mesh(self.shape2), Vector3(*x), q, Vector3(0, 0, 0), Vector3(0, 0, 1),
                                    PARTICLE, WALL, **CONTACT_OPTIONS)
        else:
            f, t = rm.body_contact(mesh(self.shape1), Vector3(0, 0, 0), self.q1, mesh(self.shape2), Vector3(*x), q,
                                   PARTICLE, PARTICLE, **CONTACT_OPTIONS)[2:]
        return np.array(f), np.array(t)

    def touching(self, d, u, q):
        return bool(np.any(self.wrench(d * u, q)[0] != 0))

    def _bisect(self, near, far, u, q):
        """The boundary between `near` (touching) and `far` (not touching) [m], to TOUCH_TOLERANCE."""
        while far - near > TOUCH_TOLERANCE:
            middle = 0.5 * (far + near)
            far, near = (far, middle) if self.touching(middle, u, q) else (middle, near)
        return far

    def first_touch(self, u, q, step=1e-3):
        """Distance [m] along the unit vector u from body 1's centre (the wall's plane) at which body 2, turned by
        q, coming from far away first touches."""
        far = self.far
        while not self.touching(far - step, u, q):
            far -= step
        return self._bisect(far - step, far, u, q)

    def track(self, u, q, previous, step=1e-4):
        """The boundary between touching and not touching along u nearest `previous` [m], the boundary at a
        neighbouring pose: outwards while touching, else inwards. It moves continuously with the pose, except where
        the stretch of touching distances it bounds vanishes (a protrusion grazing past the other body)."""
        if self.touching(previous, u, q):
            near, far = previous, previous + step
            while self.touching(far, u, q):
                near, far = far, far + step
        else:
            near, far = previous - step, previous
            while not self.touching(near, u, q):
                near, far = near - step, near
        return self._bisect(near, far, u, q)

    def stored_energy(self, u, q, overlap, points=201):
        """Work [J] of pressing body 2 (turned by q) along -u from first touch by `overlap` [m]: trapezoid rule on
        a grid refined where the force starts (x = overlap t^2), exact to below 1e-5 for F ~ x^3/2."""
        start = self.first_touch(u, q)
        x = overlap * np.linspace(0, 1, points) ** 2
        push = [float(self.wrench((start - xi) * u, q)[0] @ u) for xi in x]
        return float(np.sum(0.5 * (np.array(push[1:]) + push[:-1]) * np.diff(x)))


class Loop:
    """A closed loop of body 2's poses, s in [0, 1]: its direction from body 1 u(s) on a cone of half-angle `cone`
    about `axis`, its orientation R(b1, turn cos 2 pi s) R(b2, turn sin 2 pi s) q0. pose(1) == pose(0)."""

    def __init__(self, rng, cone=CONE_ANGLE, turn=TURN, axis=None):
        self.axis = random_unit(rng) if axis is None else np.asarray(axis, float)
        e1 = np.cross(self.axis, random_unit(rng))
        self.e1 = e1 / np.linalg.norm(e1)
        self.e2 = np.cross(self.axis, self.e1)
        self.b1, self.b2 = Vector3(*random_unit(rng)), Vector3(*random_unit(rng))
        self.q0, self.cone, self.turn = random_rotation(rng), cone, turn

    def pose(self, s):
        phase = 2 * math.pi * s
        u = math.cos(self.cone) * self.axis + math.sin(self.cone) * (math.cos(phase) * self.e1 +
                                                                     math.sin(phase) * self.e2)
        q = (Quaternion(self.b1, self.turn * math.cos(phase)) * Quaternion(self.b2, self.turn * math.sin(phase))
             * self.q0)
        q.normalize()
        return u, q


class Walk:
    """Body 2 carried round `loop` at `overlap` [m] past the touching boundary, which it tracks from pose to pose.
    Steps of s are halved where the boundary moves by more than `jump` [m] in one; where it still jumps at the
    finest step (a stretch of touching distances vanished), the walk crosses over radially, in steps of at most
    `jump`, so that the path is continuous. It ends exactly at its first pose. Each point: s, boundary d [m],
    position x [m], orientation q, force F [N] and torque T [N m] on body 2."""

    def __init__(self, contact, loop, overlap, segments, jump):
        self.contact, self.loop, self.overlap, self.jump = contact, loop, overlap, jump
        self.finest = 1 / (segments * 2 ** 12)
        u, q = loop.pose(0)
        self.points = [self._point(0.0, contact.first_touch(u, q), u, q)]
        for k in range(1, segments + 1):
            self._advance(k / segments if k < segments else None)
        first, last = self.points[0], self.points[-1]
        self._cross(last, first["d"])
        self.points.append(first)

    def _point(self, s, d, u, q, x=None):
        x = (d - self.overlap) * u if x is None else x
        f, t = self.contact.wrench(x, q)
        return {"s": s, "d": d, "u": u, "q": q, "x": x, "F": f, "T": t}

    def _advance(self, s):
        """On to s (None: back to the first pose, s = 1)."""
        a = self.points[-1]
        u, q = self.loop.pose(0.0 if s is None else s)
        d = self.contact.track(u, q, a["d"])
        if abs(d - a["d"]) > self.jump and (1.0 if s is None else s) - a["s"] > self.finest:
            self._advance(0.5 * (a["s"] + (1.0 if s is None else s)))
            self._advance(s)
        elif s is not None:
            self._cross(a, d)
            self.points.append(self._point(s, d, u, q))

    def _cross(self, a, d):
        """Radially from point a, at its pose, to boundary d, in steps of at most `jump`."""
        steps = int(abs(d - a["d"]) // self.jump)
        for dk in np.linspace(a["d"], d, steps + 2)[1:-1]:
            self.points.append(self._point(a["s"], dk, a["u"], a["q"]))
        if steps:
            self.points.append(self._point(a["s"], d, a["u"], a["q"]))

    def cumulative_work(self, tolerance=None):
        """Work [J] of the contact on body 2 from the start to each point: trapezoids of F . dx + T . dtheta. With a
        `tolerance` [J], each step between two points (body 2 moved in a straight line and turned about one axis) is
        halved, recursively, wherever halving changes its work by more than its share of the tolerance; `unrefined`
        counts the pieces still apart after REFINEMENTS halvings: where the force changes on a finer scale than the
        finest piece, or jumps."""
        pieces = [0.0]
        self.unrefined = 0
        share = None if tolerance is None else tolerance / (len(self.points) - 1)
        for a, b in zip(self.points[:-1], self.points[1:]):
            pieces.append(_trapezoid(a, b) if share is None else self._refined_work(a, b, share, REFINEMENTS))
        return np.cumsum(pieces)

    def _refined_work(self, a, b, tolerance, levels):
        """Work [J] from point a to point b, halved while halving changes it by more than `tolerance` [J]. Where
        the force changes steeply within a step (a triangle pair's S, the intersection of two projected triangles,
        grows fast where their edges cross at a small angle) one trapezoid misses much of the work: a loop of two
        bears under the energy law left 1.58 % of E with one trapezoid per step, 0.0005 % refined."""
        whole = _trapezoid(a, b)
        middle = self._point(0.5 * (a["s"] + b["s"]), 0.5 * (a["d"] + b["d"]), a["u"], a["q"].slerp(0.5, b["q"]),
                             x=0.5 * (a["x"] + b["x"]))
        halves = _trapezoid(a, middle) + _trapezoid(middle, b)
        if abs(halves - whole) <= tolerance:
            return halves
        if levels == 1:
            self.unrefined += 1
            return halves
        return (self._refined_work(a, middle, 0.5 * tolerance, levels - 1) +
                self._refined_work(middle, b, 0.5 * tolerance, levels - 1))


def _trapezoid(a, b):
    """Work [J] of the contact on body 2 from point a to point b of a walk, by one trapezoid."""
    return (0.5 * (a["F"] + b["F"]) @ (b["x"] - a["x"]) +
            0.5 * (a["T"] + b["T"]) @ rotation_vector(a["q"], b["q"]))


def loop_setting(case, seed):
    """(Contact, Loop) of `case` ('bear-pear': body 2 a bear, body 1 a pear; 'bear-wall', ...) and `seed`."""
    rng = np.random.default_rng(seed)
    shape2, shape1 = case.split("-")
    if shape1 == "wall":
        return Contact("wall", shape2), Loop(rng, cone=0.0, turn=WALL_TURN, axis=(0, 0, 1))
    return Contact(shape1, shape2, random_rotation(rng)), Loop(rng)


def loop_work_over_energy(case, overlap, seed, segments, jump=JUMP):
    """W / E of one loop, without the script's checks (for a cheap test)."""
    contact, loop = loop_setting(case, seed)
    energy = contact.stored_energy(*loop.pose(0), overlap)
    return Walk(contact, loop, overlap, segments, jump).cumulative_work(LOOP_TOLERANCE * energy)[-1] / energy


def loop_case(case, overlap, seed, segments):
    """One loop of `case` and `seed` at `overlap` [m] with `segments`, and again with half as many. Returns the CSV
    row, and s and the cumulative work / E_peak at each point of the walk."""
    contact, loop = loop_setting(case, seed)
    energy = contact.stored_energy(*loop.pose(0), overlap)
    walk, coarse = (Walk(contact, loop, overlap, n, j) for n, j in ((segments, JUMP), (segments // 2, 2 * JUMP)))
    cumulative = walk.cumulative_work(LOOP_TOLERANCE * energy)
    work, coarse_work = float(cumulative[-1]), float(coarse.cumulative_work(LOOP_TOLERANCE * energy)[-1])
    strongest = max(walk.points, key=lambda p: np.linalg.norm(p["F"]))
    peak = contact.stored_energy(strongest["u"], strongest["q"], overlap)
    row = {"case": case, "overlap_mm": overlap * 1e3, "seed": seed, "segments": segments, "points": len(walk.points),
           "crossings": sum(a["s"] == b["s"] for a, b in zip(walk.points[:-1], walk.points[1:])),
           "stored_energy_J": energy, "peak_stored_energy_J": peak, "work_J": work, "work_half_segments_J": coarse_work,
           "work_over_energy": work / energy, "work_over_peak_energy": work / peak,
           "halving_change_over_energy": abs(work - coarse_work) / energy, "unrefined_pieces": walk.unrefined}
    return row, np.array([p["s"] for p in walk.points]), cumulative / peak


def run_loops(output, quick):
    loops = 1 if quick else 4
    rows, curves = [], {}
    for case in LOOP_CASES:
        for overlap in OVERLAPS:
            for seed in range(1, loops + 1):
                start = time.monotonic()
                row, *curves[case, overlap, seed] = loop_case(case, overlap, seed,
                                                              SEGMENTS[case] // (4 if quick else 1))
                rows.append(row)
                print(f"loop {case:13s} overlap {overlap * 1e3:.1f} mm seed {seed}: "
                      f"W/E = {row['work_over_energy']:+.4%} (N/2: "
                      f"{row['work_half_segments_J'] / row['stored_energy_J']:+.4%}), W/E_peak = "
                      f"{row['work_over_peak_energy']:+.4%}, E = {row['stored_energy_J']:.3e} J, "
                      f"{row['points']} points, {row['crossings']} radial steps, {row['unrefined_pieces']} pieces "
                      f"unrefined, {time.monotonic() - start:.1f} s",
                      flush=True)
    write_csv(os.path.join(output, "energy_loops.csv"), rows)

    figure, (left, right) = plt.subplots(1, 2, figsize=(13, 4.5))
    for i, case in enumerate(LOOP_CASES):
        for overlap, marker in zip(OVERLAPS, "os"):
            values = [abs(r["work_over_energy"]) * 100 for r in rows if r["case"] == case and r["overlap_mm"] ==
                      overlap * 1e3]
            offset = 0.3 * (OVERLAPS.index(overlap) - (len(OVERLAPS) - 1) / 2)
            left.semilogy(np.full(len(values), i + offset), values, marker,
                          color=f"C{OVERLAPS.index(overlap)}",
                          label=f"{overlap * 1e3:.1f} mm overlap" if i == 0 else None)
        worst = max((r for r in rows if r["case"] == case), key=lambda r: abs(r["work_over_peak_energy"]))
        along, cumulative = curves[case, worst["overlap_mm"] / 1e3, worst["seed"]]
        right.plot(along, 100 * cumulative, label=f"{case}, {worst['overlap_mm']:.1f} mm, seed {worst['seed']}")
    left.axhline(1, color="k", ls="--", lw=1, label="issue's target, 1 %")
    left.set_xticks(range(len(LOOP_CASES)), LOOP_CASES)
    left.set(ylabel="|W| / E [%]", title="Work of the contact round a closed loop of poses")
    left.legend(fontsize=8)
    right.set(xlabel="position along the loop s", ylabel="cumulative work / E_peak [%]",
              title="Worst loop of each pair (E_peak: stored at the pose of largest force)")
    right.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(output, "energy_loops.png"), dpi=110)
    plt.close(figure)

    lines = [f"Closed loops: |W| / E [%], {loops} loops per case; E stored at the start pose, E_peak at the pose of "
             "largest force; halving: the largest change of W / E when the segments are halved; unrefined: the "
             "pieces of steps still apart after the refinement's last halving (a force steeper than they resolve, or a "
             "jump), most in a loop", "",
             "| pair | overlap [mm] | E [mJ], median | \\|W\\|/E worst | median | \\|W\\|/E_peak worst "
             "| median | halving | unrefined | W/E of each loop [%] |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for case in LOOP_CASES:
        for overlap in OVERLAPS:
            sel = [r for r in rows if r["case"] == case and r["overlap_mm"] == overlap * 1e3]
            values = np.array([r["work_over_energy"] for r in sel]) * 100
            peak = np.abs([r["work_over_peak_energy"] for r in sel]) * 100
            lines.append(f"| {case} | {overlap * 1e3:.1f} | {np.median([r['stored_energy_J'] for r in sel]) * 1e3:.3g} "
                         f"| {np.abs(values).max():.3g} % | {np.median(np.abs(values)):.3g} % | {peak.max():.3g} % | "
                         f"{np.median(peak):.3g} % | "
                         f"{100 * max(r['halving_change_over_energy'] for r in sel):.2g} % | "
                         f"{max(r['unrefined_pieces'] for r in sel)} | "
                         + " ".join(f"{v:+.3g}" for v in values) + " |")
    return lines


# --- collisions in YADE --------------------------------------------------------------------------------------

def kinetic_energies(body_ids):
    """(translational, rotational, rotational about each body's axis of least inertia [J], fastest spin [rad/s]) of
    the bodies, the rotation with the principal inertia."""
    translational = rotational = axial = fastest = 0.0
    for i in body_ids:
        state = O.bodies[i].state
        inertia = np.array(state.inertia)
        spin = np.array(state.ori.conjugate() * state.angVel)  # in the principal frame
        parts = 0.5 * inertia * spin ** 2
        translational += 0.5 * state.mass * state.vel.squaredNorm()
        rotational += parts.sum()
        axial += parts[np.argmin(inertia)]
        fastest = max(fastest, state.angVel.norm())
    return translational, rotational, axial, fastest


def kinetic_energy(body_ids):
    """Translational plus rotational kinetic energy [J]."""
    translational, rotational, _, _ = kinetic_energies(body_ids)
    return translational + rotational


_trace = []


def record():
    found = rm.contacts()
    _trace.append((kinetic_energy((0, 1)), len(found["id1"]), float(found["overlap"].max()) if len(found["id1"])
                   else 0.0))


def collide(pair, kind, depth, fraction, seed):
    """One undamped, frictionless collision of `pair` ('bear-pear', ...) of `kind` ('head-on' or 'off-centre') at
    the speed that presses two r_eq spheres to `depth` r_eq, at O.dt = dt_c / fraction. Returns the CSV row."""
    rng = np.random.default_rng(seed)
    shape1, shape2 = pair.split("-")
    q1, q2, u = random_rotation(rng), random_rotation(rng), random_unit(rng)
    distance = Contact(shape1, shape2, q1).first_touch(u, q2) + GAP
    O.reset()
    ids = (rm.add_body(mesh(shape1), (0, 0, 0), q1, PARTICLE), rm.add_body(mesh(shape2), tuple(distance * u), q2,
                                                                            PARTICLE))
    m1, m2 = (O.bodies[i].state.mass for i in ids)
    reduced = m1 * m2 / (m1 + m2)
    modulus, radius = effective_modulus(PARTICLE, PARTICLE), R_EQ / 2
    speed = math.sqrt(16 * modulus * math.sqrt(radius) * (depth * R_EQ) ** 2.5 / (15 * reduced))
    relative = -speed * u                     # velocity of body 2 relative to body 1
    if kind == "off-centre":
        side = np.cross(u, random_unit(rng))
        relative = relative + 0.5 * speed * side / np.linalg.norm(side)
        for i in ids:
            rm.set_velocity(i, angVel=0.5 * speed / R_EQ * random_unit(rng))
    O.bodies[ids[0]].state.vel = Vector3(*(-relative * m2 / (m1 + m2)))
    O.bodies[ids[1]].state.vel = Vector3(*(relative * m1 / (m1 + m2)))
    O.engines = [ForceResetter(), rm.engine(**CONTACT_OPTIONS), NewtonIntegrator(damping=0, gravity=(0, 0, 0)),
                 PyRunner(command=f"__import__('sys').modules[{__name__!r}].record()", iterPeriod=1)]
    O.dt = rm.critical_timestep() / fraction
    before = kinetic_energy(ids)
    _trace.clear()
    chunk = max(1, fraction // 4)
    while True:
        O.run(chunk, True)
        touching = np.array([t[1] for t in _trace]) > 0
        if touching.any():
            last = np.flatnonzero(touching)[-1]
            span = last - np.flatnonzero(touching)[0] + 1
            if len(_trace) - 1 - last >= max(span // 2, 20):
                break
        elif len(_trace) > 20 * GAP / (speed * O.dt):
            raise RuntimeError(f"{pair} {kind} seed {seed}: the bodies never touched")
    energies = np.array([t[0] for t in _trace])
    first = np.flatnonzero(touching)[0]
    after = energies[-1]
    return {"pair": pair, "kind": kind, "depth_target_req": depth, "dt_fraction": fraction, "seed": seed,
            "dt_s": O.dt, "impact_speed_m_s": speed, "steps_in_contact": int(span),
            "deepest_overlap_req": max(t[2] for t in _trace) / R_EQ, "kinetic_before_J": before,
            "kinetic_after_J": after, "change": after / before - 1,
            "free_flight_drift": float(np.abs(energies[:first] / before - 1).max()) if first else 0.0}


def run_collisions(output, quick):
    seeds = (1,) if quick else (1, 2, 3)
    rows = []
    for pair in PAIRS:
        for kind in KINDS:
            for depth_name, depth in DEPTHS.items():
                for seed in seeds:
                    for fraction in FRACTIONS:
                        start = time.monotonic()
                        row = collide(pair, kind, depth, fraction, seed)
                        row["depth"] = depth_name
                        rows.append(row)
                        print(f"collision {pair:13s} {kind:10s} {depth_name:5s} seed {seed} dt_c/{fraction:<3d}: "
                              f"dKE/KE = {row['change']:+.4%}, deepest {row['deepest_overlap_req']:.3f} r_eq, "
                              f"{row['steps_in_contact']} steps in contact, free-flight drift "
                              f"{row['free_flight_drift']:.1e}, {time.monotonic() - start:.1f} s", flush=True)
    O.reset()
    write_csv(os.path.join(output, "energy_collisions.csv"), rows)

    figure, axes = plt.subplots(1, 2, figsize=(13, 4.5), sharey=True)
    for ax, fraction in zip(axes, FRACTIONS):
        for i, pair in enumerate(PAIRS):
            for j, (kind, depth) in enumerate((k, d) for k in KINDS for d in DEPTHS):
                sel = [r for r in rows if r["pair"] == pair and r["kind"] == kind and r["depth"] == depth and
                       r["dt_fraction"] == fraction]
                ax.plot([r["deepest_overlap_req"] for r in sel], [100 * r["change"] for r in sel], "os^v"[i],
                        color=f"C{j}")
        ax.axhspan(-0.5, 0.5, color="0.85")
        ax.set(xlabel="deepest overlap / r_eq", title=f"O.dt = dt_c / {fraction}")
    axes[0].set_ylabel("change of kinetic energy [%]")
    handles = [plt.Line2D([], [], ls="", marker="os^v"[i], color="k", label=p) for i, p in enumerate(PAIRS)]
    handles += [plt.Line2D([], [], ls="", marker="o", color=f"C{j}", label=f"{k}, {d}")
                for j, (k, d) in enumerate((k, d) for k in KINDS for d in DEPTHS)]
    handles.append(plt.Rectangle((0, 0), 1, 1, color="0.85", label="issue's target, 0.5 %"))
    axes[1].legend(handles=handles, fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(output, "energy_collisions.png"), dpi=110)
    plt.close(figure)

    lines = [f"Collisions: change of kinetic energy [%], {len(seeds)} seeds per case; worst |change|, median", "",
             "| pair | kind | depth | deepest overlap [r_eq] | before, dt_c/50: worst | median | "
             "before, dt_c/200: worst | median |", "|---|---|---|---:|---:|---:|---:|---:|"]
    for pair in PAIRS:
        for kind in KINDS:
            for depth in DEPTHS:
                sel = [r for r in rows if r["pair"] == pair and r["kind"] == kind and r["depth"] == depth]
                cells = []
                for fraction in FRACTIONS:
                    values = np.array([100 * r["change"] for r in sel if r["dt_fraction"] == fraction])
                    cells += [f"{values[np.argmax(np.abs(values))]:+.3g} %", f"{np.median(values):+.3g} %"]
                deepest = [r["deepest_overlap_req"] for r in sel]
                lines.append(f"| {pair} | {kind} | {depth} | {min(deepest):.2f}-{max(deepest):.2f} | "
                             + " | ".join(cells) + " |")
    lines.append(f"\nlargest free-flight drift of the kinetic energy: {max(r['free_flight_drift'] for r in rows):.1e}")
    return lines


# --- how far contacts turn from facing (the energy law's facing ramp) -------------------------------------------

FACING_POSES = 40                   # random poses per pair and overlap


def facing_cosines(shape1, q1, shape2, x2, q2):
    """(cosines, energies) of the triangle contacts of body 2 at x2 turned by q2 against body 1 at the origin turned by
    q1: each contact's least facing cosine, min(n1 . n12, -n2 . n12) (Eq. B.5's measures), and its elastic energy."""
    listed = rm.triangle_contacts(mesh(shape1), Vector3(0, 0, 0), q1, mesh(shape2), Vector3(*x2), q2, PARTICLE,
                                  PARTICLE, **CONTACT_OPTIONS)
    n1 = np.asarray(mesh(shape1).normals) @ np.array(q1.toRotationMatrix()).T
    n2 = np.asarray(mesh(shape2).normals) @ np.array(q2.toRotationMatrix()).T
    n12 = listed["normal"]
    cosines = np.minimum(np.einsum("ij,ij->i", n1[listed["triangle1"]], n12),
                         -np.einsum("ij,ij->i", n2[listed["triangle2"]], n12))
    return cosines, listed["elastic_energy"]


def run_facing(output, quick):
    """How near the facing test of Eq. B.5 the triangle contacts of each pair come: random poses, body 2 pressed
    `overlap` past first touch along a random direction; the least facing cosine of a contact, and the share of the
    energy held by contacts on the energy law's facing ramp (cosine below rm.FACING_RAMP)."""
    rng = np.random.default_rng(1)
    poses = 4 if quick else FACING_POSES
    rows = []
    for pair in PAIRS:
        shape2, shape1 = pair.split("-")
        for overlap in OVERLAPS:
            for _ in range(poses):
                q1, q2, u = random_rotation(rng), random_rotation(rng), random_unit(rng)
                contact = Contact(shape1, shape2, q1)
                cosines, energies = facing_cosines(shape1, q1, shape2, (contact.first_touch(u, q2) - overlap) * u, q2)
                rows.append({"pair": pair, "overlap_mm": overlap * 1e3, "contacts": len(cosines),
                             "least_cosine": float(cosines.min()),
                             "ramp_energy_share": float(energies[cosines < rm.FACING_RAMP].sum() / energies.sum())})
    write_csv(os.path.join(output, "energy_facing.csv"), rows)
    lines = [f"Facing: {poses} random poses per pair and overlap; the least facing cosine of a triangle contact, and "
             f"the largest share of a pose's energy on the facing ramp (cosine below {rm.FACING_RAMP:g})", "",
             "| pair | overlap [mm] | contacts, median | least cosine, median | least | energy on the ramp, largest |",
             "|---|---:|---:|---:|---:|---:|"]
    for pair in PAIRS:
        for overlap in OVERLAPS:
            sel = [r for r in rows if r["pair"] == pair and r["overlap_mm"] == overlap * 1e3]
            least = [r["least_cosine"] for r in sel]
            lines.append(f"| {pair} | {overlap * 1e3:.1f} | {np.median([r['contacts'] for r in sel]):.0f} | "
                         f"{np.median(least):.3f} | {min(least):.3f} | "
                         f"{max(r['ramp_energy_share'] for r in sel):.2g} |")
    return lines


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


PARTS = {"loops": run_loops, "collisions": run_collisions, "facing": run_facing}


def main(argv):
    global LOOP_CASES
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/energy")
    parser.add_argument("--quick", action="store_true", help="fewer loops, segments and collisions")
    parser.add_argument("--only", nargs="+", choices=sorted(PARTS), help="run only these parts")
    parser.add_argument("--normal", default="pressure", choices=("pressure", "energy"),
                        help="the elastic force's law (rm.engine(normal=...)); default the paper's pressure")
    parser.add_argument("--regime", default="auto", choices=("auto", "quadrature", "direct", "exact"))
    parser.add_argument("--cases", nargs="+", help="only these loop cases (default all)")
    args = parser.parse_args(argv)
    CONTACT_OPTIONS.update(normal=args.normal, regime=args.regime)
    if args.cases:
        LOOP_CASES = tuple(c for c in LOOP_CASES if c in args.cases)
    os.makedirs(args.output, exist_ok=True)
    print(f"{machine()}\n$ {shlex.join(['scripts/validation/energy_conservation.py', *argv])}", flush=True)
    start = time.monotonic()
    tables = [make(args.output, args.quick) for name, make in PARTS.items() if not args.only or name in args.only]
    for lines in tables:
        print()
        print("\n".join(lines))
    print(f"\nwrote {args.output}/energy_*.csv and .png in {time.monotonic() - start:.0f} s")
