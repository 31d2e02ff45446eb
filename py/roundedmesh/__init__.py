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
rm.export, rm.progress, rm.checkpoint, rm.meshfiles, rm.mpi (YADE's MPI decomposition, yade.mpy), rm.shapes, rm.model_choice, rm.placement. The code of the
validation and the studies (analytic references, the reference scenes, YADE's peers, the speed-against-error study,
benchmark helpers) is the package roundedmesh_study beside this one, which uses roundedmesh; roundedmesh never
imports it. See doc/user-guide.md.

rm.cheapest_model(shape_or_mesh, error) is the cheapest mesh and engine options that meet a force error according to
the speed-against-error study (doc/speed-vs-error.md), read from the table model_table.json shipped with the
package (rm.model_choice); rm.add_body(mesh, ..., error=0.05) applies its mesh.
"""
from . import _yade  # noqa: F401  (YADE's converters must exist before _core returns vectors)
from . import checkpoint, contact, export, meshfiles, model_choice, mpi, placement, progress, scene, shapes  # noqa: F401
from ._core import FACING_RAMP, EngineOptions, HertzMaterial, Mesh
from .contact import body_contact, partner_contact, plane_contact, sphere_contact, triangle_contacts
from .model_choice import cheapest_model
from .scene import _restore_mesh  # noqa: F401  (Mesh.__reduce__ names it as roundedmesh._restore_mesh)
from .scene import (add_body, add_sphere, assign_material, contacts, critical_timestep, engine,
                    keep_triangle_forces, rounded_bodies, set_edge_radius, set_material, set_velocity, sphere_bodies,
                    statistics, triangle_forces, unbalanced_force)
from .shapes import reference_shape

Mesh.load = staticmethod(meshfiles.load)
Mesh.reference_shape = staticmethod(reference_shape)

__all__ = ["Mesh", "HertzMaterial", "EngineOptions", "add_body", "add_sphere", "assign_material", "set_material",
           "set_edge_radius", "set_velocity", "engine",
           "critical_timestep", "statistics", "rounded_bodies", "sphere_bodies", "plane_contact", "partner_contact", "body_contact",
           "sphere_contact", "triangle_contacts", "contacts", "unbalanced_force", "keep_triangle_forces",
           "triangle_forces", "cheapest_model", "FACING_RAMP"]

