"""Python names for Autolev names: kept as declared, sanitised the same way every time.

Autolev names are case-insensitive and live in separate namespaces (a body LFF and
a constant LFF, a scalar A and a vector A>).  Python has one namespace per module,
so each (namespace, name) pair gets one identifier:

* the declared spelling (first spelling for assigned names);
* a trailing `_` for Python keywords and the aliases generated code relies on;
* on a clash between namespaces, scalars keep the name and the others get a suffix
  (`_frame`, `_body`, `_point`, `_particle`, `_vec`); derivatives are `Q1p`, `Q1pp`
  (Autolev's own convention in generated C), suffixed the same way on a clash.
"""
from __future__ import annotations

import keyword
import re

RESERVED = set(keyword.kwlist) | set(keyword.softkwlist) | {
    "sm", "me", "al", "np", "model", "t", "None", "True", "False", "self", "print"}
_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")

SUFFIX = {"frame": "_frame", "newtonian": "_frame", "body": "_body", "point": "_point",
          "particle": "_particle", "vector": "_vec", "dyadic": "_dyad", "scalar": "_",
          "value": "_", "derivative": "_"}


class UnsafeName(ValueError):
    pass


class NameTable:
    def __init__(self) -> None:
        self._by_key: dict[tuple[str, str], str] = {}
        self._taken: set[str] = set()      # case-sensitive Python identifiers in use

    def _check(self, name: str) -> None:
        if not _IDENT.match(name) or not name.isidentifier():
            raise UnsafeName(name)

    def assign(self, space: str, name: str, kind: str | None = None) -> str:
        """The identifier of `name` in namespace `space` (allocated on first request)."""
        self._check(name)
        k = (space, name.lower())
        if k in self._by_key:
            return self._by_key[k]
        candidate = name
        if candidate in RESERVED or candidate.startswith("__"):
            candidate = candidate + "_"
        if self._clashes(candidate):
            candidate = name + SUFFIX.get(kind or space, "_")
        base, n = candidate, 2
        while self._clashes(candidate):
            candidate = f"{base}{n}"
            n += 1
        self._by_key[k] = candidate
        self._taken.add(candidate.lower())
        return candidate

    def _clashes(self, candidate: str) -> bool:
        # compare case-insensitively: q1 and Q1 must not become two Python names
        return candidate.lower() in self._taken or candidate in RESERVED

    def get(self, space: str, name: str) -> str | None:
        return self._by_key.get((space, name.lower()))

    def reserve(self, identifier: str) -> None:
        self._taken.add(identifier.lower())
