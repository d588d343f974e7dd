"""`autolev cache`: what the cache holds, or emptied of autolev's files.
"""
from __future__ import annotations

import argparse
import sys

from . import background
from .common import megabytes


def cmd_cache(ns: argparse.Namespace) -> int:
    """What the cache holds (built models, compiled code), or empty it."""
    from ..engine import cachekeys
    from .. import modelcache

    if ns.action == "clear":
        from ..runtime.steps import SlowStep
        with SlowStep(sys.stderr, "autolev cache clear: waiting for a compile an earlier "
                                  "run finishes in the background", after=0.5):
            background.wait_for_every_finishing()
        try:
            count, size = modelcache.clear()
        except OSError as exc:
            print(f"autolev cache: error: {exc}", file=sys.stderr)
            return 1
        print(f"removed {count} entr{'y' if count == 1 else 'ies'} ({megabytes(size)})")
        return 0
    s = modelcache.summary()
    print(f"cache: {s.folder}")
    for label, (count, size) in (("built models", s.models), ("translations", s.translations),
                                 ("run plans", s.plans), ("compiled code", s.compiled)):
        print(f"  {label + ':':14s} {count:5d}  {megabytes(size)}")
    print(f"  limit: {megabytes(s.limit)} (the oldest entries leave first)")
    if not modelcache.enabled():
        print(f"  built models and run plans are not kept: {cachekeys.DISABLE_VARIABLE} "
              "is set")
    return 0


def add_cache(sub) -> None:
    cache = sub.add_parser("cache", help="what the cache holds, or empty it",
                           description="autolev keeps the models it built (read back when "
                           "the model, autolev and its libraries are unchanged), the plans "
                           "of plain runs (what a warm `autolev run` repeats) and the "
                           "code it compiled, in $AUTOLEV_CACHE (default "
                           "~/.cache/autolev/build), private to you and kept under "
                           "$AUTOLEV_CACHE_LIMIT_MB (default 2048).  "
                           "AUTOLEV_NO_MODEL_CACHE=1 builds every model afresh.")
    cache.add_argument("action", choices=("info", "clear"), nargs="?", default="info",
                       help="info (default): entries and sizes; clear: remove them all")
    cache.set_defaults(func=cmd_cache)
