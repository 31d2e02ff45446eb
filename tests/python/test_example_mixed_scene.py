"""scripts/examples/example_mixed_scene.py, the mixed scene of doc/user-guide.md, runs as written, and the guide
shows the script's scene line for line."""
import os
import re
import subprocess
import textwrap
import xml.etree.ElementTree as ElementTree

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
SCRIPT = os.path.join(ROOT, "scripts", "examples", "example_mixed_scene.py")
GUIDE = os.path.join(ROOT, "doc", "user-guide.md")


def test_the_guide_shows_the_scene_of_the_script():
    with open(SCRIPT) as f:
        script = f.read()
    scene = script.split("# --- the scene of doc/user-guide.md, \"A mixed scene\" ---\n")[1].split(
        "    # --- end of the scene ---")[0]
    scene = textwrap.dedent(scene)  # the script's main() holds it, one level in
    with open(GUIDE) as f:
        guide = f.read()
    section = guide.split("## A mixed scene")[1]
    block = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    assert block.startswith(scene), "doc/user-guide.md, A mixed scene: the code differs from the script's"


# 600 steps (43 ms at dt = 71 us): the bodies are still falling, but every engine has run, and the ParaView series has
# the rounded bodies and the spheres as parts 0 and 1 of each frame.
def test_the_script_runs(tmp_path):
    out = subprocess.run(["/usr/bin/python3", SCRIPT, "--steps", "600", "--vtk", str(tmp_path)], capture_output=True,
                         text=True, env=os.environ)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "after 600 steps" in out.stdout and "Traceback" not in out.stderr, out.stdout + out.stderr
    datasets = ElementTree.parse(tmp_path / "mixed.pvd").getroot().findall("Collection/DataSet")
    assert [d.get("part") for d in datasets] == ["0", "1"] * 3  # frames at 0, 20 and 40 ms
    assert all((tmp_path / d.get("file")).exists() for d in datasets)
