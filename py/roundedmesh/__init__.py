"""roundedmesh: triangulated rounded bodies in YADE, with contact forces from the integrated Hertz
pressure of B. Smeets, T. Odenthal, J. Keresztes, S. Vanmaercke, P. Van Liedekerke, E. Tijskens, W. Saeys,
H. Van Oosterwyck and H. Ramon, "Modeling contact interactions between triangulated rounded bodies for the
discrete element method", Comput. Methods Appl. Mech. Engrg. 277 (2014) 219-238, doi:10.1016/j.cma.2014.04.017.

    import roundedmesh as rm
    mesh = rm.Mesh.icosphere(0.025, 3)
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3)
    ball = rm.add_body(mesh, pos=(0, 0, 0.05), material=rubber)
    floor = O.bodies.append(utils.wall(0, axis=2))
    rm.assign_material(floor, rm.HertzMaterial(young=5e6, poisson=0.4, density=2000, damping=1e-3))
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]

The user's modules come with the package: rm.scene (written as rm.bodies, rm.stepping and rm.readout), rm.contact,
rm.export, rm.progress, rm.checkpoint, rm.meshfiles, rm.shapes. The code of the validation and the studies (analytic references, the reference scenes,
YADE's peers, the speed-against-error study, benchmark helpers) is in the subpackage roundedmesh.study, imported
on first use (`from roundedmesh.study import scenes`, or rm.study.scenes); its modules' old names here
(rm.validation, `import roundedmesh.scenes`, ...) still work, with a DeprecationWarning. See doc/user-guide.md.

rm.cheapest_model(shape_or_mesh, error) is the cheapest mesh and engine options that meet a force error according to
the speed-against-error study (doc/speed-vs-error.md); rm.add_body(mesh, ..., error=0.05) applies its mesh.
"""
import importlib

from . import _yade  # noqa: F401  (YADE's converters must exist before _core returns vectors)
from . import _deprecated
from . import checkpoint, contact, export, meshfiles, progress, scene, shapes  # noqa: F401
from ._core import HertzMaterial, Mesh, plane_contact
from .contact import body_contact, partner_contact, sphere_contact, triangle_contacts
from .scene import _restore_mesh  # noqa: F401  (Mesh.__reduce__ names it as roundedmesh._restore_mesh)
from .scene import (add_body, add_sphere, assign_material, contacts, critical_timestep, engine,
                    keep_triangle_forces, rounded_bodies, set_material, sphere_bodies, statistics, triangle_forces,
                    unbalanced_force)
from .shapes import reference_shape

Mesh.load = staticmethod(meshfiles.load)
Mesh.reference_shape = staticmethod(reference_shape)

__all__ = ["Mesh", "HertzMaterial", "add_body", "add_sphere", "assign_material", "set_material", "engine",
           "critical_timestep", "statistics", "rounded_bodies", "sphere_bodies", "plane_contact", "partner_contact", "body_contact",
           "sphere_contact", "triangle_contacts", "contacts", "unbalanced_force", "keep_triangle_forces",
           "triangle_forces", "cheapest_model"]


def cheapest_model(shape_or_mesh, error, partner="both", pose_statistic="median", data=None):
    """The cheapest roundedmesh configuration (mesh nodes, curvature, the engine's regime, curvature and normal)
    whose force error meets `error`, a fraction (0.05 for 5 %), against `partner` ('both', 'plane', 'self') for
    `pose_statistic` ('median' or 'worst'), as a ModelChoice: for a shape of the speed-against-error study (by name)
    the study's measurement, for any Mesh the study's fits of error against the mesh's resolution, remeshing it
    coarser where the target allows. ModelChoice.mesh() is its mesh, ModelChoice.engine_options go to
    rm.engine(**...). Raises ValueError when nothing meets the target. roundedmesh.study.model_choice, imported on
    first call, has the details."""
    from .study.model_choice import cheapest_model as choose
    return choose(shape_or_mesh, error, partner=partner, pose_statistic=pose_statistic, data=data)


def __getattr__(name):
    """rm.study, imported on first use; the modules that moved there under their old names (rm.validation, ...),
    with a DeprecationWarning (PEP 562)."""
    if name == "study":
        return importlib.import_module(".study", __name__)
    if name in _deprecated.MOVED:
        return _deprecated.moved(name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | {"study"})
