"""What is declared once in C++ and read by Python (issue: one declaration of engine options and material fields):
the material's fields and its record by name, the engine's options and their defaults, the options kept in the
scene for rm.critical_timestep, and scenes saved with the older positional material records."""
import json
import math
import pickle

import pytest
from yade import ForceResetter, NewtonIntegrator, O, utils
from yade.minieigenHP import Quaternion

import roundedmesh as rm
from roundedmesh import _core

FRICTIONAL = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3, friction=0.5,
                              tangential_damping=0.2)


def test_a_material_record_names_every_field_and_restores_it():
    record = FRICTIONAL.record()
    assert tuple(record) == rm.HertzMaterial.fields
    assert rm.HertzMaterial.fields == ("young", "poisson", "density", "damping", "friction", "tangential_damping")
    assert rm.HertzMaterial(**record) == FRICTIONAL
    assert rm.HertzMaterial(*record.values()) == FRICTIONAL  # the constructor takes them in the same order
    assert all(getattr(FRICTIONAL, name) == value for name, value in record.items())
    assert repr(FRICTIONAL).startswith("HertzMaterial(young=1000000, poisson=0.4")


def test_the_engine_options_and_their_defaults_come_from_core():
    assert _core.ENGINE_OPTIONS == {"gamma": 10.0, "regime": "auto", "friction": "spring",
                                    "stop_overlap": _core.STOP_OVERLAP, "curvature": "mean", "normal": "pressure",
                                    "core_inset": 0.25, "threads": 0, "timing": "off"}
    assert _core.ENGINE_CHOICES == {"regime": ("auto", "quadrature", "direct", "exact"),
                                    "friction": ("spring", "viscous"), "curvature": ("mean", "principal"),
                                    "normal": ("pressure", "energy"), "timing": ("off", "stages")}
    assert rm.EngineOptions().record() == _core.ENGINE_OPTIONS
    assert rm.EngineOptions.fields == tuple(_core.ENGINE_OPTIONS)
    # The engine's command names its options' record in the scene, and carries none of them.
    command = rm.engine().command
    key = command[command.rindex("(") + 2:-2]
    assert command == f"__import__('roundedmesh').scene.step({key!r})"
    assert json.loads(O.tags[f"roundedmesh.options.{key}"]) == _core.ENGINE_OPTIONS
    for name in _core.ENGINE_OPTIONS:
        assert name not in command
    with pytest.raises(ValueError, match="curvature must be 'mean' or 'principal', got 'gaussian'"):
        rm.engine(curvature="gaussian")


def test_engine_options_are_one_struct_checked_by_field_and_between_fields():
    exact = rm.EngineOptions(regime="exact", stop_overlap=math.inf)
    assert exact.regime == "exact" and exact.stop_overlap == math.inf and exact.gamma == 10.0
    assert rm.EngineOptions(**exact.record()) == exact and exact != rm.EngineOptions()
    assert repr(exact).startswith("EngineOptions(gamma=10.0, regime='exact'")
    assert pickle.loads(pickle.dumps(exact)) == exact
    with pytest.raises(TypeError, match="unknown option.*gama"):
        rm.EngineOptions(gama=3)
    with pytest.raises(TypeError, match="keyword arguments only"):
        rm.EngineOptions(10.0)
    with pytest.raises(ValueError, match="threads must be a whole number"):
        rm.EngineOptions(threads=1.5)
    # The rule between fields: the energy law takes the contact circle.
    with pytest.raises(ValueError, match="normal='energy' takes the contact circle of curvature='mean'"):
        rm.EngineOptions(normal="energy", curvature="principal")
    # The same options by name or as options=, for the engine and the contact functions; not both.
    mesh = rm.Mesh.icosphere(0.01, 2)
    pose = dict(mesh=mesh, pos=(0, 0, 0.0099), ori=Quaternion.Identity, plane_point=(0, 0, 0),
                plane_normal=(0, 0, 1), mesh_material=FRICTIONAL, plane_material=FRICTIONAL)
    assert rm.plane_contact(**pose, options=exact) == rm.plane_contact(**pose, regime="exact")
    assert rm.plane_contact(**pose, options=exact) != rm.plane_contact(**pose)
    with pytest.raises(TypeError, match="together"):
        rm.plane_contact(**pose, options=exact, regime="direct")
    assert rm.engine(options=exact).command == rm.engine(regime="exact", stop_overlap=math.inf).command


def two_frictional_balls():
    first = rm.add_body(rm.Mesh.icosphere(0.01, 2), pos=(0, 0, 0), material=FRICTIONAL)
    rm.add_body(rm.Mesh.icosphere(0.01, 2), pos=(0, 0, 0.0199), material=FRICTIONAL)
    return first


def test_the_engine_options_are_kept_in_the_scene_for_critical_timestep():
    two_frictional_balls()
    viscous = rm.engine(friction="viscous")
    assert json.loads(O.tags["roundedmesh.options"])["friction"] == "viscous"
    with_viscous = rm.critical_timestep()
    rm.engine()  # the default spring: a tangential stiffness, a smaller limit
    with_spring = rm.critical_timestep()
    assert with_spring < with_viscous
    # The step's own options win: the engine in O.engines runs with friction='viscous' and records it.
    O.engines = [ForceResetter(), viscous, NewtonIntegrator(damping=0)]
    O.dt = 1e-7
    O.step()
    assert json.loads(O.tags["roundedmesh.options"])["friction"] == "viscous"
    assert rm.critical_timestep() == with_viscous


def test_a_scene_with_positional_material_records_still_runs(tmp_path):
    """Scenes saved before the records named their fields hold the material as a list in the constructor's
    order: they load and run as they did."""
    first = two_frictional_balls()
    wall = O.bodies.append(utils.wall((0, 0, -0.0099), axis=2))
    rm.assign_material(wall, FRICTIONAL)
    O.engines = [ForceResetter(), rm.engine(), NewtonIntegrator(damping=0, gravity=(0, 0, -9.81))]
    O.dt = 1e-6
    O.save(str(tmp_path / "named.yade"))
    O.step()
    named = O.forces.f(first)
    O.load(str(tmp_path / "named.yade"))
    for key in O.tags.keys():
        kind = key.split(".")[1] if key.startswith("roundedmesh.") else ""
        if kind == "body" and O.tags[key]:
            r = json.loads(O.tags[key])
            O.tags[key] = json.dumps({**r, "material": list(r["material"].values())})
        elif kind in ("partner", "sphere") and O.tags[key]:
            O.tags[key] = json.dumps(list(json.loads(O.tags[key]).values()))
    O.tags["roundedmesh.revision"] = "positional"
    O.step()
    assert O.forces.f(first) == named
    assert math.isfinite(rm.critical_timestep())


def test_a_scene_saved_before_the_options_were_kept_by_key_runs_with_its_own(tmp_path):
    """Scenes saved before issue 36 name the options in the engine's command and keep them in one tag without the
    threads: they load and run with those options, as they did."""
    first = two_frictional_balls()
    O.engines = [ForceResetter(), rm.engine(friction="viscous"), NewtonIntegrator(damping=0)]
    O.dt = 1e-7
    O.save(str(tmp_path / "keyed.yade"))
    O.step()
    keyed = O.forces.f(first)
    O.load(str(tmp_path / "keyed.yade"))
    rm.scene._forget_process_state()
    O.engines[1].command = ("__import__('roundedmesh').scene.step(gamma=10.0, regime='auto', friction='viscous', "
                            "stop_overlap=0.5, curvature='mean', normal='pressure')")
    for key in O.tags.keys():
        if key.startswith("roundedmesh.options."):
            O.tags[key] = ""  # a deleted tag
    O.tags["roundedmesh.options"] = json.dumps({"gamma": 10.0, "regime": "auto", "friction": "spring",
                                                "stop_overlap": 0.5, "curvature": "mean", "normal": "pressure"})
    O.step()
    assert O.forces.f(first) == keyed
    assert json.loads(O.tags["roundedmesh.options"])["friction"] == "viscous"
