"""roundedmesh_study.spin_energy (issue 41): its kinetic energies against 0.5 m v^2 + 0.5 w.L from the angular momentum
YADE keeps, and a case run end to end on two bodies."""
import numpy as np
import pytest
from yade import O
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm
from roundedmesh_study import spin_energy

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)


def test_kinetic_energies_are_those_of_the_momenta():
    mesh = rm.Mesh.spheroid(0.02, 0.01, 200)
    ori = Quaternion(Vector3(1, -2, 0.5).normalized(), 1.1)
    ids = [rm.add_body(mesh, (0, 0, 0), ori, RUBBER), rm.add_body(mesh, (1, 0, 0), ori, RUBBER)]
    state = O.bodies[ids[0]].state
    long_axis = ori * Vector3(*np.eye(3)[int(np.argmin(np.array(state.inertia)))])
    rm.set_velocity(ids[0], vel=(0.3, 0, -0.4), angVel=tuple(40 * long_axis))  # spin about the long axis alone
    rm.set_velocity(ids[1], angVel=(3, -1, 2))
    translational, rotational, axial, fastest = spin_energy.kinetic_energies(ids)
    expected = sum(0.5 * O.bodies[i].state.angVel.dot(O.bodies[i].state.angMom) for i in ids)
    assert translational == pytest.approx(0.5 * state.mass * 0.25, rel=1e-14)
    assert rotational == pytest.approx(expected, rel=1e-12)  # rounding of the rotations only
    first = 0.5 * 40 * long_axis.dot(state.angMom)
    second = O.bodies[ids[1]].state
    spin = np.array(second.ori.conjugate() * second.angVel)
    k = int(np.argmin(np.array(second.inertia)))
    assert axial == pytest.approx(first + 0.5 * second.inertia[k] * spin[k] ** 2, rel=1e-12)
    assert fastest == pytest.approx(40, rel=1e-14)


def test_a_case_runs_and_samples_its_energies():
    poses = [((0.0, 0.0, 0.05), (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 30.0)),
             ((0.0, 0.08, 0.05), (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (5.0, 0.0, 0.0))]
    rows = spin_energy.run_case("energy, at rest", poses, "spheroid", 0.002, **spin_energy.CASES["energy, at rest"])
    assert len(rows) == spin_energy.SAMPLES + 1 and rows[0][3] == 0.0
    assert rows[-1][1] == pytest.approx(0.002, rel=1e-12)
    assert rows[-1][2] > rows[0][2]  # falling under gravity, nothing touching yet


def test_a_spin_keeps_its_energy_under_the_undamped_energy_law():
    """--pair's contact under the conservative law without damping: a spheroid turning about its own axis against
    another keeps its spin's energy (measured: 2e-6 of it in 0.1 s here, at most 6e-5 with the axes parallel or the
    spin reversed; the facets' ripple alone changes it, and 1e-4 leaves room for it)."""
    start, end = spin_energy.spinning_pair("spheroid", "energy", 0.0, 400.0, True, 0.5e-3, 0.02)
    assert start > 1 and end == pytest.approx(start, rel=1e-4)


def test_damping_does_not_feed_a_spin():
    """Eq. 7's damping at the centre of pressure (issue 41) takes energy from a spin. In these 0.02 s the spin lost
    1.16 % of its energy (measured), where the damping at c fed it; undamped it gains 0.046 % (the paper's law's own
    work round the spin), so a loss of 0.5 % or more is the damping's."""
    start, end = spin_energy.spinning_pair("spheroid", "pressure", 0.01, 400.0, True, 0.5e-3, 0.02)
    assert end < (1 - 0.005) * start
