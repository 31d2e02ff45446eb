"""Analytic spheres pressed into the gummy bear's concave grooves (neck, belly) against Hertz's elliptical solution
with the smooth shape's principal curvatures: scripts/validation/validate_concave_contact.py in its quick form (6
overlaps to 0.1 r) on both of its meshes (563 and 2000 nodes), for both curvature models, 'mean' (the engine's
default) and 'principal', and both curvature sources of the mesh, 'computed' (estimated from the mesh, the paper's)
and 'exact' (the smooth shape's, Mesh.reference_shape(..., curvature='exact')); the functions are the script's. Both
materials E = 1 MPa, nu = 0.4. About 15 s.

The target: |F_model / F_hertz - 1| <= 10 % at delta = 0.1 r wherever Hertz holds (1/r + k1 > 0: the belly groove
for r = 2 and 10 mm). curvature='principal' meets it with the exact curvatures on 2000 nodes and at 10 mm on 563
(test_principal_exact_within_10_percent), and with the computed ones on 2000 nodes
(test_principal_within_10_percent); the cases missed are xfail(strict) with the measured values; when they pass
they must become plain tests. Where Hertz does not hold (the neck, the belly with r = 25 mm) only that the
principal model's force is finite and does not decrease over the quick sweep is asserted
(test_principal_where_hertz_does_not_hold).
"""
import numpy as np
import pytest

from roundedmesh_study import concave_contact as concave

# The target. Its budget on the 2000-node mesh, where the principal model meets it (F/F_hertz = 1.033 at
# r = 2 mm, 1.035 at 10 mm): the force starts 0.006 mm before the sphere reaches the smooth surface (the caps,
# from the mesh's estimate of k1, sit a little above the groove), which alone gives (1 + 0.0055 / 0.2)^1.5 = +4 % at
# r = 2 mm and +1 % at 10 mm; the mesh's estimate k1 = -33.2 1/m against the smooth shape's -40.4 moves Hertz's
# force by -0.4 % (2 mm) and -2.9 % (10 mm); and the reference is itself approximate at r = 10 mm: its contact
# ellipse reaches 4.3 mm across the groove, as wide as the concave strip (k1 < 0 within 3.9 mm of the groove line,
# k1 = -40.2 1/m only at its middle), while at r = 2 mm (0.66 mm) k1 is within 3 % of its middle value.
#
# With the exact curvatures (the smooth shape's k1 = -40.2 1/m at the belly's groove point, -39.5 at the nearest
# triangle of 563 nodes, -40.3 of 2000) the curvature error is gone, and what remains is the discretisation: the
# caps are quadrics about each triangle, so the force still starts before the sphere reaches the smooth groove,
# by 0.0014 to 0.0018 mm on 2000 nodes (F/F_hertz = 1.009 at 2 mm, 0.980 at 10 mm; NRMSE 0.8 and 1.2 %) and by
# 0.017 to 0.023 mm on 563 nodes ((1 + 0.017 / 0.2)^1.5 = 1.13: F/F_hertz = 1.109 at 2 mm, 0.958 at 10 mm), and the
# force is a sum over few triangle pairs where the contact is small against the triangles (at 2 mm its semi-axis,
# 0.66 mm, is a fifth of the 563-node mesh's 3 mm circumradius). On 563 nodes that makes the 2 mm case depend on
# where the sphere lands on the triangles: meshes of 542 to 581 nodes give F/F_hertz from 0.76 to 1.22 at 2 mm and
# 0.95 to 1.02 at 10 mm. The 10 % is the target, not a fit to these values.
TOLERANCE = 0.10
FINE = 2000            # node count of the script's finer mesh (the paper's, 563 nodes, is None in MESHES)
PAPER = 563            # the paper's node count (554) as meshed


@pytest.fixture(scope="module")
def sweep():
    grooves, frames, cases = concave.run(quick=True, curvature=concave.CURVATURES, meshes=concave.MESHES,
                                         mesh_curvature=concave.MESH_CURVATURES)
    concave.report_grooves(grooves, frames)
    concave.report_cases(cases)
    return ({g["name"]: g for g in grooves}, frames,
            {(c["curvature"], c["mesh_curvature"], c["groove"], round(c["radius"] * 1e3), c["nodes"]): c
             for c in cases})


def test_groove_points(sweep):
    """The grooves are where the script's docstring puts them: the neck's k1 of about -33.8 per shape unit (a
    1.3 mm radius) against k2 = +5.1; the belly's k1 = -1.79 per unit (25 mm) and k2 = 0, at x = 0 on the front."""
    grooves, _, _ = sweep
    neck, belly = grooves["neck"], grooves["belly"]
    assert neck["curvatures"][0] == pytest.approx(-33.77, rel=2e-3)
    assert neck["curvatures"][1] > 0
    assert 0.44 < neck["point"][2] < 0.52 and neck["point"][1] > 0
    assert belly["curvatures"][0] == pytest.approx(-1.794, rel=1e-3)
    assert abs(belly["curvatures"][1]) < 1e-3
    assert abs(belly["point"][0]) < 1e-4 and belly["normal"][1] > 0.999


def test_groove_in_the_body_frame(sweep):
    """The groove moved into the mesh's principal frame is on peers.shape_distance's surface with the same normal
    and curvatures, and within the sagitta of the nearest triangle's span (rho^2 |k| / 2: flat triangles bridge a
    groove) of the mesh."""
    _, frames, _ = sweep
    for frame in frames.values():
        assert abs(frame["f"]) < 1e-12
        assert frame["normal_check"] < 1e-6
        assert frame["curvature_check"] < 1e-4
        assert frame["mesh_distance"] <= frame["sagitta"]


def test_where_hertz_holds(sweep):
    """Hertz holds (both 1/r + k_i > 0) only for the 2 and 10 mm spheres in the belly groove: the neck's concave
    radius is 1.3 mm and the belly's 24.9 mm (so 1/r + k1 = -0.2 1/m at r = 25 mm)."""
    _, _, cases = sweep
    holds = {key[2:4] for key, c in cases.items() if "skipped" not in c}
    assert holds == {("belly", 2), ("belly", 10)}


def _check(case):
    print(f"{case['curvature']}, mesh curvature {case['mesh_curvature']}, {case['groove']}, r = {case['radius'] * 1e3:g} mm, {case['nodes']} nodes: "
          f"F/F_hertz = {case['ratio']:.4f}, NRMSE {100 * case['nrmse']:.2f} %, touch {case['touch'] * 1e3:.4f} mm")
    assert abs(case["ratio"] - 1) <= TOLERANCE


@pytest.mark.parametrize("radius", [2, 10], ids=lambda r: f"belly-{r}mm")
def test_principal_within_10_percent(sweep, radius):
    """curvature='principal' with the computed curvatures on the 2000-node mesh: within the target (TOLERANCE
    says why 10 %)."""
    _, _, cases = sweep
    _check(cases["principal", "computed", "belly", radius, FINE])


# The 2 mm sphere on 563 nodes misses by 0.009: F/F_hertz = 1.109 (TOLERANCE says why).
EXACT = [pytest.param(2, PAPER, id="belly-2mm-563nodes", marks=pytest.mark.xfail(
             strict=True, reason="F/F_hertz = 1.109, NRMSE 8.4 %, force from delta = -0.017 mm: discretisation")),
         pytest.param(10, PAPER, id="belly-10mm-563nodes"),
         pytest.param(2, FINE, id="belly-2mm-2000nodes"),
         pytest.param(10, FINE, id="belly-10mm-2000nodes")]


@pytest.mark.parametrize("radius, nodes", EXACT)
def test_principal_exact_within_10_percent(sweep, radius, nodes):
    """curvature='principal' with the mesh's curvatures the smooth shape's (curvature='exact'): within the target
    on the paper's node count and on 2000 nodes (TOLERANCE says why 10 % and what remains)."""
    _, _, cases = sweep
    _check(cases["principal", "exact", "belly", radius, nodes])


# Measured at delta = 0.1 r (the full script's NRMSE over 21 overlaps). 'mean': concave triangles are taken as flat
# (R = max_radius) whatever the mesh's curvature source, and their faces bridge the groove, 0.10 mm (563 nodes) and
# 0.025 mm (2000 nodes) outside the smooth surface, so the force starts that much early. 'principal' with the
# computed curvatures on 563 nodes: the estimate from the mesh sees 20 % of the groove's curvature
# (Mesh.principal_curvatures gives k1 = -8.0 1/m at the groove point against -40.2) because the triangles
# (circumradius 3 mm) are as wide as the groove's concave strip (7.8 mm: k1 < 0 within 3.9 mm of the groove line),
# so the caps sit only 0.02 mm below the facets and the force still starts 0.085 mm early.
MEASURED = {
    ("mean", "computed", "belly", 2, PAPER): "F/F_hertz = 1.80, NRMSE 63 %, force from delta = -0.104 mm",
    ("mean", "computed", "belly", 10, PAPER): "F/F_hertz = 1.11, NRMSE 7.3 %, force from delta = -0.105 mm",
    ("mean", "computed", "belly", 2, FINE): "F/F_hertz = 1.16, NRMSE 12 %, force from delta = -0.025 mm",
    ("mean", "computed", "belly", 10, FINE): "F/F_hertz = 1.13, NRMSE 8.0 %, force from delta = -0.026 mm",
    ("mean", "exact", "belly", 2, PAPER): "F/F_hertz = 1.80, NRMSE 63 %, force from delta = -0.104 mm",
    ("mean", "exact", "belly", 10, PAPER): "F/F_hertz = 1.13, NRMSE 7.9 %, force from delta = -0.105 mm",
    ("mean", "exact", "belly", 2, FINE): "F/F_hertz = 1.16, NRMSE 12 %, force from delta = -0.025 mm",
    ("mean", "exact", "belly", 10, FINE): "F/F_hertz = 1.13, NRMSE 8.0 %, force from delta = -0.026 mm",
    ("principal", "computed", "belly", 2, PAPER): "F/F_hertz = 1.63, NRMSE 49 %, force from delta = -0.085 mm",
    ("principal", "computed", "belly", 10, PAPER): "F/F_hertz = 1.13, NRMSE 7.8 %, force from delta = -0.086 mm",
}


@pytest.mark.parametrize("key", [pytest.param(key, id="-".join(map(str, key[:3])) + f"-{key[3]}mm-{key[4]}nodes",
                                              marks=pytest.mark.xfail(strict=True, reason=why))
                                 for key, why in MEASURED.items()])
def test_force_within_10_percent_of_hertz(sweep, key):
    _, _, cases = sweep
    _check(cases[key])


# Where Hertz does not hold, the script's full run finds the force finite but the principal model's not smooth: pairs
# whose triangle's estimated k makes 1/r + k <= 0 (no Hertz ellipse; the pair's quadric overlap has a saddle)
# still act, and carry 24 to 68 % of the force at r = 25 mm, where it jumps by up to 12 % of F(0.1 r) between
# overlaps 0.0005 r apart; at the neck with r = 2 mm (2000 nodes) it dips by 0.9 % over one such step. Only what
# the brief asks is asserted here, over the quick sweep.
NO_HERTZ = [("neck", 2), ("neck", 10), ("neck", 25), ("belly", 25)]


@pytest.mark.parametrize("source", concave.MESH_CURVATURES)
@pytest.mark.parametrize("nodes", [PAPER, FINE], ids=lambda n: f"{n}nodes")
@pytest.mark.parametrize("groove, radius", NO_HERTZ, ids=[f"{g}-{r}mm" for g, r in NO_HERTZ])
def test_principal_where_hertz_does_not_hold(sweep, groove, radius, nodes, source):
    _, _, cases = sweep
    case = cases["principal", source, groove, radius, nodes]
    assert "skipped" in case
    print(f"{groove}, r = {radius} mm, {nodes} nodes, mesh curvature {source}: F = {np.array2string(case['model'], precision=4)} N")
    assert np.all(np.isfinite(case["model"]))
    assert case["model"][-1] > 0
    assert np.all(np.diff(case["model"]) >= 0)
