"""A model's one revision, and what the numerics and interop derive from a model, kept
while it stays valid."""
from __future__ import annotations

import functools
from collections.abc import Hashable


class Revision:
    """The one count of a model's changes: every mutation (a statement's, a caller's)
    bumps it, through the model, its frames and points (their Scene) and its
    definitions.  `view` is set while the definitions are seen as they stood at a CODE
    command (Definitions.as_of): what is derived then belongs to that view."""

    def __init__(self) -> None:
        self.count = 0
        self.view: Hashable = None

    def bump(self) -> None:
        self.count += 1

    @property
    def key(self) -> tuple:
        return (self.count, self.view)


def mutation(method):
    """A method that changes what its owner holds: the owner's `note_change()` (a bump of
    the model's revision) follows it, even when it fails partway, so no caller has to
    remember it.  Each is listed in MUTATIONS (tests/test_model_revision.py calls every
    one)."""
    @functools.wraps(method)
    def changing(owner, *args, **kwargs):
        try:
            return method(owner, *args, **kwargs)
        finally:
            owner.note_change()
    MUTATIONS.append(changing)
    return changing


MUTATIONS: list = []


class Owned:
    """A part of a model (its registry, loads, constraints, I/O statements): what it
    holds changes only through its `mutation` methods, each bumping the revision."""

    def __init__(self, revision: Revision) -> None:
        self.revision = revision

    def note_change(self) -> None:
        self.revision.bump()


class DerivedCache:
    """Tables of derived things, each valid for the model's revision it was made at:
    asking for a table at another revision drops what the old one derived."""

    def __init__(self, revision: Revision) -> None:
        self.revision = revision
        self._tables: dict[str, tuple[Hashable, dict]] = {}

    def table(self, kind: str) -> dict:
        state = self.revision.key
        kept = self._tables.get(kind)
        if kept is None or kept[0] != state:
            kept = self._tables[kind] = (state, {})
        return kept[1]

    def __getstate__(self) -> dict:
        """Pickled with its model (the cache of built models, a study's workers), by
        whichever part holds it (the model, its scene): only the tables of its
        commands' numeric systems (rebuilt from their generated code when read back),
        not the rest (sympy frames, trees of joints, Jacobians), made again when
        asked."""
        return {"revision": self.revision,
                "_tables": {kind: kept for kind, kept in self._tables.items()
                            if kind in PICKLED_TABLES}}


PICKLED_TABLES = ("numeric systems", "plain dynamics")
