"""The `autolev` command line."""
from __future__ import annotations

import argparse
import contextlib
import errno
import os
import select
import signal
import sys

from .. import __version__
from . import background
from .streams import StreamWriteError, name_the_standard_streams
from ..errors import AutolevError, AutolevInternalError, AutolevSyntaxError
from .cache import add_cache
from .check import add_check
from .code import add_code
from .common import UsageError, print_diagnostics, print_warning
from .convert import add_convert
from .equations import add_equations
from .linearize import add_linearize
from .responses import add_transcript, add_verify
from .run import add_animate, add_run

# the exit status of a bug in autolev (EX_SOFTWARE of sysexits.h)
EXIT_INTERNAL = 70


# set to 1: an internal error is shown with Python's traceback
TRACEBACK_VARIABLE = "AUTOLEV_TRACEBACK"


EPILOG = f"""exit status: 0 success; 1 the model has errors, or a command failed; 2 wrong use
of the command line; {EXIT_INTERNAL} an internal error (a bug in autolev, not in the model:
the message asks for a report; {TRACEBACK_VARIABLE}=1 in the environment shows its Python
traceback); 130 interrupted."""


COMMANDS = (add_check, add_convert, add_run, add_code, add_linearize, add_animate,
            add_equations, add_transcript, add_verify, add_cache)


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(
        prog="autolev",
        description="Autolev 4.1 models in Python: check, translate and run .al files.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"autolev {__version__}")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    for add in COMMANDS:
        add(sub)
    return ap


@contextlib.contextmanager
def _warnings_as_notes():
    """Warnings printed as one-line notes while a command runs (not for the process:
    a caller of main() keeps its own warning display)."""
    import warnings
    shown = warnings.showwarning
    warnings.showwarning = print_warning
    try:
        yield
    finally:
        warnings.showwarning = shown


def entry() -> int:
    """The `autolev` command (`python -m autolev`): main, allowed to leave work to the
    background once a command's output is done (background.py)."""
    background.allow()
    name_the_standard_streams()
    try:
        status = main()
        sys.stdout.flush()              # what is still buffered: its failure said as any
        return status
    except StreamWriteError as exc:     # in that flush, or in saying an error
        _ended_by_its_streams(exc)
        return 1
    except KeyboardInterrupt:       # before main's own handling: reading the command line
        return 130
    finally:
        # a caller that goes on after it (a test) must not fork in its later main() calls
        background.disallow()


def _refuse_missing_input_file(ns: argparse.Namespace) -> None:
    """A --in file that is not there is a mistake in the command line (exit 2), said
    before the model is read."""
    infile = vars(ns).get("infile")
    if infile is not None and not os.path.lexists(infile):
        raise UsageError(f"--in {infile}: no such file")


def main(argv: list[str] | None = None) -> int:
    ap = build_parser()
    ns = ap.parse_args(argv)
    if ns.command is None:
        ap.print_help()
        return 2
    try:
        _refuse_missing_input_file(ns)
        with _warnings_as_notes():
            return ns.func(ns)
    except UsageError as exc:
        print(f"autolev {ns.command}: error: {exc}", file=sys.stderr)
        print_diagnostics(exc.diagnostics)
        return 2
    except AutolevSyntaxError as exc:
        print(exc, file=sys.stderr)
        return 1
    except AutolevInternalError as exc:
        if _ended_by_its_streams(exc):
            return 1
        _report_internal_error(exc)
        return EXIT_INTERNAL
    except AutolevError as exc:
        print(f"autolev: error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    except MemoryError:
        print("autolev: error: out of memory (the machine's limit, not a fault of the model)",
              file=sys.stderr)
        return 1
    except BrokenPipeError:
        # output piped into `head` and the like: stop quietly
        _let_go(sys.stdout)
        return 1
    except Exception as exc:  # noqa: BLE001 -- what escapes every stage is autolev's bug
        if _ended_by_its_streams(exc):
            return 1
        internal = AutolevInternalError(getattr(ns, "file", None) or "autolev",
                                        f"running `autolev {ns.command}`", exc)
        internal.__cause__ = exc
        _report_internal_error(internal)
        return EXIT_INTERNAL


def _os_error_in(exc: BaseException) -> OSError | None:
    """The OSError `exc` is, or was raised from."""
    seen = exc
    while seen is not None and not isinstance(seen, OSError):
        seen = seen.__cause__ or seen.__context__
    return seen


def _terminal_hung_up(exc: BaseException) -> bool:
    """An I/O error (EIO) from writing to a terminal that hung up (its window closed, its
    connection lost) while the command ran: the user is gone, nothing is wrong in autolev.
    A hung-up terminal polls as POLLHUP on the command's output or error stream."""
    cause = _os_error_in(exc)
    if cause is None or cause.errno != errno.EIO:
        return False
    poller = select.poll()
    for fd in (1, 2):
        poller.register(fd, select.POLLOUT)
    return any(events & select.POLLHUP for _, events in poller.poll(0))


def _end_as_hung_up() -> None:
    """End as a hang-up ends a command (SIGHUP), saying so where the error stream is not
    the terminal that went."""
    with contextlib.suppress(OSError):
        print("autolev: error: its terminal hung up; the command ended", file=sys.stderr)
    signal.signal(signal.SIGHUP, signal.SIG_DFL)
    os.kill(os.getpid(), signal.SIGHUP)
    os._exit(128 + signal.SIGHUP)


def _ended_by_its_streams(exc: BaseException) -> bool:
    """`exc` came from the command's own output or error stream: a terminal that hung up
    ends the command here, as a hang-up; any other failure is said.  Whether it was."""
    if _terminal_hung_up(exc):
        _end_as_hung_up()
    return _said_why_a_stream_failed(exc)


def _said_why_a_stream_failed(exc: BaseException) -> bool:
    """`exc` came from writing the command's output or error stream (a full disk, a device
    that refuses it): the user's disk, not autolev's bug.  The stream is let go (its text
    to /dev/null) and the failure said where it can be.  Whether it was."""
    cause = _os_error_in(exc)
    if not isinstance(cause, StreamWriteError):
        return False
    _let_go(sys.stdout if cause.stream == "output" else sys.stderr)
    try:
        print(f"autolev: error: cannot write its {cause.stream}: {cause.strerror}",
              file=sys.stderr, flush=True)
    except OSError:
        _let_go(sys.stderr)             # the error output fails too: nothing can be said
    return True


def _let_go(stream) -> None:
    """The stream's descriptor on /dev/null: what is written to it, at exit too, goes."""
    nothing = os.open(os.devnull, os.O_WRONLY)
    os.dup2(nothing, stream.fileno())
    os.close(nothing)


def _report_internal_error(exc: AutolevInternalError) -> None:
    """The bug's message; its Python traceback only when asked for."""
    print(exc, file=sys.stderr)
    if os.environ.get(TRACEBACK_VARIABLE) == "1":
        import traceback
        traceback.print_exception(exc, file=sys.stderr)
    else:
        print(f"autolev: note: {TRACEBACK_VARIABLE}=1 shows where in autolev it happened",
              file=sys.stderr)
