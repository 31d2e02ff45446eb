"""Model only what a scene needs (issue 14, doc/speed-vs-error.md): roundedmesh.study.model_choice.cheapest_model
against an independent pass over its data file, its refusals, and scripts/studies/speed_vs_error_report.py on a tiny
pair of errors.csv and costs.csv (no YADE run)."""
import csv
import json
import os
import subprocess

import pytest

import roundedmesh as rm
from roundedmesh.study import model_choice

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
REPORT = os.path.join(ROOT, "scripts", "studies", "speed_vs_error_report.py")
TARGETS = (0.005, 0.01, 0.02, 0.05, 0.2, 0.5)


def cheapest_by_hand(entries, error, statistic):
    """The entry the study says is cheapest, found without the helper: every entry meeting the target, then the
    one no other beats (lower cost, or where the shape has no cost fewer nodes; ties to the smaller error)."""
    key = f"nrmse_{statistic}"
    has_costs = any(e["cost_ms_per_step"] is not None for e in entries)
    meeting = [e for e in entries if e[key] is not None and e[key] <= error
               and (e["cost_ms_per_step"] is not None or not has_costs)]
    best = None
    for e in meeting:
        if best is None:
            best = e
            continue
        if has_costs:
            better = (e["cost_ms_per_step"] < best["cost_ms_per_step"]
                      or (e["cost_ms_per_step"] == best["cost_ms_per_step"] and e[key] < best[key]))
        else:
            order = model_choice.study_data()["regimes_by_cost"]
            mine, theirs = (e["nodes"], order.index(e["regime"])), (best["nodes"], order.index(best["regime"]))
            better = mine < theirs or (mine == theirs and e[key] < best[key])
        best = e if better else best
    return best


@pytest.mark.parametrize("shape", ["sphere", "pear", "gummy_bear"])
@pytest.mark.parametrize("statistic", ["median", "worst"])
def test_the_choice_meets_the_target_and_nothing_cheaper_does(shape, statistic):
    entries = model_choice.study_data()["shapes"][shape]
    for error in TARGETS:
        expected = cheapest_by_hand(entries, error, statistic)
        if expected is None:
            with pytest.raises(ValueError, match=shape):
                rm.cheapest_model(shape, error, statistic)
            continue
        choice = rm.cheapest_model(shape, error, statistic)
        assert choice.nrmse <= error
        assert (choice.nodes, choice.curvature, choice.regime) == (expected["nodes"], expected["curvature"],
                                                                  expected["regime"])
        assert choice.cost_ms_per_step == expected["cost_ms_per_step"]
        assert "doc/speed-vs-error.md" in choice.study


def test_the_gummy_bear_is_ranked_by_its_s1_cost_and_the_others_by_nodes():
    assert rm.cheapest_model("gummy_bear", 0.05).ranked_by == "S1 cost"
    assert rm.cheapest_model("pear", 0.05).ranked_by == "nodes"
    assert rm.cheapest_model("sphere", 0.05).cost_ms_per_step is None


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
        rm.cheapest_model("gummy_bear", 0.05, "mean")


def test_the_choice_builds_its_mesh():
    choice = rm.cheapest_model("sphere", 0.02)
    mesh = choice.mesh()
    assert abs(len(mesh.vertices) - choice.nodes) <= 0.02 * choice.nodes


ERRORS = [  # shape, family, configuration, size, partner, median, worst [%]
    ("gummy_bear", "roundedmesh", "curvature computed, auto", 150, 50.0, 53.0, 51.0, 53.1),
    ("gummy_bear", "roundedmesh", "curvature computed, auto", 300, 8.0, 30.0, 9.0, 40.0),
    ("gummy_bear", "roundedmesh", "curvature computed, auto", 1100, 0.8, 6.0, 0.9, 4.0),
    ("gummy_bear", "roundedmesh", "curvature prescribed, auto", 300, 3.0, 20.0, 4.0, 25.0),
    ("gummy_bear", "clumps", "clump", 20, 15.6, 15.6, 1e-6, 53.1),
    ("gummy_bear", "level_sets", "level set, grid 1 mm", 2047, 24.0, 53.0, 42.0, 68.0),
    ("pear", "roundedmesh", "curvature computed, auto", 150, 0.6, 15.0, 1.0, 14.0),
    ("pear", "roundedmesh", "curvature computed, direct", 150, 0.07, 14.0, 0.9, 13.0),
]
COSTS = [("curvature computed, auto", 300, 20.0), ("curvature computed, auto", 1100, 50.0),
         ("clump", 20, 6.0), ("level set, grid 1 mm", 2047, 40.0)]


def write_fixtures(folder):
    """errors.csv and costs.csv of ERRORS and COSTS, with the columns the two scripts write."""
    with open(folder / "errors.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["shape", "family", "configuration", "nodes or spheres", "partner", "NRMSE median [%]",
                         "NRMSE worst [%]"])
        for shape, family, configuration, size, plane_median, plane_worst, copy_median, copy_worst in ERRORS:
            writer.writerow([shape, family, configuration, size, "plane", plane_median, plane_worst])
            writer.writerow([shape, family, configuration, size, "self", copy_median, copy_worst])
    with open(folder / "costs.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["configuration", "size", "median_wall_ms", "median_cpu_ms", "contacts", "machine"])
        for configuration, size, cpu in COSTS:
            writer.writerow([configuration, size, cpu * 1.1, cpu, 100, "fixture"])


def test_the_report_joins_errors_and_costs(tmp_path):
    write_fixtures(tmp_path)
    out = subprocess.run(["/usr/bin/python3", REPORT, "--input", str(tmp_path), "--output", str(tmp_path)],
                         capture_output=True, text=True, timeout=60, env=os.environ)
    assert out.returncode == 0, out.stdout + out.stderr
    assert (tmp_path / "pareto.png").stat().st_size > 0
    with open(tmp_path / "pareto.csv", newline="") as f:
        rows = {(r["configuration"], int(r["nodes or spheres"])): r for r in csv.DictReader(f)}
    assert len(rows) == 6                                   # the gummy bear's configurations only
    prescribed = rows[("curvature prescribed, auto", 300)]
    assert float(prescribed["CPU ms per step"]) == 20.0     # costs as the computed mesh of its nodes and regime
    assert float(prescribed["NRMSE median, worse partner [%]"]) == 4.0
    assert rows[("curvature computed, auto", 150)]["CPU ms per step"] == ""       # no cost: in the table only
    # median front by cost: clump 6 ms (15.6 %), prescribed 300 20 ms (4 %), computed 1100 50 ms (0.9 %)
    front = {key for key, r in rows.items() if r["on the front (median)"] == "yes"}
    assert front == {("clump", 20), ("curvature prescribed, auto", 300), ("curvature computed, auto", 1100)}
    guide = (tmp_path / "guide.md").read_text()
    assert "roundedmesh / clump = 3.33" in guide            # 20 ms / 6 ms, bear on bear at 5 %
    assert "No level set reaches 5 %" in guide
    with open(tmp_path / "speed_vs_error.json") as f:
        data = json.load(f)
    choice = rm.cheapest_model("gummy_bear", 0.05, data=data)
    assert (choice.nodes, choice.curvature, choice.cost_ms_per_step) == (300, "prescribed", 20.0)
    pear = rm.cheapest_model("pear", 0.02, data=data)       # no costs: fewest nodes, then the regime cheaper on S1
    assert (pear.nodes, pear.regime, pear.ranked_by) == (150, "auto", "nodes")


def test_the_study_script_hands_its_folder_to_the_report(tmp_path):
    # the sphere has no level sets: no part runs, and --report reads the fixtures left in the folder
    write_fixtures(tmp_path)
    script = os.path.join(ROOT, "scripts", "studies", "speed_vs_error.py")
    out = subprocess.run(["/usr/bin/python3", script, "--shapes", "sphere", "--families", "level_sets", "--report",
                          "--output", str(tmp_path)], capture_output=True, text=True, timeout=60, env=os.environ)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "Which model does my scene need" in (tmp_path / "guide.md").read_text()
