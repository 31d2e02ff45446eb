"""pytest set-up: every test starts from, and leaves, an empty YADE scene; scene parts shared by tests."""
import pytest

import roundedmesh  # noqa: F401  (imports YADE)
from yade import O, utils


@pytest.fixture(autouse=True)
def empty_scene():
    O.reset()
    yield
    O.reset()


def open_box(half_width, material):
    """A floor (z = 0) and four Walls at x, y = -half_width, half_width [m], made contact partners of `material`.
    Returns their ids, the floor first."""
    walls = [O.bodies.append(utils.wall(0, axis=2, sense=1))]
    for axis in (0, 1):
        for side, sense in ((-half_width, 1), (half_width, -1)):
            walls.append(O.bodies.append(utils.wall(side, axis=axis, sense=sense)))
    for wall in walls:
        roundedmesh.assign_material(wall, material)
    return walls
