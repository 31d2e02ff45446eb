"""Is the contact force conservative? Issue 12, group 1 (doc/validation.md, "Energy: closed loops and collisions").

One cheap case of each of scripts/validation/energy_conservation.py's measurements (the functions are the script's):
  - the work W the contact does on body 2 carried quasi-statically round a closed loop of poses at a fixed overlap
    past first touch, against the energy E stored by pressing it to the loop's start pose. A force with a
    potential does no work on a closed loop;
  - the change of kinetic energy (translation and rotation) of an undamped, frictionless collision in YADE.
S1's particle material without damping or friction; bodies of volume-equivalent radius 25 mm.

The meshed spheres, whose triangle forces all point through one centre, pass, and so do pear collisions in the Hertz
range. The issue's other targets for pears and gummy bears are xfail(strict): the measurements show them missed
today; when the normal force is derived from a potential they pass, and must then become plain tests.
"""
import pytest

from roundedmesh_study import energy_conservation as energy

ISSUE_12 = pytest.mark.xfail(strict=True, reason="issue 12 group 1: the pressure-integral normal force is not derived "
                                                 "from a potential; see doc/validation.md")

# The issue's targets: |W| <= 1 % of the stored energy on a closed loop, |change of kinetic energy| <= 0.5 % in a
# collision at O.dt = dt_c / 50.
LOOP_TARGET = 0.01
COLLISION_TARGET = 0.005


def loop_work(case, segments, jump=energy.JUMP):
    """W / E of the script's loop of seed 1 for `case` at 0.6 mm with `segments` and radial steps of `jump` [m]."""
    ratio = energy.loop_work_over_energy(case, 0.6e-3, 1, segments, jump)
    print(f"{case}, 0.6 mm: W / E = {ratio:+.3g} with {segments} segments")
    return ratio


def collision_change(pair, kind="off-centre", depth=energy.DEPTHS["hertz"], fraction=50):
    row = energy.collide(pair, kind, depth, fraction, seed=1)
    print(f"{pair} {kind}: kinetic energy {row['change']:+.3%}, deepest overlap {row['deepest_overlap_req']:.3f} r_eq")
    return row["change"]


# Two 642-node spheres at 0.6 mm, the shallower and worse of the two overlaps measured: |W| / E is 0.007 to 0.23 %
# over the script's 8 sphere loops (a perfect sphere's is exactly 0; the mesh's comes from how its triangle pairs
# share the contact circle, which changes as the meshes slide). 240 segments (the script uses 720) give -0.223 %
# for this loop, as the script's -0.23 %. The tolerance is the issue's 1 %, four times the worst measured.
def test_meshed_spheres_do_almost_no_work_round_a_closed_loop():
    assert abs(loop_work("sphere-sphere", 240)) <= LOOP_TARGET


# Off-centre with spin, Hertz range, dt_c / 50, seed 1: measured +0.077 % (the worst of the script's 24 sphere
# collisions; the same at dt_c / 200, so the mesh's and not the integration's). The leap-frog alone keeps a shadow
# energy within (omega dt)^2 / 4 = (2 / 50)^2 / 4 = 0.04 % of the true one. Tolerance: the issue's 0.5 %.
def test_meshed_spheres_collide_keeping_their_kinetic_energy():
    assert abs(collision_change("sphere-sphere")) <= COLLISION_TARGET


# Two pears, off-centre with spin, Hertz range, dt_c / 50, seed 1: measured -0.018 %; the worst of the script's
# three seeds -0.08 %. The issue's 0.5 % holds today in the Hertz range (a deep head-on collision gained 4 %).
def test_pears_collide_keeping_their_kinetic_energy():
    assert abs(collision_change("pear-pear")) <= COLLISION_TARGET


# One loop each at 0.6 mm, seed 1, measured by the script (720 segments, radial steps of 50 um; the wall 2880):
# pears -44 %, bears -79 %, bear on pear +438 %, bear on a wall +5.3 % of E. Here a twelfth of the segments and
# radial steps of 200 um keep the test cheap: -44 %, -83 %, +437 %, +5.1 %, still far from the target.
@ISSUE_12
@pytest.mark.parametrize("case, segments", [("pear-pear", 60), ("bear-bear", 60), ("bear-pear", 60),
                                            ("bear-wall", 240)])
def test_non_spherical_bodies_do_no_work_round_a_closed_loop(case, segments):
    assert abs(loop_work(case, segments, jump=4 * energy.JUMP)) <= LOOP_TARGET


# Off-centre with spin, Hertz range, dt_c / 50, seed 1: measured bear-bear +3.2 %, bear-pear -2.3 %, the same to
# 0.01 % at dt_c / 200 (a property of the force, not of the integration).
@ISSUE_12
@pytest.mark.parametrize("pair", ["bear-bear", "bear-pear"])
def test_non_spherical_bodies_collide_keeping_their_kinetic_energy(pair):
    assert abs(collision_change(pair)) <= COLLISION_TARGET


# --- The energy law, rm.engine(normal='energy') (doc/physics.md, "The energy law") ----------------------------------
# Its elastic force is the exact gradient of the contacts' energy (with the facing test of Eq. B.5 made continuous), so
# a loop's work is the quadrature's error alone: each step is halved where halving changes its work by more than its
# share of energy.LOOP_TOLERANCE E = 1e-4 E. The script's 4 loops per case at 720 segments (`--normal energy`): |W| / E
# at most 0.0015 % (two pears, 1.5 mm), 0.0005 % (two bears); seed 1 at 0.6 mm with 120 segments (the wall 480), as
# here: two bears 0.00016 %, bear on pear 0.00034 %, two pears 0.00011 %, bear on a wall 0.00001 %. Tolerance 0.1 % of
# E: ten times the quadrature's tolerance and a tenth of the issue's 1 %; the paper's law misses it by 5 to 440 %.
# Collisions at dt_c / 50, off-centre, Hertz range: two bears -0.002 %, bear on pear -0.001 % (the script's worst of
# every pair and kind, seed 1: -0.025 %); tolerance the issue's 0.5 %.
@pytest.fixture
def energy_law():
    energy.CONTACT_OPTIONS.update(normal="energy")
    yield
    energy.CONTACT_OPTIONS.clear()


@pytest.mark.parametrize("case, segments", [("bear-bear", 120), ("bear-wall", 480),
                                            pytest.param("bear-pear", 120, marks=pytest.mark.slow),
                                            pytest.param("pear-pear", 120, marks=pytest.mark.slow)])
def test_the_energy_law_does_no_work_round_a_closed_loop(energy_law, case, segments):
    assert abs(loop_work(case, segments)) <= 1e-3


@pytest.mark.parametrize("pair", ["bear-bear", "bear-pear"])
def test_the_energy_law_keeps_the_kinetic_energy_of_a_collision(energy_law, pair):
    assert abs(collision_change(pair)) <= COLLISION_TARGET
