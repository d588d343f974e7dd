"""Autolev's output files: `NAME.1 ... NAME.k` (one per OUTPUT statement), `NAME.dir`.

The layout is that of Autolev 4.1's C and Matlab programs:

    % FILE: NAME.1
    %
    %       T             Q1
    %     (SEC)          (DEG)
    <blank>
      0.000000E+00   3.000000E+01

Each label is centred in a 15-character column (the first after the `%`), units in
brackets (`(UNITS)` when none was given), each value written as `" %- 14.6E"`.
Rows are written as they are computed (a run's memory does not grow with its rows),
into temporaries renamed together when the run ends (`RunFiles`).
"""
from __future__ import annotations

import errno
import math
import os
import shutil
import signal
import threading
import warnings
from contextlib import contextmanager
from pathlib import Path, PureWindowsPath

try:
    import fcntl
except ImportError:           # Windows: runs into one folder are not locked
    fcntl = None

from .errors import AutolevModelError
from .outputs import TEMPORARY_SUFFIX, Written, temporary_beside
from .numbers import row


def safe_stem(filename: str) -> str:
    """The program name of `CODE ... file.c`: its base name without the extension.
    Directories (either slash) are dropped, so files never leave the output folder."""
    base = PureWindowsPath(filename.replace("/", "\\")).name
    stem = base.rsplit(".", 1)[0] if "." in base else base
    stem = stem.strip()
    if not stem or stem in (".", "..") or any(c in stem for c in '<>:"|?*\0'):
        raise AutolevModelError(f"unusable file name in CODE: {filename!r}")
    return stem


def _centred(labels: list[str]) -> str:
    line = "%"
    for k, label in enumerate(labels):
        start = 1 + 15 * k + max(0, math.ceil((14 - len(label)) / 2))
        if len(line) >= start:
            line += " "
        else:
            line += " " * (start - len(line))
        line += label
    return line


def header(filename: str, labels: list[str], units: list[str | None]) -> str:
    """The heading of an output file: each label as the OUTPUT statement wrote it, cut to
    the column's 14 characters, and its unit as written (`(UNITS)` when none was given),
    as Autolev's programs wrote them (`dot(v_bhat_n>,` for a long expression)."""
    names = [label[:14] for label in labels]
    brackets = [f"({u or 'UNITS'})" for u in units]
    return "\n".join([f"% FILE: {filename}", "%", _centred(names) if names else "%",
                      _centred(brackets) if names else "%", ""]) + "\n"


# a run that would write more than this says so before it starts
ANNOUNCED_BYTES = 1 << 30


def check_room(folder: Path, rows: int, columns: list[int]) -> None:
    """Before a run computes anything: refuse one whose tables would not fit in the
    free space of `folder`, and announce one that writes more than ANNOUNCED_BYTES."""
    expected = rows * sum(len(row([0.0] * n)) for n in columns)
    if expected <= ANNOUNCED_BYTES:
        return
    free = shutil.disk_usage(folder).free
    what = (f"about {_size(expected)} ({rows:.3g} rows, {sum(columns)} value(s) a row, in "
            f"{len(columns)} file(s))")
    if expected > free:
        raise AutolevModelError(
            f"this run would write {what} into {folder}, where {_size(free)} is free; "
            "lower TFINAL, raise PRINTINT or INTEGSTP, or narrow the sweep")
    warnings.warn(f"this run writes {what} into {folder}")


# what a kept value costs while a run holds its rows (a Python float in a row list, and
# the array the rows become at the end)
KEPT_VALUE_BYTES = 48


def check_memory(rows: int, values: int) -> None:
    """Before a run computes anything: refuse one whose rows, kept in memory (a Result
    holding every row), would not fit in what this process may still use."""
    needed = rows * values * KEPT_VALUE_BYTES
    available = memory_available()
    if available is None or needed <= available:
        return
    raise AutolevModelError(
        f"keeping every row of this run in memory needs about {_size(needed)} ({rows:.3g} "
        f"rows of {values} value{'s' if values != 1 else ''}), where {_size(available)} is "
        "available: its files hold "
        "every row (autolev run keeps only the last without --plot, --csv or --mat; "
        "simulate and run take keep_rows=False), or lower TFINAL, raise PRINTINT or "
        "INTEGSTP, or narrow the sweep")


def memory_available() -> float | None:
    """The memory this process may still take: the machine's available memory, and its
    own address-space limit less what it uses (None where neither can be read)."""
    found = []
    try:
        found.append(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        pass
    try:
        import resource
        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft != resource.RLIM_INFINITY:
            with open("/proc/self/statm") as statm:
                used = int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
            found.append(max(soft - used, 0))
    except (ImportError, OSError, ValueError):
        pass
    return min(found) if found else None


def _size(count: float) -> str:
    for unit in ("bytes", "kB", "MB", "GB", "TB"):
        if count < 1000 or unit == "TB":
            return f"{count:.3g} {unit}"
        count /= 1000


@contextmanager
def writing_into(folder: Path):
    """A failure of the disk (a read-only or full folder, a file where the folder
    should be) as one message naming the place, not a traceback."""
    try:
        yield
    except OSError as exc:
        # a rename names its target second: the file in the way, not the temporary
        where = exc.filename2 or exc.filename or folder
        raise AutolevModelError(f"cannot write the output files into {folder}: "
                                f"{exc.strerror or exc} ({where})") from None


class OutputFiles:
    """The tables `NAME.1 ... NAME.k` of one run, written row by row into temporaries
    that `RunFiles` renames with the run's other files."""

    def __init__(self, run: "RunFiles", files: list[tuple[list, list]]):
        self.folder = run.folder
        self.paths = [run.folder / f"{run.stem}.{k}" for k in range(1, len(files) + 1)]
        self._handles = [run.open(path) for path in self.paths]
        for h, path, (labels, units) in zip(self._handles, self.paths, files):
            h.write(header(path.name, labels, units))

    def write(self, k: int, values) -> None:
        with writing_into(self.folder):
            self._handles[k].write(row(values))

    def write_rows(self, k: int, block) -> None:
        """Rows of file k at once (a numpy array: print times x columns)."""
        from .rowtext import rows_text  # numpy and ctypes: only a run writes rows
        text = rows_text(block)
        with writing_into(self.folder):
            self._handles[k].write(text)

    def note(self, text: str) -> None:
        """A message line in every file (Autolev wrote integration failures there)."""
        with writing_into(self.folder):
            for h in self._handles:
                h.write(f"% {text}\n")


# the suffix of a run's temporaries: hidden, and recognisable as stale after a crash
PART = TEMPORARY_SUFFIX


class RunFiles:
    """Every file of one run into `folder`, written as a set: under temporary names
    until `commit` renames them all (the `.dir` last), so a refused, interrupted or
    failed-to-write run leaves the previous run's files as they were.  While it is
    open the folder is locked against another run (flock on the folder itself)."""

    def __init__(self, folder: Path, stem: str, overwrite: bool = False):
        """`overwrite`: replace files autolev did not write (see outputs.Written)."""
        self.folder = Path(folder)
        self.stem = stem
        self.overwrite = overwrite
        self._staged: list[tuple[Path, Path]] = []       # (temporary, final)
        self._handles = []
        if self.folder.exists() and not self.folder.is_dir():
            raise NotADirectoryError(errno.ENOTDIR, "not a folder", str(self.folder))
        self.folder.mkdir(parents=True, exist_ok=True)
        self._lock = _lock_folder(self.folder)
        self._written = Written(self.folder)
        try:
            self._remove_stale()
        except BaseException:
            self.release()
            raise

    def _remove_stale(self) -> None:
        """Temporaries of runs that were killed (no other run can be writing here)."""
        for tmp in self.folder.glob(f".*{PART}"):
            if tmp.is_file() or tmp.is_symlink():
                tmp.unlink(missing_ok=True)

    def claim(self, names) -> None:
        """Refuse, before anything is computed, to replace files autolev did not write
        (unless told to overwrite)."""
        self._written.check(names, self.overwrite)

    def open(self, final: Path):
        """A new text file that becomes `final` at commit."""
        self._written.check([final.name], self.overwrite)
        tmp = temporary_beside(final)
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        self._staged.append((tmp, final))
        handle = os.fdopen(fd, "w", newline="\n", encoding="utf-8")
        self._handles.append(handle)
        return handle

    def text(self, name: str, text: str) -> None:
        with self.open(self.folder / name) as h:
            h.write(text)

    def tables(self, files: list[tuple[list, list]]) -> OutputFiles:
        return OutputFiles(self, files)

    def commit(self) -> list[Path]:
        """Rename every temporary to its name, the `.dir` last; returns the files, in
        writing order.  The set changes as one step for what a run can hold off
        (SIGINT, SIGTERM, SIGHUP wait until it is complete), and the previous run's
        `.dir` goes first, so that a set cut short by what cannot be held off (SIGKILL,
        a power cut) has no `.dir` and does not pass for complete."""
        for h in self._handles:
            h.close()
        self._handles = []
        order = sorted(self._staged, key=lambda pair: pair[1].suffix == ".dir")
        previous_dir = self.folder / f"{self.stem}.dir"
        with signals_held():
            self._written.expect(order)
            if previous_dir.is_file() and not previous_dir.is_symlink():
                previous_dir.unlink()      # ours, or overwrite was asked: open() checked
            for tmp, final in order:
                os.replace(tmp, final)
            self._written.record([final.name for _, final in order])
        self._staged = []
        self._remove_superseded([final for _, final in order])
        return [final for _, final in order]

    def _remove_superseded(self, written: list[Path]) -> None:
        """The previous run's tables and `.encode` this run did not write (fewer OUTPUT
        statements, no ENCODE), and what was drawn or converted from its results (plots,
        CSV, Matlab files, animations; written again after this run when asked): they
        would pass for this run's; and the `-template.in` of a run refused for want of
        values.  Only files autolev wrote and nobody changed since."""
        names = {p.name for p in written}
        gone = []
        # and the template a run refused for want of values left, still unfilled
        template = self.folder / f"{self.stem}-template.in"
        for path in [*self.folder.glob(f"{glob_escape(self.stem)}.*"), template]:
            suffix = path.name[len(self.stem) + 1:]
            if path.name in names or (path != template and not _superseded_suffix(suffix)):
                continue
            if path.is_file() and not path.is_symlink() and path.name in \
                    self._written.records and self._written.ours(path.name):
                path.unlink()
                gone.append(path.name)
        if gone:
            self._written.forget(gone)

    def discard(self) -> None:
        """Remove every temporary; a file that cannot be closed (its buffer cannot be
        flushed to a full disk) is removed all the same."""
        for h in self._handles:
            try:
                h.close()
            except OSError:
                pass            # its rows are discarded with it
        self._handles = []
        for tmp, _ in self._staged:
            tmp.unlink(missing_ok=True)
        self._staged = []

    def release(self) -> None:
        if self._lock is not None:
            os.close(self._lock)
            self._lock = None


# what autolev makes from a run's results: NAME.k.png, NAME.plot.png, NAME.csv, ...
_DERIVED = ("plot.png", "csv", "mat", "html", "gif", "mp4")


def _superseded_suffix(suffix: str) -> bool:
    """Whether NAME.<suffix> is one of a run's tables or made from its results."""
    lowered = suffix.lower()
    return suffix.isdigit() or lowered == "encode" or lowered in _DERIVED or (
        lowered.endswith(".png") and lowered[:-4].isdigit())


def glob_escape(text: str) -> str:
    return "".join(f"[{c}]" if c in "*?[" else c for c in text)


# the signals a run holds off while it changes its set of files
_HELD = tuple(s for s in (getattr(signal, n, None) for n in ("SIGINT", "SIGTERM", "SIGHUP"))
              if s is not None)


@contextmanager
def signals_held():
    """SIGINT, SIGTERM and SIGHUP wait until the block ends, then arrive as they would
    have.  In the main thread their handlers are set aside (a signal sent to the
    process may reach any of its threads, BLAS's too: masking this thread is not
    enough); elsewhere this thread masks them."""
    if threading.current_thread() is not threading.main_thread():
        if not hasattr(signal, "pthread_sigmask"):        # Windows: nothing to hold
            yield
            return
        before = signal.pthread_sigmask(signal.SIG_BLOCK, _HELD)
        try:
            yield
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, before)
        return
    arrived: list[int] = []
    previous = {s: signal.signal(s, lambda signum, frame: arrived.append(signum))
                for s in _HELD}
    try:
        yield
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        for s in dict.fromkeys(arrived):
            signal.raise_signal(s)


def _lock_folder(folder: Path):
    """An exclusive lock on the folder (its descriptor), or a clear refusal when
    another run holds it; None where the file system has no locks."""
    if fcntl is None:
        return None
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        os.close(fd)
        raise AutolevModelError(f"another autolev run is writing into {folder}; wait "
                                "for it to end, or give this one another --out") from None
    except OSError as exc:
        if exc.errno not in (errno.ENOLCK, errno.EOPNOTSUPP, errno.EINVAL):
            os.close(fd)
            raise
        os.close(fd)
        return None
    return fd


class RunInterrupted(BaseException):
    """SIGTERM or SIGHUP arrived while a run's files were being written."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


@contextmanager
def termination_cleans_up():
    """SIGTERM and SIGHUP (left at their default, in the main thread) raise
    RunInterrupted inside the block, so that its temporaries are removed; afterwards
    the signal is delivered again to its default action (the process ends as it
    would have)."""
    wanted = [s for s in (getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None))
              if s is not None]
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {s: signal.getsignal(s) for s in wanted}
    ours = [s for s in wanted if previous[s] == signal.SIG_DFL]

    def interrupt(signum, frame):
        raise RunInterrupted(signum)

    for s in ours:
        signal.signal(s, interrupt)
    try:
        yield
    except RunInterrupted as exc:
        for s in ours:
            signal.signal(s, previous[s])
        ours = []
        signal.raise_signal(exc.signum)
        raise
    finally:
        for s in ours:
            signal.signal(s, previous[s])


def dir_text(stem: str, program: str, files: list[list[str]],
             extra: list[tuple[str, str]] = ()) -> str:
    """NAME.dir: which file holds which quantities."""
    names = [f"{stem}.{k}" for k in range(1, len(files) + 1)] + [n for n, _ in extra]
    width = max(len(n) for n in names) + 4 if names else 12
    lines = [f"FILE: {stem}.dir", "", f"Output files generated by  {program}:", "",
             f"{'Filename':<{width}}Contents", f"{'--------':<{width}}--------"]
    for name, labels in zip(names, files):
        lines.append(f"{name:<{width}}{','.join(labels)}")
    for name, contents in extra:
        lines.append(f"{name:<{width}}{contents}")
    return "\n".join(lines) + "\n"


def encoded_text(values: list[tuple[str, object]]) -> str:
    """NAME.encode: the ENCODE quantities, one per line (`A[1,2]<TAB>value`, 1-based
    indices, 17 significant digits)."""
    lines = ["% values of the ENCODE quantities (1-based indices), printed %.17g"]
    for name, value in values:
        if hasattr(value, "shape") and len(value.shape) == 2:
            rows, cols = value.shape
            for i in range(rows):
                for j in range(cols):
                    idx = f"[{i + 1}]" if cols == 1 else (
                        f"[{j + 1}]" if rows == 1 else f"[{i + 1},{j + 1}]")
                    lines.append(f"{name}{idx}\t{float(value[i, j]):.17g}")
        else:
            lines.append(f"{name}\t{float(value):.17g}")
    return "\n".join(lines) + "\n"
