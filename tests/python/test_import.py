"""`import roundedmesh` works in `yade script.py`, in the interactive yade shell, and in Debian's
/usr/bin/python3 after `import yade`, with no sys.path or environment set by the user (the set-up
command installs the .pth files that make it so)."""
import os
import subprocess

import pytest

CHECK = "import roundedmesh; print('RM_OK', roundedmesh.Mesh.icosphere(1.0, 1).vertices.shape)"


@pytest.fixture
def clean_environment():
    return {key: value for key, value in os.environ.items() if not key.startswith("PYTHON")}


def test_in_a_yade_script(tmp_path, clean_environment):
    script = tmp_path / "script.py"
    script.write_text(CHECK + "\n")
    out = subprocess.run(["yade", "-n", "-x", str(script)], capture_output=True, text=True, timeout=120,
                         env=clean_environment)
    assert "RM_OK (42, 3)" in out.stdout, out.stdout + out.stderr


def test_in_the_interactive_yade_shell(clean_environment):
    out = subprocess.run(["yade", "-n"], input=CHECK + "\nexit()\n", capture_output=True, text=True, timeout=120,
                         env=clean_environment)
    assert "RM_OK (42, 3)" in out.stdout, out.stdout + out.stderr


def test_in_debian_python_after_import_yade(clean_environment):
    out = subprocess.run(["/usr/bin/python3", "-c", "import yade; " + CHECK], capture_output=True, text=True,
                         timeout=120, env=clean_environment)
    assert "RM_OK (42, 3)" in out.stdout, out.stdout + out.stderr


# `import roundedmesh as rm` is enough for every user module (rm.export.VtkSeries, rm.scene, ...) and imports none of
# roundedmesh.study, the validation and study code (issue 22: a lighter import). Checked in a new process, since this
# one has imported them all already, against the package's own files so that a new module is covered too.
def test_user_modules_come_with_the_package_and_the_study_does_not():
    import roundedmesh
    from roundedmesh._deprecated import MOVED
    folder = os.path.dirname(roundedmesh.__file__)
    names = sorted(f[:-3] for f in os.listdir(folder) if f.endswith(".py") and not f.startswith("_"))
    user = [n for n in names if n not in MOVED]
    assert {"scene", "contact", "export", "progress", "checkpoint", "meshfiles", "shapes"} <= set(user)
    assert set(names) - set(user) == set(MOVED)  # every moved module has its deprecated alias
    study = sorted(f[:-3] for f in os.listdir(os.path.join(folder, "study")) if f.endswith(".py") and f[0] != "_")
    assert set(MOVED) <= set(study)   # every module that moved there; the study's own new ones (grains, ...) beside
    from roundedmesh.study import MODULES
    assert study == sorted(MODULES)   # each reachable as rm.study.<name>
    script = (f"import sys; import roundedmesh as rm; print('MISSING', [n for n in {user!r} if not hasattr(rm, n)]); "
              "print('STUDY', sorted(m for m in sys.modules if m.startswith('roundedmesh.study') or "
              f"m in {['roundedmesh.' + n for n in MOVED]!r}))")
    out = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True, timeout=120,
                         env=os.environ)
    assert "MISSING []" in out.stdout and "STUDY []" in out.stdout, out.stdout + out.stderr


# Each way a user script may name a module that moved to roundedmesh.study still gives that module, with one
# DeprecationWarning naming the new place and pointing at the user's line. In a new process per way, so that
# an earlier import (which binds the name in the package) does not hide the warning.
OLD_NAME_FORMS = {
    "attribute": "import roundedmesh as rm\nmodule = rm.{name}\n",
    "from-import": "from roundedmesh import {name} as module\n",
    "import": "import roundedmesh.{name}\nmodule = roundedmesh.{name}\n",
}
OLD_NAME_CHECK = """import json, sys, warnings
import roundedmesh
from roundedmesh._deprecated import MOVED
result = {{}}
for name in MOVED:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        namespace = {{}}
        exec(compile({form!r}.format(name=name), __file__, "exec"), namespace)
    result[name] = {{"module": namespace["module"].__name__,
                    "warnings": [[w.category.__name__, str(w.message), w.filename] for w in caught]}}
print("RESULT", json.dumps(result))
"""


@pytest.mark.parametrize("form", sorted(OLD_NAME_FORMS))
def test_old_names_of_the_study_modules_work_and_warn(form, tmp_path):
    import json
    from roundedmesh._deprecated import MOVED
    script = tmp_path / "user_script.py"
    script.write_text(OLD_NAME_CHECK.format(form=OLD_NAME_FORMS[form]))
    out = subprocess.run(["/usr/bin/python3", str(script)], capture_output=True, text=True, timeout=120,
                         env=os.environ)
    lines = [line for line in out.stdout.splitlines() if line.startswith("RESULT ")]
    assert out.returncode == 0 and lines, out.stdout + out.stderr
    result = json.loads(lines[0][len("RESULT "):])
    assert sorted(result) == sorted(MOVED)
    for name, found in result.items():
        assert found["module"] == f"roundedmesh.study.{name}", (form, name, found)
        assert found["warnings"] == [["DeprecationWarning", f"roundedmesh.{name} has moved to roundedmesh.study.{name}; "
                                      f"use `from roundedmesh.study import {name}`", str(script)]], (form, name, found)


def test_the_new_places_and_cheapest_model_do_not_warn():
    import importlib
    import warnings

    import roundedmesh as rm
    from roundedmesh._deprecated import MOVED
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for name in MOVED:
            module = importlib.import_module(f"roundedmesh.study.{name}")
            assert getattr(rm.study, name) is module
        choice = rm.cheapest_model("gummy_bear", 0.05)
    assert [str(w.message) for w in caught if "roundedmesh" in str(w.message)] == []
    assert choice == rm.study.model_choice.cheapest_model("gummy_bear", 0.05)
    assert "cheapest_model" in rm.__all__ and callable(rm.cheapest_model)
