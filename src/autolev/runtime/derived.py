"""What the numerics and interop derive from a model, kept while it stays valid."""
from __future__ import annotations

from collections.abc import Hashable


class DerivedCache:
    """Tables of derived things, each table valid for one state of the model: asking
    for a table with another state drops what the old state derived."""

    def __init__(self) -> None:
        self._tables: dict[str, tuple[Hashable, dict]] = {}

    def table(self, kind: str, state: Hashable = None) -> dict:
        kept = self._tables.get(kind)
        if kept is None or kept[0] != state:
            kept = self._tables[kind] = (state, {})
        return kept[1]

    def kept_with_the_model(self) -> "DerivedCache":
        """The tables a pickled model keeps: its commands' numeric systems (rebuilt from
        their generated code when read back), not the rest (sympy frames, Jacobians)."""
        copy = DerivedCache()
        copy._tables = {kind: kept for kind, kept in self._tables.items()
                        if kind in PICKLED_TABLES}
        return copy


PICKLED_TABLES = ("numeric systems", "plain dynamics")
