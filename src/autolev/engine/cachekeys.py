"""What every cache key starts from (no sympy: a warm run's plan is found with it):
the digest of autolev's own code and the versions it runs on."""
from __future__ import annotations

import functools
import hashlib
import importlib.util
import os
import platform
from pathlib import Path

# the layout of what the caches keep: a change makes every entry stale
FORMAT = 1
# the names of run plans in the cache (runplan.py)
PLAN_PREFIX = "plan_"
# set (not 0): no built model, translation or run plan is kept or read
DISABLE_VARIABLE = "AUTOLEV_NO_MODEL_CACHE"
_PACKAGE = Path(__file__).resolve().parent.parent     # autolev itself


def _version_file(package: str, name: str) -> bytes:
    """The file that states an installed package's version, read without importing the
    package (a run plan's key is found without sympy; importlib.metadata costs more than
    the rest of the key)."""
    spec = importlib.util.find_spec(package)
    if spec is None or spec.origin is None:
        return b""
    try:
        return (Path(spec.origin).parent / name).read_bytes()
    except OSError:
        return b""


def enabled() -> bool:
    return os.environ.get(DISABLE_VARIABLE, "") in ("", "0")


@functools.cache
def code_digest() -> str:
    """autolev's own source and the versions it runs on."""
    h = hashlib.sha256(f"{FORMAT}\0{platform.python_version()}\0".encode()
                       + _version_file("sympy", "release.py") + b"\0"
                       + _version_file("numpy", "version.py") + b"\0")
    for path in sorted(_PACKAGE.rglob("*")):
        if path.suffix in (".py", ".c", ".g4") and "__pycache__" not in path.parts:
            h.update(str(path.relative_to(_PACKAGE)).encode() + b"\0" + path.read_bytes())
    return h.hexdigest()
