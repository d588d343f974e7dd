"""Input and output: INPUT, OUTPUT, UNITS and UNITSYSTEM, CODE, ENCODE, SAVE."""
from __future__ import annotations

from typing import Callable

from .. import ir
from ..dispatch import Dispatch
from .core import STATEMENTS, Translator
from .kinds import ValueType
from .emit import call_lines, comment, quote


_INTEGRATION = ("TINITIAL", "TFINAL", "INTEGSTP", "PRINTINT", "ABSERR", "RELERR")
# spellings seen in real files (the Autolev Tutorial writes integStep)
_INTEGRATION_ALIASES = {"INTEGSTEP": "INTEGSTP"}


def _integration_name(name: str) -> str | None:
    key = name.upper()
    key = _INTEGRATION_ALIASES.get(key, key)
    return key if key in _INTEGRATION else None


def _unit_arg(unit: ir.Unit | None) -> str:
    return "" if unit is None else f", {quote(unit.text)}"


@STATEMENTS.register(ir.Input)
def input_statement(tr: Translator, st: ir.Input) -> None:
    for item in st.items:
        target = item.target
        value = tr.scalar(item.value).code
        if isinstance(target, ir.Name) and target.name.lower() in tr.scalars:
            tr.emit(f"model.input({tr.symbol(target)}, {value}{_unit_arg(item.unit)})")
            tr.given_by_input.add(target.name.lower() + "'" * target.primes)
            continue
        if isinstance(target, ir.Name) and _integration_name(target.name) and \
                target.name.lower() not in tr.scalars and not target.primes:
            tr.emit(f"model.input({quote(_integration_name(target.name))}, {value}"
                    f"{_unit_arg(item.unit)})")
            continue
        if isinstance(target, ir.Index):
            t = tr.expr(target).code
        else:
            if target.name.lower() not in tr.scalars:
                tr.warn(f"INPUT {target.name}: not a declared name nor an integration "
                        "parameter (TINITIAL TFINAL INTEGSTP PRINTINT ABSERR RELERR); the "
                        "value is not used", target, "W104")
                tr.emit(f"# (INPUT {comment(target.name)} = ... ignored: not declared)")
                continue
            t = tr.name(target.name, target.primes, target).code
        tr.emit(f"model.input({t}, {value}{_unit_arg(item.unit)})")


@STATEMENTS.register(ir.Output)
def output_statement(tr: Translator, st: ir.Output) -> None:
    items = []
    for item in st.items:
        x = tr.expr(item.expr)
        if x.type not in (ValueType.SCALAR, ValueType.MATRIX, ValueType.UNKNOWN):
            raise tr.error(f"OUTPUT writes scalars, not a {x.type}", item.expr, "T001")
        label = _label(item.expr)
        items.append(f"({x.code}, {quote(label)}{_unit_arg(item.unit)})")
    tr.emit(call_lines("model.output(", items))


def _label(e: ir.Expr) -> str:
    """The column name Autolev printed: the expression as written."""
    if e.span is not None:
        return _text_of(e)
    return "?"


def _text_of(e: ir.Expr) -> str:
    return _TEXT.lookup(type(e))(e)


def _no_text(e: ir.Expr) -> str:
    return "?"


# an expression as written, for a heading ("?" where Autolev's heading is not known);
# parts are looked up in place, not through _text_of: one Python frame per level
_TEXT: Dispatch[Callable[[ir.Expr], str]] = Dispatch("expression text", _no_text)
_TEXT.register(ir.Range, ir.Equation, ir.Matrix, ir.NameRange)(_no_text)
_TEXT.register(ir.Number, ir.VectorName)(lambda e: e.text)
_TEXT.register(ir.Name)(lambda e: e.name + "'" * e.primes)
_TEXT.register(ir.Neg)(lambda e: "-" + _TEXT.lookup(type(e.operand))(e.operand))
_TEXT.register(ir.BinOp)(lambda e: _TEXT.lookup(type(e.left))(e.left) + e.op
                         + _TEXT.lookup(type(e.right))(e.right))
_TEXT.register(ir.Index)(lambda e: f"{e.name}[{_texts(e.indices)}]")
_TEXT.register(ir.Call)(lambda e: f"{e.name}({_texts(e.args)})")


def _texts(exprs: tuple[ir.Expr, ...]) -> str:
    return ",".join([_TEXT.lookup(type(x))(x) for x in exprs])


@STATEMENTS.register(ir.UnitsStatement)
def units_statement(tr: Translator, st: ir.UnitsStatement) -> None:
    for item in st.items:
        for target in item.targets:
            key = _integration_name(target.name) or target.name.upper()
            if key in _INTEGRATION or key == "T":
                name = quote(key)
            elif target.name.lower() in tr.scalars:
                name = tr.name(target.name, target.primes, target).code
            elif target.name.lower() in tr.values:
                # an assigned, undeclared name: its unit goes with the name
                name = quote(target.name + "'" * target.primes)
            else:
                name = quote(target.name)
            tr.emit(f"model.units({name}, {quote(item.unit.text)})")


@STATEMENTS.register(ir.UnitSystem)
def unit_system(tr: Translator, st: ir.UnitSystem) -> None:
    tr.emit(f"model.unit_system({', '.join(quote(u) for u in st.units)})")


@STATEMENTS.register(ir.Code)
def code_statement(tr: Translator, st: ir.Code) -> None:
    args = []
    for a in st.args:
        x = tr.expr(a)
        args.append(x.code if x.type != ValueType.LIST else x.code[1:-1])
    opts = ""
    if args:
        opts += f", [{', '.join(args)}]"
    if st.sweep is not None:
        sw = st.sweep
        target = tr.name(sw.target.name, sw.target.primes, sw.target).code
        # the sweep gives the swept input its values: it lacks none
        tr.given_by_input.add(sw.target.name.lower() + "'" * sw.target.primes)
        opts += (f", sweep=({target}, {tr.scalar(sw.start).code}, {tr.scalar(sw.stop).code}, "
                 f"{tr.scalar(sw.step).code}{_unit_arg(sw.unit)})")
    if st.options:
        opts += f", options=({''.join(quote(o) + ', ' for o in st.options)})"
    zero = tr.values.get("zero")
    if tr.session.kane_called and zero is not None and zero.type == ValueType.MATRIX:
        opts += f", zero={zero.py}"
    tr.code_call(f"model.code({quote(st.what)}, {quote(st.filename)}{opts})",
                 st.what.lower() in ("dynamics", "ode"))


@STATEMENTS.register(ir.Encode)
def encode(tr: Translator, st: ir.Encode) -> None:
    items = []
    for e in st.exprs:
        x = tr.expr(e)
        items.append(f"({quote(_text_of(e))}, {x.code})")
    tr.emit(call_lines("model.encode(", items))


@STATEMENTS.register(ir.Save)
def save(tr: Translator, st: ir.Save) -> None:
    tr.emit(f"# (SAVE wrote Autolev's session transcript {comment(st.filename)})")

