"""rm.engine(timing='stages'): rm.statistics() gives the CPU time of the stages inside the pairs, and the near pairs
scanned; the forces are those of an untimed step, bit for bit."""
import pytest
from yade import ForceResetter, NewtonIntegrator, O
from yade.minieigenHP import Quaternion, Vector3

import roundedmesh as rm

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
STAGES = ("lists_cpu_ms", "near_search_cpu_ms", "narrow_phase_cpu_ms", "law_cpu_ms", "core_cpu_ms")


def two_balls_step(timing):
    """Two icospheres 0.5 mm into each other, one step; their forces and the step's statistics."""
    O.reset()
    mesh = rm.Mesh.icosphere(0.025, 3)
    a = rm.add_body(mesh, pos=(0, 0, 0), material=RUBBER)
    b = rm.add_body(mesh, pos=(0, 0, 0.0495), ori=Quaternion(Vector3(1, 0, 0), 0.3), material=RUBBER)
    O.engines = [ForceResetter(), rm.engine(timing=timing), NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.step()
    return (O.forces.f(a), O.forces.t(a), O.forces.f(b), O.forces.t(b)), rm.statistics()


def test_timed_stages_change_no_force_and_are_measured():
    plain, untimed = two_balls_step("off")
    forces, timed = two_balls_step("stages")
    assert timed["quadrature_contacts"] + timed["direct_contacts"] > 0, "the balls must touch"
    assert forces == plain
    assert all(untimed[stage] == 0 for stage in STAGES)
    assert timed["narrow_phase_cpu_ms"] > 0 and timed["law_cpu_ms"] > 0 and timed["lists_cpu_ms"] > 0
    # The first step builds the near list from the trees and scans it for the candidates.
    assert timed["near_rebuilds"] == 1 and 0 < timed["near_search_cpu_ms"] <= timed["lists_cpu_ms"]
    assert timed["near_pairs_scanned"] >= timed["candidates"] > 0
    assert sum(timed[stage] for stage in STAGES) - timed["near_search_cpu_ms"] <= timed["pairs_ms"] + 0.05


def test_an_unknown_timing_is_refused_by_name():
    with pytest.raises(ValueError, match="timing"):
        rm.engine(timing="all")
