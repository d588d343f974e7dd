"""`python -m autolev.cli`: the `autolev` command."""
import sys

from . import main

sys.exit(main())
