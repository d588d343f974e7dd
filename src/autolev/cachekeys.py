"""What the caches' keys are made of (no sympy: a warm run's plan is found with them):
the digest of autolev's own code and the versions it runs on, and the manifest of
the files a model's translation read."""
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
_PACKAGE = Path(__file__).resolve().parent


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


def file_key(kind: str, path: Path, raw: bytes, *more: bytes) -> str:
    """The digest naming a cache entry of `kind` made from the file at `path` that holds
    `raw` (and from `more`): autolev's code, the file's name and its content."""
    h = hashlib.sha256(code_digest().encode() + b"\0" + kind.encode() + b"\0"
                       + str(path).encode("utf-8", "surrogatepass") + b"\0" + raw)
    for part in more:
        h.update(b"\0" + part)
    return h.hexdigest()


def manifest(root: Path, files: list[str]) -> tuple:
    """The digest of every file read, and in every folder looked in (each read file's
    folder and those up to the model's own) the names that could change what is read:
    macros and functions (NAME.A, NAME.R) and any name a read file has, in any case
    (outputs written beside the model change nothing)."""
    base = root.parent.resolve()
    digests, folders = [], {base}
    named = {root.name.lower()}
    for name in files:
        path = Path(name)
        named.update(part.lower() for part in path.parts)
        try:
            digests.append((name, hashlib.sha256(path.read_bytes()).hexdigest()))
        except OSError:
            digests.append((name, None))
        folder = path.parent.resolve()
        while folder not in folders and base in folder.parents:
            folders.add(folder)
            folder = folder.parent
    listings = []
    for folder in sorted(folders):
        try:
            listings.append((str(folder), tuple(sorted(
                n for n in os.listdir(folder)
                if n.lower().endswith((".a", ".r")) or n.lower() in named))))
        except OSError:
            listings.append((str(folder), None))
    return tuple(digests), tuple(listings)
