"""Model only what a scene needs (issue 14, doc/speed-vs-error.md): roundedmesh.model_choice.cheapest_model against an
independent pass over the study's data file, the table it reads against that data, its refusals, and the study's
report (roundedmesh_study.speed_vs_error_report) on tiny errors.csv and costs.csv files (no YADE run)."""
import csv
import json
import math
import os
import re
import subprocess
import types

import numpy as np
import pytest

import roundedmesh as rm
from roundedmesh import model_choice
from roundedmesh_study import model_table
from roundedmesh_study import speed_vs_error_report as report

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
TARGETS = (0.005, 0.01, 0.02, 0.05, 0.2, 0.5)


def cheapest_by_hand(entries, error, statistic, partner):
    """The entry the study says is cheapest, found without the helper: every entry meeting the target, then the
    one no other beats (lower cost, or where the shape has no cost fewer nodes, then the regime's cost; then the
    law's default options; then the smaller error)."""
    order = model_table.study_data()["regimes_by_cost"]
    has_costs = any(e["cost_ms_per_step"] is not None for e in entries)

    def error_of(e):
        return e["nrmse"][statistic][partner]
    meeting = [e for e in entries if error_of(e) is not None and error_of(e) <= error
               and (e["cost_ms_per_step"] is not None or not has_costs)]
    best = None
    for e in meeting:
        mine = (([e["cost_ms_per_step"]] if has_costs else [e["nodes"], order.index(e["regime"])])
                + [(e["law_curvature"] != "mean") + (e["normal"] != "pressure"), error_of(e)])
        if best is None or mine < best[0]:
            best = (mine, e)
    return None if best is None else best[1]


SHAPES = ("sphere", "pear", "gummy_bear", "spheroid", "pill", "tetra_grain")


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("statistic", ["median", "worst"])
@pytest.mark.parametrize("partner", ["both", "plane", "self"])
def test_the_choice_meets_the_target_and_nothing_cheaper_does(shape, statistic, partner):
    entries = model_table.study_data()["shapes"][shape]
    for error in TARGETS:
        expected = cheapest_by_hand(entries, error, statistic, partner)
        if expected is None:
            with pytest.raises(ValueError, match=shape):
                rm.cheapest_model(shape, error, partner, statistic)
            continue
        choice = rm.cheapest_model(shape, error, partner, statistic)
        assert choice.nrmse <= error
        assert (choice.nodes, choice.curvature, *choice.engine_options.values()) == (
            expected["nodes"], expected["curvature"], expected["regime"], expected["law_curvature"],
            expected["normal"])
        assert choice.cost_ms_per_step == expected["cost_ms_per_step"]
        assert "doc/speed-vs-error.md" in choice.study


def test_the_shapes_with_s1_costs_are_ranked_by_them_and_the_others_by_nodes():
    data = model_table.study_data()
    for shape in SHAPES:
        timed = any(e["cost_ms_per_step"] is not None for e in data["shapes"][shape])
        assert rm.cheapest_model(shape, 0.2).ranked_by == ("S1 cost" if timed else "nodes")
    assert rm.cheapest_model("gummy_bear", 0.2).ranked_by == "S1 cost"


def test_a_looser_target_is_never_dearer():
    costs = [rm.cheapest_model("gummy_bear", e).cost_ms_per_step for e in (0.01, 0.05, 0.2)]
    assert costs == sorted(costs, reverse=True)


def test_refusals_name_the_shape_and_the_target():
    with pytest.raises(ValueError, match="'cube' is not in the speed-against-error study"):
        rm.cheapest_model("cube", 0.05)
    with pytest.raises(ValueError, match="meets 1e-06 NRMSE .*'gummy_bear'"):
        rm.cheapest_model("gummy_bear", 1e-6)
    with pytest.raises(ValueError, match="not a fraction"):
        rm.cheapest_model("gummy_bear", 5)           # 5 % is 0.05
    with pytest.raises(ValueError, match="pose_statistic"):
        rm.cheapest_model("gummy_bear", 0.05, pose_statistic="mean")
    with pytest.raises(ValueError, match="partner"):
        rm.cheapest_model("gummy_bear", 0.05, partner="wall")
    with pytest.raises(TypeError, match="a study shape's name or a roundedmesh.Mesh"):
        rm.cheapest_model(3, 0.05)


def test_the_choice_builds_its_mesh():
    choice = rm.cheapest_model("sphere", 0.02)
    mesh = choice.mesh()
    assert abs(len(mesh.vertices) - choice.nodes) <= 0.02 * choice.nodes


def _same_table(shipped, computed, where="table"):
    """Equal structure, names and counts; the fitted numbers equal to 1e-9 relative. The fits are least squares through
    numpy's LAPACK, whose kernels differ between processors (AVX2, AVX-512) in the last bits: 2e-15 relative seen on
    the cost fits' slopes. A table out of date with the study's data differs in the leading digits."""
    if isinstance(shipped, dict):
        assert isinstance(computed, dict) and shipped.keys() == computed.keys(), where
        for key in shipped:
            _same_table(shipped[key], computed[key], f"{where}[{key!r}]")
    elif isinstance(shipped, list):
        assert isinstance(computed, list) and len(shipped) == len(computed), where
        for k, (a, b) in enumerate(zip(shipped, computed)):
            _same_table(a, b, f"{where}[{k}]")
    elif isinstance(shipped, float):
        assert computed == pytest.approx(shipped, rel=1e-9, abs=1e-300), where
    else:
        assert shipped == computed, where


def test_the_table_is_what_the_study_data_gives():
    # py/roundedmesh/model_table.json, which the library reads, is roundedmesh_study.model_table's table of the
    # study's speed_vs_error.json: rewrite it with write_model_table() after the study's data changes
    _same_table(model_choice.model_table(), model_table.model_table())


@pytest.mark.parametrize("shape, nodes, curvature", [("sphere", 162, "prescribed"), ("pear", 150, "computed"),
                                                     ("spheroid", 150, "prescribed"), ("pill", 150, "computed"),
                                                     ("tetra_grain", 150, "computed")])
def test_the_table_builds_the_mesh_the_study_measured(shape, nodes, curvature):
    from roundedmesh_study.shape_error import rounded_mesh
    study = rounded_mesh(shape, nodes, curvature).mesh
    library = model_choice.shape_mesh(model_choice.model_table()["shapes"][shape]["generator"], nodes, curvature)
    for quantity in ("vertices", "triangles", "principal_curvatures"):
        assert np.array_equal(np.array(getattr(library, quantity)), np.array(getattr(study, quantity))), quantity


# --- any mesh: the fits ------------------------------------------------------------------------------------

def power_law_data(alpha=1.5, scale=0.5):
    """A study of one shape 'blob' whose error is exactly scale q^alpha at four node counts, q = 0.2 sqrt(600 / N),
    for the law's defaults; nothing else. The fit must recover it with no scatter."""
    entries, resolution = [], {}
    for nodes in (300, 600, 1200, 2400):
        q = 0.2 * (600 / nodes) ** 0.5
        resolution[str(nodes)] = {"median": q, "worst": 2 * q}
        value = {p: scale * q ** alpha for p in model_choice.PARTNERS}
        entries.append({"nodes": nodes, "curvature": "computed", "regime": "auto", "law_curvature": "mean",
                        "normal": "pressure", "nrmse": {"median": value, "worst": {p: 2 * v for p, v in value.items()}},
                        "cost_ms_per_step": None, "cost_from": None})
    return {"study": "fixture", "regimes_by_cost": ["auto"], "shapes": {"blob": entries},
            "resolution": {"blob": resolution}}


def test_the_fit_recovers_an_exact_power_law():
    fit = model_table.error_fits(power_law_data())[(("computed", "auto", "mean", "pressure"), "median", "both")]
    assert (fit.alpha, math.exp(fit.log_c)) == (pytest.approx(1.5, rel=1e-9), pytest.approx(0.5, rel=1e-9))
    assert fit.sigma < 1e-9 and fit.points == 4


def test_a_fine_mesh_is_remeshed_to_the_nodes_the_target_needs():
    # The 2562-node icosphere has q0 (mesh_resolution); with the fixture's law the target is met at
    # N = 2562 (q0 / q*)^2, q* = (target / 0.5)^(1 / 1.5). Choose the target for N = 642: the choice asks for that
    # count (to one node: rounding up) and remeshes to it (within 10 %, Mesh.remeshed).
    mesh = rm.Mesh.icosphere(0.025, 4, curvature="computed")
    q0 = model_choice.mesh_resolution(mesh)["median"]
    target = 0.5 * (q0 * math.sqrt(2562 / 642)) ** 1.5
    choice = rm.cheapest_model(mesh, target, table=model_table.model_table(power_law_data()))
    assert choice.ranked_by == "fit"
    assert abs(choice.nodes - 642) <= 1
    assert choice.nrmse == pytest.approx(target, rel=1e-3)
    assert abs(len(choice.mesh().vertices) / 642 - 1) < 0.1
    assert choice.engine_options == {"regime": "auto", "curvature": "mean", "normal": "pressure"}


def test_a_mesh_too_coarse_for_the_target_is_refused_with_the_nodes_it_needs():
    mesh = rm.Mesh.icosphere(0.025, 2, curvature="computed")     # 162 nodes
    q0 = model_choice.mesh_resolution(mesh)["median"]
    target = 0.5 * (q0 * math.sqrt(162 / 1000)) ** 1.5            # needs 1000 nodes
    with pytest.raises(ValueError, match="needs about 100[01] nodes of the same shape") as refusal:
        rm.cheapest_model(mesh, target, table=model_table.model_table(power_law_data()))
    given = float(str(refusal.value).split("this mesh: ")[1].split(")")[0])
    assert given == pytest.approx(0.5 * q0 ** 1.5, rel=1e-3)      # what this mesh gives (to the message's 3 digits)


YADE_HORSE = "/usr/share/doc/yade/examples/gts-horse/horse.coarse.gts"   # Debian's yade package installs it


def test_yade_horse_gets_a_model_meeting_the_target_or_a_refusal_naming_the_nodes():
    # issue 36: YADE's GTS horse at 56 mm, prepared by Mesh.load, was given a 16,369-node model predicted at 113 %
    # for 20 % (8,380 nodes at 50 %); every answer now meets its target or refuses, naming the nodes needed
    if not os.path.exists(YADE_HORSE):
        pytest.skip(f"{YADE_HORSE} is not installed (Debian's yade package installs YADE's examples)")
    extent = np.ptp(np.asarray(rm.Mesh.load(YADE_HORSE, tolerance=None).vertices), axis=0).max()
    with pytest.warns(RuntimeWarning, match="remeshed"):
        horse = rm.Mesh.load(YADE_HORSE, scale=0.056 / extent)
    for target in (0.05, 0.2, 0.5):
        try:
            choice = rm.cheapest_model(horse, target)
        except ValueError as refusal:
            assert re.search(r"needs about \d+ nodes", str(refusal)), refusal
        else:
            assert choice.nrmse <= target


def test_mesh_resolution_is_the_angle_a_triangle_spans():
    # On a sphere of radius R the estimated principal curvatures are 1/R (to the estimate's error, a few % on an
    # icosphere), so each triangle's q is its longest edge over R: the median lies between the shortest and the
    # longest edge of the mesh over R, 5 % allowed for the estimate. Subdividing halves every edge: q halves from
    # 162 to 642 nodes, to the same 5 %.
    q = []
    for subdivisions in (2, 3):
        mesh = rm.Mesh.icosphere(0.025, subdivisions, curvature="computed")
        corners = np.array(mesh.vertices)[np.array(mesh.triangles)]
        edges = np.linalg.norm(corners - np.roll(corners, 1, axis=1), axis=2)
        q.append(model_choice.mesh_resolution(mesh)["median"])
        assert 0.95 * edges.min() / 0.025 <= q[-1] <= 1.05 * edges.max() / 0.025
    assert q[0] / q[1] == pytest.approx(2, rel=0.05)


def test_add_body_with_an_error_gets_the_chosen_mesh_and_warns_of_other_engine_options(monkeypatch):
    from yade import O
    table = model_table.model_table(power_law_data())
    monkeypatch.setattr(model_choice, "model_table", lambda path=None: table)
    mesh = rm.Mesh.icosphere(0.025, 4, curvature="computed")
    q0 = model_choice.mesh_resolution(mesh)["median"]
    target = 0.5 * (q0 * math.sqrt(2562 / 642)) ** 1.5
    O.reset()
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=1000)
    O.engines = [rm.engine(regime="direct")]
    with pytest.warns(UserWarning, match="measured with rm.engine options"):
        body = rm.add_body(mesh, (0, 0, 0), material=rubber, error=target)
    assert abs(len(rm.rounded_bodies()[body].vertices) / 642 - 1) < 0.1
    count = len(O.bodies)
    with pytest.raises(ValueError, match="not a fraction"):
        rm.add_body(mesh, (0, 0, 0.1), material=rubber, error=5)
    assert len(O.bodies) == count      # bad input leaves the scene as it was


ERRORS = [  # shape, family, configuration, size, plane median, plane worst, copy median, copy worst [%]
    ("sphere", "roundedmesh", "curvature computed, auto", 42, 0.5, 1.0, 0.6, 1.2),
    ("sphere", "roundedmesh", "curvature computed, auto", 162, 0.1, 0.3, 0.2, 0.4),
    ("sphere", "clumps", "sphere", 1, 0.0, 0.0, 0.0, 0.0),
    ("gummy_bear", "roundedmesh", "curvature computed, auto", 150, 50.0, 53.0, 51.0, 53.1),
    ("gummy_bear", "roundedmesh", "curvature computed, auto", 300, 8.0, 30.0, 9.0, 40.0),
    ("gummy_bear", "roundedmesh", "curvature computed, auto", 1100, 0.8, 6.0, 0.9, 4.0),
    ("gummy_bear", "roundedmesh", "curvature computed, quadrature", 300, 7.0, 30.0, 8.5, 40.0),
    ("gummy_bear", "roundedmesh", "curvature computed, exact", 300, 6.0, 20.0, 6.5, 25.0),
    ("gummy_bear", "roundedmesh", "curvature prescribed, auto", 300, 3.0, 20.0, 4.0, 25.0),
    ("gummy_bear", "roundedmesh", "curvature prescribed, auto, principal", 300, 3.5, 20.0, 3.8, 22.0),
    ("gummy_bear", "clumps", "clump", 20, 15.6, 15.6, 1e-6, 53.1),
    ("gummy_bear", "level_sets", "level set, grid 1 mm", 2047, 24.0, 53.0, 42.0, 68.0),
    ("pear", "roundedmesh", "curvature computed, auto", 150, 0.6, 15.0, 1.0, 14.0),
    ("pear", "roundedmesh", "curvature computed, direct", 150, 0.07, 14.0, 0.9, 13.0),
    ("pear", "roundedmesh", "curvature prescribed, auto, principal, energy", 300, 0.1, 1.0, 0.2, 2.0),
    ("pear", "clumps", "clump", 2, 20.0, 30.0, 25.0, 40.0),
    ("spheroid", "roundedmesh", "curvature computed, auto", 300, 4.0, 10.0, 6.0, 12.0),
    ("spheroid", "roundedmesh", "curvature computed, auto", 600, 1.0, 5.0, 2.0, 6.0),
    ("spheroid", "roundedmesh", "curvature computed, quadrature", 600, 0.9, 5.0, 1.9, 6.0),
    ("spheroid", "roundedmesh", "curvature prescribed, auto", 300, 0.5, 3.0, 0.8, 4.0),
    ("spheroid", "clumps", "clump", 40, 3.0, 8.0, 4.0, 9.0),
]
# the bear's costs.csv, written before the 'shape' column: (configuration, size, CPU ms per step)
COSTS = [("curvature computed, auto", 300, 20.0), ("curvature computed, auto", 1100, 50.0),
         ("curvature computed, quadrature", 300, 22.0), ("clump", 20, 6.0), ("level set, grid 1 mm", 2047, 40.0)]
# the grains' costs.csv, another folder, with the 'shape' column: (shape, configuration, size, CPU ms per step)
GRAIN_COSTS = [("spheroid", "curvature computed, auto", 300, 15.0), ("spheroid", "curvature computed, auto", 600, 25.0),
               ("spheroid", "clump", 40, 30.0)]
COST_COLUMNS = ["configuration", "size", "median_wall_ms", "median_cpu_ms", "contacts", "machine"]


def write_errors(path, shapes):
    """errors.csv of the ERRORS rows of `shapes`, with the columns (those the report reads) speed_vs_error.py writes."""
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["shape", "family", "configuration", "nodes or spheres", "partner", "NRMSE median [%]",
                         "NRMSE worst [%]"])
        for shape, family, configuration, size, plane_median, plane_worst, copy_median, copy_worst in ERRORS:
            if shape in shapes:
                writer.writerow([shape, family, configuration, size, "plane", plane_median, plane_worst])
                writer.writerow([shape, family, configuration, size, "self", copy_median, copy_worst])


def write_fixtures(folder):
    """errors.csv of every shape and the bear's costs.csv in `folder`; the grains' costs.csv in folder/grains."""
    write_errors(folder / "errors.csv", {row[0] for row in ERRORS})
    with open(folder / "costs.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(COST_COLUMNS)
        for configuration, size, cpu in COSTS:
            writer.writerow([configuration, size, cpu * 1.1, cpu, 100, "fixture"])
    (folder / "grains").mkdir()
    with open(folder / "grains" / "costs.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["shape"] + COST_COLUMNS)
        for shape, configuration, size, cpu in GRAIN_COSTS:
            writer.writerow([shape, configuration, size, cpu * 1.1, cpu, 100, "grain fixture"])


def test_the_report_reads_the_roundedmesh_labels():
    assert report.parse_configuration("curvature computed, exact") == ("computed", "exact", "mean", "pressure")
    assert (report.parse_configuration("curvature prescribed, auto, principal, energy")
            == ("prescribed", "auto", "principal", "energy"))
    assert report.parse_configuration("curvature computed, auto, energy") == ("computed", "auto", "mean", "energy")
    for wrong in ("clump", "curvature computed", "curvature computed, auto, energy, principal",
                  "curvature computed, auto, ellipse"):
        with pytest.raises(ValueError, match="not a roundedmesh label"):
            report.parse_configuration(wrong)
    timed = {"curvature computed, auto", "curvature computed, direct", "clump"}
    assert report.timed_as("roundedmesh", "curvature prescribed, direct", timed) == "curvature computed, direct"
    assert report.timed_as("roundedmesh", "curvature prescribed, exact, principal", timed) == "curvature computed, auto"
    assert report.timed_as("roundedmesh", "curvature computed, auto", {"clump"}) is None
    assert report.timed_as("clumps", "clump", timed) == "clump"
    assert report.timed_as("level_sets", "level set, grid 1 mm", timed) is None


def test_the_report_joins_errors_and_costs(tmp_path, monkeypatch, capsys):
    # meshes are not built: the resolution of the N-node mesh of a shape is read as N / 1000 (median), N / 500 (worst)
    import roundedmesh_study.shape_error as se
    monkeypatch.setattr(se, "rounded_mesh", lambda shape, nodes: types.SimpleNamespace(mesh=(shape, nodes)))
    monkeypatch.setattr(model_choice, "mesh_resolution", lambda mesh: {"median": mesh[1] / 1000,
                                                                       "worst": mesh[1] / 500}, raising=False)
    write_fixtures(tmp_path)
    report.main(["--input", str(tmp_path), "--output", str(tmp_path / "report"), "--costs",
                 str(tmp_path / "costs.csv"), str(tmp_path / "grains" / "costs.csv"), str(tmp_path / "none.csv")])
    assert "no costs file " + str(tmp_path / "none.csv") in capsys.readouterr().err   # named, and skipped
    out = tmp_path / "report"
    # Pareto table and plot for the shapes with costs only: the bear (costs.csv) and the spheroid (the grains')
    assert sorted(p.name for p in out.glob("pareto_*")) == [f"pareto_{s}.{e}" for s in ("gummy_bear", "spheroid")
                                                             for e in ("csv", "md", "png")]
    assert (out / "pareto_gummy_bear.png").stat().st_size > 0
    with open(out / "pareto_gummy_bear.csv", newline="") as f:
        rows = {(r["configuration"], int(r["nodes or spheres"])): r for r in csv.DictReader(f)}
    assert len(rows) == 9                                   # the gummy bear's configurations only
    prescribed = rows[("curvature prescribed, auto", 300)]
    assert float(prescribed["CPU ms per step"]) == 20.0     # costs as the computed mesh of its nodes and regime
    assert prescribed["cost"] == "as 'curvature computed, auto'"
    assert float(prescribed["NRMSE median, worse partner [%]"]) == 4.0
    assert rows[("curvature computed, quadrature", 300)]["cost"] == "measured"
    assert float(rows[("curvature computed, quadrature", 300)]["CPU ms per step"]) == 22.0
    assert float(rows[("curvature computed, exact", 300)]["CPU ms per step"]) == 20.0    # not timed: as 'auto'
    assert rows[("curvature computed, auto", 150)]["CPU ms per step"] == ""       # no cost: in the table only
    # median front by cost: clump 6 ms (15.6 %), prescribed principal 300 20 ms (3.8 %), computed 1100 50 ms (0.9 %)
    front = {key for key, r in rows.items() if r["on the front (median)"] == "yes"}
    assert front == {("clump", 20), ("curvature prescribed, auto, principal", 300), ("curvature computed, auto", 1100)}
    with open(out / "pareto_spheroid.csv", newline="") as f:
        spheroid = {(r["configuration"], int(r["nodes or spheres"])): r for r in csv.DictReader(f)}
    assert float(spheroid[("curvature computed, quadrature", 600)]["CPU ms per step"]) == 25.0  # regime not timed

    guide = (out / "guide.md").read_text()
    assert "roundedmesh / clump = 3.33" in guide            # 20 ms / 6 ms, bear on bear at 5 %
    assert "No level set reaches 5 %" in guide
    assert "## pear (no S1 cost: ranked by nodes)" in guide
    assert "roundedmesh / clump = 0.50 (faster: 2.00 times)" in guide             # spheroid: 15 ms / 30 ms
    lines = [line for line in (out / "guide_summary.md").read_text().splitlines() if line.startswith("| ")]
    table = {cells[0]: cells for cells in ([c.strip() for c in line.strip("|").split("|")] for line in lines[1:])}
    assert list(table) == ["sphere", "pear", "gummy bear", "spheroid"]   # one row per shape, the study's order
    assert table["gummy bear"][1] == "S1 cost" and table["pear"][1] == "nodes"
    assert table["gummy bear"][3].startswith("roundedmesh, curvature prescribed, auto, principal, 300 nodes: 3.8 %")
    assert table["gummy bear"][5] == "none (best: 15.6 %)"  # the clump at 5 %
    assert table["pear"][2].startswith("roundedmesh, curvature computed, auto, 150 nodes: 1 %")   # fewest, 'auto'
    assert table["pear"][6] == "none in the study"          # no level set of the pear
    assert table["spheroid"][5].startswith("clump of 40 spheres: 4 %")

    with open(out / "speed_vs_error.json") as f:
        data = json.load(f)
    assert set(data) == {"study", "error", "cost", "machine", "regimes_by_cost", "shapes", "resolution"}
    assert data["machine"] == "fixture; grain fixture"
    assert data["regimes_by_cost"] == ["auto", "quadrature", "direct", "exact"]   # measured, then by name
    # roundedmesh only, every configuration of every shape
    assert {shape: len(entries) for shape, entries in data["shapes"].items()} == {
        "sphere": 2, "pear": 3, "gummy_bear": 7, "spheroid": 4}
    entry = next(e for e in data["shapes"]["gummy_bear"] if e["law_curvature"] == "principal")
    assert entry == {"nodes": 300, "curvature": "prescribed", "regime": "auto", "law_curvature": "principal",
                     "normal": "pressure", "nrmse": {"median": {"plane": 0.035, "self": 0.038, "both": 0.038},
                                                     "worst": {"plane": 0.2, "self": 0.22, "both": 0.22}},
                     "cost_ms_per_step": 20.0, "cost_from": "curvature computed, auto"}
    energy = next(e for e in data["shapes"]["pear"] if e["normal"] == "energy")
    assert (energy["curvature"], energy["law_curvature"], energy["cost_ms_per_step"], energy["cost_from"]) == (
        "prescribed", "principal", None, None)
    assert data["resolution"]["gummy_bear"] == {str(n): {"median": n / 1000, "worst": n / 500}
                                                for n in (150, 300, 1100)}
    assert {shape: sorted(map(int, nodes)) for shape, nodes in data["resolution"].items()} == {
        "sphere": [42, 162], "pear": [150, 300], "gummy_bear": [150, 300, 1100], "spheroid": [300, 600]}


def test_the_study_script_hands_its_folder_to_the_report(tmp_path):
    # the sphere has no level sets: no part runs, and --report reads the errors.csv left in the folder; without a
    # costs.csv the report names it and ranks by nodes. The sphere's meshes (icospheres) are quick to build for the
    # resolution.
    write_errors(tmp_path / "errors.csv", {"sphere"})
    script = os.path.join(ROOT, "scripts", "studies", "speed_vs_error.py")
    out = subprocess.run(["/usr/bin/python3", script, "--shapes", "sphere", "--families", "level_sets", "--report",
                          "--output", str(tmp_path)], capture_output=True, text=True, env=os.environ)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "no costs file" in out.stderr
    assert "Which model does my scene need" in (tmp_path / "guide.md").read_text()
    assert "| sphere | nodes |" in (tmp_path / "guide_summary.md").read_text()
    with open(tmp_path / "speed_vs_error.json") as f:
        data = json.load(f)
    assert set(data["resolution"]["sphere"]) == {"42", "162"}
    assert data["machine"] is None


def test_the_check_measures_the_choice_for_a_mesh_as_the_study_measures_its_own():
    # roundedmesh_study.model_check (scripts/studies/model_choice_check.py) on the sphere at 3 poses: the choice for the 2562-node icosphere given as
    # a plain Mesh is remeshed onto the sphere and pressed like the study's meshes; a remeshed sphere of 150 nodes or
    # more is within 1 % of Hertz (the study's icospheres: 0.3 % from 162 nodes), so 5 % is met, and the row names
    # the cheapest measured configuration with its cost ratio.
    from roundedmesh_study.model_check import check
    from roundedmesh_study.validation import pair_poses
    row = check("sphere", 0.05, list(pair_poses(3, seed=1)), "median", model_choice.model_table())
    assert row["met"] and row["measured [%]"] < 1.0
    assert row["cheapest measured"].startswith("42 nodes") and row["cost ratio"] > 0


def test_remeshed_nodes_are_moved_onto_the_sampled_surface():
    # Mesh.remeshed leaves the 642 new nodes on the 2562-node icosphere's flat triangles, up to its sagitta inside the
    # sphere; the order-2 moving least squares over the old nodes puts them back on the sphere to the quadric's error,
    # O(h^3 / R^2) with h the old mesh's longest edge (1.7 mm here: 1.3e-5 m), and far closer than the sagitta.
    source = rm.Mesh.icosphere(0.025, 4, curvature="computed")
    coarse = source.remeshed(642)

    def input_frame(m):
        return np.array(m.vertices) @ np.array(m.orientation.toRotationMatrix()).T + np.array(m.centroid)
    corners = np.array(source.vertices)[np.array(source.triangles)]
    h = np.linalg.norm(corners - np.roll(corners, 1, axis=1), axis=2).max()
    before = np.abs(np.linalg.norm(input_frame(coarse), axis=1) - 0.025).max()
    after = np.abs(np.linalg.norm(model_choice.on_sampled_surface(input_frame(source), input_frame(coarse)),
                                  axis=1) - 0.025).max()
    assert after < h ** 3 / 0.025 ** 2 and after < before / 10
