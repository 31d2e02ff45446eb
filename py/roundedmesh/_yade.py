"""Imports YADE, from Debian's yade-double build if the `yade` module is not already importable.

Debian's own link for `import yade` points to a directory that does not exist; `yade script.py` and the
yade shell have YADE loaded already, plain /usr/bin/python3 needs the path added. The set-up command
(tools/setup) installs a .pth file for it too; this keeps `import roundedmesh` working without it.
"""
import sys

YADE_PYTHON_DIR = "/usr/lib/x86_64-linux-gnu/yade-double/py"

try:
    import yade  # noqa: F401
except ImportError:
    sys.path.append(YADE_PYTHON_DIR)
    import yade  # noqa: F401
