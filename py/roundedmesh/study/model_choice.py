"""Model only what a scene needs: the cheapest roundedmesh configuration (mesh nodes, curvature, regime) whose
force error meets a target, according to the speed-against-error study of issue 14 (doc/speed-vs-error.md;
scripts/studies/speed_vs_error.py for the errors, scripts/studies/speed_vs_error_costs.py for the costs,
scripts/studies/speed_vs_error_report.py writes the data file speed_vs_error.json beside this module).

    cheapest_model(shape, error, pose_statistic="median") -> ModelChoice
    ModelChoice.mesh()     the study's mesh of that configuration; give its regime to rm.engine(regime=...)

Error: NRMSE of the contact force against Hertz's solution at the smooth shape's contact point, overlaps up to 2 %
of r = 25 mm, the worse of the shape pressed on a rigid plane and on a copy of itself, as the median or the worst
over the study's random poses; a fraction (0.05 is 5 %). Cost: CPU ms per step of scene S1's settled packing of 250
gummy bears on one thread, measured for the gummy bear only.
"""
import functools
import json
import os
from dataclasses import dataclass
from typing import Optional

_DATA = os.path.join(os.path.dirname(os.path.realpath(__file__)), "speed_vs_error.json")
POSE_STATISTICS = ("median", "worst")


@dataclass(frozen=True)
class ModelChoice:
    """One roundedmesh configuration of the study: `nodes` asked of the mesher (the mesh has about as many),
    `curvature` 'computed' (Eq. 1) or 'prescribed' (the smooth shape's mean curvature), `regime` of the pressure
    integration ('auto', 'quadrature', 'direct'), `nrmse` the study's error for `pose_statistic` (a fraction),
    `cost_ms_per_step` the CPU ms per step of S1 (None where the study has no cost), `ranked_by` 'S1 cost' or
    'nodes' (see cheapest_model), `study` where the numbers come from."""
    shape: str
    nodes: int
    curvature: str
    regime: str
    nrmse: float
    pose_statistic: str
    cost_ms_per_step: Optional[float]
    ranked_by: str
    study: str

    def mesh(self):
        """The study's Mesh of this configuration (shape_error.rounded_mesh): Mesh.reference_shape(shape, nodes)
        for the pear and the gummy bear, with each triangle's curvature replaced by the smooth shape's if
        prescribed; for the sphere the icosphere of radius 25 mm. The regime is not part of a Mesh: pass
        rm.engine(regime=choice.regime)."""
        from .shape_error import rounded_mesh
        return rounded_mesh(self.shape, self.nodes, self.curvature, self.regime).mesh


@functools.lru_cache(maxsize=None)
def study_data(path=_DATA):
    """The contents of speed_vs_error.json (scripts/studies/speed_vs_error_report.py --package-data)."""
    with open(path) as f:
        return json.load(f)


def cheapest_model(shape, error, pose_statistic="median", data=None):
    """The cheapest roundedmesh configuration of `shape` ('sphere', 'pear', 'gummy_bear') whose force error in the
    speed-against-error study (doc/speed-vs-error.md, scripts/studies/speed_vs_error*.py) is at most `error`, a fraction
    (0.05 for 5 %), for `pose_statistic` 'median' (a typical contact) or 'worst' (the worst pose of the study),
    as a ModelChoice. The study's error is the NRMSE of the force against Hertz up to an overlap of 2 % of the
    volume-equivalent radius, the worse of pressing on a plane and on a copy of the shape.

    Ranking: where the study has S1 costs (the gummy bear), the lowest CPU ms per step; configurations without
    a cost (the 150-node bear, which S1 cannot start from) are not offered. For shapes without costs (the sphere,
    the pear), the fewest nodes, then the regime that is cheaper on the gummy bear's S1 (the JSON's
    regimes_by_cost). Equal ranks (prescribed and computed curvature cost the same) go to the smaller error.
    A prescribed-curvature answer needs that mesh: ModelChoice.mesh() builds it. The regime must be given to
    rm.engine(regime=...) by the user. `data`: the study's contents (default study_data()).

    Raises ValueError naming the shape and the target when the shape is not in the study, when `error` is not a
    fraction in (0, 1), or when no configuration of the study meets it."""
    data = study_data() if data is None else data
    if pose_statistic not in POSE_STATISTICS:
        raise ValueError(f"pose_statistic: {pose_statistic!r} is not one of {', '.join(POSE_STATISTICS)}")
    if not 0 < error < 1:
        raise ValueError(f"error: {error!r} is not a fraction in (0, 1); 0.05 asks for 5 %")
    entries = data["shapes"].get(shape)
    if entries is None:
        raise ValueError(f"shape: {shape!r} is not in the speed-against-error study; it has "
                         f"{', '.join(sorted(data['shapes']))}")
    key = f"nrmse_{pose_statistic}"
    with_costs = any(e["cost_ms_per_step"] is not None for e in entries)
    offered = [e for e in entries if e[key] is not None and (e["cost_ms_per_step"] is not None or not with_costs)]
    meeting = [e for e in offered if e[key] <= error]
    if not meeting:
        best = min((e[key] for e in offered), default=float("nan"))
        raise ValueError(f"no roundedmesh configuration of the study meets {error:.3g} NRMSE ({pose_statistic} pose) "
                         f"for {shape!r}; the smallest is {best:.3g}")
    regimes = data["regimes_by_cost"]
    if with_costs:
        chosen = min(meeting, key=lambda e: (e["cost_ms_per_step"], e[key]))
    else:
        chosen = min(meeting, key=lambda e: (e["nodes"], regimes.index(e["regime"]), e[key]))
    return ModelChoice(shape=shape, nodes=chosen["nodes"], curvature=chosen["curvature"], regime=chosen["regime"],
                       nrmse=chosen[key], pose_statistic=pose_statistic, cost_ms_per_step=chosen["cost_ms_per_step"],
                       ranked_by="S1 cost" if with_costs else "nodes", study=data["study"])
