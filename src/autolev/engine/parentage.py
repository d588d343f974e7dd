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


def killed_with_parent():
    """A subprocess preexec_fn: the started process (a compiler) is killed when the
    process that waits for it dies; None off Linux."""
    if not sys.platform.startswith("linux"):
        return None
    import ctypes
    prctl = ctypes.CDLL(None, use_errno=True).prctl     # looked up before the fork

    def set_death_signal() -> None:
        prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
    return set_death_signal
