"""Body-body contact against Hertz (roundedmesh_study.validation): two meshed spheres and a meshed sphere against an
analytic sphere (S2 pair, R* = R/2), spheroid pairs and cylinders (S5, paper Section 3.2). E* = 0.5 Pa (both
bodies E = 1 Pa, nu = 0), curvature prescribed. The S5 tables are printed (pytest -s); the full figures come
from scripts/validation/validate_body_contact.py. Last, the energy law's force against the paper's law's on smooth
bodies."""
import numpy as np
import pytest

from roundedmesh_study import validation as v

POSES = 6  # the icosphere frames (vertex on vertex, the worst pose measured) and 5 random pairs, seed 1


@pytest.fixture(scope="module")
def sphere_errors():
    """Worst NRMSE over the poses, per (partner, subdivisions)."""
    return {(partner, k): v.sphere_pair(k, partner, poses=POSES).worst
            for partner in ("mesh", "sphere") for k in (2, 3, 4)}


# --- S2 pair ---------------------------------------------------------------------------------------------

# The thresholds, worst over every pose: 3 % at 162 nodes, 1.5 % at 642 (R* = R/2 makes the contact
# circle sqrt(2) smaller than against a plane at the same overlap, hence the looser 642-node bound than S2's 1 %).
@pytest.mark.parametrize("partner", ["mesh", "sphere"])
def test_162_nodes_within_3_percent(sphere_errors, partner):
    assert sphere_errors[partner, 2] <= 0.03


@pytest.mark.parametrize("partner", ["mesh", "sphere"])
def test_642_nodes_within_1_5_percent(sphere_errors, partner):
    assert sphere_errors[partner, 3] <= 0.015


# With prescribed curvature the pressure integral converges to Hertz as the triangles shrink against the
# contact circle, so the worst error falls with each subdivision (162 -> 642 -> 2562 nodes). At 42 nodes every
# pair takes the direct regime, exact for a sphere, so that level is left out.
@pytest.mark.parametrize("partner", ["mesh", "sphere"])
def test_error_decreases_with_refinement(sphere_errors, partner):
    assert sphere_errors[partner, 2] > sphere_errors[partner, 3] > sphere_errors[partner, 4]


# --- S5 spheroids ----------------------------------------------------------------------------------------

# 642 nodes keep the file fast; the script shows the error is mesh-converged there (ratio 2, worst / mean of 3
# poses: 642 nodes 2.12 / 1.68 %, 2562 nodes 1.72 / 1.70 %, 10257 nodes 1.73 / 1.73 %), and
# test_spheroid_error_is_mesh_converged checks 642 against 2562.
SPHEROID_NODES = 642


@pytest.fixture(scope="module")
def spheroids():
    sweeps = {ratio: v.spheroid_pair(ratio, SPHEROID_NODES) for ratio in v.S5_RATIOS}
    print(f"\nS5 spheroid pairs, {SPHEROID_NODES} nodes, 3 poses: NRMSE [%] against exact elliptical Hertz "
          "(over the overlaps within the engine's search limit)")
    print("ratio  worst   mean   F/F_exact at limit   circular Hertz (mean curvature) vs exact")
    for ratio, s in sweeps.items():
        last = np.flatnonzero(s.in_range)[-1]
        print(f"{ratio:5.1f}  {100 * s.errors_in_range.max():5.2f}  {100 * s.errors_in_range.mean():5.2f}"
              f"        {np.mean(s.forces[:, last]) / s.reference[last]:.3f}                {100 * s.model_error:5.2f}")
    return sweeps


# The paper (Fig. 7, Section 3.2) finds the circular-contact model close to elliptical Hertz for a/b < 2.5; the
# issue's bound is 5 % NRMSE up to R_max/R_min = 2 (measured worst: 0.2, 0.6, 2.1 %).
@pytest.mark.parametrize("ratio", [1.0, 1.5, 2.0])
def test_spheroid_pair_close_to_elliptical_hertz(spheroids, ratio):
    assert spheroids[ratio].errors_in_range.max() < 0.05


# Sanity over every ratio, asserting only what holds whatever the model's accuracy: forces finite and positive
# and rising with the overlap. Rising is asserted up to the engine's search limit (DEEPEST_OVERLAP = 0.1 of
# the volume-equivalent radius): deeper, at ratios >= 2.5 where 7.5 % of a exceeds it, the triangle pair search
# drops the deepest pairs and the force can fall (ratio 4, 2562 nodes, one pose) -- reported, not asserted.
def test_spheroid_forces_are_sane(spheroids):
    for ratio, s in spheroids.items():
        assert np.all(np.isfinite(s.forces)) and np.all(s.forces > 0), ratio
        assert s.increasing(in_range_only=True).all(), ratio


# The circular contact cannot follow the contact ellipse, so the error grows with the curvature ratio (paper
# Fig. 7); mean over the poses, which the mesh perturbs by a few tenths of a per cent only.
def test_spheroid_error_grows_with_ratio(spheroids):
    mean = [spheroids[ratio].errors_in_range.mean() for ratio in v.S5_RATIOS]
    assert mean == sorted(mean)


# 642 and 2562 nodes give the same mean error within 0.5 percentage points (measured 0.02 at ratio 2), far below
# the 1.7 % error itself: what remains is the circular-contact model's error, not the mesh's.
def test_spheroid_error_is_mesh_converged(spheroids):
    fine = v.spheroid_pair(2.0, 2562)
    assert abs(fine.errors_in_range.mean() - spheroids[2.0].errors_in_range.mean()) < 0.005


# --- S5 cylinders ----------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def cylinders():
    sweeps = {arrangement: v.cylinder_pair(arrangement, 2562) for arrangement in ("crossed", "parallel")}
    print("\nS5 cylinders, 2562 nodes, 3 poses (R = 1 m, L = 4 m, overlap to 7.5 % of R)")
    for arrangement, s in sweeps.items():
        exponents = [v.power_law_exponent(s.overlaps, f) for f in s.forces]
        line = (f"{arrangement:8s}  NRMSE worst {100 * s.worst:5.2f} %  mean {100 * s.mean:5.2f} %  "
                f"F/F_ref at max {np.mean(s.forces[:, -1]) / s.reference[-1]:.3f}  exponent {np.mean(exponents):.3f}")
        if arrangement == "parallel":
            line += f"  stiffness error {100 * np.mean(s.stiffness_errors()):.1f} % (paper: about 23 %)"
        print(line)
    return sweeps


@pytest.mark.parametrize("arrangement", ["crossed", "parallel"])
def test_cylinder_forces_are_sane(cylinders, arrangement):
    s = cylinders[arrangement]
    assert np.all(np.isfinite(s.forces)) and np.all(s.forces > 0)
    assert s.increasing().all()  # the sweep stays within the search limit (0.075 R < 0.144 R)
    assert s.overlaps[-1] <= s.limit


# F ~ delta^n: a point contact (crossed) has n = 3/2 and a line contact (parallel) n = 1, for Hertz and for the
# model alike (on a fine mesh each pair's circle has radius sqrt(delta R*) across the line and a pressure
# ~ sqrt(delta), so F/L ~ delta). The mesh shifts each pair's overlap by O(h^2/R), which bends the curve at
# small overlaps (measured n = 1.55 crossed, 1.10 parallel); 0.2 is well short of the 0.5 that separates the
# two laws.
@pytest.mark.parametrize("arrangement, exponent", [("crossed", 1.5), ("parallel", 1.0)])
def test_cylinder_force_follows_the_contact_type(cylinders, arrangement, exponent):
    s = cylinders[arrangement]
    for force in s.forces:
        assert abs(v.power_law_exponent(s.overlaps, force) - exponent) < 0.2


# Where a contact has no sharp edge, the energy law's force, the gradient of the contacts' energy, is the paper's
# integrated pressure to within what S's own change does to the gradient: two pears, spheroids (2:1) and pills
# (superellipsoids) pressed along two axes, and two gummy bears side by side, to 0.02 and 0.05 r_eq, within 0.1-2 %
# measured (3 % allowed; doc/validation.md, "Why the paper's law stays the default").
@pytest.mark.parametrize("shape, axes", [("pear", (0, 2)), ("spheroid", (0, 2)), ("pill", (0, 2)),
                                         ("gummy_bear", (0,))])
def test_the_energy_law_pushes_as_the_papers_on_smooth_bodies(shape, axes):
    import math
    import roundedmesh as rm
    from roundedmesh_study import grains
    mesh = (rm.Mesh.reference_shape(shape) if shape in ("pear", "gummy_bear")
            else grains.grain(shape).mesh(grains.REFERENCE_NODES))
    r_eq = (3 * mesh.volume / (4 * math.pi)) ** (1 / 3)
    material = rm.HertzMaterial(young=1e6, poisson=0.4, density=1000)
    for axis in axes:
        forces = {normal: v.pressed_pair(mesh, mesh, np.array([0.02, 0.05]) * r_eq, material, axis=axis, normal=normal)
                  for normal in ("pressure", "energy")}
        assert np.all(forces["pressure"] > 0)
        assert forces["energy"] == pytest.approx(forces["pressure"], rel=0.03)
