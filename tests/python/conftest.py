"""Shared fixtures of the Python tests: paths given by ctest (tests/python/CMakeLists.txt)."""
import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def source_dir() -> pathlib.Path:
    return pathlib.Path(os.environ.get("SSIMARCH_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def cli() -> str:
    path = os.environ.get("SSIMARCH_CLI", "")
    if not path or not os.path.exists(path):
        pytest.fail(f"the ssimarch CLI is needed (SSIMARCH_CLI={path!r} does not exist)")
    return path


@pytest.fixture(scope="session")
def viviani(source_dir) -> pathlib.Path:
    return source_dir / "examples" / "viviani.json"
