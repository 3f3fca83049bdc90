# The Python module's tests (docs/python.md, docs/testing.md): pytest on lavapipe under the
# Khronos validation layer; ctest runs them as python.pytest with PYTHONPATH at the build tree's
# package. One device serves the suite; it must end without a validation message.
import os
from pathlib import Path

import pytest

import candela

SHARED = Path(os.environ.get("CANDELA_SHARED_ASSETS", Path(__file__).resolve().parents[3] / "shared" / "assets"))
CANDELA = os.environ.get("CANDELA_EXECUTABLE", "")


def shared_model(name):
    """The path of a shared sample model, or a skip when the shared assets are not here."""
    for path in (SHARED / "models" / name / "glTF-Binary" / f"{name}.glb", SHARED / "models" / name / "glTF" / f"{name}.gltf"):
        if path.exists():
            return path
    pytest.skip(f"no shared sample {name} in {SHARED}")


@pytest.fixture(scope="session")
def device():
    with candela.Device(validation=True, pipeline_cache="off") as device:
        yield device
        assert device.validation_messages == 0


@pytest.fixture(scope="session")
def sky():
    return candela.load_environment()


@pytest.fixture(scope="session")
def helmet():
    """DamagedHelmet, read once for the suite."""
    return candela.load_scene(shared_model("DamagedHelmet"))


@pytest.fixture(scope="session")
def grid():
    return candela.Scene.sphere_grid(3)


def pytest_configure(config):
    # Debian 12's dask.distributed (2022.12) calls tornado's deprecated IOLoop.make_current when a
    # LocalCluster starts: theirs, not Candela's.
    config.addinivalue_line("filterwarnings", "ignore:make_current is deprecated:DeprecationWarning")
