"""Fixtures; the helpers tests import live in tests/helpers."""
from pathlib import Path

import pytest

from helpers import CORPUS


@pytest.fixture(scope="session")
def corpus() -> Path:
    if not CORPUS.is_dir():
        pytest.skip(f"corpus not materialized at {CORPUS} (see shared/corpus/materialize.py)")
    return CORPUS
