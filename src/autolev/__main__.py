"""`python -m autolev ...`: the `autolev` command."""
import sys

from .cli import entry

sys.exit(entry())
