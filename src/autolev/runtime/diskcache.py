"""autolev's cache on disk: compiled libraries and objects, and built models.

One folder, private to the user: $AUTOLEV_CACHE, else $XDG_CACHE_HOME/autolev/build.
Anyone who can put a file there could run code in our process (a library we load, a
pickle we read), so a folder that is not the user's own or that others may write is
not used, and every entry is checked against the SHA-256 recorded beside it when it was
written: a truncated, garbage or planted file is not read.  Entries are written
atomically (concurrent writers never see half a file) and the folder is kept under a
size limit ($AUTOLEV_CACHE_LIMIT_MB, by default 2048), the least recently written
entries leaving first.
"""
from __future__ import annotations

import atexit
import hashlib
import os
import shutil
import tempfile
import warnings
from dataclasses import dataclass
from pathlib import Path

LIMIT_VARIABLE = "AUTOLEV_CACHE_LIMIT_MB"
DEFAULT_LIMIT_MB = 2048
DIGEST_SUFFIX = ".sha256"

# a private build folder of this process, when the user's cache cannot be trusted
_FALLBACK_CACHE: list = []


def cache_dir() -> Path:
    """The cache folder: $AUTOLEV_CACHE, else $XDG_CACHE_HOME/autolev/build (created
    0700).  A folder that is not the user's own or that others may write is not used:
    the cache then goes to a private temporary folder, with a warning."""
    base = os.environ.get("AUTOLEV_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "autolev", "build")
    path = Path(base)
    try:
        _make_private_dirs(path)
        problem = not_private(path)
    except OSError as exc:
        problem = f"cannot be created ({exc.strerror})"
    if problem is None:
        return path
    if not _FALLBACK_CACHE:
        warnings.warn(f"the build cache {path} {problem}; building in a private temporary "
                      "folder instead (set AUTOLEV_CACHE to a folder of your own, mode 700)",
                      stacklevel=3)
        folder = tempfile.mkdtemp(prefix="autolev-build-")
        atexit.register(shutil.rmtree, folder, ignore_errors=True)   # nothing left in /tmp
        _FALLBACK_CACHE.append(Path(folder))
    return _FALLBACK_CACHE[0]


def _make_private_dirs(path: Path) -> None:
    """mkdir -p with mode 700 for every folder made (whatever the umask)."""
    missing = []
    p = path
    while not p.exists():
        missing.append(p)
        p = p.parent
    for d in reversed(missing):
        try:
            d.mkdir(mode=0o700)
        except FileExistsError:
            continue
        os.chmod(d, 0o700)


def not_private(path: Path) -> str | None:
    """Why a file or folder may hold someone else's code, or None."""
    st = path.stat()
    if hasattr(os, "getuid") and st.st_uid != os.getuid():
        return f"belongs to another user (uid {st.st_uid})"
    if st.st_mode & 0o022:
        return f"is writable by others (mode {st.st_mode & 0o777:o})"
    return None


def digest_file(entry: Path) -> Path:
    return entry.with_name(entry.name + DIGEST_SUFFIX)


def verified(entry: Path) -> bool:
    """An entry that is ours, private, and exactly what was written (its SHA-256
    recorded beside it)."""
    return read_verified(entry) is not None


def read_verified(entry: Path) -> bytes | None:
    """The bytes of a verified entry (read once, checked as read), or None."""
    try:
        if not_private(entry) is not None:
            return None
        expected = digest_file(entry).read_text().strip()
        data = entry.read_bytes()
    except OSError:
        return None
    return data if hashlib.sha256(data).hexdigest() == expected else None


def install(data: bytes, target: Path) -> None:
    """Put an entry into the cache atomically, with its digest; then keep the folder
    under its size limit."""
    tmp = target.with_name(target.name + f".{os.getpid()}.tmp")
    tmp.write_bytes(data)
    os.chmod(tmp, 0o700)
    os.replace(tmp, target)                  # atomic: concurrent writers never see half
    side = digest_file(target)
    tmp_side = side.with_name(side.name + f".{os.getpid()}.tmp")
    tmp_side.write_text(hashlib.sha256(data).hexdigest() + "\n")
    os.replace(tmp_side, side)
    trim(target.parent, keep=target)


@dataclass(frozen=True)
class Entry:
    path: Path
    size: int          # with its digest file
    written: float     # seconds since the epoch


def entries(folder: Path) -> list[Entry]:
    """The cache's entries (each with its digest file), oldest first."""
    out = []
    try:
        names = os.listdir(folder)
    except OSError:
        return []
    for name in names:
        if name.endswith((DIGEST_SUFFIX, ".tmp")):
            continue
        path = folder / name
        try:
            st = path.stat()
            size = st.st_size + (digest_file(path).stat().st_size
                                 if digest_file(path).exists() else 0)
        except OSError:                 # removed by another process meanwhile
            continue
        out.append(Entry(path, size, st.st_mtime))
    return sorted(out, key=lambda e: e.written)


def limit_bytes() -> int:
    text = os.environ.get(LIMIT_VARIABLE, "")
    try:
        megabytes = float(text) if text else DEFAULT_LIMIT_MB
    except ValueError:
        megabytes = DEFAULT_LIMIT_MB
    return int(max(megabytes, 0) * 2 ** 20)


def trim(folder: Path, keep: Path | None = None, limit: int | None = None) -> int:
    """Remove the oldest entries until the folder is within `limit` bytes (the size
    limit by default); never `keep`, the entry just written.  Returns entries removed."""
    limit = limit_bytes() if limit is None else limit
    found = entries(folder)
    total = sum(e.size for e in found)
    removed = 0
    for entry in found:
        if total <= limit:
            break
        if entry.path == keep:
            continue
        remove(entry.path)
        total -= entry.size
        removed += 1
    return removed


def remove(entry: Path) -> None:
    for p in (entry, digest_file(entry)):
        try:
            p.unlink()
        except FileNotFoundError:
            pass
