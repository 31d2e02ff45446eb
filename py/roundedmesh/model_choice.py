"""Model only what a scene needs: the cheapest roundedmesh configuration (mesh nodes, curvature, the contact law's
options) whose force error meets a target, for a shape of the speed-against-error study or for any mesh
(doc/speed-vs-error.md), read from model_table.json beside this module: the study's measured configurations and its
fits, which roundedmesh_study.model_table writes from the study's data (scripts/studies/speed_vs_error_report.py
--package-data).

    cheapest_model(shape_or_mesh, error, partner="both", pose_statistic="median") -> ModelChoice
    ModelChoice.mesh()             the mesh to use; ModelChoice.engine_options go to rm.engine(**...)
    mesh_resolution(mesh)          how finely a mesh resolves its own curvature (the fits' variable)

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
mesh is remeshed to it (Mesh.remeshed, the new nodes moved onto the surface the old ones sample) when that is
coarser than the given one. A finer count cannot be made from the mesh: remeshing a coarse mesh adds nodes on its
flat triangles, not shape; the choice then refuses (ValueError) and says how many nodes of the same shape the
target needs, so that every answer's predicted error meets the target.
"""
import functools
import json
import math
import os
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ._core import Mesh
from .shapes import reference_shape

TABLE = os.path.join(os.path.dirname(os.path.realpath(__file__)), "model_table.json")
POSE_STATISTICS = ("median", "worst")
PARTNERS = ("both", "plane", "self")
# Area-weighted quantiles of the per-triangle resolution that stand for a typical contact (median pose) and for the
# worst one (worst pose: the contacts on the finest features).
RESOLUTION_QUANTILES = {"median": 0.5, "worst": 0.98}
# The node counts a choice for a mesh is kept within: the study's range (42 to 2562 nodes), and no finer than the
# engine's meshes are meant to be.
NODE_RANGE = (150, 20000)
# The columns of a shape's configurations in the table: the nodes, the mesh's curvature, the law's options, the S1
# cost [ms per step] or None, and the error (a fraction, None where not measured) per pose statistic and partner.
COLUMNS = (("nodes", "curvature", "regime", "law_curvature", "normal", "cost_ms_per_step")
           + tuple(f"nrmse {statistic} {partner}" for statistic in POSE_STATISTICS for partner in PARTNERS))


@functools.lru_cache(maxsize=None)
def model_table(path=TABLE):
    """The contents of model_table.json (roundedmesh_study.model_table.model_table writes it)."""
    with open(path) as f:
        return json.load(f)


@dataclass(frozen=True)
class ModelChoice:
    """One roundedmesh configuration: about `nodes` nodes, the mesh's `curvature` ('computed', Eq. 1, or
    'prescribed': the smooth shape's, which only the study's shapes have), and the law's options `regime`,
    `law_curvature` ('mean' or 'principal'), `normal` ('pressure' or 'energy'); `nrmse` its error (a fraction) for
    `pose_statistic` and `partner`, measured by the study for its shapes, predicted by its fits for the mesh that
    mesh() returns; `cost_ms_per_step` the S1 CPU ms per step (measured; for a mesh, estimated from the gummy bear's
    at that node count; None where unknown); `ranked_by` 'S1 cost', 'nodes' or 'fit'; `shape` the study's shape or
    None; `source` the mesh given (for a mesh); `generator` how the study meshes its shape (for a shape)."""
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
    generator: Optional[dict] = field(default=None, compare=False, repr=False)

    @property
    def engine_options(self):
        """The options of rm.engine this configuration was measured with."""
        return {"regime": self.regime, "curvature": self.law_curvature, "normal": self.normal}

    def mesh(self):
        """The mesh of this configuration: for a shape of the study the study's mesh of it (shape_mesh); for a given
        mesh, that mesh remeshed to `nodes` (Mesh.remeshed), or the mesh itself when the target needs no fewer
        nodes than about its count (within 10 %)."""
        if self.source is None:
            return shape_mesh(self.generator, self.nodes, self.curvature)
        if self.nodes >= 0.9 * len(self.source.vertices):
            return self.source
        return _remeshed(self.source, self.nodes)


def shape_mesh(generator, nodes, curvature):
    """The study's mesh of a shape with about `nodes` nodes and its curvature 'computed' (Eq. 1) or 'prescribed'
    (the smooth shape's), as the table's `generator` of the shape names it: {'mesh': 'icosphere', 'parameters':
    [radius]} (nodes one of 42, 162, 642, 2562), {'mesh': 'reference_shape', 'parameters': [name]}, or a generator
    of Mesh ('spheroid', 'superellipsoid', 'rounded_tetrahedron') with its parameters [m]."""
    exact = "exact" if curvature == "prescribed" else "computed"
    kind, parameters = generator["mesh"], generator["parameters"]
    if kind == "icosphere":
        subdivisions = round(math.log((nodes - 2) / 10, 4))     # an icosphere of s subdivisions has 10 4^s + 2 nodes
        return Mesh.icosphere(*parameters, subdivisions, curvature=exact)
    if kind == "reference_shape":
        return reference_shape(*parameters, nodes, exact)
    return getattr(Mesh, kind)(*parameters, nodes, curvature=exact)


@functools.lru_cache(maxsize=32)
def _remeshed(mesh, nodes):
    """`mesh` remeshed to about `nodes` nodes on the smooth surface its nodes sample: Mesh.remeshed puts the new
    nodes on the old flat triangles, whose curvature computed at a node inside a triangle is that of a plane; each
    is moved onto the quadric fitted to the old nodes around it (on_sampled_surface), in the old mesh's input
    frame, which the new mesh keeps."""
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


def mesh_resolution(mesh):
    """{'median': q50, 'worst': q98}: quantiles (RESOLUTION_QUANTILES) over the triangles of q = longest edge [m] x
    largest |principal curvature| [1/m], the curvature estimated from the mesh's own nodes (Rusinkiewicz's estimate,
    as Mesh.from_arrays computes it), whatever curvature the mesh carries. q is the angle a triangle spans on the
    surface it samples: small where the mesh resolves its curvature. Each convex triangle weighs its area times its
    Gaussian curvature k1 k2, the share of directions its normals cover: a body touched from a random direction
    touches there with that probability (its support point's normal is that direction), which puts the contacts on
    a pill's edges and a grain's corners far more often than on their nearly flat faces, and never in a concave
    groove (weight 0)."""
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
    """(curvature, regime, law_curvature, normal) of a configuration of the table (or of the study's data)."""
    return entry["curvature"], entry["regime"], entry["law_curvature"], entry["normal"]


def _check(error, partner, pose_statistic):
    if pose_statistic not in POSE_STATISTICS:
        raise ValueError(f"pose_statistic: {pose_statistic!r} is not one of {', '.join(POSE_STATISTICS)}")
    if partner not in PARTNERS:
        raise ValueError(f"partner: {partner!r} is not one of {', '.join(PARTNERS)}")
    if not (isinstance(error, (int, float)) and 0 < error < 1):
        raise ValueError(f"error: {error!r} is not a fraction in (0, 1); 0.05 asks for 5 %")


def cheapest_model(shape_or_mesh, error, partner="both", pose_statistic="median", table=None):
    """The cheapest roundedmesh configuration whose force error is at most `error` (a fraction: 0.05 for 5 %)
    against `partner` ('both': the worse of a rigid plane and a copy; 'plane'; 'self') for `pose_statistic`
    ('median': a typical contact; 'worst': the study's worst pose), as a ModelChoice; `table` the model table
    (default: model_table.json).

    shape_or_mesh: a shape of the study ('sphere', 'pear', 'gummy_bear', 'spheroid', 'pill', 'tetra_grain'): the
    study's measured configurations; ranked by their S1 cost where the study timed that shape, else by node count,
    then by the regimes' cost on the gummy bear (the table's regimes_by_cost); at equal rank the law's default
    options come first, then the smaller error.
    Or a roundedmesh Mesh: the study's fits (module docstring), computed curvature, the fewest nodes that meet the
    target; the cost then estimated from the gummy bear's S1 cost at that node count.

    Raises ValueError naming the shape, the target and the smallest error available when nothing meets it; for a
    mesh, naming the node count of its shape the target needs when that is more than the mesh has or than the
    engine's meshes are meant for; and for an unknown shape, partner or statistic, or an error that is not a
    fraction in (0, 1)."""
    _check(error, partner, pose_statistic)
    table = model_table() if table is None else table
    if isinstance(shape_or_mesh, str):
        return _for_shape(shape_or_mesh, error, partner, pose_statistic, table)
    return _for_mesh(shape_or_mesh, error, partner, pose_statistic, table)


def _for_shape(shape, error, partner, pose_statistic, table):
    study_shape = table["shapes"].get(shape)
    if study_shape is None:
        raise ValueError(f"shape: {shape!r} is not in the speed-against-error study; it has "
                         f"{', '.join(sorted(table['shapes']))} (or pass a Mesh)")
    entries = [dict(zip(table["columns"], row)) for row in study_shape["configurations"]]
    def nrmse(e):
        return e[f"nrmse {pose_statistic} {partner}"]
    with_costs = any(e["cost_ms_per_step"] is not None for e in entries)
    offered = [e for e in entries if nrmse(e) is not None and (e["cost_ms_per_step"] is not None or not with_costs)]
    meeting = [e for e in offered if nrmse(e) <= error]
    if not meeting:
        best = min((nrmse(e) for e in offered), default=float("nan"))
        raise ValueError(f"no roundedmesh configuration of the study meets {error:.3g} NRMSE ({pose_statistic} pose, "
                         f"partner {partner}) for {shape!r}; the smallest is {best:.3g}")
    regimes = table["regimes_by_cost"]

    def rank(e):   # the cost, else the nodes and the regime's cost; then the law's defaults before its options
        regime = regimes.index(e["regime"]) if e["regime"] in regimes else len(regimes)
        options = (e["law_curvature"] != "mean") + (e["normal"] != "pressure")
        return ((e["cost_ms_per_step"],) if with_costs else (e["nodes"], regime)) + (options, nrmse(e))
    chosen = min(meeting, key=rank)
    return ModelChoice(shape, chosen["nodes"], *variant(chosen), nrmse=nrmse(chosen), pose_statistic=pose_statistic,
                       partner=partner, cost_ms_per_step=chosen["cost_ms_per_step"],
                       ranked_by="S1 cost" if with_costs else "nodes", study=table["study"],
                       generator=study_shape["generator"])


def estimated_cost(nodes, regime, table):
    """CPU ms per step of S1 with 250 bodies of `nodes` nodes, from the table's power law through the gummy bear's
    measured costs in `regime` ('auto' if that regime was not timed); None where it has none."""
    fits = table["cost_fits"]
    fit = fits[regime] if regime in fits else fits.get("auto")
    if fit is None:
        return None
    return float(math.exp(fit["intercept"] + fit["slope"] * math.log(nodes)))


def _for_mesh(mesh, error, partner, pose_statistic, table):
    if not isinstance(mesh, Mesh):
        raise TypeError(f"shape_or_mesh: expected a study shape's name or a roundedmesh.Mesh, got {mesh!r}")
    q0 = mesh_resolution(mesh)[pose_statistic]
    n0 = len(mesh.vertices)
    regimes = table["regimes_by_cost"]
    candidates = []
    for entry in table["fits"]:
        fit = ErrorFit(entry["log_c"], entry["alpha"], entry["sigma"], entry["points"])
        if entry["statistic"] != pose_statistic or entry["partner"] != partner or fit.alpha <= 0:
            continue   # only fits whose error falls with refinement can be inverted
        options = variant(entry)
        nodes = n0 * (q0 / fit.resolution_for(error)) ** 2
        rank = regimes.index(options[1]) if options[1] in regimes else len(regimes)
        candidates.append((max(nodes, NODE_RANGE[0]), rank, options, fit))
    if not candidates:
        raise ValueError(f"the study has no error fit for partner {partner!r}, {pose_statistic} pose")
    nodes, _, options, fit = min(candidates, key=lambda c: (c[0], c[1]))
    target = f"{error:.3g} NRMSE ({pose_statistic} pose, partner {partner})"
    if nodes > NODE_RANGE[1]:
        raise ValueError(f"mesh of {n0} nodes: {target} needs about {nodes:.0f} nodes of its shape, beyond the "
                         f"{NODE_RANGE[1]} the engine's meshes are meant for; the closest the study's fits reach "
                         f"there is {fit.error(q0 * math.sqrt(n0 / NODE_RANGE[1])):.3g}")
    nodes = int(math.ceil(nodes))
    if nodes > n0:
        raise ValueError(f"mesh of {n0} nodes: {target} needs about {nodes} nodes of the same shape (the study's "
                         f"fits; this mesh: {fit.error(q0):.3g}); remeshing cannot add shape: give a finer mesh of it")
    return ModelChoice(None, nodes, *options, nrmse=fit.error(q0 * math.sqrt(n0 / nodes)),
                       pose_statistic=pose_statistic, partner=partner,
                       cost_ms_per_step=estimated_cost(nodes, options[1], table), ranked_by="fit",
                       study=table["study"], source=mesh)
