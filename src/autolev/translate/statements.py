"""Statement writers: declarations, assignments, commands, input/output, settings."""
from __future__ import annotations

import re
import textwrap
from typing import Callable

from .. import ir
from ..dispatch import Dispatch
from .core import STATEMENTS, Entry, Translator, Typed
from .emit import comment, quote
from .functions import FUNCTIONS
from .special import assign_vector


def _assign_names(tr: Translator, names: list[str], call: str) -> None:
    """`A, B = call`, the names wrapped in parentheses when the line is long."""
    left = ", ".join(names)
    line = f"{left} = {call}"
    wrapped = textwrap.wrap(left, 80, break_long_words=False)
    if len(line) <= 92 or len(wrapped) == 1:
        tr.emit(line)
        return
    tr.emit("(" + wrapped[0])
    for part in wrapped[1:-1]:
        tr.emit(" " + part)
    tr.emit(" " + wrapped[-1] + f") = {call}")


def _quoted_names(names: list[str]) -> str:
    text = " ".join(names)
    if len(text) <= 70:
        return quote(text)
    parts = textwrap.wrap(text, 70, break_long_words=False)   # never split a name
    return "(" + " ".join(quote(p + (" " if i < len(parts) - 1 else ""))
                          for i, p in enumerate(parts)) + ")"


# -- declarations ------------------------------------------------------------------
_ENTITY_DECL = {"newtonian": "newtonian", "frames": "frame", "bodies": "body",
                "particles": "particle", "points": "point"}
_SCALAR_DECL = {"constants": "constant", "variables": "variable",
                "motionvariables": "motionvariable", "specifieds": "specified",
                "imaginary": "imaginary"}


@STATEMENTS.register(ir.Declaration)
def declaration(tr: Translator, st: ir.Declaration) -> None:
    if st.what in _ENTITY_DECL:
        _declare_entities(tr, st)
    else:
        _declare_scalars(tr, st)


def _referenced(tr: Translator, name: str) -> bool:
    cache = getattr(tr, "_words", None)
    if cache is None:
        cache = set()
        for s in tr.program.statements:
            cache.update(w.lower() for w in re.split(r"[^A-Za-z0-9]+", s.text) if w)
            cache.update(w.lower() for w in re.split(r"[^A-Za-z0-9_]+", s.text) if w)
        tr._words = cache
    return name.lower() in cache


def _declare_entities(tr: Translator, st: ir.Declaration) -> None:
    kind = _ENTITY_DECL[st.what]
    names = [n for item in st.items for n in item.names]
    for item in st.items:
        if item.value is not None or item.sign is not None or item.primes:
            raise tr.error(f"{st.what.upper()} names take no value, sign or prime", item, "T010")
    if kind == "newtonian":
        if len(names) != 1:
            raise tr.error("NEWTONIAN declares one frame", st, "T007")
        n = names[0]
        py = tr.py_name("entity", n, "frame")
        tr.entities[n.lower()] = Entry(py, "newtonian", "frame")
        tr.emit(f"{py} = model.newtonian({quote(n)})")
        _implicit_point(tr, n + "O", f"{py}.origin")
        return
    pys = []
    for n in names:
        if n.lower() in tr.entities:
            tr.warn(f"'{n}' is declared again; the new {kind} replaces it", st)
        py = tr.py_name("entity", n, kind)
        tr.entities[n.lower()] = Entry(py, kind, "frame" if kind in ("frame", "body")
                                       else "point")
        pys.append(py)
    method = {"frame": "frames", "body": "bodies", "particle": "particles",
              "point": "points"}[kind]
    _assign_names(tr, pys, f"model.{method}({_quoted_names(names)})")
    if kind in ("body", "frame"):
        # every frame has its origin AO, as NEWTONIAN N has NO and BODIES B has BO
        attribute = "masscenter" if kind == "body" else "origin"
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
    tr.entities[name.lower()] = Entry(py, "point", "point")


def entry_key(tr: Translator, entry: Entry) -> str:
    return next(k for k, e in tr.scalars.items() if e is entry)


def _declare_scalars(tr: Translator, st: ir.Declaration) -> None:
    kind = _SCALAR_DECL[st.what]
    groups: dict[tuple, list[tuple[str, str]]] = {}
    definitions = []
    for item in st.items:
        order = max(item.primes, st.keyword_primes)
        for n in item.names:
            key = n.lower()
            if key in tr.scalars:
                if item.value is None:
                    tr.warn(f"'{n}' is declared again", item, "W102")
                entry = tr.scalars[key]
            else:
                entry = tr.declare_scalar(n, kind, order)
                groups.setdefault((order, item.sign), []).append((n, entry.py))
            if item.value is not None:
                definitions.append((entry, item.value, item))
    for (order, sign), items in groups.items():
        names = [n for n, _ in items]
        pys = [p for _, p in items]
        if kind == "imaginary":
            for p in pys:
                tr.emit(f"{p} = sm.I")
            continue
        method = {"constant": "constants", "variable": "variables",
                  "motionvariable": "motion_variables", "specified": "specifieds"}[kind]
        opts = ""
        if order and kind != "constant":
            opts += f", order={order}"
        if sign:
            opts += f", sign={quote(sign)}"
        _assign_names(tr, pys, f"model.{method}({_quoted_names(names)}{opts})")
        for k in range(1, order + 1):
            used = [(n, p) for n, p in items if (n.lower(), k) in tr._used_primes]
            if used:
                ds = [tr.derivative_name(n, k) for n, _ in used]
                base = ", ".join(p for _, p in used)
                order_arg = f", order={k}" if k > 1 else ""
                _assign_names(tr, ds, f"al.derivatives({base}{order_arg})")
    for entry, value, item in definitions:
        tr.emit(f"model.define({entry.py}, {tr.scalar(value).code})")
        tr.defined.add((entry_key(tr, entry), 0))


# -- mass and inertia --------------------------------------------------------------------
def _implicit_constant(tr: Translator, e: ir.Expr) -> None:
    """MASS B=mB and INERTIA B, I1, ... declare names that are new (as constants)."""
    if isinstance(e, ir.Name) and not e.primes:
        key = e.name.lower()
        if key not in tr.scalars and key not in tr.values and key not in ("t", "pi"):
            entry = tr.declare_scalar(e.name, "constant", 0)
            tr.emit(f"{entry.py} = model.constants({quote(e.name)})")


@STATEMENTS.register(ir.MassStatement)
def mass(tr: Translator, st: ir.MassStatement) -> None:
    for item in st.items:
        target = tr.entities.get(item.target.lower())
        if target is None or target.kind not in ("body", "particle"):
            raise tr.error(f"MASS is given to bodies and particles; '{item.target}' is not "
                           "one", item, "T008")
        _implicit_constant(tr, item.value)
        value = tr.scalar(item.value)
        tr.emit(f"{target.py}.mass = {value.code}")
        if item.value_of_value is not None:
            tr.emit(f"model.define({value.code}, {tr.scalar(item.value_of_value).code})")
            tr.defined.add((item.value.name.lower(), 0))


@STATEMENTS.register(ir.InertiaStatement)
def inertia(tr: Translator, st: ir.InertiaStatement) -> None:
    body = tr.entities.get(st.body.lower())
    about = None
    if body is None or body.kind != "body":
        pieces = st.body.split("_")
        for i in range(1, len(pieces)):
            b = tr.entities.get("_".join(pieces[:i]).lower())
            p = tr.entities.get("_".join(pieces[i:]).lower())
            if b is not None and b.kind == "body" and p is not None and \
                    p.kind in ("point", "particle"):
                body, about = b, p
                break
        else:
            raise tr.error(f"INERTIA is given to a body; '{st.body}' is not one", st, "T008")
    frame = None
    if st.frame is not None:
        frame = tr.entities.get(st.frame.lower())
        if frame is None or frame.kind not in ("frame", "newtonian", "body"):
            raise tr.error(f"'{st.frame}' is not a frame", st, "T008")
    for name, value in st.definitions:
        v = tr.scalar(value)
        if name.lower() in tr.scalars:
            tr.emit(f"model.define({tr.scalars[name.lower()].py}, {v.code})")
            tr.defined.add((name.lower(), 0))
        else:
            py = tr.py_name("value", name)
            tr.values[name.lower()] = Entry(py, "value", "scalar")
            tr.emit(f"{py} = {v.code}")
    for v in st.values:
        _implicit_constant(tr, v)
    values = [tr.scalar(v).code for v in st.values]
    if len(values) == 1:
        values = values * 3
    opts = ""
    if frame is not None:
        opts += f", frame={frame.py}"
    if about is not None:
        opts += f", about={about.py}"
    tr.emit(f"{body.py}.set_inertia({', '.join(values)}{opts})")


# -- assignments ---------------------------------------------------------------------------
_COMPOUND = {"+=": "+", "-=": "-", "*=": "*", "/=": "/", "^=": "**"}


@STATEMENTS.register(ir.Assignment)
def assignment(tr: Translator, st: ir.Assignment) -> None:
    assign(tr, st.target, st.op, st.value)


def assign(tr: Translator, target: ir.Expr, op: str, value_expr: ir.Expr) -> None:
    if isinstance(target, ir.Name) and op in ("=", ":="):
        tr.redefining = (target.name.lower(), target.primes)
    try:
        value = tr.expr(value_expr)
    finally:
        tr.redefining = None
    if value.type in ("frame", "point", "list"):
        raise tr.error(f"a {value.type} cannot be assigned", value_expr, "T001")
    if isinstance(target, ir.VectorName):
        assign_vector(tr, target, op, value)
        return
    if isinstance(target, ir.Index):
        _assign_element(tr, target, op, value)
        return
    name, primes = target.name, target.primes
    key = name.lower()
    if key == "zee_not" and not primes:
        tr.emit(f"model.zee_not({value.code})")
        return
    if key in tr.scalars:
        sym = _symbol_code(tr, target)
        if op in ("=", ":="):
            rhs = value.code
        else:
            rhs = f"model.rhs({sym}) {_COMPOUND[op]} {value.wrapped(6)}"
        if value.type == "matrix":
            raise tr.error(f"{name} is a scalar; the right side is a matrix", value_expr, "T001")
        tr.emit(f"model.define({sym}, {rhs})")
        tr.defined.add((key, primes))
        return
    if primes:
        raise tr.error(f"{name}{chr(39) * primes} needs {name} declared (VARIABLES "
                       f"{name}{chr(39) * primes})", target, "T002")
    if key not in tr.values:
        parts = tr.split_entities(name, ("frame", "newtonian", "body"), 2)
        if parts is not None:
            if op not in ("=", ":="):
                raise tr.error(f"{op} is not defined for a direction cosine matrix", target, "T010")
            a, b = parts
            tr.emit(f"{b.py}.orient_dcm({a.py}, {value.code})")
            return
    entry = tr.values.get(key)
    if entry is None:
        if op not in ("=", ":="):
            raise tr.error(f"{name} has no value yet", target, "T002")
        entry = Entry(tr.py_name("value", name), "value", value.type)
        tr.values[key] = entry
        tr.emit(f"{entry.py} = {value.code}")
        return
    if op in ("=", ":="):
        entry.type = value.type
        tr.emit(f"{entry.py} = {value.code}")
    else:
        tr.emit(f"{entry.py} = {entry.py} {_COMPOUND[op]} {value.wrapped(6)}")


def _assign_element(tr: Translator, target: ir.Index, op: str, value: Typed) -> None:
    key = target.name.lower()
    if target.primes:
        raise tr.error("a primed name cannot be indexed", target, "T010")
    if value.type not in ("scalar", "unknown"):
        raise tr.error(f"a matrix element is a scalar, not a {value.type}", target, "T001")
    idx = ", ".join(_one_based(tr, i) for i in target.indices)
    entry = tr.values.get(key)
    if entry is None:
        if key in tr.scalars:
            raise tr.error(f"{target.name} is a declared scalar, not a matrix", target, "T008")
        if op not in ("=", ":="):
            raise tr.error(f"{target.name} has no value yet ({op} needs one)", target,
                           "T002")
        entry = Entry(tr.py_name("value", target.name), "value", "matrix")
        tr.values[key] = entry
        current = "None"
    else:
        current = entry.py
        entry.type = "matrix"
    if op not in ("=", ":="):
        old = f"{entry.py}[{', '.join(tr.index_code(i) for i in target.indices)}]"
        rhs = f"{old} {_COMPOUND[op]} {value.wrapped(6)}"
    else:
        rhs = value.code
    tr.emit(f"{entry.py} = al.set_element({current}, ({idx},), {rhs})")


def _one_based(tr: Translator, e: ir.Expr) -> str:
    x = tr.scalar(e)
    return x.code


# -- commands --------------------------------------------------------------------------------
COMMANDS: dict = {}
IN_PLACE = {"EXPAND", "FACTOR", "ARRANGE", "EXPRESS", "EXPLICIT", "ZEE", "SIMPLIFY"}


def command(*names):
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
    raise tr.error(f"unknown command {name}()", c, "T003")


@STATEMENTS.register(ir.Display)
def display(tr: Translator, st: ir.Display) -> None:
    tr.expr(st.expr)
    tr.emit("# (displayed by Autolev; nothing to compute)")


def _angle(tr: Translator, e: ir.Expr) -> str:
    """A number is an angle in degrees unless DEGREES OFF; an angle written with PI
    (PI/2) is in radians either way (docs/language.md)."""
    x = tr.scalar(e)
    if tr.degrees and _is_plain_number(e):
        return f"al.degrees_to_radians({x.code})"
    return x.code


def _is_plain_number(e: ir.Expr) -> bool:
    return not any(isinstance(n, (ir.Name, ir.Call, ir.Index, ir.VectorName))
                   for n in ir.walk(e))


@command("SIMPROT")
def _simprot(tr, c):
    args = _n(tr, c, 4)
    a, b = tr.frame(args[0]).code, tr.frame(args[1]).code
    axis = args[2]
    x = tr.expr(axis)
    if x.type == "vector":
        axis_code = x.code
    elif x.exact is not None and x.exact.denominator == 1 and abs(int(x.exact)) in (1, 2, 3):
        k = int(x.exact)
        axis_code = ("-" if k < 0 else "") + f"{a}.{'xyz'[abs(k) - 1]}"
    else:
        raise tr.error("SIMPROT's axis is 1, 2, 3 (negative for the other way) or a vector",
                       axis, "T009")
    tr.emit(f"{b}.orient_axis({a}, {axis_code}, {_angle(tr, args[3])})")


@command("DIRCOS")
def _dircos(tr, c):
    if len(c.args) < 4 or not isinstance(c.args[2], ir.Name):
        raise tr.error("DIRCOS(A, B, BODYijk|SPACEijk|EULER, angles...)", c, "T009")
    a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
    kind = c.args[2].name.upper()
    angles = [_angle(tr, x) for x in c.args[3:]]
    if kind == "EULER":
        if len(angles) != 4:
            raise tr.error("DIRCOS(A, B, EULER, e1, e2, e3, e4) takes 4 parameters", c, "T007")
        tr.emit(f"{b}.orient_euler_parameters({a}, {', '.join(angles)})")
        return
    if kind == "RODRIGUES":
        if len(angles) != 3:
            raise tr.error("DIRCOS(A, B, RODRIGUES, g1, g2, g3) takes 3 parameters", c, "T007")
        tr.emit(f"{b}.orient_rodrigues({a}, {', '.join(angles)})")
        return
    m = re.fullmatch(r"(BODY|SPACE)([123]{3})", kind)
    if not m or len(angles) != 3:
        raise tr.error(f"DIRCOS does not know {c.args[2].name}; expected BODYijk, SPACEijk "
                       "or EULER", c.args[2], "T003")
    method = "orient_body_fixed" if m.group(1) == "BODY" else "orient_space_fixed"
    tr.emit(f"{b}.{method}({a}, ({', '.join(angles)}), {quote(m.group(2))})")


@command("KINDIFFS")
def _kindiffs(tr, c):
    if len(c.args) < 4 or not isinstance(c.args[2], ir.Name):
        raise tr.error("KINDIFFS(A, B, BODYijk|SPACEijk|EULER, q...)", c, "T009")
    a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
    coords = [_symbol_code(tr, x) for x in c.args[3:]]
    tr.emit(f"model.kindiffs({a}, {b}, {quote(c.args[2].name.upper())}, {', '.join(coords)})")
    for x in c.args[3:]:
        if isinstance(x, ir.Name):
            tr.defined.add((x.name.lower(), x.primes + 1))


@command("ANGVEL")
def _angvel(tr, c):
    if len(c.args) == 2:
        a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
        tr.emit(f"# (Autolev displayed {comment(f'W_{c.args[1].name}_{c.args[0].name}>')})")
        tr.emit(f"{b}.ang_vel_in({a})")
        return
    if len(c.args) == 6 and isinstance(c.args[2], ir.Name):
        a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
        angles = [tr.scalar(x).code for x in c.args[3:]]
        tr.emit(f"model.angvel({a}, {b}, {quote(c.args[2].name.upper())}, {', '.join(angles)})")
        return
    raise tr.error("ANGVEL(A, B) or ANGVEL(A, B, BODYijk|SPACEijk|RODRIGUES, a1, a2, a3)", c,
                   "T009")


def _theory(method):
    def write(tr, c):
        args = _n(tr, c, 4)
        outer, fixed = tr.frame(args[0]).code, tr.frame(args[1]).code
        o, p = tr.point(args[2]).code, tr.point(args[3]).code
        tr.emit(f"{p}.{method}({o}, {outer}, {fixed})")
    return write


COMMANDS["V2PTS"] = _theory("v2pt_theory")
COMMANDS["V1PT"] = _theory("v1pt_theory")
COMMANDS["A2PTS"] = _theory("a2pt_theory")
COMMANDS["A1PT"] = _theory("a1pt_theory")


def _n(tr, c, *counts):
    if len(c.args) not in counts:
        raise tr.error(f"{c.name.upper()} takes {' or '.join(map(str, counts))} arguments, "
                       f"not {len(c.args)}", c, "T007")
    for a in c.args:
        if isinstance(a, (ir.Range, ir.Equation)):
            raise tr.error(f"unexpected '{'=' if isinstance(a, ir.Equation) else ':'}' in "
                           f"{c.name.upper()}", a, "T009")
    return list(c.args)


@command("GRAVITY")
def _gravity(tr, c):
    if not c.args:
        raise tr.error("GRAVITY(g>) or GRAVITY(g>, B, ...)", c, "T007")
    g = tr.expr(c.args[0])
    if g.type not in ("vector", "unknown"):
        raise tr.error(f"GRAVITY takes a vector, not a {g.type}", c.args[0], "T001")
    rest = [tr.entity(a, ("body", "particle")).py for a in c.args[1:]]
    tr.emit(f"model.gravity({', '.join([g.code] + rest)})")


def _pair(tr, e, kinds):
    """`A/B` in FORCE and TORQUE: the two things, or one."""
    if isinstance(e, ir.BinOp) and e.op == "/":
        return tr.entity(e.left, kinds), tr.entity(e.right, kinds)
    return None, tr.entity(e, kinds)


@command("FORCE")
def _force(tr, c):
    a, f = _n(tr, c, 2)
    first, second = _pair(tr, a, ("point", "particle"))
    v = tr.expr(f)
    if v.type not in ("vector", "unknown"):
        raise tr.error(f"FORCE takes a vector, not a {v.type}", f, "T001")
    if first is None:
        tr.emit(f"model.force({second.py}, {v.code})")
    else:
        tr.emit(f"model.force_pair({first.py}, {second.py}, {v.code})")


@command("TORQUE")
def _torque(tr, c):
    a, f = _n(tr, c, 2)
    first, second = _pair(tr, a, ("frame", "newtonian", "body"))
    v = tr.expr(f)
    if v.type not in ("vector", "unknown"):
        raise tr.error(f"TORQUE takes a vector, not a {v.type}", f, "T001")
    if first is None:
        tr.emit(f"model.torque({second.py}, {v.code})")
    else:
        tr.emit(f"model.torque_pair({first.py}, {second.py}, {v.code})")


@command("CONSTRAIN", "CONSTRAINT")
def _constrain(tr, c):
    if not c.args:
        raise tr.error("CONSTRAIN(DEPENDENT[u, ...]) or CONSTRAIN(AUXILIARY[u, ...])", c, "T007")
    for a in c.args:
        if not isinstance(a, ir.Index):
            raise tr.error("CONSTRAIN takes DEPENDENT[u, ...] or AUXILIARY[u, ...]", a, "T009")
        which = a.name.upper()
        eqs = tr.values.get(a.name.lower())
        if eqs is None:
            raise tr.error(f"{a.name} has no equations yet ({a.name}[1] = ...)", a, "T002")
        speeds = [_symbol_code(tr, i) for i in a.indices]
        method = "constrain_auxiliary" if which == "AUXILIARY" else "constrain"
        tr.emit(f"model.{method}({eqs.py}, [{', '.join(speeds)}])")
        for i in a.indices:
            if isinstance(i, ir.Name):
                tr.defined.add((i.name.lower(), i.primes))
                tr.defined.add((i.name.lower(), i.primes + 1))


@command("KANE")
def _kane(tr, c):
    unknowns = [tr.scalar(a).code for a in c.args]
    tr.kane_called = True
    tr.emit(f"model.kane({', '.join(unknowns)})")


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
            unknowns.append(_symbol_code(tr, n))
            if isinstance(n, ir.Name):
                tr.defined.add((n.name.lower(), n.primes))
    tr.emit(f"model.solve({eqs.code}, [{', '.join(unknowns)}])")


def _symbol_code(tr: Translator, e: ir.Expr) -> str:
    """A declared name as the symbol itself (never its RHS, whatever AUTORHS says)."""
    if isinstance(e, ir.Name) and e.name.lower() in tr.scalars:
        return tr.ensure_derivative(e.name, e.primes) if e.primes else \
            tr.scalars[e.name.lower()].py
    return tr.expr(e).code


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
            entry = Entry(tr.py_name("value", a.name), "value", "matrix")
            tr.values[key] = entry
        names.append(entry.py)
    tr.emit(f"{names[0]}, {names[1]} = al.eig(model.explicit({m.code}), vectors=True)")


@command("ANIMATE")
def _animate(tr, c):
    tr.emit("# (ANIMATE wrote Animake files; not translated)")


# -- input, output, units, code --------------------------------------------------------------
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
            tr.emit(f"model.input({_symbol_code(tr, target)}, {value}{_unit_arg(item.unit)})")
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
        if x.type not in ("scalar", "matrix", "unknown"):
            raise tr.error(f"OUTPUT writes scalars, not a {x.type}", item.expr, "T001")
        label = _label(item.expr)
        items.append(f"({x.code}, {quote(label)}{_unit_arg(item.unit)})")
    _call_lines(tr, "model.output(", items)


def _call_lines(tr: Translator, head: str, items: list[str]) -> None:
    """head + items + ')' on one line, or one item per line when that is long."""
    line = head + ", ".join(items) + ")"
    if len(line) <= 92:
        tr.emit(line)
        return
    tr.emit(head)
    for it in items:
        tr.emit(f"    {it},")
    tr.emit(")")


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
        args.append(x.code if x.type != "list" else x.code[1:-1])
    opts = ""
    if args:
        opts += f", [{', '.join(args)}]"
    if st.sweep is not None:
        sw = st.sweep
        target = tr.name(sw.target.name, sw.target.primes, sw.target).code
        opts += (f", sweep=({target}, {tr.scalar(sw.start).code}, {tr.scalar(sw.stop).code}, "
                 f"{tr.scalar(sw.step).code}{_unit_arg(sw.unit)})")
    if st.options:
        opts += f", options=({''.join(quote(o) + ', ' for o in st.options)})"
    zero = tr.values.get("zero")
    if tr.kane_called and zero is not None and zero.type == "matrix":
        opts += f", zero={zero.py}"
    tr.has_code = True
    tr.emit(f"model.code({quote(st.what)}, {quote(st.filename)}{opts})")


@STATEMENTS.register(ir.Encode)
def encode(tr: Translator, st: ir.Encode) -> None:
    items = []
    for e in st.exprs:
        x = tr.expr(e)
        items.append(f"({quote(_text_of(e))}, {x.code})")
    _call_lines(tr, "model.encode(", items)


@STATEMENTS.register(ir.Save)
def save(tr: Translator, st: ir.Save) -> None:
    tr.emit(f"# (SAVE wrote Autolev's session transcript {comment(st.filename)})")


@STATEMENTS.register(ir.Run)
def run(tr: Translator, st: ir.Run) -> None:
    tr.emit(f"# (the statements of {comment(st.filename)} follow)")


@STATEMENTS.register(ir.MacroCall)
def macro(tr: Translator, st: ir.MacroCall) -> None:
    tr.emit(f"# (macro {comment(st.name)}: its statements follow)")


@STATEMENTS.register(ir.Exit)
def exit_statement(tr: Translator, st: ir.Exit) -> None:
    tr.emit("# (EXIT ends the Autolev session)")
    tr.exited = True


@STATEMENTS.register(ir.Setting)
def setting(tr: Translator, st: ir.Setting) -> None:
    if st.name == "DEGREES":
        tr.degrees = st.value != "OFF"
    elif st.name == "AUTORHS":
        tr.autorhs = st.value in ("ON", "ALL")
    elif st.name == "COMPLEX":
        tr.complex = st.value == "ON"
    value = "None" if st.value is None else quote(st.value)
    tr.emit(f"model.setting({quote(st.name)}, {value})")

