"""The cache of built models: a model whose generated module, autolev's own code and
the versions of what it runs on are unchanged is not built again; the `Model` its
module built (Kane's equations, the definitions and Z's, every D() and TAYLOR of the
model) is read back from the cache instead.

The key is the SHA-256 of the module's Python text (which holds every RUN file and
macro the model reads, expanded), the model's file name, and a digest of autolev's
source files and of the versions of Python, sympy and numpy: a change to any of them is
another key.  Entries live in the private cache folder of `engine.diskcache`, verified
by their digest before they are read.  The warnings a model's statements gave while it
was built are kept with it and given again when it is read back.

$AUTOLEV_NO_MODEL_CACHE=1 turns the cache off (the build cache of compiled code stays).
"""
from __future__ import annotations

import hashlib
import io
import pickle
import sys
import warnings
from dataclasses import dataclass
from pathlib import Path

from .engine.cachekeys import PLAN_PREFIX, code_digest, enabled
from .engine import diskcache, reading
from .engine.reading import ReadSet

PREFIX = "model_"
TRANSLATION_PREFIX = "translation_"


@dataclass
class Built:
    """What building a model left: the model, and the warnings its statements gave
    (message, category, file, line)."""

    model: object
    warnings: list[tuple[str, type, str, int]]

    def warn_again(self) -> None:
        for message, category, filename, lineno in self.warnings:
            warnings.warn_explicit(message, category, filename, lineno)


def key(code: str, filename: str) -> str:
    # a built model holds compiled functions: the knobs that choose them are in its key
    from .engine.request import environment
    text = f"{code_digest()}\0{filename}\0{code}\0{environment()!r}"
    return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()


def _entry(key_: str) -> Path:
    return diskcache.cache_dir() / f"{PREFIX}{key_[:40]}.pickle"


def read(key_: str) -> Built | None:
    """The built model of `key_`, or None when there is none (or it is not intact)."""
    if not enabled():
        return None
    built = _load(_entry(key_))
    return built if isinstance(built, Built) else None


def write(key_: str, built: Built) -> bool:
    """Keep a built model; False when it cannot be kept (it holds something that does
    not pickle, or nests deeper than pickling can walk): it is then built every time."""
    return enabled() and _keep(_entry(key_), built, "the built model")


# sympy expressions nest deeply: pickling walks them recursively
_RECURSION = 20000


def _load(entry: Path):
    """What a verified entry holds, or None."""
    data = diskcache.read_verified(entry)
    if data is None:
        return None
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, _RECURSION))
    try:
        return pickle.loads(data)
    finally:
        sys.setrecursionlimit(limit)


def _keep(entry: Path, obj, what: str) -> bool:
    """Write `obj` as the entry; False when it does not pickle or the disk refuses."""
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, _RECURSION))
    try:
        buffer = io.BytesIO()
        _ExpressionPickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(obj)
    except (pickle.PicklingError, TypeError, AttributeError, RecursionError):
        return False
    finally:
        sys.setrecursionlimit(limit)
    try:
        diskcache.install(buffer.getvalue(), entry)
    except OSError as exc:          # a full or read-only disk: it is built again next time
        warnings.warn(f"{what} could not be cached: {exc.strerror or exc}", stacklevel=3)
        return False
    return True


# -- translations -------------------------------------------------------------------
@dataclass
class _KeptTranslation:
    translation: object
    reads: ReadSet              # every file and folder search it read, as it read them


def translation(path: Path, make):
    """The translation of the model file at `path`: read back while the file, every
    file its translation read (RUN files, macros, functions) and the answers of the
    folder searches it made (a NAME.R added next to the model changes what NAME(x)
    means) are as they were; else `make()`, kept under the digest of the model as
    `make` read it, unless a file changed while it was read."""
    if not enabled():
        return make()
    try:
        raw = reading.read_bytes(path)
    except OSError:
        return make()                  # the translation reports the unreadable file
    kept = _load(_translation_entry(path, reading.digest(raw)))
    if isinstance(kept, _KeptTranslation) and kept.reads.holds():
        return kept.translation
    with reading.recording() as reads:
        result = make()
    read_as = reads.digest_of(path)
    if read_as is not None and not reads.torn:
        _keep(_translation_entry(path, read_as), _KeptTranslation(result, reads.snapshot()),
              "the translation")
    return result


def _translation_entry(path: Path, digest: str) -> Path:
    # the path as given: the translation's messages name the model so
    text = f"{code_digest()}\0translation\0{path}\0{digest}"
    key_ = hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()
    return diskcache.cache_dir() / f"{TRANSLATION_PREFIX}{key_[:40]}.pickle"


class _ExpressionPickler(pickle.Pickler):
    """Sums, products and powers are written as their parts, to be put together again
    as they were (sympy's own pickling rebuilds them through their constructors, which
    sort and combine the terms anew: 2.7 times slower to read on the 3-D gait model).
    sympy is not imported for it: while no one has imported it, what is written holds
    no expression (a translation, kept before any model is built: the note naming
    missing values comes before sympy's import)."""

    def __init__(self, file, protocol=None) -> None:
        super().__init__(file, protocol)
        sm = sys.modules.get("sympy")
        if sm is None:
            self._sums, self._pow, self._joined, self._power = (), None, None, None
        else:
            from .runtime.libraries import power_as_given, sum_or_product_as_given
            self._sums, self._pow = (sm.Add, sm.Mul), sm.Pow
            self._joined, self._power = sum_or_product_as_given, power_as_given

    def reducer_override(self, obj):
        kind = type(obj)
        if kind in self._sums:
            return self._joined, (kind, obj.args, obj.is_commutative)
        if kind is self._pow:
            return self._power, obj.args
        return NotImplemented


@dataclass(frozen=True)
class Summary:
    """(entries, bytes) of each kind of entry."""

    folder: Path
    models: tuple[int, int]
    translations: tuple[int, int]
    plans: tuple[int, int]
    compiled: tuple[int, int]
    limit: int


def summary() -> Summary:
    folder = diskcache.cache_dir()
    found = diskcache.entries(folder)
    kinds: dict[str, list] = {PREFIX: [], TRANSLATION_PREFIX: [], PLAN_PREFIX: [], "": []}
    for e in found:
        kinds[next(k for k in kinds if e.path.name.startswith(k))].append(e)
    return Summary(folder, *[(len(v), sum(e.size for e in v)) for v in kinds.values()],
                   diskcache.limit_bytes())


def clear() -> tuple[int, int]:
    """Remove every entry (models and compiled code) of the configured cache folder;
    (entries, bytes) removed.  Raises diskcache.CacheFolderError for a folder that is
    not autolev's cache."""
    folder = diskcache.configured_dir()
    if not folder.exists():
        return 0, 0
    return diskcache.clear(folder)
