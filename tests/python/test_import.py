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


# `import roundedmesh as rm` is enough for every submodule: rm.export.VtkSeries, rm.scenes.S3, ... Checked in a
# new process, since this one has imported them all already, against the package's own files so that a new
# module is covered too.
def test_every_submodule_comes_with_the_package():
    import roundedmesh
    folder = os.path.dirname(roundedmesh.__file__)
    names = sorted(f[:-3] for f in os.listdir(folder) if f.endswith(".py") and not f.startswith("_"))
    assert {"export", "progress", "scenes", "analytic", "validation", "benchmarking", "shapes"} <= set(names)
    script = f"import roundedmesh as rm; print('MISSING', [n for n in {names!r} if not hasattr(rm, n)])"
    out = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True, timeout=120,
                         env=os.environ)
    assert "MISSING []" in out.stdout, out.stdout + out.stderr
