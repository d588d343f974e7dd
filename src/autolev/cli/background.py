"""A cold run's last wait, done in the background: what it keeps for later runs.

A cold `autolev run` integrates in Python while its right-hand side's C compiles, and
that C is for the runs to come (they start from it, or from a run plan that needs it);
so are the built model and the run plan it writes to the cache (half a second of a
large model's run).  The user has the files before these are done, so the command
returns then: at its start
it forks (before any thread), the parent waits only until the child says its outputs
are done and exits with the child's status, and the child goes on with its output
closed, compiles, and writes the caches.  A later command on the same model waits for that
child (a lock in the cache folder), so it is warm and nothing is built twice.  The lock
appears already held (made aside, locked, then linked to its name) and goes before it is
let go, so a lock no process holds is one a killed child left: the next command removes
it.

Only the `autolev` command does this (`allow`), on POSIX, with a lasting cache; set
AUTOLEV_FOREGROUND=1 to keep the wait in the foreground.

The child has a process group of its own and writes to the terminal while it works
(progress, messages): it ignores SIGTTOU, so a terminal with `stty tostop` does not stop
it there.  A child that dies of a signal before its outputs are done makes the parent
end as it would have: by the signal passed on from the user, else with what happened
said (SIGKILL, as the system kills for memory: exit 1; any other: a crash, exit 70),
the child's partial files removed.
"""
from __future__ import annotations

import atexit
import hashlib
import os
import signal
import sys
import threading
from pathlib import Path

from ..engine.parentage import die_with_parent

FOREGROUND_VARIABLE = "AUTOLEV_FOREGROUND"
# the signals a user sends the command: passed on to the child doing the work
_PASSED_ON = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT)
# the exit status of a crash of the work (an internal error, as cli.EXIT_INTERNAL)
_CRASHED = 70

_allowed = [False]


def allow() -> None:
    """The process is the `autolev` command itself (not a caller of cli.main)."""
    _allowed[0] = True


def disallow() -> None:
    """The command is over: later calls of cli.main wait in the foreground."""
    _allowed[0] = False


def allowed() -> bool:
    """Whether a command may leave its last wait to a forked child now."""
    return _allowed[0]


def lock_file(model_path: Path) -> Path | None:
    """The lock a model's finishing child holds, or None without a lasting cache."""
    from ..engine import diskcache
    folder = diskcache.lasting_dir()
    if folder is None:
        return None
    # realpath: a model that is a link to itself resolves to a name (Path.resolve raises
    # RuntimeError), which its read then refuses with the reason
    digest = hashlib.sha256(os.path.realpath(model_path).encode()).hexdigest()[:40]
    return folder / f"finishing_{digest}.lock"


def wait_for_finishing(model_path: Path, progress) -> None:
    """Wait while an earlier run of this model finishes its compile in the background
    (announced on `progress` after two seconds)."""
    lock = lock_file(model_path) if os.name == "posix" else None
    if lock is None or not lock.exists():
        return
    from ..runtime.steps import SlowStep
    with SlowStep(progress, f"{model_path}: waiting for its C, compiling since an "
                            "earlier run"):
        _wait_on(lock)


def wait_for_every_finishing() -> None:
    """Wait while any run finishes its compile in the background (before emptying the
    cache: what it writes would come after)."""
    from ..engine import diskcache
    folder = diskcache.lasting_dir() if os.name == "posix" else None
    if folder is None:
        return
    for name in sorted(os.listdir(folder)):
        if diskcache.is_finishing_lock(name):
            _wait_on(folder / name)


def _wait_on(lock: Path) -> None:
    """Wait until no process holds `lock`; then remove it if it is still there: a lock
    no process holds was left by a child that was killed, or whose cache turned
    read-only (a child's lock appears already held, and goes before it is let go)."""
    import fcntl
    try:
        fd = os.open(lock, os.O_RDONLY | os.O_NOFOLLOW)
    except OSError:
        return                          # gone meanwhile, or not ours to read
    try:
        fcntl.flock(fd, fcntl.LOCK_SH)
    finally:
        os.close(fd)
    _remove_if_left(lock)


def _remove_if_left(lock: Path) -> bool:
    """Remove `lock` if no process holds it (left behind); whether it is gone.  It is
    removed while this process holds it, and only if the name still leads to it: a run
    that takes the name meanwhile cannot have its fresh lock removed."""
    import fcntl
    try:
        fd = os.open(lock, os.O_RDONLY | os.O_NOFOLLOW)
    except FileNotFoundError:
        return True
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        if os.lstat(lock).st_ino != os.fstat(fd).st_ino:
            return False                # replaced meanwhile: a fresh one
        lock.unlink()
        return True
    except OSError:                     # held (a child compiles), or not ours to remove
        return False
    finally:
        os.close(fd)


class Finishing:
    """The child's side: `detach` once the outputs are done."""

    def __init__(self, to_parent: int):
        self._to_parent = to_parent

    def detach(self, status: int, model_path: Path) -> None:
        """Give the parent `status` (it exits with it) and go on with stdin, stdout and
        stderr closed (/dev/null), holding the model's lock until this process ends."""
        lock = lock_file(model_path)
        if lock is not None:
            _hold(lock)
        for stream in (sys.stdout, sys.stderr, sys.__stdout__, sys.__stderr__):
            if stream is not None:
                stream.flush()
        signal.signal(signal.SIGHUP, signal.SIG_IGN)
        die_with_parent(0)
        nothing = os.open(os.devnull, os.O_RDWR)
        for fd in (0, 1, 2):
            os.dup2(nothing, fd)
        os.close(nothing)
        os.write(self._to_parent, bytes([min(max(status, 0), 255)]))
        os.close(self._to_parent)


def foreground_asked() -> bool:
    """AUTOLEV_FOREGROUND set to anything but 0."""
    return os.environ.get(FOREGROUND_VARIABLE, "") not in ("", "0")


def split_off(out_folder: Path) -> Finishing | None:
    """In the `autolev` command on POSIX (no thread running, AUTOLEV_FOREGROUND unset):
    fork; the parent never returns (it exits with the child's status once the child
    detaches or ends), the child returns its Finishing.  Else None: no background.
    `out_folder`: where the work writes its files (a killed child's partial files
    there are removed)."""
    if not allowed() or os.name != "posix" or foreground_asked() \
            or threading.active_count() != 1:
        return None
    from ..engine import diskcache
    if diskcache.lasting_dir() is None:
        return None
    for stream in (sys.stdout, sys.stderr):
        stream.flush()
    parent = os.getpid()
    try:
        readable, writable = os.pipe()
    except OSError:                     # out of descriptors: the command waits itself
        return None
    # held until the parent passes them on: none may come between the fork and that
    unblock = signal.pthread_sigmask(signal.SIG_BLOCK, _PASSED_ON + (signal.SIGTSTP,))
    try:
        child = os.fork()
    except OSError:                     # out of processes or memory: the same
        signal.pthread_sigmask(signal.SIG_SETMASK, unblock)
        os.close(readable)
        os.close(writable)
        return None
    if child == 0:
        signal.pthread_sigmask(signal.SIG_SETMASK, unblock)
        os.close(readable)
        os.setpgid(0, 0)        # the terminal's Ctrl-C reaches the parent, which passes it on
        # in a group of its own it is in the background: writing to a terminal with
        # `stty tostop` would stop it (and the parent waiting for it) for good
        signal.signal(signal.SIGTTOU, signal.SIG_IGN)
        die_with_parent(signal.SIGTERM)
        if os.getppid() != parent:      # the parent died before that took effect
            os._exit(1)
        return Finishing(writable)
    os.close(writable)
    _wait_as_parent(child, readable, unblock, out_folder)


def _wait_as_parent(child: int, readable: int, unblock, out_folder: Path):
    """Pass signals on to the child (those held since the fork first); exit with the
    status it sends, or with its own."""
    def pass_on(signum, _frame):
        try:
            os.kill(child, signum)
        except ProcessLookupError:
            pass

    def stop_both(_signum, _frame):     # Ctrl-Z: the work stops with the command
        pass_on(signal.SIGSTOP, None)
        signal.signal(signal.SIGTSTP, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGTSTP)
        # continued (fg, bg): the work goes on too
        signal.signal(signal.SIGTSTP, stop_both)
        pass_on(signal.SIGCONT, None)
    for signum in _PASSED_ON:
        signal.signal(signum, pass_on)
    signal.signal(signal.SIGTSTP, stop_both)
    signal.pthread_sigmask(signal.SIG_SETMASK, unblock)
    said = os.read(readable, 1)
    if said:
        os._exit(said[0])
    _, how = os.waitpid(child, 0)
    code = os.waitstatus_to_exitcode(how)
    if code < 0:
        _remove_partial_files(out_folder, child)
        _end_as_the_work(-code)
    os._exit(code)


def _end_as_the_work(signum: int) -> None:
    """The child died of `signum` before its outputs were done: a signal the user sent
    (passed on) ends the command the same way; SIGKILL (the system's, for memory, or
    another process's) is said, exit 1; any other is a crash of the work."""
    name = signal.Signals(signum).name
    if signum in _PASSED_ON:
        signal.signal(signum, signal.SIG_DFL)
        os.kill(os.getpid(), signum)
        os._exit(128 + signum)
    if signum == signal.SIGKILL:
        _say(f"autolev: error: the work was killed ({name}) before its files were written, "
             "as the system kills a process when memory runs out: its files were not "
             "written")
        os._exit(1)
    _say(f"autolev: internal error: the work crashed ({name}) before its files were "
         "written: a bug in autolev; please report it with the model and the command")
    os._exit(_CRASHED)


def _say(text: str) -> None:
    try:
        os.write(2, (text + "\n").encode())
    except OSError:
        pass                            # no terminal left to tell


def _remove_partial_files(folder: Path, pid: int) -> None:
    """The temporaries process `pid` was writing in `folder` (engine.outputs'
    names, which carry the writer's pid)."""
    from ..engine.outputs import is_temporary_of
    try:
        names = os.listdir(folder)
    except OSError:
        return
    for name in names:
        if is_temporary_of(name, pid):
            try:
                os.unlink(folder / name)
            except OSError:
                pass                    # gone already, or not ours to remove


def _hold(lock: Path) -> int | None:
    """Take the lock until exit (without waiting: another run's child may hold it);
    its descriptor, or None.  The lock is made aside, locked, then linked to its name,
    so that it is never there unheld while its child lives; one left by a killed child
    is taken over."""
    import fcntl

    from ..engine.outputs import temporary_beside
    aside = temporary_beside(lock)
    try:
        fd = os.open(aside, os.O_RDWR | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
    except OSError:
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)      # nobody else knows the file
        linked = _link_held(aside, lock)
    except OSError:
        linked = False
    finally:
        _unlink_quietly(aside)
    if not linked:
        os.close(fd)
        return None

    def release() -> None:
        _unlink_quietly(lock)           # first: a lock there unheld is one left behind
        os.close(fd)
    atexit.register(release)
    return fd


def _link_held(aside: Path, lock: Path) -> bool:
    """Give the held file `aside` the lock's name; False when another child holds the
    lock (OSError when the folder takes no links)."""
    for _ in range(3):                  # a left lock removed, the name taken again
        try:
            os.link(aside, lock)
            return True
        except FileExistsError:
            if not _remove_if_left(lock):       # another child holds it
                return False
    return False


def _unlink_quietly(path: Path) -> None:
    try:
        path.unlink(missing_ok=True)
    except OSError:
        pass                            # the cache turned read-only, or went away
