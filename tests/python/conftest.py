"""Shared fixtures of the Python module's tests: the raylab binary, the source tree, a scratch directory, and a
helper that runs the command line for the results the module must equal."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest


def _path(variable: str) -> Path:
    value = os.environ.get(variable)
    if not value:
        raise RuntimeError(f"{variable} is not set: run these tests through ctest (tests/python/CMakeLists.txt)")
    return Path(value)


@pytest.fixture(scope="session")
def raylab_binary() -> Path:
    return _path("RAYLAB_BINARY")


@pytest.fixture(scope="session")
def source_dir() -> Path:
    return _path("RAYLAB_SOURCE_DIR")


@pytest.fixture
def work(request) -> Path:
    # Emptied first: results of an earlier run (the farm's finished cells) must not stand in for this run's.
    directory = _path("RAYLAB_TEST_WORK") / request.node.name
    shutil.rmtree(directory, ignore_errors=True)
    directory.mkdir(parents=True)
    return directory


@pytest.fixture(scope="session")
def run_raylab(raylab_binary):
    def run(*arguments, check=True):
        result = subprocess.run([str(raylab_binary), *map(str, arguments)], capture_output=True, text=True)
        if check and result.returncode != 0:
            raise AssertionError(f"raylab {' '.join(map(str, arguments))} exited {result.returncode}:\n"
                                 f"{result.stdout}{result.stderr}")
        return result
    return run
