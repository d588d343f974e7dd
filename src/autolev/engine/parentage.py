"""A process that dies with the one that started it (Linux's PR_SET_PDEATHSIG): the
compilers a run starts do not outlive it when it is killed (as the system kills for
memory), nor does a background child outlive its command."""
from __future__ import annotations

import signal
import sys

_PR_SET_PDEATHSIG = 1               # linux/prctl.h


def die_with_parent(signum: int) -> None:
    """Linux: this process gets `signum` when the thread that started it ends (0: no
    longer).  Elsewhere nothing."""
    if not sys.platform.startswith("linux"):
        return
    import ctypes
    ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, int(signum), 0, 0, 0)


# sets the death signal, then becomes the compiler: the run starts this with vfork (no
# preexec_fn, whose plain fork runs OpenBLAS's fork handler, which stops its threads under
# a solve running in another thread: the solve then waited for ever)
_LAUNCHER = ("import ctypes, os, sys; "
             f"ctypes.CDLL(None, use_errno=True).prctl({_PR_SET_PDEATHSIG}, "
             f"{int(signal.SIGKILL)}, 0, 0, 0); "
             "os.execv(sys.argv[1], sys.argv[1:])")


def killed_with_parent(argv: list) -> list:
    """`argv` started so that the process (a compiler) is killed when the thread that
    waits for it dies (Linux; elsewhere `argv` as it is)."""
    if not sys.platform.startswith("linux") or not sys.executable:
        return argv
    return [sys.executable, "-S", "-I", "-c", _LAUNCHER, *argv]
