"""pytest set-up: every test starts from, and leaves, an empty YADE scene."""
import pytest

import roundedmesh  # noqa: F401  (imports YADE)
from yade import O


@pytest.fixture(autouse=True)
def empty_scene():
    O.reset()
    yield
    O.reset()
