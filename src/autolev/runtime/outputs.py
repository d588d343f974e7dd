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
