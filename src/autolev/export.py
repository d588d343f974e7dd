"""`autolev convert --to sympy`: a model as a standalone SymPy script, runnable without
autolev (it imports only sympy, numpy and scipy).

Here, the equations level (export_mechanics.py writes the mechanics level, and
chooses): the CODE command's state, its rates (the kinematical and other explicit
differential equations) and the mass matrix and forcing from which the other rates are
solved, with every intermediate (Autolev's Z's,
the model's definitions) a named assignment in the order it is computed, as sympy
expressions in dynamicsymbols.  It reads what `autolev run` integrates (the command's
NumericSystem and inputs), so the two agree by construction of the same equations, not
by a second formulation.  Names stay the model's (`K` is `sm.Symbol('K')`, no
assumptions), made into Python identifiers; text from the model reaches the script only
as identifiers it checked or as quoted strings.

Each level's script is a Script: a method per section (the docstring, the symbols, ...,
the values, the runner), the sections the levels share written once.
"""
from __future__ import annotations

import keyword
import math
import re
import textwrap

import sympy as sm
from sympy.printing.precedence import precedence
from sympy.printing.str import StrPrinter

from .runtime import symbols as S
from .runtime.equations_of import Equations, state_of
from .engine.errors import AutolevModelError

# names the script itself defines: a model's quantity of the same name is renamed
SCRIPT_NAMES = frozenset({
    "sys", "np", "sm", "me", "solve_ivp", "t", "states", "rates", "unknowns",
    "unknown_states", "mass_matrix", "forcing", "full_mass", "full_forcing", "system",
    "constants", "initial_conditions", "specified", "integration", "integration_method",
    "outputs",
    "numeric_functions", "integrate", "main", "row", "column", "k", "j", "intermediates",
    "expanded", "after_solving", "kane", "loads", "bodies", "kd_eqs",
    "velocity_constraints", "dependent", "auxiliary", "at_start", "coefficients", "rest",
    "lacking"})


class ScriptPrinter(StrPrinter):
    """Expressions as Python that builds them with sympy (`sm.sin(Q1)`,
    `sm.Rational(1, 2)`), each symbol by the identifier the script gave it."""

    def __init__(self, names: dict):
        super().__init__({"full_prec": True})
        self.names = names

    def _print_Symbol(self, expr):
        if expr not in self.names:
            raise AutolevModelError(f"the SymPy export has no value for {expr}")
        return self.names[expr]

    def _print_Function(self, expr):
        name = type(expr).__name__
        if getattr(sm, name, None) is not type(expr):
            raise AutolevModelError(f"the SymPy export cannot write the function {name}")
        return f"sm.{name}({', '.join(self._print(a) for a in expr.args)})"

    def _print_Rational(self, expr):
        return f"sm.Rational({expr.p}, {expr.q})"

    def _print_Float(self, expr):
        return repr(float(expr))

    def _print_Pow(self, expr, rational=False):
        prec = precedence(expr)
        return (f"{self.parenthesize(expr.base, prec, strict=True)}**"
                f"{self.parenthesize(expr.exp, prec, strict=True)}")

    def _print_Pi(self, expr):
        return "sm.pi"

    def _print_Exp1(self, expr):
        return "sm.E"

    def _print_ImaginaryUnit(self, expr):
        return "sm.I"

    def _print_BooleanTrue(self, expr):
        return "sm.true"

    def _print_BooleanFalse(self, expr):
        return "sm.false"


def identifier(name: str, taken: set) -> str:
    """A Python identifier for a model's name, distinct from `taken` (then added)."""
    base = re.sub(r"\W", "_", name.replace("'", "p"), flags=re.ASCII) or "q"
    if base[0].isdigit():
        base = "_" + base
    out, k = base, 1
    while out in taken or keyword.iskeyword(out) or out in SCRIPT_NAMES:
        k += 1
        out = f"{base}_{k}"
    taken.add(out)
    return out


class Script:
    """A standalone SymPy script of a command's equations, printed a section at a time:
    `SECTIONS` names, in the script's order, the methods that give each section's lines;
    a subclass per level names the model's symbols and writes its own sections."""

    SECTIONS: tuple[str, ...] = ()
    # what the script is, in its docstring's first line
    TITLE: str = ""

    eqs: Equations              # the command's equations, values and outputs
    source: str                 # the model's file, named in the docstring
    taken: set                  # the identifiers given so far
    names: dict                 # each symbol (and frame, point, body) -> its identifier
    unknown_names: dict         # each rate solved from the mass matrix -> its identifier
    before: list                # (name, value) of the definitions the equations need
    after: list                 # (name, value) of those that need the solved rates
    printer: ScriptPrinter      # the expressions, by `names`

    def text(self) -> str:
        lines: list = []
        for section in self.SECTIONS:
            lines += getattr(self, section)()
        return "\n".join(lines) + "\n"

    def printed(self, expr) -> str:
        """`expr` as the Python that builds it."""
        return self.printer.doprint(expr)

    def docstring(self) -> list:
        eqs = self.eqs
        return [f'"""{quoted_text(eqs.model_name)}: {self.TITLE}, written by autolev from\n'
                f"{quoted_text(self.source)} ({quoted_text(eqs.command)}).",
                "",
                *self.description(),
                "`python THIS.py [OUT.csv]` integrates from TINITIAL to TFINAL with scipy",
                f"({eqs.method}, RELERR and ABSERR) and writes the OUTPUT columns as CSV.",
                '"""']

    def description(self) -> list:
        """The docstring's lines on what the level holds and what importing defines."""
        raise NotImplementedError

    def imports(self) -> list:
        return ["import sys", "", "import numpy as np", "import sympy as sm",
                "import sympy.physics.mechanics as me", "from scipy.integrate import solve_ivp",
                "", "t = me.dynamicsymbols._t", ""]

    def definition_lists(self, after_note: str) -> list:
        """`intermediates` and `after_solving`: (name, what it is) in the order they are
        computed; `after_note` says what the second list is."""
        def entries(definitions) -> list:
            return [f"    ({self.names[z]}, {expression_text(self.printed, e)}),"
                    for z, e in definitions]
        return (["intermediates = ["] + entries(self.before)
                + ["]", after_note, "after_solving = ["] + entries(self.after) + ["]"])

    def values(self) -> list:
        """`constants`, `initial_conditions`, `specified`, `integration`,
        `integration_method` and `outputs`."""
        eqs, names = self.eqs, self.names
        lacking = [names[c] for c, v in eqs.constants.items() if v is None]
        out = ["# values (SI units, radians) from the model's INPUT statements"
               + ("; None: no value given (give one here)" if lacking else ""),
               "constants = {" + ", ".join(f"{names[c]}: "
                                           + ("None" if v is None else number_text(v))
                                           for c, v in eqs.constants.items()) + "}",
               "initial_conditions = {" + ", ".join(f"{names[x]}: {number_text(v)}"
                                                    for x, v in eqs.initial.items()) + "}",
               "# each a number or a function of time; 0 unless given",
               "specified = {" + ", ".join(f"{names[s]}: 0.0" for s in eqs.specified) + "}",
               "integration = {" + ", ".join(f"{k!r}: {number_text(v)}"
                                             for k, v in eqs.integration.items()) + "}",
               "# scipy's method for the program's integrator: " + eqs.method_reason,
               f"integration_method = {eqs.method!r}",
               "# OUTPUT columns: (label, unit, expression in the unit)",
               "outputs = ["]
        for label, unit, expr, degrees in eqs.outputs:
            shown = self.printed(expr) + (" * 180 / sm.pi" if degrees else "")
            out.append(f"    ({label!r}, {unit!r}, {shown}),")
        return out + ["]"]

    def runner(self) -> list:
        return ["", "", RUNNER]


class EquationsScript(Script):
    """The equations level (see the module's docstring): the state, the explicit rates,
    the mass matrix and forcing, every intermediate a named assignment."""

    SECTIONS = ("docstring", "imports", "symbols", "intermediates", "equations", "values",
                "runner")
    TITLE = "its equations of motion as SymPy expressions"

    why: str | None             # why not the mechanics level, said at the top (None: not said)

    def __init__(self, eqs: Equations, source: str, why: str | None = None):
        self.eqs, self.source, self.why = eqs, source, why
        self.taken, self.names, self.unknown_names = set(), {S.TIME: "t"}, {}
        for s in (eqs.states + eqs.specified + list(eqs.constants)
                  + [s for s, _ in eqs.definitions]):
            self.names[s] = self.identifier_of(s)
        for u in eqs.unknowns:
            self.unknown_names[u] = self.names[u] = self.identifier_of(u)
        self.printer = ScriptPrinter(self.names)
        self.before, self.after = split_at_the_unknowns(eqs)

    def identifier_of(self, s) -> str:
        """A derivative's identifier: its quantity's name with a p per order (Xpp)."""
        base, order = S.base_and_order(s)
        return identifier(base.name + "p" * order, self.taken)

    def description(self) -> list:
        return ["Level: equations.  The state, the rates given explicitly, and the mass matrix and",
                "forcing from which the other rates (`unknowns`) are solved, as Autolev's Kane's",
                "method formed them, with every intermediate (Autolev's Z's) a named assignment.",
                *(textwrap.wrap(f"Not the mechanics level: {quoted_text(self.why)}.", 88)
                  if self.why else []),
                "Importing defines `system` (a sympy.physics.mechanics.SymbolicSystem: full_mass *",
                "d(states)/dt = full_forcing, in the intermediates), `constants`,",
                "`initial_conditions` and `specified`;"]

    def symbols(self) -> list:
        eqs, names = self.eqs, self.names
        out = ["# the state: functions of time"]
        out += [f"{names[x]} = me.dynamicsymbols({names[x]!r})" for x in eqs.states]
        if eqs.specified:
            out += ["", "# specified quantities: functions of time (values in `specified`)"]
            out += [f"{names[s]} = me.dynamicsymbols({names[s]!r})" for s in eqs.specified]
        if eqs.constants:
            out += ["", "# constants"]
            out += [f"{names[c]} = sm.Symbol({names[c]!r})" for c in eqs.constants]
        if eqs.unknowns:
            out += ["", "# the rates solved from the mass matrix"]
            out += [f"{self.unknown_names[u]} = {names[state_of(u)]}.diff(t)"
                    for u in eqs.unknowns]
        return out

    def intermediates(self) -> list:
        out = []
        if self.eqs.definitions:
            out += ["", "# intermediates (Autolev's Z's) and the model's definitions, as "
                    "functions of",
                    "# time, and what each is, in the order they are computed; "
                    "`expanded(expr)`",
                    "# replaces them in an expression"]
            out += [f"{self.names[z]} = me.dynamicsymbols({self.names[z]!r})"
                    for z, _ in self.eqs.definitions]
        return out + self.definition_lists("# those that need the solved rates (outputs only)")

    def equations(self) -> list:
        """`states`, `rates`, the mass matrix and forcing, and them as one `system`."""
        eqs, names, p = self.eqs, self.names, self.printed
        return ["", "states = [" + ", ".join(names[x] for x in eqs.states) + "]",
                "# d(state)/dt where it is given; None where it is solved (`unknowns`)",
                "rates = [" + ", ".join("None" if r is None else p(r) for r in eqs.rates) + "]",
                "unknowns = [" + ", ".join(self.unknown_names[u] for u in eqs.unknowns) + "]",
                "unknown_states = [" + ", ".join(
                    str(eqs.states.index(state_of(u))) for u in eqs.unknowns) + "]",
                f"mass_matrix = sm.Matrix({len(eqs.mass)}, {len(eqs.mass)}, ["
                + ", ".join(p(e) for r in eqs.mass for e in r) + "])",
                f"forcing = sm.Matrix({len(eqs.forcing)}, 1, ["
                + ", ".join(p(e) for e in eqs.forcing) + "])",
                "",
                "# as one system: full_mass * d(states)/dt = full_forcing",
                "full_mass = sm.eye(len(states))",
                "full_forcing = sm.Matrix([0 if r is None else r for r in rates])",
                "for row, k in enumerate(unknown_states):",
                "    full_mass[k, k] = 0",
                "    for column, j in enumerate(unknown_states):",
                "        full_mass[k, j] = mass_matrix[row, column]",
                "    full_forcing[k] = forcing[row]",
                "system = me.SymbolicSystem(states, full_forcing, mass_matrix=full_mass)",
                ""]


def split_at_the_unknowns(eqs: Equations) -> tuple[list, list]:
    """The definitions the equations need (in order), and those that need the solved
    rates, which only the outputs use."""
    late = set(eqs.unknowns)
    before, after = [], []
    for name, value in eqs.definitions:
        if sm.sympify(value).free_symbols & late:
            late.add(name)
            after.append((name, value))
        else:
            before.append((name, value))
    return before, after


def expression_text(p, e) -> str:
    """An assignment's right side: always a sympy object (a plain 0 would be an int)."""
    text = p(e)
    return f"sm.sympify({text})" if sm.sympify(e).is_Number else text


def number_text(value) -> str:
    if isinstance(value, int):
        return repr(value)
    if math.isfinite(value):
        return repr(float(value))
    return f"float({str(value)!r})"


def quoted_text(text: str) -> str:
    """Text from the model inside the script's docstring: no quotes or backslashes."""
    return "".join(c if c.isprintable() and c not in '"\\' else "?" for c in text)


RUNNER = '''def expanded(expr):
    """`expr` with every intermediate replaced by what it is (large for large models)."""
    for name, value in reversed(intermediates + after_solving):
        expr = expr.xreplace({name: value})
    return expr


def numeric_functions():
    """full_mass, full_forcing and the outputs as numpy functions of (t, state, constants,
    specified values[, unknowns]), each computing the intermediates in order."""
    # every argument a Dummy: a model's constant named `sin` must not shadow numpy's
    plain = {f: sm.Dummy() for f in states + list(specified) + unknowns + list(constants)
             + [name for name, _ in intermediates + after_solving]}
    steps = [(plain[name], value.xreplace(plain)) for name, value in intermediates]
    late = [(plain[name], value.xreplace(plain)) for name, value in after_solving]
    arguments = [t, [plain[x] for x in states], [plain[c] for c in constants],
                 [plain[s] for s in specified]]

    def function(expr, more=(), after=()):
        def shared(e):
            # then sympy's common subexpressions: a KanesMethod's are not named as Z's
            common, reduced = sm.cse(e, list=False)
            return steps + list(after) + common, reduced
        return sm.lambdify(arguments + list(more), expr.xreplace(plain), "numpy", cse=shared)
    columns = sm.Matrix([e for _, _, e in outputs])
    return (function(full_mass), function(full_forcing),
            function(columns, [[plain[u] for u in unknowns]], late))


def integrate(tfinal=None):
    """The OUTPUT rows from TINITIAL to TFINAL (or `tfinal`) as Autolev's programs print
    them, as an array (a column per output)."""
    lacking = [str(c) for c, v in constants.items() if v is None]
    if lacking:
        raise ValueError(f"no value for {', '.join(lacking)}: give each in `constants`")
    mass, force, columns = numeric_functions()
    p = [constants[c] for c in constants]
    x0 = np.array([initial_conditions[x] for x in states], dtype=float)
    t0, t1 = integration["TINITIAL"], tfinal if tfinal is not None else integration["TFINAL"]

    def values_of_specified(time):
        return [v(time) if callable(v) else v for v in specified.values()]

    def rates_of(time, x):
        s = values_of_specified(time)
        return np.linalg.solve(np.asarray(mass(time, x, p, s), dtype=float),
                               np.asarray(force(time, x, p, s), dtype=float).ravel())

    def row_at(time, x):
        rate = rates_of(time, x)
        return np.asarray(columns(time, x, p, values_of_specified(time),
                                  [rate[k] for k in unknown_states]), dtype=float).ravel()

    # Autolev's loop: a step of INTEGSTP while T + INTEGSTP/100 falls short of TFINAL,
    # a row every PRINTINT steps and after the last (which may pass TFINAL)
    h, every = integration["INTEGSTP"], integration["PRINTINT"]

    def done(time):
        ahead = time + 0.01 * h
        return ahead >= t1 if t1 >= t0 else ahead <= t1
    times, time, steps = [t0], t0, 0
    while not done(time):
        time, steps = time + h, steps + 1
        if steps % every == 0 or done(time):
            times.append(time)
    if len(times) == 1:
        return np.array([row_at(t0, x0)])
    solution = solve_ivp(rates_of, (t0, times[-1]), x0, method=integration_method, t_eval=times,
                         rtol=integration["RELERR"], atol=integration["ABSERR"])
    if not solution.success:
        raise RuntimeError(solution.message)
    return np.array([row_at(time, x) for time, x in zip(solution.t, solution.y.T)])


def main(argv):
    try:
        rows = integrate()
    except ValueError as exc:
        sys.stderr.write(f"{__file__}: {exc}\\n")
        return 1
    text = ",".join(label for label, _, _ in outputs) + "\\n" + "".join(
        ",".join(repr(float(v)) for v in row) + "\\n" for row in rows)
    if argv:
        with open(argv[0], "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))'''
