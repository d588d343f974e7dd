"""autolev's cache on disk: compiled libraries and objects, and built models.

One folder, private to the user: $AUTOLEV_CACHE, else $XDG_CACHE_HOME/autolev/build
(either only when it is an absolute path, as the XDG rule asks).  Anyone who can put a
file there could run code in our process (a library we load, a pickle we read), so:

* a folder that is not the user's own or that others may write is not used;
* every entry is authenticated before it is read: the HMAC-SHA256 recorded beside it
  is keyed by a secret kept outside the cache ($XDG_CONFIG_HOME/autolev/cache.key,
  made on first use, mode 600), so a cache that arrives with a project (a clone, an
  archive) or a planted entry with a digest anyone can compute is never trusted;
* autolev removes only what it made: its entries' own names (with their digests and
  its temporaries), in a folder marked as its cache by a CACHEDIR.TAG; a folder
  without the tag that holds other files is not used, nor emptied.

Entries are written atomically (concurrent writers never see half a file, a failed
write leaves nothing) with mode 600, and the folder is kept under a size limit
($AUTOLEV_CACHE_LIMIT_MB, by default 2048), the least recently written entries
leaving first, never one written in the last minutes (another process may be loading
or linking it).
"""
from __future__ import annotations

import atexit
import hashlib
import hmac
import math
import os
import re
import secrets
import shutil
import tempfile
import time
import warnings
from dataclasses import dataclass
from pathlib import Path

from .outputs import TEMPORARY_SUFFIX, write_whole

LIMIT_VARIABLE = "AUTOLEV_CACHE_LIMIT_MB"
DEFAULT_LIMIT_MB = 2048
DIGEST_SUFFIX = ".mac"
MARKER = "CACHEDIR.TAG"
MARKER_TEXT = ("Signature: 8a477f597d28d172789f06886806bc55\n"
               "# This file is a cache directory tag created by autolev.\n"
               "# For information about cache directory tags see https://bford.info/cachedir/\n")
# an entry written this recently may be in use by another process: the trim spares it
RECENT_SECONDS = 300

# the names of what autolev writes: compiled objects and libraries, built models and
# translations; their digests (.sha256 of earlier versions too) and temporaries
_ENTRY = re.compile(r"(al_[0-9a-f]{24}\.(o|so|dll)|(model|translation|plan)_[0-9a-f]{40}\.pickle)")
_SIDE = re.compile(r"(\.mac|\.sha256)?")
_LEGACY_TEMPORARY = re.compile(r"\.\d+(\.[0-9a-f]+)?\.tmp")     # of earlier versions
_TEMPORARY = re.compile(r"\.(?P<name>.+)\.\d+\.[0-9a-f]+" + re.escape(TEMPORARY_SUFFIX))
# held by a run finishing its compile in the background (cli/background.py)
_LOCK = re.compile(r"finishing_[0-9a-f]{40}\.lock")


class CacheFolderError(OSError):
    """The cache folder cannot be used or emptied (the message says why)."""


def is_finishing_lock(name: str) -> bool:
    """The lock of a run finishing its compile in the background (cli/background.py)."""
    return _LOCK.fullmatch(name) is not None


def is_ours(name: str) -> bool:
    """A file name autolev writes into its cache (entry, digest, temporary, tag)."""
    if name == MARKER or is_finishing_lock(name):
        return True
    temporary = _TEMPORARY.fullmatch(name)
    if temporary is not None:
        return is_ours(temporary.group("name")) and temporary.group("name") != MARKER
    m = _ENTRY.match(name)
    if m is None:
        return False
    rest = name[m.end():]
    side = _SIDE.match(rest)
    rest = rest[side.end():]
    return rest == "" or _LEGACY_TEMPORARY.fullmatch(rest) is not None


# -- where the cache is ----------------------------------------------------------------
# a private build folder of this process, when the user's cache cannot be used
_FALLBACK_CACHE: list = []
# folders found usable in this process (checking lists the folder: done once)
_USABLE: set = set()


# the settings said to be relative, once each per process
_SAID_RELATIVE: set = set()


def _absolute(variable: str) -> str | None:
    """An environment variable's folder, when it is an absolute path (else None, with a
    warning, once, when it was set: a relative one would follow the current folder)."""
    value = os.environ.get(variable, "")
    if value and not os.path.isabs(value):
        if (variable, value) not in _SAID_RELATIVE:
            _SAID_RELATIVE.add((variable, value))
            warnings.warn(f"{variable}={value} is not an absolute path: ignored",
                          stacklevel=4)
        return None
    return value or None


def configured_dir() -> Path:
    """The folder the settings name (not yet checked)."""
    own = _absolute("AUTOLEV_CACHE")
    if own:
        return Path(own)
    base = _absolute("XDG_CACHE_HOME") or os.path.expanduser("~/.cache")
    return Path(base) / "autolev" / "build"


def cache_dir() -> Path:
    """The cache folder (created 0700, with its CACHEDIR.TAG).  A folder that is not the
    user's own, that others may write, or that holds files autolev did not make
    without being marked as its cache is not used, nor is any cache when the secret
    that authenticates its entries cannot be kept: the cache then goes to a private
    temporary folder, with a warning."""
    path = configured_dir()
    if str(path) in _USABLE and path.is_dir():
        return path
    problem = _problem_with(path) or _secret_problem()
    if problem is None:
        _USABLE.add(str(path))
        return path
    if not _FALLBACK_CACHE:
        warnings.warn(f"the build cache {path} {problem}; building in a private temporary "
                      "folder instead (set AUTOLEV_CACHE to a folder of your own, mode 700)",
                      stacklevel=3)
    return fallback_dir()


def lasting_dir() -> Path | None:
    """The cache folder when it outlasts this process (not the private fallback)."""
    path = cache_dir()
    return None if _FALLBACK_CACHE and path == _FALLBACK_CACHE[0] else path


def fallback_dir() -> Path:
    """This process's private build folder, removed when it ends."""
    if not _FALLBACK_CACHE:
        folder = tempfile.mkdtemp(prefix="autolev-build-")
        atexit.register(shutil.rmtree, folder, ignore_errors=True)   # nothing left in /tmp
        _FALLBACK_CACHE.append(Path(folder))
    return _FALLBACK_CACHE[0]


def _problem_with(path: Path) -> str | None:
    """Why `path` cannot be the cache, or None (then it exists, is private and tagged)."""
    try:
        _make_private_dirs(path)
        problem = not_private(path)
        if problem is None:
            problem = _claim(path)
    except OSError as exc:
        problem = f"cannot be used ({exc.strerror or exc})"
    return problem


def _claim(path: Path) -> str | None:
    """Tag a folder that holds nothing but autolev's files as its cache; why not, or
    None."""
    if (path / MARKER).is_file():
        return None
    foreign = sorted(n for n in os.listdir(path) if not is_ours(n))
    if foreign:
        return (f"holds files autolev did not make ({', '.join(foreign[:3])}"
                f"{', ...' if len(foreign) > 3 else ''}) and is not marked as its cache "
                f"({MARKER})")
    try:
        _write_new(path / MARKER, MARKER_TEXT.encode())
    except FileExistsError:     # tagged meanwhile by another process or thread
        pass
    return None


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


# -- the secret that authenticates entries -----------------------------------------------
_SECRET: list = []          # (key, where it lives) once read or made
# the key of this process's own fallback folder, when the user's cannot be kept
_PROCESS_KEY: list = []


def secret_file() -> Path:
    base = _absolute("XDG_CONFIG_HOME") or os.path.expanduser("~/.config")
    return Path(base) / "autolev" / "cache.key"


def _secret_problem() -> str | None:
    try:
        _user_key()
    except OSError as exc:
        return f"cannot be trusted: its key {secret_file()} {exc.strerror or exc}"
    return None


def _secret() -> bytes:
    """The key entries are authenticated with: the user's (made on first use), else,
    when it cannot be made or read (a read-only home, a file where its folder goes, a
    key cut short), this process's own: the cache is then this process's private
    folder (cache_dir), which no other process reads."""
    try:
        return _user_key()
    except OSError:
        if not _PROCESS_KEY:
            _PROCESS_KEY.append(secrets.token_bytes(32))
        return _PROCESS_KEY[0]


def _user_key() -> bytes:
    """The key of this user's cache (made on first use); OSError saying why it cannot
    be had."""
    path = secret_file()
    if _SECRET and _SECRET[0][1] == path:
        return _SECRET[0][0]
    _make_private_dirs(path.parent)
    for folder in (path.parent, path):
        if folder.exists() and not_private(folder) is not None:
            raise OSError(f"{not_private(folder)}")
    if not path.exists():
        try:
            _write_new(path, secrets.token_hex(32).encode())
        except FileExistsError:       # made by another process meanwhile
            pass
    key = path.read_bytes().strip()
    if len(key) < 32:
        raise OSError("is too short to be a key")
    _SECRET[:] = [(key, path)]
    return key


def _mac(data: bytes, key: bytes | None = None) -> str:
    return hmac.new(_secret() if key is None else key, data, hashlib.sha256).hexdigest()


# -- entries --------------------------------------------------------------------------
def digest_file(entry: Path) -> Path:
    return entry.with_name(entry.name + DIGEST_SUFFIX)


def verified(entry: Path) -> bool:
    """An entry that is ours, private, and exactly what we wrote (authenticated)."""
    return read_verified(entry) is not None


def read_verified(entry: Path) -> bytes | None:
    """The bytes of an authenticated entry (read once, checked as read), or None."""
    try:
        if not_private(entry) is not None:
            return None
        expected = digest_file(entry).read_text().strip()
        data = entry.read_bytes()
        return data if hmac.compare_digest(_mac(data), expected) else None
    except (OSError, UnicodeDecodeError):
        return None


def _write_new(path: Path, data: bytes) -> None:
    """Create `path` (mode 600) holding `data`; nothing is left when writing fails."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
    except BaseException:
        path.unlink(missing_ok=True)
        raise


def install(data: bytes, target: Path) -> None:
    """Put an entry into the cache atomically, with its authentication; then keep the
    folder under its size limit.  Raises OSError (a full or read-only disk) with
    nothing of it left behind."""
    mac = _mac(data)
    digest_file(target).unlink(missing_ok=True)     # never an entry beside a stale digest
    write_whole(target, data, mode=0o600)
    try:
        write_whole(digest_file(target), mac + "\n", mode=0o600)
    except BaseException:
        target.unlink(missing_ok=True)
        raise
    trim(target.parent, keep=target)


def install_or_aside(data: bytes, target: Path) -> Path:
    """`install`, or, when the cache cannot be written, the same entry in this process's
    private folder (with a warning); returns where it is."""
    try:
        install(data, target)
        return target
    except OSError as exc:
        aside = fallback_dir() / target.name
        warnings.warn(f"the build cache {target.parent} cannot be written "
                      f"({exc.strerror or exc}): {target.name} is kept for this run only",
                      stacklevel=3)
        install(data, aside)
        return aside


@dataclass(frozen=True)
class Entry:
    path: Path
    size: int          # with its digest file
    written: float     # seconds since the epoch


def entries(folder: Path) -> list[Entry]:
    """The cache's entries (each with its digest file), oldest first: only files of
    autolev's own names."""
    out = []
    try:
        names = os.listdir(folder)
    except OSError:
        return []
    for name in names:
        if _ENTRY.fullmatch(name) is None:
            continue
        path = folder / name
        try:
            st = path.lstat()
            side = digest_file(path)
            size = st.st_size + (side.lstat().st_size if side.exists() else 0)
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
    if not math.isfinite(megabytes):
        megabytes = DEFAULT_LIMIT_MB
    return int(min(max(megabytes, 0), 2 ** 40) * 2 ** 20)


def trim(folder: Path, keep: Path | None = None, limit: int | None = None) -> int:
    """Remove the oldest entries until the folder is within `limit` bytes (the size
    limit by default); never `keep`, the entry just written, nor one written in the
    last RECENT_SECONDS.  Returns entries removed."""
    limit = limit_bytes() if limit is None else limit
    found = entries(folder)
    total = sum(e.size for e in found)
    recent = time.time() - RECENT_SECONDS
    removed = 0
    for entry in found:
        if total <= limit:
            break
        if entry.path == keep or entry.written > recent:
            continue
        remove(entry.path)
        total -= entry.size
        removed += 1
    return removed


def remove(entry: Path) -> None:
    """An entry and its digests (autolev's names only)."""
    if not is_ours(entry.name):
        raise ValueError(f"{entry} is not a file autolev made")
    for p in (entry, digest_file(entry), entry.with_name(entry.name + ".sha256")):
        p.unlink(missing_ok=True)


def clear(folder: Path) -> tuple[int, int]:
    """Remove every entry, digest and temporary autolev left in its cache folder;
    (entries, bytes) removed.  A folder not marked as autolev's cache is refused."""
    problem = not_private(folder) or (None if (folder / MARKER).is_file() else
                                      f"is not marked as autolev's cache ({MARKER})")
    if problem:
        raise CacheFolderError(f"{folder} {problem}: nothing removed")
    found = entries(folder)
    for e in found:
        remove(e.path)
    for name in os.listdir(folder):        # digests and temporaries left by others
        if name != MARKER and is_ours(name) and _ENTRY.fullmatch(name) is None:
            (folder / name).unlink(missing_ok=True)
    return len(found), sum(e.size for e in found)
