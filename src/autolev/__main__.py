"""`python -m autolev ...`: the `autolev` command.

Ctrl-C while the command starts (its modules imported, before `main` takes the
interrupt) ends it as an interrupt in the command does, exit status 130, without a
traceback: the package's own __init__ imports nothing (its names are lazy), so the
interrupt lands here."""
import sys


def _command() -> int:
    try:
        from .cli import entry
    except KeyboardInterrupt:
        return 130
    return entry()


sys.exit(_command())
