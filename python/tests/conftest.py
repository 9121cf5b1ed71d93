import os

import numpy as np
import pytest


def pytest_addoption(parser):
    parser.addoption("--lpd-binary", default=None, help="the lpd program, to compare with")


@pytest.fixture
def lpd_binary(request):
    path = request.config.getoption("--lpd-binary")
    if not path or not os.path.exists(path):
        pytest.skip("no lpd program given (--lpd-binary)")
    return path


@pytest.fixture
def shared_data():
    path = os.environ.get("LPD_DATA", os.path.join(os.path.dirname(__file__), "../../../shared/data"))
    if not os.path.isdir(path):
        pytest.skip(f"shared data not found at {path} (set LPD_DATA)")
    return path


def noisy_box(n, sigma, seed):
    """n points on the faces of the unit cube, area-uniform, with Gaussian noise sigma."""
    rng = np.random.default_rng(seed)
    points = rng.random((n, 3))
    axis = rng.integers(0, 3, n)
    side = rng.integers(0, 2, n).astype(float)
    points[np.arange(n), axis] = side
    return points + rng.normal(0.0, sigma, (n, 3))
