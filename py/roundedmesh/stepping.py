"""The engine of a scene with rounded bodies (rm.engine), and its step: a YADE PyRunner that calls step() each
iteration, between ForceResetter and NewtonIntegrator. The step itself is C++ (pkg/engine/ContactStep.hpp, through
_core.SceneContacts): what stays here is building its state from the scene's tags, raising the error that stops
the run, and the warnings, from the step's report. The engine's options (EngineOptions) are kept in the scene's
tags, and its command names their record by key: the step sets them in the C++ model when the key changes, and
otherwise crosses into C++ once, for the step itself.
"""
import functools
import json
import sys
import warnings

from yade import ForceResetter, NewtonIntegrator, O, PyRunner

from ._core import DEEPEST_OVERLAP, FAST_STEP, EngineOptions, SceneContacts, partner_kind
from ._records import (_REVISION, _engine_options, _load_mesh, _material, _new_revision, _options_from_record,
                       _set_tag, _store_engine_options, _tag, _tags_named)
from .bodies import _body_or_none
from .contact import engine_options

_ENGINE_COMMAND = "__import__('roundedmesh').scene.step"
# STOP_OVERLAP, DEEPEST_OVERLAP and FAST_STEP come from _core (pkg/engine/ContactModel.hpp, ContactStep.hpp):
# past STOP_OVERLAP of the smaller side's size (a rounded body's volume-equivalent radius r_eq, a sphere's radius)
# a pair whose overlap grows stops the run; past DEEPEST_OVERLAP a pair is deeper than a Hertz contact is meant to
# reach (at the start of a run, a body placed inside another); a body that moves more than FAST_STEP of its contact
# depth in one step is warned of (doc/physics.md, "Deep overlaps and fast impacts"). DEEP_OVERLAP, the older name of
# DEEPEST_OVERLAP here, stays for scripts that use it.
DEEP_OVERLAP = DEEPEST_OVERLAP
_WARNED_PAIRS = 10


def engine(label="", options=None, **named):
    """The engine to put in O.engines between ForceResetter and NewtonIntegrator. Its options: `options=` an
    rm.EngineOptions, or its fields by name (rm.engine(regime='exact')), every one left out at its default;
    help(rm.EngineOptions) lists them (gamma, regime, friction, stop_overlap, curvature, normal, core_inset, threads,
    timing) with their
    meanings and allowed values. The options are kept in the scene (O.tags), so that O.save keeps them and
    rm.critical_timestep uses them. A body whose centre passes through a Wall, Facet or Box it was near in the step before stops the run too
    (doc/user-guide.md, "Choosing the time step")."""
    if not isinstance(label, str):
        raise TypeError(f"label: expected a string, got {label!r}")
    key = _store_engine_options(engine_options(options, **named))
    return PyRunner(command=f"{_ENGINE_COMMAND}({key!r})", iterPeriod=1, initRun=True, label=label)


def _mpi_rank():
    """This process's rank once YADE's MPI decomposition (yade.mpy) has split the scene, else -1: the engine then
    computes this process's pairs and applies the wrenches of its bodies (rm.mpi, doc/user-guide.md)."""
    mpy = sys.modules.get("yade.mpy")
    return mpy.rank if mpy is not None and getattr(O, "splitted", False) else -1


class _SceneState:
    """The contacts of the scene (_core.SceneContacts) built from one revision of its tags. Under yade.mpy (rank >=
    0) a process holds only some of the bodies: the others are kept, absent, until they arrive."""

    def __init__(self, revision, rank=-1):
        self.revision = revision
        self.contacts = SceneContacts()
        self.meshes = {}  # keeps the meshes alive, and shared between bodies, while this state lives
        self.body_ids, self.partner_ids = [], []
        materials = []
        for body_id, record in sorted(_tags_named("body").items(), key=lambda item: int(item[0])):
            r = json.loads(record)
            mesh = self.meshes.setdefault(r["mesh"], _load_mesh(r["mesh"]))
            materials.append(_material(r["material"]))
            self.contacts.add_body(int(body_id), mesh, materials[-1])
            self.body_ids.append(int(body_id))
        partners = [(int(i), r, kind) for kind in ("sphere", "partner") for i, r in _tags_named(kind).items()]
        for body_id, record, kind in sorted(partners):
            body = _body_or_none(body_id)
            if body is None and (rank < 0 or kind == "sphere"):
                continue
            materials.append(_material(json.loads(record)))
            edge_radius = _tag(f"edge_radius.{body_id}")
            edge_radius = float(edge_radius) if edge_radius else -1.0
            if kind == "sphere":
                self.contacts.add_sphere(body, materials[-1])
            elif body is None:
                self.contacts.add_absent_partner(body_id, materials[-1], edge_radius)
            else:
                self.contacts.add_partner(body, materials[-1], edge_radius)
            self.partner_ids.append(body_id)
        self.materials = materials
        self.rank = rank
        self.options = None
        self.options_key = None  # the key of the options the last step ran with (_follow)
        self.keeps_triangle_forces = False
        self.stepped_iteration = None  # O.iter of the last step computed; None before the first
        self.warned_fast = False  # whether a body has been too fast for the step (_warn_fast_bodies)

    def _apply(self, options):
        if options != self.options:
            self.contacts.set_options(options)
            if options.friction == "viscous" and (self.options is None or self.options.friction != "viscous"):
                _warn_viscous_without_damping(self.materials)
            self.options = options

    def follow(self, key, legacy):
        """Runs the next steps with the options of the engine whose command names `key`, or (a scene saved before
        the options were kept by key, whose command names them) with `legacy`; they become the scene's."""
        if key is None:
            key = "named:" + repr(sorted(legacy.items()))
        if key == self.options_key:
            return
        text = _tag("options." + key)
        options = _options_from_record(text) if text else EngineOptions(**legacy)
        self._apply(options)
        self.options_key = key
        record = json.dumps(options.record(), sort_keys=True)
        if _tag("options") != record:
            _set_tag("options", record)

    def stability(self, impact_speed=0.0):
        """(limit [s], body id, id of the other body, whether the tangential contact sets it) for the masses and
        inertias the bodies have in YADE now and the scene's engine options, and with impact_speed > 0 for impacts
        at that speed [m/s]. A body erased since the last step (the next step forgets it) puts no limit."""
        self._apply(_engine_options())
        self.options_key = None  # the next step sets its engine's own
        return self.contacts.stability_limit(O, float(impact_speed))


_state = None


def _warn_viscous_without_damping(materials):
    for m in materials:
        if m.friction > 0 and m.tangential_damping == 0 and not any(o.tangential_damping > 0 for o in materials):
            warnings.warn(f"roundedmesh: friction={m.friction:g} with tangential_damping=0 on every material under "
                          "the viscous friction law: Eq. 21 lets no contact slide and the no-slip force is zero, so "
                          "there is no friction; give a tangential damping c, or use the default friction='spring' "
                          "(doc/physics.md)", RuntimeWarning)
            break


def _current_state():
    global _state
    revision = O.tags[_REVISION] if O.tags.has_key(_REVISION) else None
    if revision is None:
        return None
    rank = _mpi_rank()
    if _state is None or _state.revision != revision or _state.rank != rank:
        _state = _SceneState(revision, rank)
    return _state


def _check_engines():
    """One roundedmesh engine, running every step, after ForceResetter and before NewtonIntegrator."""
    engines = O.engines
    ours = [i for i, e in enumerate(engines) if isinstance(e, PyRunner) and e.command.startswith(_ENGINE_COMMAND)]
    if len(ours) != 1:
        raise ValueError(f"O.engines holds {len(ours)} roundedmesh engines; it needs exactly one")
    runner = engines[ours[0]]
    if runner.iterPeriod != 1 or runner.virtPeriod != 0 or runner.realPeriod != 0:
        raise ValueError("O.engines: the roundedmesh engine must run every step (iterPeriod=1, no virtPeriod "
                         "or realPeriod)")
    before = engines[:ours[0]]
    if not any(isinstance(e, ForceResetter) for e in before) or any(isinstance(e, NewtonIntegrator) for e in before):
        raise ValueError("O.engines: the roundedmesh engine must come after ForceResetter and before "
                         "NewtonIntegrator")


def _forget(body_ids):
    for body_id in body_ids:
        _set_tag(f"body.{body_id}", "")
        _set_tag(f"partner.{body_id}", "")
        _set_tag(f"sphere.{body_id}", "")
        _set_tag(f"edge_radius.{body_id}", "")
    _new_revision()


def _stop_the_run(step):
    """Runs `step` so that an error stops the run with a message that names its cause, and no traceback.

    YADE's PyRunner prints the traceback of an exception leaving its command (PyErr_Print), then throws it on
    as "PyRunner error ... STACK TRACE ..."; the ThreadRunner of O.run logs that as a FATAL ERROR, and
    O.run(n, True) or O.step() raise it once more as a RuntimeError. The exception has to leave the
    command, since only that aborts the step before NewtonIntegrator moves the bodies without their contact
    forces (O.pause() would let the step finish) and makes a script's O.run(n, True) raise instead of
    carrying on. What can go is the traceback through roundedmesh: the error is raised with a message that
    stands alone, and the excepthook that PyErr_Print calls for it prints nothing and drops the traceback
    that YADE formats into its message. The hook is restored as soon as it has run."""
    @functools.wraps(step)
    def stopping_step(*args, **kwargs):
        try:
            step(*args, **kwargs)
        except Exception as cause:
            if getattr(cause, "stops_the_run", False):  # from the step's own retry after erased bodies
                raise
            error = RuntimeError(f"roundedmesh stopped the run at iteration {O.iter}: {cause}")
            error.stops_the_run = True
            _rewind_engines()
            _quiet_in_pyrunner(error)
            raise error from None
    return stopping_step


def _rewind_engines():
    """PyRunner, a PeriodicEngine, has counted the failed step as run (iterLast = O.iter) and would skip the
    step when the user runs again, which would then go by without contact forces: make it due again."""
    for e in O.engines:
        if isinstance(e, PyRunner) and e.command.startswith(_ENGINE_COMMAND):
            e.iterLast = O.iter - max(e.iterPeriod, 1)


def _quiet_in_pyrunner(error):
    previous = sys.excepthook

    def hook(kind, value, traceback):
        if sys.excepthook is hook:
            sys.excepthook = previous
        # Only PyRunner's PyErr_Print, whose outermost frame is its command "<string>", is kept quiet: the same
        # error escaping a script (a direct call of step) is printed as usual.
        if value is error and traceback is not None and traceback.tb_frame.f_code.co_filename == "<string>":
            sys.last_traceback = None
            return
        previous(kind, value, traceback)

    sys.excepthook = hook


@_stop_the_run
def step(options=None, **legacy):
    """One contact step on the current scene; run by the engine's PyRunner, whose command names the key of its
    options' record in the scene's tags (a scene saved before names the options themselves: `legacy`)."""
    state = _current_state()
    if state is None:
        return
    state.follow(options, legacy)
    _check_engines()
    keep = _keeps_triangle_forces()
    if keep != state.keeps_triangle_forces:
        state.contacts.keep_triangle_contacts = state.keeps_triangle_forces = keep
    report = state.contacts.step(O, state.rank)
    if "missing" in report:  # bodies erased from the scene leave the engine too
        _forget(report["missing"])
        step(options, **legacy)
        return
    if report["unstable"]:  # nothing was computed
        raise ValueError(_unstable_message(state, report["unstable"]))
    if report["stops"]:  # nothing was applied, and the step is not kept: redoing it stops again
        raise ValueError(_stop_message(state, report))
    first = state.stepped_iteration is None
    state.stepped_iteration = O.iter
    if O.trackEnergy:
        _track_energy(report["energy"])
    if first:
        _warn_deep_overlaps(state, report["deep_starts"])
    _warn_fast_bodies(state, report["fastest"])


def _keeps_triangle_forces():
    return bool(_tag("triangle_forces"))


# Energy keys in O.energy, named as YADE names its own: the elastic energy of the contacts, set every step (a state,
# as YADE's elastPotential), and the energies dissipated by normal damping and by friction, accumulated (as
# YADE's plastDissip and viscDamp). doc/physics.md, "Energy".
ELASTIC_ENERGY, NORMAL_DAMPING_ENERGY, FRICTION_ENERGY = "rmElastPotential", "rmNormDamp", "rmFrictDissip"


def _track_energy(energy):
    elastic, damping_power, friction_power = energy
    keys = set(O.energy.keys())
    O.energy[ELASTIC_ENERGY] = elastic
    for key, power in ((NORMAL_DAMPING_ENERGY, damping_power), (FRICTION_ENERGY, friction_power)):
        O.energy[key] = (O.energy[key] if key in keys else 0.0) + power * O.dt


def _unstable_message(state, unstable):
    limit, body, other, tangential = unstable
    which = "tangential contact (friction: its stiffness and tangential damping c)" if tangential else "contact"
    return (f"O.dt = {O.dt:g} s is above the stability limit {limit:g} s of the {which} between "
            f"{'rounded' if body in state.body_ids else 'sphere'} body {body} and body {other} "
            "(roundedmesh.critical_timestep()); reduce O.dt")


def _warn_deep_overlaps(state, deep):
    """Warns, after the first step of a scene's engine (and after every change of its bodies or partners), of the
    pairs that overlap by more than DEEP_OVERLAP of the smaller body's volume-equivalent radius: by their depth
    (contacts()['depth']), what the stop rule compares. The deepest triangle contact can run through two bodies at a
    slant: in a settled packing of S1 it reached 0.34 r_eq where no pair was deeper than 0.09 r_eq."""
    if not deep:
        return
    listed = "; ".join(f"bodies {a} and {b} by {overlap:.3g} m ({overlap / size:.2f} r_eq)"
                       for a, b, overlap, size in deep[:_WARNED_PAIRS])
    more = f"; and {len(deep) - _WARNED_PAIRS} more pairs" if len(deep) > _WARNED_PAIRS else ""
    warnings.warn(f"roundedmesh: {len(deep)} pair(s) start overlapped deeper than {DEEP_OVERLAP:g} of the smaller "
                  f"body's volume-equivalent radius r_eq, beyond what a Hertz contact describes: {listed}{more}. "
                  "Move the bodies apart before the run", RuntimeWarning)


def _describe(state, body_id):
    """'rounded body 3', 'sphere body 4', 'Wall 0', ... ."""
    if body_id in state.body_ids:
        return f"rounded body {body_id}"
    if _tag(f"sphere.{body_id}"):
        return f"sphere body {body_id}"
    body = _body_or_none(body_id)
    return f"{partner_kind(body) if body is not None else 'body'} {body_id}"


def _size_name(state, body_id):
    return "r_eq" if body_id in state.body_ids else "radius"


def _stop_message(state, report):
    """Why the run stops, naming the body, with the remedy: a time step for its speed, or that no step helps."""
    stops = report["stops"]
    cause, body, other, overlap, size, point = stops[0]
    where = "at ({}) m".format(", ".join(f"{round(x, 9) + 0.0:.4g}" for x in point))  # to the nanometre, no -0
    name, other_name = _describe(state, body), _describe(state, other)
    both_sized = other in state.body_ids or bool(_tag(f"sphere.{other}"))
    unit = _size_name(state, body) if not both_sized or _size_name(state, body) == _size_name(state, other) else "size"
    if cause == "crossed":
        what = (f"the centre of {name} has passed through {other_name} since the last step (their bounds overlapped "
                f"then), and the contact now pushes it on through; it is {where}")
    else:
        what = (f"{name} overlaps {other_name} by {overlap:.3g} m ({overlap / size:.2f} "
                f"{'of the smaller ' + unit if both_sized else unit}, {unit} = {size:.3g} m) {where}, and the overlap grows: "
                f"past {state.options.stop_overlap:g} {unit} (rm.engine(stop_overlap=...)) the contact no longer "
                "describes it")
    speed, bound = report["stop_speed"], report["stop_time_step"]
    own = _size_name(state, body)
    own_size = size if not both_sized else None
    if speed > 0:
        moves = f"{speed * O.dt / own_size:.2g} {own}" if own_size else f"{speed * O.dt:.3g} m"
        if O.dt > bound:
            advice = (f"At {speed:.3g} m/s it moves {moves} per step (O.dt = {O.dt:.3g} s): reduce O.dt to "
                      f"rm.critical_timestep(impact_speed={speed:.3g}) = {bound:.3g} s or less and start again from a "
                      "state before the impact (rm.checkpoint)")
        else:
            advice = (f"O.dt = {O.dt:.3g} s is already within rm.critical_timestep(impact_speed={speed:.3g}) = "
                      f"{bound:.3g} s: no smaller step helps, the contact cannot hold these bodies apart (an impact "
                      "too fast, or a load too large, for such soft materials)")
    else:
        advice = "The bodies are at rest: the contact cannot hold them apart (a load too large for such soft materials)"
    more = ""
    if len(stops) > 1:
        others = [f"{_describe(state, b)} with {_describe(state, o)}" for _, b, o, *_ in stops[1:4]]
        more = f" Also: {'; '.join(others)}{'; ...' if len(stops) > 4 else ''}."
    return f"{what}. {advice}.{more}"


def _warn_fast_bodies(state, fastest):
    """Warns, once per run, of a body that moved more than FAST_STEP of its contact depth in the last step."""
    body, speed, fraction, depth, bound = fastest
    if state.warned_fast or not fraction > FAST_STEP:
        return
    state.warned_fast = True
    warnings.warn(f"roundedmesh: {_describe(state, body)} moves {fraction:.2g} of its contact depth ({depth:.3g} m, "
                  f"0.1 {_size_name(state, body)}) in one step at {speed:.3g} m/s with O.dt = {O.dt:.3g} s: an impact "
                  f"at this speed is not resolved; use O.dt <= rm.critical_timestep(impact_speed={speed:.3g}) = "
                  f"{bound:.3g} s", RuntimeWarning)
