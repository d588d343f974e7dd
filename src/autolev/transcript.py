"""What Autolev displayed: a model's session transcript, laid out as its `.all` files.

Every input line is numbered `(n)`; after each assignment come the responses Autolev
printed for it: the intermediate Z variables its value uses that were not shown before
(`-> (n) Z3 = ...`), then `-> (n) NAME = value`.  Values are written in Autolev's
syntax (`SIN(Q1)`, `Q1^2`, `L*A1>`, `c*A1>*B2>`, `[a, b; c, d]`), numbers to 7
significant digits as Autolev displayed them.  Our Z variables are ours: their
numbering need not be Autolev's, and `autolev verify` judges a transcript by value.

Only assignments get responses here; Autolev also echoed what some commands defined
(INERTIA's I_B_BO>>, DIRCOS's direction cosines), which this transcript leaves out.
"""
from __future__ import annotations

from pathlib import Path

import sympy as sm
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

from .errors import AutolevError
from .pipeline import parse
from .runtime.symbols import TIME, Z
from .runtime.vector import Dyadic, Vector
from .source import decode
from .verification import Response, Session, _build


class AutolevPrinter(StrPrinter):
    """sympy expressions in Autolev's printed syntax."""

    printmethod = "_autolevstr"          # not the objects' own _sympystr (Z's: z1)

    def _print_Symbol(self, expr) -> str:
        return "T" if expr == TIME else expr.name

    def _print_Dummy(self, expr) -> str:
        return expr.name.upper() if isinstance(expr, Z) else expr.name

    def _print_Float(self, expr) -> str:
        return f"{float(expr):.7g}"

    def _print_Pi(self, expr) -> str:
        return "PI"

    def _print_ImaginaryUnit(self, expr) -> str:
        return "I"

    def _print_Function(self, expr) -> str:
        name = type(expr).__name__.upper()
        return f"{name}({', '.join(self._print(a) for a in expr.args)})"

    def _print_Abs(self, expr) -> str:
        return f"ABS({self._print(expr.args[0])})"

    def _print_Pow(self, expr, rational=False) -> str:
        base, exp = expr.as_base_exp()
        if exp == sm.S.Half:
            return f"SQRT({self._print(base)})"
        if exp == -sm.S.Half:
            return f"1/SQRT({self._print(base)})"
        if exp == -1:
            return f"1/{self.parenthesize(base, PRECEDENCE['Pow'])}"
        return (f"{self.parenthesize(base, PRECEDENCE['Pow'], strict=True)}^"
                f"{self.parenthesize(exp, PRECEDENCE['Pow'], strict=True)}")

    def _print_MatrixBase(self, expr) -> str:
        return "[" + "; ".join(", ".join(self._print(expr[i, j]) for j in range(expr.cols))
                               for i in range(expr.rows)) + "]"

    _print_MutableDenseMatrix = _print_ImmutableDenseMatrix = _print_MatrixBase


_PRINTER = AutolevPrinter()


def expression(value) -> str:
    """A value (scalar, Vector, Dyadic, matrix) as Autolev printed it."""
    if isinstance(value, Vector):
        return _terms([(c, f"{frame.name}{i + 1}>") for frame, comps in value.terms.items()
                       for i, c in enumerate(comps)], "0>")
    if isinstance(value, Dyadic):
        return _terms([(m[i, j], f"{a.name}{i + 1}>*{b.name}{j + 1}>")
                       for (a, b), m in value.terms.items()
                       for i in range(3) for j in range(3)], "0>>")
    if isinstance(value, (list, tuple)):
        value = sm.Matrix(value)
    return _PRINTER.doprint(value if isinstance(value, sm.MatrixBase) else sm.sympify(value))


def _terms(terms, zero: str) -> str:
    """coefficient*unit terms joined with their signs (`Z15*A3> - Z16*N3>`)."""
    out = ""
    for coef, unit in terms:
        coef = sm.sympify(coef)
        if coef == 0:
            continue
        negative = coef.could_extract_minus_sign()
        magnitude = -coef if negative else coef
        if magnitude == 1:
            text = unit
        elif precedence(magnitude) < PRECEDENCE["Mul"]:
            text = f"({_PRINTER.doprint(magnitude)})*{unit}"
        else:
            text = f"{_PRINTER.doprint(magnitude)}*{unit}"
        out += (" - " if negative else " + ") + text if out else ("-" if negative else "") + text
    return out or zero


def _z_used(value) -> list:
    """The Z variables a value's expressions name directly."""
    if isinstance(value, Vector):
        exprs = [c for comps in value.terms.values() for c in comps]
    elif isinstance(value, Dyadic):
        exprs = [x for m in value.terms.values() for x in m]
    elif isinstance(value, (sm.MatrixBase, list, tuple)):
        exprs = list(sm.Matrix(value))
    else:
        exprs = [sm.sympify(value)]
    found = set()
    for e in exprs:
        found |= {s for s in getattr(e, "free_symbols", ()) if isinstance(s, Z)}
    return sorted(found, key=lambda z: int(z.name[1:]) if z.name[1:].isdigit() else 0)


def transcript(path) -> str:
    """The `.all` transcript of the model at `path` (raises as autolev.load does)."""
    p = Path(path)
    text = decode(p.read_bytes())
    lines = text.splitlines()
    program = parse(p)
    responses, written = [], []
    for st in program.statements:
        span = st.span
        if st.kind != "assignment" or span is None or Path(span.start.file) != p:
            continue
        lhs, _, rhs = st.text.partition("=")
        lhs = lhs.rstrip(":+-*/^ ").strip()
        # a derivative's value is its definition, which a later X' = ... replaces: the
        # response is the right side as the statement gave it
        captured_as = f"({rhs.strip()})" if lhs.endswith("'") and st.op == "=" else lhs
        responses.append(Response(len(responses) + 1, span.end.line, captured_as, "",
                                  span.end.line))
        written.append(lhs)
    session = Session("\n".join(lines) + "\n", responses, str(p))
    model, captured, skipped = _build(session, p)
    if model is None:
        raise AutolevError(skipped)
    after: dict[int, list[int]] = {}
    for k, r in enumerate(responses):
        if k in captured:
            after.setdefault(r.after, []).append(k)
    out, number, shown = [], 0, set()
    for no, line in enumerate(lines, 1):
        number += 1
        out.append(f"   ({number}) {line}")
        for k in after.get(no, []):
            value, _ = captured[k]
            for z in _z_chain(model, value, shown):
                number += 1
                out.append(f"-> ({number}) {expression(z)} = "
                           f"{expression(model.defs.rhs[z])}")
            number += 1
            out.append(f"-> ({number}) {written[k]} = {expression(value)}")
        if after.get(no):
            out.append("")
    return "\n".join(out) + "\n"


def _z_chain(model, value, shown: set) -> list:
    """The Z variables a value needs that were not shown yet, each after those its own
    definition needs."""
    order: list = []

    def visit(z):
        if z in shown:
            return
        shown.add(z)
        for inner in _z_used(model.defs.rhs.get(z, 0)):
            visit(inner)
        order.append(z)
    for z in _z_used(value):
        visit(z)
    return [z for z in order if z in model.defs.rhs]
