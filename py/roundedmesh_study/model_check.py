"""Does rm.cheapest_model choose well for a mesh it has not seen? (issue 27; doc/speed-vs-error.md, "Any mesh";
scripts/studies/model_choice_check.py runs it)

For a shape of the study and a target error, the shape's 2200-node mesh (the 2562-node icosphere for the sphere) is
handed to rm.cheapest_model as a plain Mesh, as a user's STL would be: it predicts from the study's fits the fewest
nodes and the law options that meet the target, and remeshes the mesh to them, or refuses, naming the nodes the
target needs, when that is more than the mesh has. The choice is then measured as the study measures its
configurations (shape_error: the same poses, partners and references), and set against the cheapest configuration
the study measured for that shape and target (rm.cheapest_model by name):

    met          the choice's measured error (the worse of plane and copy, the pose statistic asked) <= the target
    cost ratio   its S1 cost over the cheapest measured configuration's, and over the cheapest with the curvature
                 computed from the mesh (all a user's mesh can have; prescribed curvature needs the smooth shape):
                 the gummy bear's cost model at both node counts where the shape's own costs are missing, so that
                 both sides are estimated alike
"""
import numpy as np
import roundedmesh as rm
from roundedmesh.model_choice import estimated_cost

from . import shape_error as se

SHAPES = ("sphere", "pear", "gummy_bear", "spheroid", "pill", "tetra_grain")


def measured_error(name, choice, poses, statistic):
    """The study's error of `choice` (a ModelChoice for a mesh of `name`): the worse of plane and copy, the
    `statistic` over the poses where the shape has a reference, as a fraction."""
    mesh = choice.mesh()
    representation = se.RoundedMesh(mesh, se.remeshed_frame(name, mesh), choice.regime, choice.law_curvature,
                                    choice.normal)
    common = se.SmoothShape(name)
    per_partner = {}
    for partner in se.PARTNERS:
        errors = []
        for upper, lower in poses:
            lower = None if partner == "plane" else lower
            reference = se.press_geometry(common, upper, lower)
            if reference.left_out:
                continue
            geometry = se.press_geometry(representation.shape, upper, lower)
            errors.append(se.pose_errors(representation, geometry, reference=reference.reference(se.overlaps()))[0])
        per_partner[partner] = np.median(errors) if statistic == "median" else np.max(errors)
    return max(per_partner.values())


def computed_only(table, name):
    """`table` (roundedmesh.model_choice's) with only the configurations of `name` whose curvature is computed."""
    curvature = table["columns"].index("curvature")
    shape = table["shapes"][name]
    return {**table, "shapes": {name: {**shape, "configurations": [row for row in shape["configurations"]
                                                                   if row[curvature] == "computed"]}}}


def check(name, target, poses, statistic, table):
    """One row of the check's table for shape `name` at `target` (a fraction) over `poses` (validation.pair_poses)
    for the pose `statistic`, from the model table `table`: the choice, predicted and measured errors [%], whether
    it meets the target, or the refusal; the cheapest measured configuration, overall and with computed curvature,
    and the choice's cost ratio to each."""
    row = {"shape": name, "target [%]": 100 * target, "statistic": statistic}
    try:
        choice = rm.cheapest_model(se.source_mesh(name), target, pose_statistic=statistic, table=table)
    except ValueError as refusal:
        row.update({"choice": f"refused: {refusal}", "predicted [%]": None, "measured [%]": None, "met": None})
        choice = None
    else:
        error = measured_error(name, choice, poses, statistic)
        nodes = len(choice.mesh().vertices)
        row.update({"choice": f"{nodes} nodes, {choice.regime}, {choice.law_curvature}, {choice.normal}",
                    "predicted [%]": 100 * choice.nrmse, "measured [%]": 100 * error, "met": error <= target})
    ours = None if choice is None else estimated_cost(len(choice.mesh().vertices), choice.regime, table)
    for kind, study in (("", table), (", computed", computed_only(table, name))):
        try:
            best = rm.cheapest_model(name, target, pose_statistic=statistic, table=study)
        except ValueError:
            best = None
        theirs = None if best is None else (best.cost_ms_per_step if best.cost_ms_per_step is not None
                                            else estimated_cost(best.nodes, best.regime, table))
        row[f"cheapest measured{kind}"] = "none" if best is None else (
            f"{best.nodes} nodes, {best.curvature}, {best.regime}, {best.law_curvature}, {best.normal}: "
            f"{100 * best.nrmse:.3g} %")
        row[f"cost ratio{kind}"] = None if ours is None or theirs is None else ours / theirs
    return row
