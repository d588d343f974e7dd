"""`python -m autolev ...`: the `autolev` command."""
import sys

from .cli import main

sys.exit(main())
