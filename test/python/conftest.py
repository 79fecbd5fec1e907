"""Shared fixtures: where the driver and the source tree are (set by meson test;
tests that need the driver skip with a reason when run outside meson)."""
import os
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def driver():
    path = os.environ.get("SEISPULSE_DRIVER")
    if not path or not Path(path).exists():
        pytest.skip("SEISPULSE_DRIVER not set: run through `meson test` or `make test`")
    return path


@pytest.fixture(scope="session")
def source_root():
    return Path(os.environ.get("SEISPULSE_SOURCE_ROOT", Path(__file__).resolve().parents[2]))
