"""The table rm.cheapest_model reads (py/roundedmesh/model_table.json), made from the speed-against-error study's
data (speed_vs_error.json beside this module, which scripts/studies/speed_vs_error_report.py --package-data writes;
doc/speed-vs-error.md):

    study_data()              the study's data: every roundedmesh configuration of every shape with its errors,
                              S1 cost and the resolution of its mesh
    error_fits(data)          the study's error against resolution, per law option, partner and statistic
    model_table(data)         the compact table: per shape how the study meshes it and its configurations, the
                              fits, and the power laws of the gummy bear's S1 cost per regime
    write_model_table(path)   writes model_table(study_data()) to the library (scripts/studies/speed_vs_error_report.py
                              --package-data)

roundedmesh.model_choice chooses from the table; this module is how the table follows from the study.
"""
import functools
import json
import os

import numpy as np
from roundedmesh import model_choice
from roundedmesh.model_choice import POSE_STATISTICS, PARTNERS, ErrorFit, variant

from . import grains, shape_error

DATA = os.path.join(os.path.dirname(os.path.realpath(__file__)), "speed_vs_error.json")


@functools.lru_cache(maxsize=None)
def study_data(path=DATA):
    """The contents of speed_vs_error.json (scripts/studies/speed_vs_error_report.py --package-data)."""
    with open(path) as f:
        return json.load(f)


# Errors at the reference's own accuracy (below) say nothing of the mesh; a body that gives no force within the
# study's overlaps (NRMSE 53.1 %) neither: both are left out of the fits. So is the sphere: an icosphere's nodes lie
# on one sphere, so the curvature computed from them is the sphere's own, exactly, as no other mesh's is.
_FIT_FLOOR, _NO_FORCE = 1e-4, 0.5
_NOT_FITTED = ("sphere",)


def error_fits(data=None):
    """{((curvature, regime, law_curvature, normal), statistic, partner): ErrorFit} from the study's computed-
    curvature configurations of every shape but the sphere (ErrorFit; at least 4 points each)."""
    data = study_data() if data is None else data
    points = {}
    for shape, entries in data["shapes"].items():
        for entry in entries:
            if entry["curvature"] != "computed" or shape in _NOT_FITTED:   # a user's mesh has no smooth shape
                continue
            q = data["resolution"][shape][str(entry["nodes"])]
            for statistic in POSE_STATISTICS:
                for partner in PARTNERS:
                    value = entry["nrmse"][statistic][partner]
                    if value is not None and _FIT_FLOOR < value < _NO_FORCE:
                        points.setdefault((variant(entry), statistic, partner), []).append((q[statistic], value))
    fits = {}
    for key, pairs in points.items():
        if len(pairs) < 4:
            continue
        x, y = np.log(np.array(pairs)).T
        alpha, log_c = np.polyfit(x, y, 1)
        sigma = float(np.std(y - (log_c + alpha * x), ddof=2)) if len(pairs) > 2 else 0.0
        fits[key] = ErrorFit(float(log_c), float(alpha), sigma, len(pairs))
    return fits


def variant_label(curvature, regime, law_curvature, normal):
    """The study's name of a roundedmesh configuration (errors.csv, costs.csv, cost_from): 'curvature computed,
    auto' for the law's defaults, then ', principal' (Hertz's ellipse) or ', energy'."""
    return ", ".join([f"curvature {curvature}", regime] + ([law_curvature] if law_curvature != "mean" else [])
                     + ([normal] if normal != "pressure" else []))


def cost_fits(data):
    """{regime: {'slope', 'intercept'} or None}: the power law log cost = intercept + slope log nodes through the
    gummy bear's measured S1 costs of each regime timed with computed curvature (cost grows about linearly with
    the nodes); None for a regime timed at fewer than two node counts."""
    timed = [e for e in data["shapes"].get("gummy_bear", []) if e["cost_ms_per_step"] is not None
             and e["curvature"] == "computed" and e["cost_from"] == variant_label(*variant(e))]
    fits = {}
    for regime in dict.fromkeys(e["regime"] for e in timed):
        chosen = [e for e in timed if e["regime"] == regime]
        if len(chosen) < 2:
            fits[regime] = None
            continue
        x, y = np.log([[e["nodes"], e["cost_ms_per_step"]] for e in chosen]).T
        slope, intercept = np.polyfit(x, y, 1)
        fits[regime] = {"slope": float(slope), "intercept": float(intercept)}
    return fits


def generator(shape):
    """How the study meshes `shape` (shape_error.rounded_mesh), as roundedmesh.model_choice.shape_mesh reads it."""
    if shape == "sphere":
        return {"mesh": "icosphere", "parameters": [shape_error.RADIUS]}
    if shape in grains.NAMES:
        grain = grains.grain(shape)
        mesh = {"spheroid": "spheroid", "superellipsoid": "superellipsoid", "tetrahedron": "rounded_tetrahedron"}
        return {"mesh": mesh[grain.kind], "parameters": list(grain.parameters)}
    return {"mesh": "reference_shape", "parameters": [shape]}


def _row(entry):
    """A configuration of the study's data as a row of the table (roundedmesh.model_choice.COLUMNS)."""
    errors = {f"nrmse {s} {p}": value for s, by_partner in entry["nrmse"].items() for p, value in by_partner.items()}
    return [errors[column] if column in errors else entry[column] for column in model_choice.COLUMNS]


def model_table(data=None):
    """The table roundedmesh.model_choice reads, from the study's `data` (default study_data()): the study's
    description, its regimes by cost, per shape its generator and its configurations (a row of
    roundedmesh.model_choice.COLUMNS each: nodes, options, S1 cost, errors), the error fits (error_fits, in their
    order) and the cost fits (cost_fits)."""
    data = study_data() if data is None else data
    return {"study": data["study"], "regimes_by_cost": data["regimes_by_cost"],
            "columns": list(model_choice.COLUMNS),
            "shapes": {shape: {"generator": generator(shape),
                               "configurations": [_row(e) for e in entries]}
                       for shape, entries in data["shapes"].items()},
            "fits": [{"curvature": options[0], "regime": options[1], "law_curvature": options[2],
                      "normal": options[3], "statistic": statistic, "partner": partner, "log_c": fit.log_c,
                      "alpha": fit.alpha, "sigma": fit.sigma, "points": fit.points}
                     for (options, statistic, partner), fit in error_fits(data).items()],
            "cost_fits": cost_fits(data)}


def write_model_table(path=model_choice.TABLE, data=None):
    """Writes model_table(data) to `path` (default: the library's model_table.json), one configuration or fit a
    line."""
    table = model_table(data)
    with open(path, "w") as f:
        f.write(json.dumps(table, separators=(",", ":")).replace("],[", "],\n[").replace("},{", "},\n{"))
        f.write("\n")
