"""Two gummy bears (rm.Mesh.reference_shape("gummy_bear"), E = 1 MPa, nu = 0.4) pressed together in 40 random
orientations (seed 1), as scripts/validation/deep_monotonicity.py does (doc/validation.md, "Deep overlaps"). The
overlap is the approach of the centres along their line from first touch (the largest centre distance with a triangle
pair in contact), in steps of 0.01 r_eq; the force is the second body's, along the approach. "Monotone" means that it
never falls below its largest value so far by more than 1e-9 of that value (round-off).

Within the Hertz range (0.1 r_eq) it is monotone in every orientation. Issue 12 asks the same to 0.5 r_eq in any
orientation: with lists that lose no triangle pair (DeepContactTest) it falls in 31 of 200 orientations (20 by
more than 5 %; 174 before the deep-contact lists), partly where the shapes themselves make less new overlap, mostly
by the triangle-pair law's own doing (doc/physics.md, "Deep overlaps and fast impacts"): marked xfail, strict, until
a contact law derived from a potential of the overlap (issue 12, group 1) makes it pass, or the requirement is
restated for what these shapes allow."""
import functools

import numpy as np
import pytest

import roundedmesh as rm
from roundedmesh_study import deep_monotonicity as deep

ORIENTATIONS = 40
SEED = 1


@functools.lru_cache(maxsize=None)
def sweeps():
    """Per orientation, (F.u, |F|) at overlaps 0, 0.01, ..., 0.5 r_eq."""
    mesh = rm.Mesh.reference_shape("gummy_bear")
    r_eq = (3 * mesh.volume / (4 * np.pi)) ** (1 / 3)
    overlaps = np.arange(51) * 0.01 * r_eq
    result = []
    for q1, q2, u in deep.random_orientations(ORIENTATIONS, SEED):
        _, forces = deep.approach_sweep(mesh, q1, q2, u, overlaps)
        result.append((forces @ u, np.linalg.norm(forces, axis=1)))
    return result


def falls(up_to):
    """[(orientation, worst fall of F.u, of |F|)] of the orientations whose force falls within `up_to` r_eq."""
    last = int(round(up_to / 0.01))
    found = []
    for n, (along, magnitude) in enumerate(sweeps()):
        worst = deep.worst_fall(along[:last + 1])[0], deep.worst_fall(magnitude[:last + 1])[0]
        if max(worst) > 0:
            found.append((n, *worst))
    return found


@pytest.mark.slow
def test_the_force_grows_with_the_overlap_through_the_hertz_range_in_every_orientation():
    assert all(along[-1] > 0 for along, _ in sweeps())  # every pair pushes apart at half a radius
    assert falls(0.1) == []


@pytest.mark.xfail(strict=True, reason="issue 12: the triangle-pair law falls past the Hertz range in some "
                                       "orientations (doc/validation.md, 'Deep overlaps')")
def test_the_force_grows_with_the_overlap_to_half_a_radius_in_every_orientation():
    assert falls(0.5) == []
