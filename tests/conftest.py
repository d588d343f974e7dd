"""Fixtures; the helpers tests import live in tests/helpers."""
import os
import shutil
import tempfile
from pathlib import Path

import pytest

from helpers import CORPUS

# Tests build their models afresh (several replace a runtime function to see what a
# build does); tests/test_model_cache.py turns the cache of built models on where it
# tests it, and AUTOLEV_NO_MODEL_CACHE=0 runs the whole suite with it.
os.environ.setdefault("AUTOLEV_NO_MODEL_CACHE", "1")
# what autolev records of the folders it wrote into stays with the tests' own state,
# removed when the session ends
_STATE = None
if "XDG_STATE_HOME" not in os.environ:
    _STATE = os.environ["XDG_STATE_HOME"] = tempfile.mkdtemp(prefix="autolev-test-state-")


def pytest_unconfigure(config):
    if _STATE is not None:
        shutil.rmtree(_STATE, ignore_errors=True)


@pytest.fixture(scope="session")
def corpus() -> Path:
    if not CORPUS.is_dir():
        pytest.skip(f"corpus not materialized at {CORPUS} (see shared/corpus/materialize.py)")
    return CORPUS


@pytest.fixture(autouse=True)
def _background_left_to_the_command():
    # the fork of background.py belongs to the `autolev` process alone: a test leaving it
    # allowed makes every later in-process run fork the test session itself
    yield
    from autolev.cli import background
    assert not background.allowed(), "a test left background.allow() in force"
