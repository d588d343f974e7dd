"""Declarations: CONSTANTS, VARIABLES, MOTIONVARIABLES, SPECIFIEDS, IMAGINARY and the
NEWTONIAN, FRAMES, BODIES, PARTICLES, POINTS that name the model's entities."""
from __future__ import annotations

import re

from .. import ir
from .core import STATEMENTS, Translator
from .kinds import Entry, NameKind, ValueType
from .emit import assign_names, quote, quoted_names


# -- declarations ------------------------------------------------------------------
_ENTITY_DECL = {"newtonian": NameKind.NEWTONIAN, "frames": NameKind.FRAME,
                "bodies": NameKind.BODY, "particles": NameKind.PARTICLE,
                "points": NameKind.POINT}
_SCALAR_DECL = {"constants": NameKind.CONSTANT, "variables": NameKind.VARIABLE,
                "motionvariables": NameKind.MOTIONVARIABLE,
                "specifieds": NameKind.SPECIFIED, "imaginary": NameKind.IMAGINARY}


@STATEMENTS.register(ir.Declaration)
def declaration(tr: Translator, st: ir.Declaration) -> None:
    if st.what in _ENTITY_DECL:
        _declare_entities(tr, st)
    else:
        _declare_scalars(tr, st)


def _referenced(tr: Translator, name: str) -> bool:
    cache = tr.words
    if cache is None:
        cache = set()
        for s in tr.program.statements:
            cache.update(w.lower() for w in re.split(r"[^A-Za-z0-9]+", s.text) if w)
            cache.update(w.lower() for w in re.split(r"[^A-Za-z0-9_]+", s.text) if w)
        tr.words = cache
    return name.lower() in cache


def _declare_entities(tr: Translator, st: ir.Declaration) -> None:
    kind = _ENTITY_DECL[st.what]
    names = [n for item in st.items for n in item.names]
    for item in st.items:
        if item.value is not None or item.sign is not None or item.primes:
            raise tr.error(f"{st.what.upper()} names take no value, sign or prime", item, "T010")
    if kind == NameKind.NEWTONIAN:
        if len(names) != 1:
            raise tr.error("NEWTONIAN declares one frame", st, "T007")
        n = names[0]
        py = tr.py_name("entity", n, "frame")
        tr.entities[n.lower()] = Entry(py, NameKind.NEWTONIAN, ValueType.FRAME)
        tr.emit(f"{py} = model.newtonian({quote(n)})")
        _implicit_point(tr, n + "O", f"{py}.origin")
        return
    pys = []
    for n, item in ((n, item) for item in st.items for n in item.names):
        if n.lower() in tr.entities:
            tr.warn(f"'{n}' is declared again; the new {kind} replaces it", item)
        py = tr.py_name("entity", n, kind.value)     # the name table keeps its own words
        tr.entities[n.lower()] = Entry(py, kind, ValueType.FRAME if kind in
                                       (NameKind.FRAME, NameKind.BODY) else ValueType.POINT)
        pys.append(py)
    method = {NameKind.FRAME: "frames", NameKind.BODY: "bodies",
              NameKind.PARTICLE: "particles", NameKind.POINT: "points"}[kind]
    tr.emit(assign_names(pys, f"model.{method}({quoted_names(names)})"))
    if kind in (NameKind.BODY, NameKind.FRAME):
        # every frame has its origin AO, as NEWTONIAN N has NO and BODIES B has BO
        attribute = "masscenter" if kind == NameKind.BODY else "origin"
        for n, py in zip(names, pys):
            _implicit_point(tr, n + "O", f"{py}.{attribute}")


def _implicit_point(tr: Translator, name: str, code: str) -> None:
    if name.lower() in tr.entities:
        return
    if _referenced(tr, name):
        py = tr.py_name("entity", name, "point")
        tr.emit(f"{py} = {code}")
    else:
        py = code
    tr.entities[name.lower()] = Entry(py, NameKind.POINT, ValueType.POINT)


def _entry_key(tr: Translator, entry: Entry) -> str:
    return next(k for k, e in tr.scalars.items() if e is entry)


_KIND_WORDS = {NameKind.CONSTANT: "constant", NameKind.VARIABLE: "variable",
               NameKind.MOTIONVARIABLE: "motion variable",
               NameKind.SPECIFIED: "specified quantity", NameKind.IMAGINARY: "imaginary unit"}


def _warn_time_replaced(tr: Translator, name: str, kind: NameKind, item) -> None:
    # a declared name is the model's own (docs/language.md), time's T included
    what = _KIND_WORDS[kind]
    tr.warn(f"'{name}' is declared as a {what}: in this model {name} is that {what}, not "
            f"the time (expressions with {name} mean it, and OUTPUT {name} prints it); "
            "runs still integrate over time and plot against it (rename it to keep T the "
            "time)", item, "W105")


def _declare_scalars(tr: Translator, st: ir.Declaration) -> None:
    kind = _SCALAR_DECL[st.what]
    groups: dict[tuple, list[tuple[str, str]]] = {}
    definitions = []
    for item in st.items:
        order = max(item.primes, st.keyword_primes)
        for n in item.names:
            key = n.lower()
            if key in tr.scalars:      # declared again: reading warned (W001)
                entry = tr.scalars[key]
            else:
                entry = tr.declare_scalar(n, kind, order)
                groups.setdefault((order, item.sign), []).append((n, entry.py))
                if key == "t":
                    _warn_time_replaced(tr, n, kind, item)
            if item.value is not None:
                definitions.append((entry, item.value, item))
    for (order, sign), items in groups.items():
        names = [n for n, _ in items]
        pys = [p for _, p in items]
        if kind == NameKind.IMAGINARY:
            for p in pys:
                tr.emit(f"{p} = sm.I")
            continue
        method = {NameKind.CONSTANT: "constants", NameKind.VARIABLE: "variables",
                  NameKind.MOTIONVARIABLE: "motion_variables",
                  NameKind.SPECIFIED: "specifieds"}[kind]
        opts = ""
        if order and kind != NameKind.CONSTANT:
            opts += f", order={order}"
        if sign:
            opts += f", sign={quote(sign)}"
        tr.emit(assign_names(pys, f"model.{method}({quoted_names(names)}{opts})"))
        for k in range(1, order + 1):
            used = [(n, p) for n, p in items if (n.lower(), k) in tr._used_primes]
            if used:
                ds = [tr.derivative_name(n, k) for n, _ in used]
                base = ", ".join(p for _, p in used)
                order_arg = f", order={k}" if k > 1 else ""
                tr.emit(assign_names(ds, f"al.derivatives({base}{order_arg})"))
    for entry, value, item in definitions:
        tr.emit(f"model.define({entry.py}, {tr.scalar(value).code})")
        tr.defined.add((_entry_key(tr, entry), 0))

