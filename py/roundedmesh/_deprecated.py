"""The modules that moved from roundedmesh to roundedmesh.study (issue 22). Their old names keep working, with a
DeprecationWarning that names the new place:

    rm.validation, from roundedmesh import validation    roundedmesh.__getattr__ (PEP 562) -> moved()
    import roundedmesh.validation                         the alias module roundedmesh/validation.py -> alias()

Either way the module is roundedmesh.study.validation itself, not a copy."""
import importlib
import os
import sys
import warnings

MOVED = ("analytic", "benchmarking", "hertz_reference", "model_choice", "peers", "scenes", "shape_error", "validation")

_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _caller_stacklevel():
    """The stacklevel of warnings.warn in moved() that names the first frame outside this package and the import
    machinery: the user's `import` or attribute access, so that the warning shows where Python shows a
    DeprecationWarning (in __main__, and in pytest). warnings.warn does not count the frames of importlib's
    bootstrap, so neither does this."""
    frame, level = sys._getframe(1), 1   # moved()
    while frame.f_back is not None:
        frame = frame.f_back
        name = frame.f_code.co_filename
        if "importlib" in name and "_bootstrap" in name:
            continue
        level += 1
        if not os.path.abspath(name).startswith(_PACKAGE + os.sep):
            break
    return level


def _probed_by_from_import():
    """Whether the attribute lookup that called moved() is importlib's probe (hasattr in _handle_fromlist): `from
    roundedmesh import validation` looks the name up twice, there and then in the statement itself, which warns."""
    code = sys._getframe(3).f_code   # this <- moved() <- roundedmesh.__getattr__ <- the lookup
    return code.co_name == "_handle_fromlist" and "importlib" in code.co_filename


def moved(name):
    """The module roundedmesh.study.<name>, with a DeprecationWarning for its old name roundedmesh.<name>."""
    if not _probed_by_from_import():
        warnings.warn(f"roundedmesh.{name} has moved to roundedmesh.study.{name}; use "
                      f"`from roundedmesh.study import {name}`", DeprecationWarning, stacklevel=_caller_stacklevel())
    return importlib.import_module(f"roundedmesh.study.{name}")


def alias(old):
    """Makes the alias module `old` (roundedmesh.<name>, being imported) the module roundedmesh.study.<name>."""
    sys.modules[old] = moved(old.rpartition(".")[2])
