import pytest

from exudyn_bearing import catalog


@pytest.fixture
def b6208():
    return catalog["6208"]


@pytest.fixture
def b7208():
    return catalog["7208"]
