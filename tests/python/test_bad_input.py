"""Bad input gets an exception that names the argument, and the scene is left as it was."""
import math
import os
import pickle
import warnings
import subprocess
import textwrap

import numpy as np
import pytest
from yade import ForceResetter, NewtonIntegrator, O, PolyhedraMat, polyhedra_utils, utils
from yade.minieigenHP import Quaternion

import roundedmesh as rm

RUBBER = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000)


def scene_snapshot():
    return len(O.bodies), {key: O.tags[key] for key in O.tags.keys()}


@pytest.mark.parametrize("arguments, named", [
    (dict(young=-1e6, poisson=0.3, density=1000), "young"),
    (dict(young=0.0, poisson=0.3, density=1000), "young"),
    (dict(young=math.nan, poisson=0.3, density=1000), "young"),
    (dict(young=1e6, poisson=0.5, density=1000), "poisson"),
    (dict(young=1e6, poisson=-1.0, density=1000), "poisson"),
    (dict(young=1e6, poisson=0.3, density=0.0), "density"),
    (dict(young=1e6, poisson=0.3, density=1000, damping=-0.1), "damping"),
    (dict(young=1e6, poisson=0.3, density=1000, friction=math.nan), "friction"),
])
def test_material_out_of_range(arguments, named):
    with pytest.raises(ValueError, match=named):
        rm.HertzMaterial(**arguments)


@pytest.mark.parametrize("radius, subdivisions, named", [
    (-1.0, 2, "radius"), (0.0, 2, "radius"), (math.inf, 2, "radius"), (1.0, -1, "subdivisions"),
    (1.0, 9, "subdivisions")])
def test_icosphere_arguments(radius, subdivisions, named):
    with pytest.raises(ValueError, match=named):
        rm.Mesh.icosphere(radius, subdivisions)


def test_mesh_without_volume():
    flat = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
    with pytest.raises(ValueError, match="volume"):
        rm.Mesh(flat, [[0, 1, 2], [0, 2, 1]], 1.0)


def test_mesh_arrays():
    sphere = rm.Mesh.icosphere(1.0, 1)
    with pytest.raises(ValueError, match="radius"):
        rm.Mesh(sphere.vertices, sphere.triangles, 0.0)
    with pytest.raises(ValueError, match="radius"):
        rm.Mesh(sphere.vertices, sphere.triangles, np.ones(3))
    with pytest.raises(ValueError, match="triangles"):
        rm.Mesh(sphere.vertices, sphere.triangles + 0.5, 1.0)
    with pytest.raises(ValueError, match="vertices"):
        rm.Mesh(sphere.vertices[:, :2], sphere.triangles, 1.0)
    broken = sphere.vertices.copy()
    broken[7, 1] = math.nan
    with pytest.raises(ValueError, match=r"1 vertex with a non-finite coordinate, first vertex 7 \(.*, nan, "):
        rm.Mesh(broken, sphere.triangles, 1.0)


@pytest.mark.parametrize("change, named", [
    (dict(pos=(0, math.nan, 0)), "pos"),
    (dict(pos=(0, 0)), "pos"),
    (dict(pos="123"), "pos"),
    (dict(ori=Quaternion(math.nan, 0, 0, 1)), "ori"),
    (dict(ori=(1, 0, 0, 0)), "ori"),
    (dict(material=None), "material"),
    (dict(mesh="sphere.stl"), "mesh"),
])
def test_add_body_leaves_the_scene_as_it_was(change, named):
    rm.add_body(rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 0), material=RUBBER)
    before = scene_snapshot()
    arguments = dict(mesh=rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 1), material=RUBBER)
    arguments.update(change)
    with pytest.raises((TypeError, ValueError), match=named):
        rm.add_body(**arguments)
    assert scene_snapshot() == before


def test_open_meshes_name_the_edge_and_misoriented_ones_are_turned():
    sphere = rm.Mesh.icosphere(1.0, 1)
    with pytest.raises(ValueError, match=r"3 boundary edges \(the surface is not closed\), first at the edge from vertex"):
        rm.Mesh(sphere.vertices, sphere.triangles[1:], 1.0)
    flipped = sphere.triangles.copy()
    flipped[5] = flipped[5][::-1]
    turned = rm.Mesh(sphere.vertices, flipped, 1.0)
    assert turned.volume == pytest.approx(sphere.volume, rel=1e-14)
    np.testing.assert_allclose(turned.normals, sphere.normals, atol=1e-15)


def test_radius_errors_name_the_argument():
    sphere = rm.Mesh.icosphere(1.0, 1)
    with pytest.raises(ValueError, match="^radius: triangle 0 has radius nan"):
        rm.Mesh(sphere.vertices, sphere.triangles, math.nan)


def test_assign_material_checks_the_body_and_the_material():
    rm.add_body(rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 1), material=RUBBER)
    polyhedron = O.bodies.append(polyhedra_utils.polyhedra(PolyhedraMat(), size=(0.1, 0.1, 0.1)))
    wall = O.bodies.append(utils.wall(0, axis=2))
    before = scene_snapshot()
    with pytest.raises(ValueError, match="body_id: there is no body 99"):
        rm.assign_material(99, RUBBER)
    with pytest.raises(TypeError, match="material"):
        rm.assign_material(wall, None)
    with pytest.raises(ValueError, match=f"body {polyhedron}: a Polyhedra cannot be"):
        rm.assign_material(polyhedron, RUBBER)
    for not_an_id in (True, -1, 1.0, "1"):
        with pytest.raises(TypeError, match="body_id: expected a body id"):
            rm.assign_material(not_an_id, RUBBER)
    assert scene_snapshot() == before


def test_two_rigid_bodies_cannot_be_partners():
    rigid = rm.HertzMaterial(young=math.inf, poisson=0.3, density=7800)
    ball = rm.add_body(rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 1), material=rigid)
    wall = O.bodies.append(utils.wall(0, axis=2))
    before = scene_snapshot()
    with pytest.raises(ValueError, match=f"material: a rigid material .* rigid rounded bod\\(ies\\) {ball}"):
        rm.assign_material(wall, rigid)
    assert scene_snapshot() == before
    rm.assign_material(wall, RUBBER)  # a rigid body against a deformable partner is fine

    O.reset()
    rigid_wall = O.bodies.append(utils.wall(0, axis=2))
    rm.assign_material(rigid_wall, rigid)
    before = scene_snapshot()
    with pytest.raises(ValueError, match=f"rigid bod\\(ies\\) {rigid_wall}"):
        rm.add_body(rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 1), material=rigid)
    assert scene_snapshot() == before

    O.reset()
    first = rm.add_body(rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 1), material=rigid)
    before = scene_snapshot()
    with pytest.raises(ValueError, match=f"rigid bod\\(ies\\) {first}"):
        rm.add_body(rm.Mesh.icosphere(0.02, 1), pos=(0, 0, 2), material=rigid)
    assert scene_snapshot() == before


def test_engine_options():
    with pytest.raises(TypeError, match="unknown option.*gama"):
        rm.engine(gama=3)
    with pytest.raises(ValueError, match="gamma"):
        rm.engine(gamma=-1)
    with pytest.raises(ValueError, match="regime"):
        rm.engine(regime="trapezoid")
    with pytest.raises(TypeError, match="regime"):
        rm.engine(regime=3)
    with pytest.raises(TypeError, match="label"):
        rm.engine(label=3)
    with pytest.raises(TypeError, match="gamma"):
        rm.engine(gamma="ten")


def test_plane_contact_arguments():
    mesh = rm.Mesh.icosphere(1.0, 1)
    args = dict(mesh=mesh, pos=(0, 0, 0.99), ori=Quaternion.Identity, plane_point=(0, 0, 0),
                plane_normal=(0, 0, 1), mesh_material=RUBBER, plane_material=RUBBER)
    for name, bad in [("pos", (0, 0, math.nan)), ("plane_normal", (0, 0, 0)), ("vel", (math.inf, 0, 0))]:
        with pytest.raises(ValueError, match=name):
            rm.plane_contact(**{**args, name: bad})


def bouncing_sphere_scene():
    ball = rm.add_body(rm.Mesh.icosphere(0.025, 2), pos=(0, 0, 0.0249), material=RUBBER)
    wall = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(wall, RUBBER)
    return ball


def test_time_step_above_the_stability_limit_stops_the_run_before_any_force():
    ball = bouncing_sphere_scene()
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = 1.5 * rm.critical_timestep()
    with pytest.raises(RuntimeError, match=f"stability limit .* rounded body {ball}"):
        O.run(5, True)
    assert O.iter == 0
    assert O.bodies[ball].state.pos == (0, 0, 0.0249)
    O.dt = 0.5 * rm.critical_timestep()
    O.run(5, True)
    assert O.iter == 5


def test_engine_out_of_order():
    bouncing_sphere_scene()
    O.engines = [rm.engine(), ForceResetter(), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-5
    with pytest.raises(RuntimeError, match="after ForceResetter and before NewtonIntegrator"):
        O.run(1, True)


# O.engines is checked every step, not only the first: a later edit is caught too.
@pytest.mark.parametrize("edit, message", [
    (lambda e: [e[0], e[2], e[1]], "after ForceResetter and before NewtonIntegrator"),
    (lambda e: [e[0], e[1], rm.engine(), e[2]], "2 roundedmesh engines"),
    (lambda e: [e[0], rm.engine(label="slow"), e[2]], None),
])
def test_engines_edited_during_a_run(edit, message):
    bouncing_sphere_scene()
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = 1e-5
    O.run(3, True)
    engines = edit(O.engines)
    if message is None:  # an engine that does not run every step
        engines[1].iterPeriod = 2
        message = "must run every step"
    O.engines = engines
    with pytest.raises(RuntimeError, match=message):
        O.run(3, True)


# Under the paper's viscous law, Eq. 21 never lets a contact slide without tangential damping, and the no-slip force
# is then zero: friction without c does nothing, which the user hears about once. The default spring needs no c.
def test_friction_without_tangential_damping_is_announced():
    bouncing_sphere_scene()
    rm.assign_material(1, rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, friction=0.5))
    O.engines = [ForceResetter(), rm.engine(friction="viscous"), NewtonIntegrator(damping=0)]
    O.dt = 1e-5
    with pytest.warns(RuntimeWarning, match="friction=0.5 .* tangential_damping=0 .* viscous .* no friction"):
        O.step()
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0)]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        O.step()


def test_an_unknown_friction_law_is_refused():
    with pytest.raises(ValueError, match="friction must be 'spring' or 'viscous', got 'dry'"):
        rm.engine(friction="dry")
    with pytest.raises(TypeError, match="friction: expected a string"):
        rm.engine(friction=1)


# A mesh given far from the origin (here 100 m away, 4000 radii) pickles and comes back exactly.
def test_material_and_mesh_pickle_round_trip():
    sphere = rm.Mesh.icosphere(0.025, 3)
    mesh = rm.Mesh(sphere.vertices + [3.0, 100.0, -40.0], sphere.triangles, 0.025)
    copy = pickle.loads(pickle.dumps(mesh))
    np.testing.assert_array_equal(copy.vertices, mesh.vertices)
    np.testing.assert_array_equal(copy.centroid, mesh.centroid)
    assert pickle.loads(pickle.dumps(RUBBER)) == RUBBER


# An error in the engine stops the run and reaches the user without a traceback through roundedmesh or
# YADE's PyRunner: YADE reports it as it reports its own engines' errors (ThreadRunner's FATAL ERROR line for
# O.run; nothing for O.step), and the caller gets it as the RuntimeError of O.run(n, True) or O.step(). Left
# uncaught, it ends the script with the script's own one-frame traceback. Run in a new process to see what a
# user sees on the terminal.
def test_an_engine_error_is_reported_without_tracebacks(tmp_path):
    script = tmp_path / "too_large_a_step.py"
    script.write_text(textwrap.dedent("""
        import roundedmesh as rm
        from yade import O
        from roundedmesh_study.scenes import build_bouncing_sphere
        build_bouncing_sphere(1)
        O.dt = 1.5 * rm.critical_timestep()
        for run in (lambda: O.run(5, True), O.step):
            try:
                run()
            except RuntimeError as error:
                print("CAUGHT", str(error).count("roundedmesh stopped the run at iteration 0: O.dt = "))
        print("ITERATION", O.iter)
        O.run(5, True)
    """))
    out = subprocess.run(["/usr/bin/python3", str(script)], capture_output=True, text=True,
                         env=os.environ)
    assert out.returncode == 1
    assert "CAUGHT 2\nCAUGHT 2\nITERATION 0\n" in out.stdout, out.stdout + out.stderr
    # Once for each O.run, in YADE's FATAL ERROR report; the uncaught one once more with its traceback.
    assert out.stderr.count("FATAL ERROR") == 2, out.stderr
    assert out.stderr.count("Traceback") == 1, out.stderr
    traceback = out.stderr[out.stderr.index("Traceback"):]
    assert 'too_large_a_step.py", line 13, in <module>\n    O.run(5, True)\nRuntimeError: PyRunner error.' in traceback
    assert "roundedmesh/scene.py" not in out.stderr
    assert "stability limit" in traceback and "reduce O.dt" in traceback
