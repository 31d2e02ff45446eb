"""`import roundedmesh` works in `yade script.py`, in the interactive yade shell, and in Debian's
/usr/bin/python3 after `import yade`, with no sys.path or environment set by the user (the set-up
command installs the .pth files that make it so)."""
import ast
import importlib
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
    out = subprocess.run(["yade", "-n", "-x", str(script)], capture_output=True, text=True,
                         env=clean_environment)
    assert "RM_OK (42, 3)" in out.stdout, out.stdout + out.stderr


def test_in_the_interactive_yade_shell(clean_environment):
    out = subprocess.run(["yade", "-n"], input=CHECK + "\nexit()\n", capture_output=True, text=True,
                         env=clean_environment)
    assert "RM_OK (42, 3)" in out.stdout, out.stdout + out.stderr


def test_in_debian_python_after_import_yade(clean_environment):
    out = subprocess.run(["/usr/bin/python3", "-c", "import yade; " + CHECK], capture_output=True, text=True,
                         env=clean_environment)
    assert "RM_OK (42, 3)" in out.stdout, out.stdout + out.stderr


# `import roundedmesh as rm` is enough for every user module (rm.export.VtkSeries, rm.scene, ...) and imports nothing
# of roundedmesh_study, the validation and study code, which uses roundedmesh (issue 36: the package without its
# research). Checked in a new process, since this one has imported them all already, against the package's own files
# so that a new module is covered too.
def test_user_modules_come_with_the_package_and_the_study_does_not():
    import roundedmesh
    folder = os.path.dirname(roundedmesh.__file__)
    user = sorted(f[:-3] for f in os.listdir(folder) if f.endswith(".py") and not f.startswith("_"))
    assert {"scene", "contact", "export", "progress", "checkpoint", "meshfiles", "shapes", "model_choice"} <= set(user)
    script = (f"import sys; import roundedmesh as rm; print('MISSING', [n for n in {user!r} if not hasattr(rm, n)]); "
              "print('STUDY', sorted(m for m in sys.modules if m.startswith('roundedmesh_study')))")
    out = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True, env=os.environ)
    assert "MISSING []" in out.stdout and "STUDY []" in out.stdout, out.stdout + out.stderr


def package_imports(package):
    """{module: the modules of `package` it imports}, read from the source of the package's own files (every import
    statement, at module level or inside a function: a cycle through a function's import is still a cycle)."""
    folder = os.path.dirname(importlib.import_module(package).__file__)
    modules = {f[:-3] for f in os.listdir(folder) if f.endswith(".py")}

    def named(node):   # the dotted names an import statement reaches, relative to the package ('' for the package)
        if isinstance(node, ast.Import):
            return [a.name[len(package) + 1:] for a in node.names if a.name.startswith(package + ".")]
        base = node.module or ""
        if node.level == 0:
            if base != package and not base.startswith(package + "."):
                return []
            base = base[len(package) + 1:]
        return [base] if base else [a.name for a in node.names]
    graph = {}
    for name in modules:
        with open(os.path.join(folder, name + ".py")) as f:
            tree = ast.parse(f.read())
        reached = {dotted.split(".")[0] for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))
                   for dotted in named(node)}
        graph[name] = (reached & modules) - {name, "__init__"}
    return graph


def cycles(graph):
    """Every import cycle of `graph` ({module: imported modules}), each as the list of its modules."""
    found, state = [], {}

    def visit(module, path):
        state[module] = "open"
        for other in sorted(graph[module]):
            if state.get(other) == "open":
                found.append(path[path.index(other):] + [other])
            elif other not in state:
                visit(other, path + [other])
        state[module] = "done"
    for module in sorted(graph):
        if module not in state:
            visit(module, [module])
    return found


def test_no_import_cycle_in_the_package():
    graph = package_imports("roundedmesh")
    assert graph["bodies"] >= {"model_choice"}     # the graph is read: add_body(error=) chooses with model_choice
    assert cycles(graph) == []
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == [["a", "b", "c", "a"]]   # and a cycle would be found


def test_the_study_uses_the_package_and_cheapest_model_needs_no_study():
    import roundedmesh as rm
    import roundedmesh_study
    from roundedmesh_study import peers
    assert roundedmesh_study.__file__ != rm.__file__ and peers.scene is rm.scene
    assert "cheapest_model" in rm.__all__ and callable(rm.cheapest_model)
    assert rm.cheapest_model("gummy_bear", 0.05) == rm.model_choice.cheapest_model("gummy_bear", 0.05)
