"""Rounded bodies in a YADE scene: creating them, naming their contact partners, the engine that adds their contact
forces each step, and what that step computed. This module gathers the scene's API, written along its concerns:
    bodies.py     rounded bodies, sphere bodies and the materials of contact partners (add_body, add_sphere,
                  assign_material, set_material, set_edge_radius, set_velocity, rounded_bodies, sphere_bodies)
    stepping.py   the engine (rm.engine) and its step: a PyRunner calling step(), which runs the C++ contact step
                  (pkg/engine/ContactStep.hpp) and raises or warns from its report
    readout.py    what the last step computed (contacts, statistics, triangle_forces, unbalanced_force) and the
                  time step the contacts allow (critical_timestep)
    _records.py   what roundedmesh keeps of a scene in its O.tags, so that O.save / O.load keep the rounded bodies
A saved scene's engine calls roundedmesh.scene.step: that name stays.
"""
from . import _records, stepping
from ._core import DEEPEST_OVERLAP, FAST_STEP, STOP_OVERLAP  # noqa: F401
from ._records import _restore_mesh, _tags_named  # noqa: F401
from .bodies import (add_body, add_sphere, assign_material, rounded_bodies, set_edge_radius, set_material,  # noqa: F401
                     set_velocity, sphere_bodies)
from .readout import (contacts, critical_timestep, keep_triangle_forces, statistics,  # noqa: F401
                      triangle_forces, unbalanced_force)
from .stepping import (DEEP_OVERLAP, ELASTIC_ENERGY, FRICTION_ENERGY, NORMAL_DAMPING_ENERGY,  # noqa: F401
                       _current_state, engine, step)


def _forget_process_state():
    """Forgets what this process holds of any scene (the engine's state, the meshes shared between bodies), as a
    new process would find it: for tests of O.save / O.load."""
    stepping._state = None
    _records._meshes.clear()
    _records._keys.clear()
