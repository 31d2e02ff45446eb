"""Which term of today's normal force does work round a closed loop? Issue 12, group 1: an analysis, the model is
not changed.

scripts/validation/energy_conservation.py carries body 2 quasi-statically round closed loops of poses at a fixed
overlap and finds that the contact does work W on it (up to 192 % of the stored energy E for two gummy bears). This
script walks the same loops (its Contact, Loop and Walk, imported) and, at every pose of the walk, takes the triangle
pairs of rm.triangle_contacts: per pair k the magnitude F_k [N] (the Hertz pressure integrated over the share S ∩
circle), the normal n_k = (s2_k - s1_k)/|s2_k - s1_k| (s1_k, s2_k the centres of the two triangles' encompassing
spheres, rm.Mesh.sphere_centres), the point c_eff_k and the node forces of Eq. 15. From the same F_k it rebuilds the
force F [N] and torque T [N m] (about body 2's centre) on body 2 of three force models, and their loop work W = sum of
trapezoids of F . dx2 + T . dtheta2 [J]:

  A   today's law: F_k n_k applied through the node forces of Eq. 15 at body 2's triangle corners (the centre of
      pressure of S ∩ circle). Must reproduce W of rm.body_contact's wrench (checked: column "A - today").
  A'  F_k n_k applied at c_eff_k (the point of S nearest the circle's centre; not exactly today's lever arm).
  B   central: F_k along n_k through s2_k (equivalently s1_k: n_k is parallel to s2_k - s1_k), so the torque on
      body 2 is (s2_k - x2) x F_k n_k. A and B have the same forces, only the torques differ. A central force
      between two points fixed in the bodies is conservative if its magnitude depends only on their distance
      (on delta_s,k); B's F_k also depends on the share S ∩ circle, which moves with the relative pose.
A model "C" (a magnitude from the pair's full circle, no share) is left out: with unequal spheres there is no
pose-independent weight that makes the pairs of one contact add up to its force.

The wall: rm.triangle_contacts cannot take a plane, so "bear-wall" replaces the plane z = 0 by an analytic sphere of
radius 1000 r_eq = 25 m (centred at (0, 0, -25 m), under the bear's centre, which stays on the z axis), for the
walk too (rm.sphere_contact's wrench), so that A is checked against the same force. Its surface falls below the
plane by at most x^2 / (2 R) = 12.5 um at 25 mm from the axis.

Materials and bodies as energy_conservation.py (S1's, no damping, no friction; r_eq = 25 mm). E [J]: the energy
stored by pressing body 2 to the loop's start pose. Reported per case: |W| / E worst and median over the loops, for
today's wrench and for A, A', B, and the largest |W_A - W_today| / E; "B removes": 1 - sum |W_B| / sum |W_today|
over the case's loops; and B's work split by pair: the trapezoids of pairs in contact at both ends of a step
("continuing": the smooth change of their shares) and the half trapezoids of pairs at one end only ("coming or
going").

    /usr/bin/python3 scripts/validation/energy_terms.py [--loops 4] [--segments 0.25] [--overlaps 0.6 1.5] [--cases ...]
                                                        [--regime auto|quadrature] [--output out/energy]

--regime quadrature: the pressure integrated by quadrature over S ∩ square for every pair (no switch to Eq. 14's
direct regime, whose area fraction is not the integral of an energy density), in the walk and the pairs alike.

--segments scales energy_conservation.py's segments per loop (720, the wall 2880). Writes energy_terms_<regime>.csv.
With the defaults one overlap takes about 3.5 min (doc/validation.md's table: --overlaps 0.6 and --overlaps 1.5 run
side by side, 204 s each, on a busy 2-core AMD EPYC). Result (doc/validation.md, "Which term does the work"): B does
as much work as today's law, so the work is the share term, not the lever arm.
"""
import argparse
import os
import shlex
import sys
import time

import numpy as np
import roundedmesh as rm
from roundedmesh_study import energy_conservation as energy
from roundedmesh_study.benchmarking import machine
from yade.minieigenHP import Quaternion, Vector3

CASES = ("sphere-sphere", "bear-bear", "bear-pear", "bear-wall")
WALL_RADIUS = 1e3 * energy.R_EQ     # the analytic sphere standing for the wall [m]
WALL_CENTRE = np.array([0.0, 0.0, -WALL_RADIUS])
MODELS = ("today", "A", "A'", "B")
REGIME = "auto"                     # the pressure integration (Eq. 14): 'auto', or 'quadrature' throughout


class BodyPair(energy.Contact):
    """energy_conservation.py's Contact of two bodies, with the pressure integration REGIME."""

    def wrench(self, x, q):
        f, t = rm.body_contact(energy.mesh(self.shape1), Vector3(0, 0, 0), self.q1, energy.mesh(self.shape2),
                               Vector3(*x), q, energy.PARTICLE, energy.PARTICLE, regime=REGIME)[2:]
        return np.array(f), np.array(t)


class SphereWall(energy.Contact):
    """The bear against the analytic sphere of radius WALL_RADIUS touching z = 0 from below (the wall's stand-in)."""

    def wrench(self, x, q):
        f, t = rm.sphere_contact(energy.mesh(self.shape2), Vector3(*x), q, Vector3(*WALL_CENTRE), WALL_RADIUS,
                                 energy.PARTICLE, energy.WALL, regime=REGIME)[:2]
        return np.array(f), np.array(t)


def rotation(q):
    return np.array(q.toRotationMatrix())


def model_wrenches(contact, x, q):
    """{model: (force, torque about x)} on body 2 at x turned by q, rebuilt from the triangle pairs."""
    body = energy.mesh(contact.shape2)
    centres, vertices, triangles = (np.asarray(a) for a in (body.sphere_centres, body.vertices, body.triangles))
    rot = rotation(q)
    if contact.shape1 == "wall":
        # The moving body is triangle_contacts' body 1 here; the analytic sphere is its body 2: the moving body
        # receives the opposite of the listed forces on body 2.
        tc = rm.triangle_contacts(body, Vector3(*x), q, WALL_RADIUS, Vector3(*WALL_CENTRE), Quaternion.Identity,
                                  energy.PARTICLE, energy.WALL, regime=REGIME)
        sign, mine, nodes = -1.0, tc["triangle1"], tc["node_forces1"]
    else:
        tc = rm.triangle_contacts(energy.mesh(contact.shape1), Vector3(0, 0, 0), contact.q1, body, Vector3(*x), q,
                                  energy.PARTICLE, energy.PARTICLE, regime=REGIME)
        sign, mine, nodes = 1.0, tc["triangle2"], tc["node_forces2"]
    if len(mine) == 0:
        zero = np.zeros(3)
        return {m: (zero, zero) for m in MODELS[1:]}, {}
    n, magnitude = tc["normal"], tc["normal_force"]
    force = sign * magnitude[:, None] * n                         # each pair's force on the moving body
    total = force.sum(0)
    corners = x + vertices[triangles[mine]] @ rot.T               # (k, 3 corners, 3)
    node_torque = np.cross(corners - x, sign * nodes[:, :, None] * n[:, None, :]).sum((0, 1))
    ceff_torque = np.cross(tc["point"] - x, force).sum(0)
    own_centre = x + centres[mine] @ rot.T                        # s of the moving body's triangles
    central_torque = np.cross(own_centre - x, force).sum(0)
    if contact.shape1 != "wall":                                  # check: n_k is along s2 - s1
        other = centres_of(contact)[tc["triangle1"]] @ rotation(contact.q1).T
        line = own_centre - other
        assert np.abs(line / np.linalg.norm(line, axis=1)[:, None] - n).max() < 1e-9
    return ({"A": (total, node_torque), "A'": (total, ceff_torque), "B": (total, central_torque)},
            {pair: (f, t) for pair, f, t in zip(zip(tc["triangle1"].tolist(), tc["triangle2"].tolist()), force,
                                                np.cross(own_centre - x, force))})


def centres_of(contact):
    return np.asarray(energy.mesh(contact.shape1).sphere_centres)


def loop_terms(case, overlap, seed, segments):
    contact, loop = energy.loop_setting(case, seed)
    if case.endswith("wall"):
        contact = SphereWall("wall", contact.shape2)
    else:
        contact = BodyPair(contact.shape1, contact.shape2, contact.q1)
    stored = contact.stored_energy(*loop.pose(0), overlap)
    walk = energy.Walk(contact, loop, overlap, segments, energy.JUMP)
    cumulative = {"today": walk.cumulative_work()}
    per_point = [model_wrenches(contact, p["x"], p["q"]) for p in walk.points]
    pairs = [k for _, k in per_point]
    original = walk.points
    for model in MODELS[1:]:
        walk.points = [dict(p, F=w[model][0], T=w[model][1]) for p, (w, _) in zip(original, per_point)]
        cumulative[model] = walk.cumulative_work()
    walk.points = original
    works = {model: c[-1] for model, c in cumulative.items()}
    # B's work split by pair: trapezoids of the pairs in contact at both ends of a step ("continuing"), and the half
    # trapezoids of those at one end only (pairs coming or going: their share reaches zero at h = a, or not: the
    # facing check of Eq. B.5 switches a pair with its force).
    continuing = switching = 0.0
    for a, b, pa, pb in zip(original[:-1], original[1:], pairs[:-1], pairs[1:]):
        dx, dtheta = b["x"] - a["x"], energy.rotation_vector(a["q"], b["q"])
        for key in pa.keys() | pb.keys():
            fa, ta = pa.get(key, (np.zeros(3), np.zeros(3)))
            fb, tb = pb.get(key, (np.zeros(3), np.zeros(3)))
            piece = 0.5 * (fa + fb) @ dx + 0.5 * (ta + tb) @ dtheta
            if key in pa and key in pb:
                continuing += piece
            else:
                switching += piece
    assert abs(continuing + switching - works["B"]) <= 1e-9 * stored + 1e-12 * abs(works["B"])
    row = {"case": case, "overlap_mm": overlap * 1e3, "seed": seed, "segments": segments, "points": len(original),
           "mean_pairs": float(np.mean([len(k) for k in pairs])), "stored_energy_J": stored,
           "W_B_continuing_over_E": continuing / stored, "W_B_switching_over_E": switching / stored}
    for model in MODELS:
        row[f"W_{model}_J"] = float(works[model])
        row[f"W_{model}_over_E"] = float(works[model] / stored)
    row["W_Ac_over_E"] = row["W_A'_over_E"]
    row["A_minus_today_over_E"] = float((works["A"] - works["today"]) / stored)
    return row


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default="out/energy")
    parser.add_argument("--loops", type=int, default=4)
    parser.add_argument("--segments", type=float, default=0.25, help="fraction of energy_conservation.py's segments")
    parser.add_argument("--cases", nargs="+", default=list(CASES), choices=CASES)
    parser.add_argument("--overlaps", nargs="+", type=float, default=[o * 1e3 for o in energy.OVERLAPS],
                        help="[mm]")
    parser.add_argument("--regime", default="auto", choices=("auto", "quadrature"),
                        help="pressure integration (Eq. 14) for the walk and the triangle pairs alike")
    args = parser.parse_args(argv)
    global REGIME
    REGIME = args.regime
    os.makedirs(args.output, exist_ok=True)
    print(f"{machine()}\n$ {shlex.join(['scripts/validation/energy_terms.py', *argv])}", flush=True)
    start = time.monotonic()
    rows = []
    for case in args.cases:
        for overlap in args.overlaps:
            for seed in range(1, args.loops + 1):
                begin = time.monotonic()
                row = loop_terms(case, overlap * 1e-3, seed, int(energy.SEGMENTS[case] * args.segments))
                rows.append(row)
                print(f"{case:13s} {overlap:.1f} mm seed {seed}: W/E today {row['W_today_over_E']:+.4%}, A "
                      f"{row['W_A_over_E']:+.4%}, A' {row['W_Ac_over_E']:+.4%}, B "
                      f"{row['W_B_over_E']:+.4%}; {row['points']} points, {row['mean_pairs']:.1f} pairs, "
                      f"{time.monotonic() - begin:.1f} s; B of pairs continuing {row['W_B_continuing_over_E']:+.4%}, "
                      f"coming or going {row['W_B_switching_over_E']:+.4%}", flush=True)
    path = os.path.join(args.output, f"energy_terms_{REGIME}.csv")
    energy.write_csv(path, rows)
    lines = [f"|W|/E [%] worst, median over {args.loops} loops; segments x {args.segments:g}; regime {REGIME}", "",
             "| pair | overlap [mm] | today: worst | median | A (node forces) | \\|A − today\\|/E | A' (c_eff): worst "
             "| median | B (central): worst | median | B removes | B, pairs continuing: worst | median "
             "| B, pairs coming or going: worst | median |",
             "|---|---:|" + "---:|" * 13]
    for case in args.cases:
        for overlap in args.overlaps:
            sel = [r for r in rows if r["case"] == case and r["overlap_mm"] == overlap]
            cells = []
            for model in MODELS:
                v = np.abs([r[f"W_{model}_over_E"] for r in sel]) * 100
                cells += [f"{v.max():.3g} %"] if model == "A" else [f"{v.max():.3g} %", f"{np.median(v):.3g} %"]
            check = max(abs(r["A_minus_today_over_E"]) for r in sel)
            today = np.array([abs(r["W_today_J"]) for r in sel])
            central = np.array([abs(r["W_B_J"]) for r in sel])
            cells.insert(3, f"{check:.1e}")
            cells.append(f"{100 * (1 - central.sum() / today.sum()):.0f} %")
            for part in ("continuing", "switching"):
                v = np.abs([r[f"W_B_{part}_over_E"] for r in sel]) * 100
                cells += [f"{v.max():.3g} %", f"{np.median(v):.3g} %"]
            lines.append(f"| {case} | {overlap:.1f} | " + " | ".join(cells) + " |")
    lines.append("")
    lines.append("W/E of each loop [%], today / B: " + "; ".join(
        f"{r['case']} {r['overlap_mm']:.1f} s{r['seed']}: {100 * r['W_today_over_E']:+.3g} / "
        f"{100 * r['W_B_over_E']:+.3g}" for r in rows))
    print("\n".join(lines))
    print(f"\nwrote {path} in {time.monotonic() - start:.0f} s")


if __name__ == "__main__":
    main(sys.argv[1:])
