import os

import pytest

import prism

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture(scope="session")
def ctx():
    # One context for the session: it compiles the kernels once.
    return prism.Context("cpu")


@pytest.fixture(scope="session")
def scenes_dir():
    return os.path.join(REPO, "scenes")
