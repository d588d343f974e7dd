"""Files autolev writes, written whole and where they belong: the one writer behind the
run's tables, the programs of `autolev code`, converted modules, transcripts, pictures,
eigenvalue tables and the cache's entries.

A file is created under a fresh name of its own beside its target (O_EXCL: never an
existing file, nor a link planted there) and renamed over the target once whole; the
rename replaces whatever is at the name, a planted symbolic link included, and never
writes through it.  A failed write (a full disk, an interrupt) leaves neither the
target changed nor the temporary behind.  A name under an output folder may not lead
outside it, through `..` or through a folder that is a symbolic link.
"""
from __future__ import annotations

import errno
import hashlib
import json
import os
import secrets
from pathlib import Path

# the suffix of a temporary: hidden by its leading dot, recognisable as left by a crash
TEMPORARY_SUFFIX = ".autolev-part"


class OutsideFolder(OSError):
    """A name that would leave its output folder."""


def temporary_beside(target: Path) -> Path:
    """A fresh hidden name in `target`'s folder, for writing it aside."""
    return target.with_name(f".{target.name}.{os.getpid()}.{secrets.token_hex(4)}"
                            f"{TEMPORARY_SUFFIX}")


def temporary_writer(name: str) -> int | None:
    """The process that made `name` with `temporary_beside`, or None for another name."""
    if not (name.startswith(".") and name.endswith(TEMPORARY_SUFFIX)):
        return None
    parts = name[:-len(TEMPORARY_SUFFIX)].rsplit(".", 2)
    return int(parts[1]) if len(parts) == 3 and parts[1].isdigit() else None


def is_temporary_of(name: str, pid: int) -> bool:
    """Whether `name` is a temporary `temporary_beside` made in process `pid`."""
    return temporary_writer(name) == pid


def write_whole(target: Path, data: bytes | str, mode: int = 0o666) -> Path:
    """Create or replace `target` with `data` in one step (text as UTF-8, newlines as
    given); `mode` before the umask.  Returns `target`."""
    target = Path(target)
    tmp = temporary_beside(target)
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, mode)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data.encode("utf-8") if isinstance(data, str) else data)
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return target


def inside(folder: Path, relative: str | os.PathLike) -> Path:
    """`folder/relative`, its missing folders made, refused (OutsideFolder) when it or a
    folder on its way leads outside `folder`."""
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(errno.ENOENT, f"no folder {folder}", str(folder))
    root = folder.resolve()
    target = folder / relative
    parent = target.parent
    made = []
    while not parent.exists():
        made.append(parent)
        parent = parent.parent
    if parent.resolve() != root and root not in parent.resolve().parents:
        raise OutsideFolder(errno.EPERM, f"{target} leads outside {folder}")
    for d in reversed(made):
        d.mkdir(exist_ok=True)
        if d.resolve() != root and root not in d.resolve().parents:
            raise OutsideFolder(errno.EPERM, f"{target} leads outside {folder}")
    if target.is_symlink() and target.is_dir():
        raise OutsideFolder(errno.EPERM, f"{target} is a link to a folder")
    return target


# -- files autolev wrote in a folder -------------------------------------------------
# what autolev wrote in each output folder, so that a file it did not write (Autolev's
# own output, a .in the user edited) is never replaced without being told to: kept
# with the user's state, not in the folder ($XDG_STATE_HOME/autolev/written)
RECORDS_KEPT = 2000        # record files beyond this: those of folders gone are dropped


class NotWrittenByAutolev(OSError):
    """Files in the way that autolev did not write, or that were changed since."""


def _identity(path: Path) -> list:
    st = path.stat()
    return [st.st_ino, st.st_size, st.st_mtime_ns]


class Written:
    """The record of the files autolev wrote in one folder (name -> the inode, size and
    modification time it left them with; while a set of files is renamed into place,
    the old and the new ones, so that a run killed half-way leaves none unknown)."""

    def __init__(self, folder: Path):
        self.folder = Path(folder)
        where = str(self.folder.resolve())
        self.path = records_dir() / (hashlib.sha256(where.encode("utf-8", "surrogatepass"))
                                     .hexdigest()[:32] + ".json")
        self.records: dict = {}
        try:
            found = json.loads(self.path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            found = {}
        if isinstance(found, dict) and found.get("folder") == where and \
                isinstance(found.get("files"), dict):
            self.records = found["files"]

    def ours(self, name: str) -> bool:
        """Whether `name` may be replaced: absent, a link (replacing it writes nothing
        through it), or as autolev left it."""
        target = self.folder / name
        if target.is_symlink() or not target.exists():
            return True
        try:
            return _identity(target) in self.records.get(name, [])
        except OSError:
            return False

    def check(self, names, overwrite: bool = False) -> None:
        """Refuse (NotWrittenByAutolev) to replace a file autolev did not write."""
        theirs = [n for n in names if not self.ours(n)]
        if theirs and not overwrite:
            shown = ", ".join(theirs[:4]) + (", ..." if len(theirs) > 4 else "")
            raise NotWrittenByAutolev(
                errno.EEXIST, f"{shown} in {self.folder} {'was' if len(theirs) == 1 else 'were'}"
                " not written by autolev, or changed since (an edited .in, Autolev's own "
                "output): not replaced; --overwrite replaces them")

    def record(self, names) -> None:
        """The files `names` in the folder are autolev's, as they are now."""
        for name in names:
            target = self.folder / name
            if target.is_file() and not target.is_symlink():
                self.records[name] = [_identity(target)]
        self._save()

    def expect(self, renames) -> None:
        """Before (temporary, final) pairs are renamed: each final name may hold its old
        file or the new one (a rename keeps the inode and the time)."""
        for tmp, final in renames:
            self.records[final.name] = self.records.get(final.name, [])[-1:] + \
                [_identity(tmp)]
        self._save()

    def _save(self) -> None:
        folder = self.path.parent
        new = not self.path.exists()
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        write_whole(self.path, json.dumps({"folder": str(self.folder.resolve()),
                                           "files": self.records}, sort_keys=True), 0o600)
        if new:
            _drop_records_of_folders_gone(folder)
        _remove_temporaries_of_the_dead(folder, self.path.name)

    def forget(self, names) -> None:
        for name in names:
            self.records.pop(name, None)
        self._save()


def records_dir() -> Path:
    state = os.environ.get("XDG_STATE_HOME", "")
    base = state if os.path.isabs(state) else os.path.expanduser("~/.local/state")
    return Path(base) / "autolev" / "written"


def _remove_temporaries_of_the_dead(folder: Path, record: str) -> None:
    """The temporaries of `record` left by a process that was killed while it wrote it
    (as the system kills for memory): each names its writer, gone now."""
    for path in folder.glob(f".{record}.*{TEMPORARY_SUFFIX}"):
        writer = temporary_writer(path.name)
        if writer is not None and not _alive(writer):
            path.unlink(missing_ok=True)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True                     # another user's process: alive
    return True


def _drop_records_of_folders_gone(folder: Path) -> None:
    dated = []
    for path in folder.glob("*.json"):
        try:
            dated.append((path.stat().st_mtime, path))
        except FileNotFoundError:       # another run dropped it after the listing
            continue
    dated.sort()
    for _, path in dated[:max(0, len(dated) - RECORDS_KEPT)]:
        try:
            kept = json.loads(path.read_text(encoding="utf-8")).get("folder", "")
        except (OSError, ValueError, AttributeError):
            kept = ""
        if not kept or not os.path.isdir(kept):
            path.unlink(missing_ok=True)


def write_output(folder: Path, name: str | os.PathLike, data: bytes | str,
                 overwrite: bool = False) -> Path:
    """`write_whole` of folder/name (kept inside the folder), unless a file autolev did
    not write is in the way (NotWrittenByAutolev); the file is then recorded as ours."""
    target = inside(folder, name)
    written = Written(target.parent)
    written.check([target.name], overwrite)
    write_whole(target, data)
    written.record([target.name])
    return target
