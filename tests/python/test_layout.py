"""The C++ core's folders follow its two libraries and YADE's roles, and no include points up (issue 36): a folder
includes only its own headers and those of the folders below it in LAYERS, the order doc/architecture.md gives."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Lowest first. roundedmesh_contact is common to engine, roundedmesh_meshing (CGAL) is meshing and io.
LAYERS = ["common", "math", "shape", "bound", "material", "phys", "geom", "law", "engine", "meshing", "io"]
CONTACT_LIBRARY = LAYERS[:LAYERS.index("engine") + 1]
INCLUDE = re.compile(r'#include "pkg/([a-z]+)/')


def includes():
    """(folder, included folder, file) of every include of another pkg/ folder."""
    for path in sorted((ROOT / "pkg").rglob("*.[ch]pp")):
        folder = path.parent.name
        for included in INCLUDE.findall(path.read_text()):
            if included != folder:
                yield folder, included, path.relative_to(ROOT)


def test_every_folder_has_a_layer():
    assert sorted(p.name for p in (ROOT / "pkg").iterdir() if p.is_dir()) == sorted(LAYERS)


def test_no_include_points_up():
    upward = [f"{file}: {folder} includes {included}" for folder, included, file in includes()
              if LAYERS.index(included) > LAYERS.index(folder)]
    assert upward == []


def test_the_contact_library_uses_nothing_of_the_meshing_library():
    assert [str(file) for folder, included, file in includes()
            if folder in CONTACT_LIBRARY and included not in CONTACT_LIBRARY] == []


def test_the_libraries_are_made_of_whole_folders():
    cmake = (ROOT / "CMakeLists.txt").read_text()
    contact = cmake[cmake.index("CONTACT_SOURCES CONFIGURE_DEPENDS"):cmake.index("add_library(roundedmesh_contact")]
    meshing = cmake[cmake.index("MESHING_SOURCES CONFIGURE_DEPENDS"):cmake.index("add_library(roundedmesh_meshing")]
    assert sorted(re.findall(r"pkg/([a-z]+)/\*\.cpp", contact)) == sorted(set(CONTACT_LIBRARY) - {"common"})
    assert sorted(re.findall(r"pkg/([a-z]+)/\*\.cpp", meshing)) == ["io", "meshing"]
