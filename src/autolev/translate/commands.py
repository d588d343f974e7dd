"""Commands: the table of command calls (`NAME(args)` as a statement), their dispatch,
DISPLAY, and the commands of no family of their own: SOLVE, EIG, ANIMATE and the
in-place ones (EXPAND(X) rewrites X).  kinematics.py and dynamics.py add theirs."""
from __future__ import annotations

from pathlib import Path

from .. import ir
from .assignments import assign
from .core import STATEMENTS, Translator
from .kinds import Entry, NameKind, ValueType
from .functions.table import FUNCTIONS, did_you_mean


# command name -> handler(translator, call); filled by @command here and in the families
COMMANDS: dict = {}
# commands whose first argument, a name, is rewritten with the command's result
IN_PLACE = {"EXPAND", "FACTOR", "ARRANGE", "EXPRESS", "EXPLICIT", "ZEE", "SIMPLIFY"}


def command(*names):
    """Register a handler for the commands `names` (aliases share it)."""
    def register(fn):
        for n in names:
            COMMANDS[n] = fn
        return fn
    return register


@STATEMENTS.register(ir.Command)
def command_statement(tr: Translator, st: ir.Command) -> None:
    c = st.call
    name = c.name.upper()
    fn = COMMANDS.get(name)
    if fn is not None:
        fn(tr, c)
        return
    if name in IN_PLACE and c.args and isinstance(c.args[0], (ir.Name, ir.VectorName)):
        assign(tr, c.args[0], "=", c)
        return
    if name in FUNCTIONS:
        tr.expr(c)      # checked, and displayed by Autolev; nothing to keep
        tr.emit("# (displayed by Autolev; nothing to compute)")
        return
    # a statement that is only a call is a macro call where NAME.A exists (read before
    # translation): none was found, so say where it was looked for
    beside = Path(st.span.start.file).name if st.span is not None else "the model"
    raise tr.error(f"unknown command {name}(): not one of Autolev's, and no macro file "
                   f"{c.name.lower()}.a (any case) next to {beside}"
                   + did_you_mean(name, [*COMMANDS, *IN_PLACE, *FUNCTIONS]), c, "T003")


@STATEMENTS.register(ir.Display)
def display(tr: Translator, st: ir.Display) -> None:
    tr.expr(st.expr)
    tr.emit("# (displayed by Autolev; nothing to compute)")


def arguments(tr, c, *counts):
    """The call's arguments, checked to be one of `counts` plain expressions."""
    if len(c.args) not in counts:
        raise tr.error(f"{c.name.upper()} takes {' or '.join(map(str, counts))} arguments, "
                       f"not {len(c.args)}", c, "T007")
    for a in c.args:
        if isinstance(a, (ir.Range, ir.Equation)):
            raise tr.error(f"unexpected '{'=' if isinstance(a, ir.Equation) else ':'}' in "
                           f"{c.name.upper()}", a, "T009")
    return list(c.args)


@command("SOLVE")
def _solve(tr, c):
    if len(c.args) < 2:
        raise tr.error("SOLVE(equations, x, ...)", c, "T007")
    eqs = tr.expr(c.args[0])
    unknowns = []
    for a in c.args[1:]:
        if isinstance(a, ir.NameRange):
            names = a.names
        elif isinstance(a, ir.Matrix):          # SOLVE(WR, [Q4', Q5'])
            names = [x for row in a.rows for x in row]
        else:
            names = [a]
        for n in names:
            unknowns.append(tr.symbol(n))
            if isinstance(n, ir.Name):
                tr.defined.add((n.name.lower(), n.primes))
    tr.emit(f"model.solve({eqs.code}, [{', '.join(unknowns)}])")


@command("EIG")
def _eig_command(tr, c):
    if len(c.args) == 1:
        tr.expr(c)
        tr.emit("# (displayed by Autolev; nothing to compute)")
        return
    if len(c.args) != 3 or not all(isinstance(a, ir.Name) for a in c.args[1:]):
        raise tr.error("EIG(M) or EIG(M, VALUES, VECTORS)", c, "T009")
    m = tr.expr(c.args[0])
    names = []
    for a in c.args[1:]:
        key = a.name.lower()
        entry = tr.values.get(key)
        if entry is None:
            entry = Entry(tr.py_name("value", a.name), NameKind.VALUE, ValueType.MATRIX)
            tr.values[key] = entry
        entry.type, entry.shape, entry.elements = ValueType.MATRIX, None, None
        names.append(entry.py)
    tr.emit(f"{names[0]}, {names[1]} = al.eig(model.explicit({m.code}), vectors=True)")


@command("ANIMATE")
def _animate(tr, c):
    tr.emit("# (ANIMATE wrote Animake files; not translated)")

