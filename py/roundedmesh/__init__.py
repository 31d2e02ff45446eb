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

The submodules come with the package (rm.export, rm.progress, rm.scenes, rm.analytic, rm.validation,
rm.benchmarking, rm.shapes, rm.contact, rm.scene, rm.meshfiles, rm.checkpoint, rm.hertz_reference,
rm.shape_error, rm.model_choice). See doc/user-guide.md.

rm.cheapest_model(shape, error) is the cheapest mesh and regime that meets a force error according to the
speed-against-error study (doc/speed-vs-error.md).
"""
from . import _yade  # noqa: F401  (YADE's converters must exist before _core returns vectors)
from . import (analytic, benchmarking, checkpoint, contact, export, hertz_reference, meshfiles,  # noqa: F401
               model_choice, peers, progress, scene, scenes, shape_error, shapes, validation)
from ._core import HertzMaterial, Mesh, plane_contact
from .contact import body_contact, partner_contact, sphere_contact, triangle_contacts
from .scene import _restore_mesh  # noqa: F401  (Mesh.__reduce__ names it as roundedmesh._restore_mesh)
from .scene import (add_body, add_sphere, assign_material, contacts, critical_timestep, engine,
                    keep_triangle_forces, rounded_bodies, set_material, sphere_bodies, statistics, triangle_forces,
                    unbalanced_force)
from .model_choice import cheapest_model
from .shapes import reference_shape

Mesh.load = staticmethod(meshfiles.load)
Mesh.reference_shape = staticmethod(reference_shape)

__all__ = ["Mesh", "HertzMaterial", "add_body", "add_sphere", "assign_material", "set_material", "engine",
           "critical_timestep", "statistics", "rounded_bodies", "sphere_bodies", "plane_contact", "partner_contact", "body_contact",
           "sphere_contact", "triangle_contacts", "contacts", "unbalanced_force", "keep_triangle_forces",
           "triangle_forces", "cheapest_model"]
