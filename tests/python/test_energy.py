"""O.energy with rounded bodies: the elastic energy of the contacts (rmElastPotential) and the energies dissipated
by normal damping (rmNormDamp) and friction (rmFrictDissip), beside YADE's kinetic energy and gravity work.

A 642-node icosphere (exact curvature) falls 1 cm onto a Wall at 1/100 of the stability limit. Two errors bound
how far O.energy.total() may stray from its start:
  - the model's: the elastic energy is (2/5) F_elastic delta_s per triangle contact, exact for the Hertz force
    F ~ delta^3/2; the integrated pressure departs from that law by its quadrature error, so (2/5) F delta differs
    from the work integral of F. It is measured here without time integration, from rm.plane_contact along the
    same path, and allowed once;
  - leap-frog's: YADE's kinetic energy is that of velocities half a step away from the positions the elastic
    energy is taken at, which shifts it by up to F v dt / 2 <= (omega dt / 2) E_max for a contact of angular
    frequency omega storing at most E_max; rm.critical_timestep() is 2 / omega_max, so omega dt <= 2 * 0.01.
"""
import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, PyRunner, utils
from yade.minieigenHP import Quaternion

import roundedmesh as rm
from roundedmesh_study import analytic

R = 0.025
FRACTION = 0.01  # of rm.critical_timestep()
KEYS = ("rmElastPotential", "rmNormDamp", "rmFrictDissip")
_totals = []


def record():
    _totals.append((O.energy.total(), dict(O.energy.items())))


def bouncing(damping=0.0, friction=0.0, tangential_damping=0.0, vel=(0, 0, 0), duration=0.12, law="spring"):
    ball_material = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=damping, friction=friction,
                                     tangential_damping=tangential_damping)
    wall_material = rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=damping, friction=friction,
                                     tangential_damping=tangential_damping)
    ball = rm.add_body(rm.Mesh.icosphere(R, 3), pos=(0, 0, R + 0.01), material=ball_material)
    O.bodies[ball].state.vel = vel
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, wall_material)
    O.engines = [ForceResetter(), rm.engine(friction=law), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0),
                 PyRunner(command=f"__import__('sys').modules[{__name__!r}].record()", iterPeriod=1)]
    O.dt = FRACTION * rm.critical_timestep()
    O.trackEnergy = True
    _totals.clear()
    O.run(int(duration / O.dt), True)
    return ball_material, wall_material, list(_totals)


def model_error(ball_material, wall_material, deepest):
    """max over delta of |(2/5) F delta - integral of F| along the quasi-static path of the bounce, from
    rm.plane_contact (trapezoid rule on 2,000 intervals: error below 1e-6 of the energy)."""
    mesh = rm.Mesh.icosphere(R, 3)
    deltas = np.linspace(0, deepest, 2001)
    forces = np.array([rm.plane_contact(mesh, (0, 0, R - d), Quaternion.Identity, (0, 0, 0), (0, 0, 1),
                                        ball_material, wall_material)[0][2] for d in deltas])
    work = np.concatenate([[0], np.cumsum(0.5 * (forces[1:] + forces[:-1]) * np.diff(deltas))])
    return np.max(np.abs(0.4 * forces * deltas - work))


def deepest_overlap(energy, ball_material, wall_material):
    """The Hertz overlap storing `energy`, from (2/5) F delta = (8/15) E* sqrt(R) delta^5/2 [m]."""
    e_star = analytic.effective_modulus(ball_material, wall_material)
    return (energy * 15 / (8 * e_star * np.sqrt(R))) ** 0.4


def test_undamped_frictionless_bounce_conserves_the_total():
    ball_material, wall_material, rows = bouncing()
    totals = np.array([t for t, _ in rows])
    elastic = np.array([e.get("rmElastPotential", 0.0) for _, e in rows])
    assert all(e["rmNormDamp"] == 0 and e["rmFrictDissip"] == 0 for _, e in rows)
    largest = elastic.max()
    fall = 9.81 * 0.01 * O.bodies[0].state.mass
    # At the deepest point the contact holds the fall's energy, m g (1 cm + the overlap, about 2 mm).
    assert fall < largest < 1.3 * fall
    assert elastic[-1] == 0, "the ball must have left the wall again"
    model = model_error(ball_material, wall_material, deepest_overlap(1.1 * largest, ball_material, wall_material))
    bound = model + FRACTION * largest
    deviation = np.max(np.abs(totals - totals[0]))
    print(f"largest elastic energy {largest:.4g} J, model error {model:.3g} J ({model / largest:.2%}), "
          f"deviation {deviation:.3g} J ({deviation / largest:.2%}), bound {bound:.3g} J ({bound / largest:.2%})")
    assert deviation <= bound


# Thrown sideways at 0.5 m/s onto the wall: normal damping and friction both work. The dissipated energies are sums
# of power times dt at the half-step velocities the forces were computed with, which shifts them by the same
# (omega dt / 2) relative amount as the kinetic energy: the bound adds FRACTION times what was dissipated. Under the
# tangential spring (whose stored energy is in rmElastPotential, and rmFrictDissip what the bodies lose beyond it)
# with c = 5 N s/m, a quarter of the spring's critical damping, and under the paper's viscous law with c = 50 N s/m.
@pytest.mark.parametrize("law, c", [("spring", 5.0), ("viscous", 50.0)])
def test_damped_bounce_with_friction_balances_the_dissipation(law, c):
    ball_material, wall_material, rows = bouncing(damping=1e-3, friction=0.3, tangential_damping=c,
                                                  vel=(0.5, 0, 0), law=law)
    totals = np.array([t for t, _ in rows])
    final = rows[-1][1]
    dissipated = final["rmNormDamp"] + final["rmFrictDissip"]
    assert final["rmNormDamp"] > 0.1 * totals[0] and final["rmFrictDissip"] > 0.1 * totals[0]
    largest = max(e.get("rmElastPotential", 0.0) for _, e in rows)
    model = model_error(ball_material, wall_material, deepest_overlap(1.1 * largest, ball_material, wall_material))
    bound = model + FRACTION * (largest + dissipated)
    deviation = np.max(np.abs(totals - totals[0]))
    print(f"dissipated {final['rmNormDamp']:.4g} + {final['rmFrictDissip']:.4g} J of {totals[0]:.4g} J, "
          f"largest elastic energy {largest:.4g} J, deviation {deviation:.3g} J, bound {bound:.3g} J")
    assert deviation <= bound
