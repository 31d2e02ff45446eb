"""Model only what a scene needs: the cheapest roundedmesh configuration (mesh nodes, curvature, the contact law's
options) whose force error meets a target, for a shape of the speed-against-error study or for any mesh
(doc/speed-vs-error.md; scripts/studies/speed_vs_error.py for the errors, speed_vs_error_costs.py for the costs,
speed_vs_error_report.py writes the data file speed_vs_error.json beside this module).

    cheapest_model(shape_or_mesh, error, partner="both", pose_statistic="median") -> ModelChoice
    ModelChoice.mesh()             the mesh to use; ModelChoice.engine_options go to rm.engine(**...)
    mesh_resolution(mesh)          how finely a mesh resolves its own curvature (the fits' variable)
    error_fits(data)               the study's error against resolution, per law option, partner and statistic

Error: NRMSE of the contact force against the smooth shape's reference (Hertz at the contact point's principal
curvatures, or the elastic half-space solution of the shapes' gap where the curvature changes over the contact),
overlaps up to 2 % of the volume-equivalent radius, pressed on a rigid plane ('plane'), on a copy of itself
('self'), or the worse of the two ('both'); the median or the worst over the study's random poses; a fraction (0.05
is 5 %). Cost: CPU ms per step of scene S1's settled packing of 250 bodies of the shape on one thread, where the
study measured it.

For a shape of the study the answer is the study's own measurement. For any other mesh (a user's STL, a scan), the
answer comes from fits of the study's errors over all its shapes and node counts against the mesh's resolution
q = longest edge x largest principal curvature of each triangle, computed from the mesh (mesh_resolution): the
error of a law option goes as C q^alpha, and q of a mesh remeshed to N nodes as sqrt(N0 / N) (edges scale so).
The node count that meets the target with one standard deviation of the fit's scatter to spare is chosen, and the
mesh is remeshed to it (Mesh.remeshed) when that is coarser than the given one. A finer count cannot be made from
the mesh: remeshing a coarse mesh adds nodes on its flat triangles, not shape; the choice then keeps the mesh,
warns, and says how many nodes of the same shape the target needs.
"""
import functools
import json
import math
import os
import warnings
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

_DATA = os.path.join(os.path.dirname(os.path.realpath(__file__)), "speed_vs_error.json")
POSE_STATISTICS = ("median", "worst")
PARTNERS = ("both", "plane", "self")
# Area-weighted quantiles of the per-triangle resolution that stand for a typical contact (median pose) and for the
# worst one (worst pose: the contacts on the finest features).
RESOLUTION_QUANTILES = {"median": 0.5, "worst": 0.98}
# The node counts a choice for a mesh is kept within: the study's range (42 to 2562 nodes), and no finer than the
# engine's meshes are meant to be.
NODE_RANGE = (150, 20000)


@dataclass(frozen=True)
class ModelChoice:
    """One roundedmesh configuration: about `nodes` nodes, the mesh's `curvature` ('computed', Eq. 1, or
    'prescribed': the smooth shape's, which only the study's shapes have), and the law's options `regime`,
    `law_curvature` ('mean' or 'principal'), `normal` ('pressure' or 'energy'); `nrmse` its error (a fraction) for
    `pose_statistic` and `partner`, measured by the study for its shapes, predicted by its fits for a mesh;
    `cost_ms_per_step` the S1 CPU ms per step (measured; for a mesh, estimated from the gummy bear's at that node
    count; None where unknown); `ranked_by` 'S1 cost', 'nodes' or 'fit'; `shape` the study's shape or None;
    `source` the mesh given (for a mesh); `finer_needed` True when the target needs more nodes of the same shape
    than the given mesh has."""
    shape: Optional[str]
    nodes: int
    curvature: str
    regime: str
    law_curvature: str
    normal: str
    nrmse: float
    pose_statistic: str
    partner: str
    cost_ms_per_step: Optional[float]
    ranked_by: str
    study: str
    source: object = field(default=None, compare=False, repr=False)
    finer_needed: bool = False

    @property
    def engine_options(self):
        """The options of rm.engine this configuration was measured with."""
        return {"regime": self.regime, "curvature": self.law_curvature, "normal": self.normal}

    def mesh(self):
        """The mesh of this configuration: for a shape of the study its mesh (shape_error.rounded_mesh); for a
        given mesh, that mesh remeshed to `nodes` (Mesh.remeshed), or the mesh itself when the target needs no
        fewer nodes than it has (finer_needed, or within 10 % of its count)."""
        if self.source is None:
            from .shape_error import rounded_mesh
            return rounded_mesh(self.shape, self.nodes, self.curvature).mesh
        if self.finer_needed or self.nodes >= 0.9 * len(self.source.vertices):
            return self.source
        return _remeshed(self.source, self.nodes)


@functools.lru_cache(maxsize=32)
def _remeshed(mesh, nodes):
    """`mesh` remeshed to about `nodes` nodes on the smooth surface its nodes sample: Mesh.remeshed puts the new
    nodes on the old flat triangles, whose curvature computed at a node inside a triangle is that of a plane; each
    is moved onto the quadric fitted to the old nodes around it (on_sampled_surface), in the old mesh's input
    frame, which the new mesh keeps."""
    from .._core import Mesh
    coarse = mesh.remeshed(nodes)
    def input_frame(m):
        return np.array(m.vertices) @ np.array(m.orientation.toRotationMatrix()).T + np.array(m.centroid)
    return Mesh.from_arrays(on_sampled_surface(input_frame(mesh), input_frame(coarse)), np.array(coarse.triangles))


# Nodes a local quadric is fitted to: a second-order height field has 6 coefficients; 15 neighbours (two rings of
# a regular mesh) keep the fit well posed without reaching across a thin part.
QUADRIC_NEIGHBOURS = 15


def on_sampled_surface(samples, points, neighbours=QUADRIC_NEIGHBOURS):
    """`points` (n, 3) [m] moved onto the smooth surface that `samples` (m, 3) [m], nodes of a mesh, lie on: for
    each point, the height field w = a + b u + c v + d u^2 + e u v + f v^2 fitted by least squares to its nearest
    samples, in the frame of their principal axes (w along the least spread, the surface's normal), and the point
    moved along w onto it (moving least squares, Levin 2003, of order 2). A point already on a sphere's sampled
    surface stays within the quadric's error of it, O(h^3 / R^2)."""
    from scipy.spatial import cKDTree
    _, nearest = cKDTree(samples).query(points, k=neighbours)
    local = samples[nearest]                                     # (n, k, 3)
    centre = local.mean(axis=1)
    _, _, axes = np.linalg.svd(local - centre[:, None, :])       # rows of axes: principal directions, normal last
    relative = np.einsum("nkj,nij->nki", local - centre[:, None, :], axes)
    u, v, w = relative[..., 0], relative[..., 1], relative[..., 2]
    design = np.stack([np.ones_like(u), u, v, u * u, u * v, v * v], axis=-1)
    normal = np.einsum("nki,nkj->nij", design, design)
    coefficients = np.linalg.solve(normal, np.einsum("nki,nk->ni", design, w)[..., None])[..., 0]
    p = np.einsum("nj,nij->ni", points - centre, axes)
    pu, pv = p[:, 0], p[:, 1]
    height = np.einsum("ni,ni->n", np.stack([np.ones_like(pu), pu, pv, pu * pu, pu * pv, pv * pv], axis=-1),
                       coefficients)
    return centre + pu[:, None] * axes[:, 0] + pv[:, None] * axes[:, 1] + height[:, None] * axes[:, 2]


@functools.lru_cache(maxsize=None)
def study_data(path=_DATA):
    """The contents of speed_vs_error.json (scripts/studies/speed_vs_error_report.py --package-data)."""
    with open(path) as f:
        return json.load(f)


def mesh_resolution(mesh):
    """{'median': q50, 'worst': q98}: quantiles (RESOLUTION_QUANTILES) over the triangles of q = longest edge [m] x
    largest |principal curvature| [1/m], the curvature estimated from the mesh's own nodes (Rusinkiewicz's estimate,
    as Mesh.from_arrays computes it), whatever curvature the mesh carries. q is the angle a triangle spans on the
    surface it samples: small where the mesh resolves its curvature. Each convex triangle weighs its area times its
    Gaussian curvature k1 k2, the share of directions its normals cover: a body touched from a random direction
    touches there with that probability (its support point's normal is that direction), which puts the contacts on
    a pill's edges and a grain's corners far more often than on their nearly flat faces, and never in a concave
    groove (weight 0)."""
    from .._core import Mesh
    vertices, triangles = np.array(mesh.vertices), np.array(mesh.triangles)
    principal = np.array(Mesh.from_arrays(vertices, triangles, tolerance=None).principal_curvatures)
    corners = vertices[triangles]
    edges = np.linalg.norm(corners - np.roll(corners, 1, axis=1), axis=2).max(axis=1)
    areas = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    q = edges * np.abs(principal).max(axis=1)
    weights = areas * np.where(principal[:, 1] > 0, principal.prod(axis=1), 0.0)   # k1 >= k2 > 0: convex
    order = np.argsort(q)
    cumulative = np.cumsum(weights[order]) / weights.sum()
    return {statistic: float(q[order][np.searchsorted(cumulative, quantile)])
            for statistic, quantile in RESOLUTION_QUANTILES.items()}


@dataclass(frozen=True)
class ErrorFit:
    """log NRMSE = log_c + alpha log q over `points` (shape, nodes) of the study; sigma the residuals' standard
    deviation (natural log)."""
    log_c: float
    alpha: float
    sigma: float
    points: int

    def error(self, q, spare=1.0):
        """The predicted NRMSE at resolution q, with `spare` standard deviations added."""
        return math.exp(self.log_c + self.alpha * math.log(q) + spare * self.sigma)

    def resolution_for(self, error, spare=1.0):
        """The resolution q at which the predicted NRMSE (with `spare` deviations) is `error`."""
        return math.exp((math.log(error) - self.log_c - spare * self.sigma) / self.alpha)


def variant(entry):
    """(curvature, regime, law_curvature, normal) of a study entry."""
    return entry["curvature"], entry["regime"], entry["law_curvature"], entry["normal"]


# Errors at the reference's own accuracy (below) say nothing of the mesh; a body that gives no force within the
# study's overlaps (NRMSE 53.1 %) neither: both are left out of the fits. So is the sphere: an icosphere's nodes lie
# on one sphere, so the curvature computed from them is the sphere's own, exactly, as no other mesh's is.
_FIT_FLOOR, _NO_FORCE = 1e-4, 0.5
_NOT_FITTED = ("sphere",)


def error_fits(data=None):
    """{((curvature, regime, law_curvature, normal), statistic, partner): ErrorFit} from the study's computed-
    curvature configurations of every shape but the sphere (ErrorFit; at least 4 points each). A few hundred numbers:
    computed on each call."""
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


def _check(error, partner, pose_statistic):
    if pose_statistic not in POSE_STATISTICS:
        raise ValueError(f"pose_statistic: {pose_statistic!r} is not one of {', '.join(POSE_STATISTICS)}")
    if partner not in PARTNERS:
        raise ValueError(f"partner: {partner!r} is not one of {', '.join(PARTNERS)}")
    if not (isinstance(error, (int, float)) and 0 < error < 1):
        raise ValueError(f"error: {error!r} is not a fraction in (0, 1); 0.05 asks for 5 %")


def cheapest_model(shape_or_mesh, error, partner="both", pose_statistic="median", data=None):
    """The cheapest roundedmesh configuration whose force error is at most `error` (a fraction: 0.05 for 5 %)
    against `partner` ('both': the worse of a rigid plane and a copy; 'plane'; 'self') for `pose_statistic`
    ('median': a typical contact; 'worst': the study's worst pose), as a ModelChoice.

    shape_or_mesh: a shape of the study ('sphere', 'pear', 'gummy_bear', 'spheroid', 'pill', 'tetra_grain'): the
    study's measured configurations; ranked by their S1 cost where the study timed that shape, else by node count,
    then by the regimes' cost on the gummy bear (the data's regimes_by_cost); at equal rank the law's default
    options come first, then the smaller error.
    Or a roundedmesh Mesh: the fits of error_fits (module docstring), computed curvature, the fewest nodes that
    meet the target; the cost then estimated from the gummy bear's S1 cost at that node count.

    Raises ValueError naming the shape, the target and the smallest error available when nothing meets it, and for
    an unknown shape, partner or statistic, or an error that is not a fraction in (0, 1)."""
    _check(error, partner, pose_statistic)
    data = study_data() if data is None else data
    if isinstance(shape_or_mesh, str):
        return _for_shape(shape_or_mesh, error, partner, pose_statistic, data)
    return _for_mesh(shape_or_mesh, error, partner, pose_statistic, data)


def _for_shape(shape, error, partner, pose_statistic, data):
    entries = data["shapes"].get(shape)
    if entries is None:
        raise ValueError(f"shape: {shape!r} is not in the speed-against-error study; it has "
                         f"{', '.join(sorted(data['shapes']))} (or pass a Mesh)")
    def nrmse(e):
        return e["nrmse"][pose_statistic][partner]
    with_costs = any(e["cost_ms_per_step"] is not None for e in entries)
    offered = [e for e in entries if nrmse(e) is not None and (e["cost_ms_per_step"] is not None or not with_costs)]
    meeting = [e for e in offered if nrmse(e) <= error]
    if not meeting:
        best = min((nrmse(e) for e in offered), default=float("nan"))
        raise ValueError(f"no roundedmesh configuration of the study meets {error:.3g} NRMSE ({pose_statistic} pose, "
                         f"partner {partner}) for {shape!r}; the smallest is {best:.3g}")
    regimes = data["regimes_by_cost"]

    def rank(e):   # the cost, else the nodes and the regime's cost; then the law's defaults before its options
        regime = regimes.index(e["regime"]) if e["regime"] in regimes else len(regimes)
        options = (e["law_curvature"] != "mean") + (e["normal"] != "pressure")
        return ((e["cost_ms_per_step"],) if with_costs else (e["nodes"], regime)) + (options, nrmse(e))
    chosen = min(meeting, key=rank)
    return ModelChoice(shape, chosen["nodes"], *variant(chosen), nrmse=nrmse(chosen), pose_statistic=pose_statistic,
                       partner=partner, cost_ms_per_step=chosen["cost_ms_per_step"],
                       ranked_by="S1 cost" if with_costs else "nodes", study=data["study"])


def estimated_cost(nodes, regime, data):
    """CPU ms per step of S1 with 250 bodies of `nodes` nodes, from the gummy bear's measured costs in `regime`
    ('auto' if that regime was not timed): a power law through them (cost grows about linearly with the nodes).
    None without costs."""
    timed = [e for e in data["shapes"].get("gummy_bear", []) if e["cost_ms_per_step"] is not None
             and e["curvature"] == "computed" and e["cost_from"] == variant_label(*variant(e))]
    chosen = [e for e in timed if e["regime"] == regime] or [e for e in timed if e["regime"] == "auto"]
    if len(chosen) < 2:
        return None
    x, y = np.log([[e["nodes"], e["cost_ms_per_step"]] for e in chosen]).T
    slope, intercept = np.polyfit(x, y, 1)
    return float(math.exp(intercept + slope * math.log(nodes)))


def variant_label(curvature, regime, law_curvature, normal):
    """The study's name of a roundedmesh configuration (errors.csv, costs.csv, cost_from): 'curvature computed,
    auto' for the law's defaults, then ', principal' (Hertz's ellipse) or ', energy'."""
    return ", ".join([f"curvature {curvature}", regime] + ([law_curvature] if law_curvature != "mean" else [])
                     + ([normal] if normal != "pressure" else []))


def _for_mesh(mesh, error, partner, pose_statistic, data):
    from .._core import Mesh
    if not isinstance(mesh, Mesh):
        raise TypeError(f"shape_or_mesh: expected a study shape's name or a roundedmesh.Mesh, got {mesh!r}")
    q0 = mesh_resolution(mesh)[pose_statistic]
    n0 = len(mesh.vertices)
    regimes = data["regimes_by_cost"]
    candidates = []
    for (options, statistic, fit_partner), fit in error_fits(data).items():
        if statistic != pose_statistic or fit_partner != partner or fit.alpha <= 0:
            continue   # only fits whose error falls with refinement can be inverted
        nodes = n0 * (q0 / fit.resolution_for(error)) ** 2
        rank = regimes.index(options[1]) if options[1] in regimes else len(regimes)
        candidates.append((max(nodes, NODE_RANGE[0]), rank, options, fit))
    if not candidates:
        raise ValueError(f"the study has no error fit for partner {partner!r}, {pose_statistic} pose")
    nodes, _, options, fit = min(candidates, key=lambda c: (c[0], c[1]))
    if nodes > NODE_RANGE[1]:
        raise ValueError(f"mesh of {n0} nodes: {error:.3g} NRMSE ({pose_statistic} pose, partner {partner}) needs "
                         f"about {nodes:.0f} nodes of its shape, beyond the {NODE_RANGE[1]} the engine's meshes are "
                         f"meant for; the closest the study's fits reach there is "
                         f"{fit.error(q0 * math.sqrt(n0 / NODE_RANGE[1])):.3g}")
    nodes = int(math.ceil(nodes))
    finer = nodes > 1.1 * n0
    predicted = fit.error(q0 if finer else q0 * math.sqrt(n0 / nodes))   # the given mesh's own, if kept
    if finer:
        warnings.warn(f"mesh of {n0} nodes: {error:.3g} NRMSE ({pose_statistic} pose, partner {partner}) needs about "
                      f"{nodes} nodes of the same shape (the study's fits; this mesh: {predicted:.3g}); remeshing "
                      f"cannot add shape: give a finer mesh of it. The mesh is used as it is.", stacklevel=3)
    return ModelChoice(None, nodes, *options, nrmse=predicted, pose_statistic=pose_statistic, partner=partner,
                       cost_ms_per_step=estimated_cost(min(nodes, n0) if finer else nodes, options[1], data),
                       ranked_by="fit", study=data["study"], source=mesh, finer_needed=finer)
