"""A CODE command's program in Matlab (GNU Octave runs it too), section for section in
the layout of Autolev 4.1's Matlab programs: one function file whose subfunctions
ReadUserInput (the input values as a table, the unit conversions, "Evaluate
constants"), DoCalculations ("Quantities to be specified" and what depends on them),
PrintUserOutput (the OUTPUT rows and the ENCODE arrays) share their quantities as
globals."""
from __future__ import annotations

import re

import sympy as sm

from .. import __version__
from ..runtime import symbols as S
from ..runtime import units
from ..engine.errors import AutolevModelError
from ..engine.functions import called_names
from ..runtime.numerics import codegen
from ..engine.files import header as output_header
from ..engine.numbers import format_value
from ..runtime.printer import ATOM, POW, CPrinter
from .plan import (Plan, c_name, dynamics_names, element_indices, print_dynamics, printed,
                   program_name, rename_clashes, shown_values, with_sources)

# Matlab's keywords and constants and the functions a program may call (its layout's,
# log10, and those the function records spell), as spelt (Matlab tells case apart)
LANGUAGE_NAMES = frozenset("""
break case catch classdef continue else elseif end for function global if otherwise
parfor persistent return spmd switch try while log10 zeros fopen fclose fprintf error
disp warning length all any nan NaN inf Inf eps pi i j ans
""".split()) | called_names("matlab")
# the program's own names, as spelt: its functions and the globals they share
OWN_NAMES = frozenset("""
z Encode Pi DEGtoRAD RADtoDEG Output FileIdentifier fileIdentifier
numberOfOutputQuantities ReadUserInput DoCalculations PrintUserOutput WriteOutput
CloseOutputFilesAndTerminate OpenOutputFilesAndWriteHeadings
""".split())
# names a program that solves equations or sweeps an input uses besides
_SOLVING_NAMES = frozenset("COEF RHS SolutionToAxEqualsB ABSERR RELERR iter ipoint".split())

_RULE = "%" + "-" * 31 + "+" + "-" * 26 + "+" + "-" * 19 + "+" + "-" * 17


class MatlabPrinter(CPrinter):
    """The C printer's walk, with Matlab's power operator, function names and
    constants."""

    LANGUAGE, LANGUAGE_NAME = "matlab", "Matlab"

    def _constant(self, e):
        if e is sm.pi:
            return "pi", ATOM
        if e is sm.E:
            return "exp(1)", ATOM
        return self._number(sm.Float(e))

    def _number(self, e):
        if e is sm.nan or e is sm.zoo:
            return "NaN", ATOM
        if e in (sm.oo, -sm.oo):
            return ("Inf" if e is sm.oo else "(-Inf)"), ATOM
        return super()._number(e)

    def _pow(self, e):
        if e.exp == sm.Rational(-1, 2):     # x^-0.5: Matlab's power, not 1.0/sqrt(x)
            return self._power(e.base, e.exp)
        return super()._pow(e)

    def _power(self, base, exp):
        return f"{self._wrap(base, ATOM)}^{self._wrap(exp, ATOM)}", POW

    def _piecewise(self, e):
        raise AutolevModelError("a piecewise quantity has no expression form in Matlab: "
                                "write the program in C")

    def _relational(self, e):
        op = {"!=": "~="}.get(e.rel_op, e.rel_op)
        return f"({self._p(e.lhs)[0]} {op} {self._p(e.rhs)[0]})", ATOM


def m_string(text: str, fmt: bool = False) -> str:
    """`text` inside a Matlab single-quoted string; `fmt`: of an fprintf format that
    prints `text` as it is."""
    if fmt:
        text = text.replace("\\", "\\\\").replace("%", "%%").replace("\n", "\\n")
    # outside text (labels, units, file names): printable ASCII only, quotes doubled
    return "".join(ch if " " <= ch <= "~" else "?" for ch in text.replace("'", "''"))


def function_name(filename: str) -> str:
    """The Matlab function a program file defines: its base name, which must be an
    identifier (Matlab finds the function by the file's name)."""
    name = re.split(r"[\\/]", program_name(filename))[-1].rpartition(".")[0]
    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,62}", name):
        raise AutolevModelError(
            f"{filename}: {name!r} cannot name a Matlab function (a letter, then "
            "letters, digits or _): rename the CODE file")
    return name


_WRITE_OUTPUT = [
    "numberOfOutputQuantities = length( Output );",
    "if( numberOfOutputQuantities > 0 )",
    "  for( i = 1 : numberOfOutputQuantities )",
    "    fprintf( fileIdentifier, ' %- 14.6E', Output(i) );",
    "  end",
    "  fprintf( fileIdentifier, '\\n' );",
    "end"]


def _m_lines(pairs: list, sources: dict) -> list[str]:
    return with_sources(pairs, sources,
                        lambda source: "% " + "".join(ch if " " <= ch <= "~" else "?"
                                                      for ch in source),
                        lambda target, text: [f"{target} = {text};"])


def _showing(plan, texts: list, blank_line: bool = False) -> list[str]:
    """The lines that show the quantities (`texts`: the printed shown_values): one
    line of Output(n)=...; per OUTPUT file, the WriteOutput calls (file 1 also to the
    screen), then the ENCODE elements (from 1) and the Encode block."""
    texts = list(texts)
    lines, n = [], 0
    for cols in plan.files:
        row = []
        for _, _, unit in cols:
            n += 1
            text = texts.pop(0)
            row.append(f"Output({n})="
                       + (f"({text})*RADtoDEG" if units.is_degrees(unit) else text) + ";")
        lines.append("  ".join(row))
    if plan.files:
        lines.append("FileIdentifier = fopen('all');")
        first = 1
        for k, cols in enumerate(plan.files, 1):
            span = f"Output({first}:{first + len(cols) - 1})"
            if k == 1:
                lines.append(f"WriteOutput( 1,                 {span} );")
            lines.append(f"WriteOutput( FileIdentifier({k}), {span} );")
            first += len(cols)
    else:
        lines.append("Output = [];")
    if blank_line:
        lines.append("")
    for e in plan.encoded:
        for index in element_indices(e.shape):
            target = e.name + ("(" + ",".join(str(i + 1) for i in index) + ")"
                               if index else "")
            text = texts.pop(0)
            if text != target:      # (a quantity computed by that name already)
                lines.append(f"{target} = {text};")
    if plan.encoded:
        lines += [""] + [f"Encode({k}) = 0.0;" for k in range(1, len(plan.encoded) + 1)]
    return lines


def _depending_on(statements: list, specified: set) -> list[bool]:
    """Which statements depend on a specified quantity, through the symbols and
    repeated subexpressions they read (DoCalculations computes those, after the
    quantities are specified)."""
    defined_at = {st.defines: k for k, st in enumerate(statements) if st.defines is not None}
    bound_at = {st.expr: k for k, st in enumerate(statements) if st.holds_call}
    depends: list = []
    for k, st in enumerate(statements):
        nodes = codegen.post_order([st.expr], set())
        symbols = {a for node in nodes for a in node.args if a.is_Symbol}
        if st.expr.is_Symbol:
            symbols.add(st.expr)
        reads = {defined_at[s] for s in symbols if s in defined_at} | \
            {bound_at[node] for node in nodes if node in bound_at}
        depends.append(bool(symbols & specified)
                       or any(depends[j] for j in reads if j < k))
    return depends


class MProgram:
    """The text of one plan's Matlab program."""

    def __init__(self, plan: Plan):
        self.plan = plan
        self.name = program_name(plan.filename)
        self.function = function_name(plan.filename)
        rename_clashes(plan, LANGUAGE_NAMES | OWN_NAMES | {self.function}
                       | (_SOLVING_NAMES if plan.solves_or_sweeps() else frozenset()),
                       "Matlab")
        self.stem = self.name.rpartition(".")[0]
        self.unknowns, self.computed = plan.unknowns, plan.computed
        self.where = {s: plan.name_of(s) for s in plan.inputs + plan.specified + plan.named
                      + self.computed}

    def text(self) -> str:
        p = self.plan
        # ReadUserInput computes what depends on none of the specified quantities,
        # unknowns and swept input; DoCalculations the rest: the slots follow that order
        later = _depending_on(p.statements, set(p.specified) | set(self.unknowns)
                              | set(self.computed))
        order = [k for k in range(len(later)) if not later[k]] + \
            [k for k in range(len(later)) if later[k]]
        part = printed(p.statements, shown_values(p), self.where, MatlabPrinter,
                       lambda k: f"z({k})", order=order, name_of=p.name_of)
        size = part.top
        solution = []
        if p.solving is not None:
            solution, size = self._solution(size)
        constants = _m_lines([pair for k, pair in enumerate(part.statements)
                              if not later[k]], p.sources)
        calculations = _m_lines([pair for k, pair in enumerate(part.statements)
                                 if later[k]], p.sources)
        globals_ = self._globals()
        lines = [f"function {self.function}",
                 f"% File  {self.name}  created by autolev {__version__} in the layout "
                 "of Autolev 4.1's programs", ""] + globals_ + [""]
        if p.files:
            lines.append("OpenOutputFilesAndWriteHeadings;")
        lines.append("ReadUserInput;")
        if p.sweep is None:
            lines += ["DoCalculations;", "PrintUserOutput;"]
        else:
            lines += self._sweeping()
        lines.append("CloseOutputFilesAndTerminate;")
        lines += self._function("ReadUserInput", globals_, self._table() + [
            "", "% Unit conversions", "Pi       = 3.141592653589793;",
            "DEGtoRAD = Pi/180.0;", "RADtoDEG = 180.0/Pi;"]
            + [f"{p.name_of(s)} = {p.name_of(s)}*DEGtoRAD;" for s in p.degree_inputs]
            + ["", "% Reserve space and initialize matrices", f"z = zeros({size},1);",
               "", "% Evaluate constants"] + constants)
        lines += self._function("DoCalculations", globals_, [
            "% Quantities to be specified"] + [f"{p.name_of(s)} = 0;" for s in p.specified]
            + [""] + solution + calculations)
        lines += self._function("Output = PrintUserOutput", globals_,
                                _showing(p, part.values, blank_line=True))
        lines += self._function("WriteOutput( fileIdentifier, Output )", [], _WRITE_OUTPUT)
        if p.files:
            lines += self._function("OpenOutputFilesAndWriteHeadings", [],
                                    self._headings())
        lines += self._function("CloseOutputFilesAndTerminate", globals_, self._closing())
        return "\n".join(lines) + "\n"

    def _sweeping(self) -> list[str]:
        """The main function's loop over the swept input's values."""
        sweep = self.plan.sweep
        lines = [f"for ipoint = 0:{sweep.count - 1}"]
        if sweep.target is not None:
            name = self.plan.name_of(sweep.target)
            lines.append(f"  {name} = {sweep.start!r} + {sweep.step!r}*ipoint;")
            if sweep.degrees:
                lines.append(f"  {name} = {name}*DEGtoRAD;")
        return lines + ["  DoCalculations;", "  PrintUserOutput;", "end"]

    def _solution(self, offset: int) -> tuple[list, int]:
        """DoCalculations' solution of the equations for the unknowns (its z slots
        above `offset`, the constants' being kept), and the highest slot."""
        solving, n = self.plan.solving, len(self.unknowns)
        part = printed(solving.statements, solving.matrix + solving.right, self.where,
                       MatlabPrinter, lambda k: f"z({k})", offset,
                       name_of=self.plan.name_of)
        matrix, right = part.values[:n * n], part.values[n * n:]
        body = _m_lines(part.statements, self.plan.sources)
        body += [f"COEF = zeros({n},{n});"]
        body += [f"COEF({i + 1},{j + 1}) = {matrix[i * n + j]};"
                 for i in range(n) for j in range(n)]
        body += [f"RHS = zeros(1,{n});"] + [f"RHS({i + 1}) = -({right[i]});"
                                            for i in range(n)]
        body.append("SolutionToAxEqualsB = COEF\\RHS';")
        names = [self.plan.name_of(u) for u in self.unknowns]
        if solving.method == "linear":
            lines = [f"% Solve the linear equations for {', '.join(names)}"] + body
            lines += [f"{name} = SolutionToAxEqualsB({i});" for i, name in enumerate(names, 1)]
            return lines + [""], part.top
        # Newton's method from the guesses, as autolev run (docs/language.md)
        lines = [f"% Solve the nonlinear equations for {', '.join(names)} (Newton's "
                 "method from the guesses)", f"for iter = 1:{solving.ITERATIONS}"]
        lines += ["  " + line for line in body]
        lines += [f"  {name} = {name} + SolutionToAxEqualsB({i});"
                  for i, name in enumerate(names, 1)]
        lines += [f"  if( all(abs(SolutionToAxEqualsB) <= max(ABSERR, RELERR*abs(["
                  f"{'; '.join(names)}]))) ) break; end",
                  f"  if( iter == {solving.ITERATIONS} ) error('Newton''s method did not "
                  f"converge in {solving.ITERATIONS} iterations'); end", "end", ""]
        return lines, part.top

    # -- pieces ---------------------------------------------------------------------
    def _globals(self) -> list[str]:
        p = self.plan
        groups = [[p.name_of(s) for s in p.inputs], [p.name_of(s) for s in p.specified],
                  sorted((p.name_of(s) for s in p.named + self.computed),
                         key=lambda n: (n.lower(), n))]
        named = {n for g in groups for n in g}
        misc = ["DEGtoRAD", "RADtoDEG", "z"] + [e.name for e in p.encoded
                                                 if e.shape or e.name not in named] \
            + ["Encode"]
        if p.solving is not None and p.solving.method == "newton":
            misc = ["ABSERR", "RELERR"] + misc
        groups.append(misc)
        return [f"global   {' '.join(g)};" for g in groups if g]

    @staticmethod
    def _function(head: str, globals_: list, body: list) -> list[str]:
        return ["", "", "", "%" + "=" * 75, f"function {head}"] + globals_ + [""] + body

    def _table(self) -> list[str]:
        rows = [_RULE,
                f"% {'Quantity':<30}| {'Value':<25}| {'Units':<18}| Description",
                _RULE.replace("+", "|")]
        unknowns = set(self.unknowns)
        for s in self.plan.inputs:
            value = self.plan.values[s]
            unit = value.unit or "UNITS"
            rows.append(f"{self.plan.name_of(s):<32}= {format_value(value.given) + ';':<25}"
                        f"% {unit:<20}{'Initial Guess' if s in unknowns else 'Constant'}")
        if self.plan.solving is not None and self.plan.solving.method == "newton":
            rows.append("")
            for key, what in (("ABSERR", "Absolute Error"), ("RELERR", "Relative Error")):
                value = format_value(self.plan.values[key].given)
                rows.append(f"{key:<32}= {value + ';':<25}% {'':<20}{what}")
        return rows + [_RULE]

    def _headings(self) -> list[str]:
        lines = []
        for k, cols in enumerate(self.plan.files, 1):
            file = f"{self.stem}.{k}"
            head = output_header(file, [c[1] for c in cols], [c[2] for c in cols])
            lines.append(f"FileIdentifier = fopen('{m_string(file)}', 'wt');   "
                         "if( FileIdentifier == -1 ) error('Error: unable to open file "
                         f"{m_string(file)}'); end")
            if k == 1:
                names_and_units = head.split("\n", 2)[2]
                lines.append(f"fprintf( 1, '{m_string(names_and_units, fmt=True)}' );")
            lines.append(f"fprintf( FileIdentifier, '{m_string(head, fmt=True)}' );")
        return lines

    def _closing(self) -> list[str]:
        n = len(self.plan.files)
        if not n:
            return []
        what = (f"file {self.stem}.1" if n == 1 else f"files {self.stem}.i  (i=1,...,{n})")
        return ["fclose( 'all' );",
                f"fprintf( 1, '\\n Output is in the {m_string(what, fmt=True)}\\n' );"]


def write_m(plan: Plan) -> dict:
    """{file name: text}: the program (a Matlab program holds its input values)."""
    return {plan.filename: MProgram(plan).text()}



# a DYNAMICS program's own names besides: its S-function's and ode45's, its loop's
_DYNAMICS_NAMES = frozenset("""
VAR VARp sys u t x flag T Sfunction mdlDerivatives mdlOutputs mdlTerminate
mdlInitializeSizes SolveOrdinaryDifferentialEquations PrintCounter OdeMatlabOptions
TimeOdeArray VarOdeArray TimeAtEndOfArray TINITIAL TFINAL INTEGSTP PRINTINT ABSERR RELERR
ode45 odeset COEF RHS SolutionToAxEqualsB
""".split())

_INTEGRATION_ROWS = (("TINITIAL", "Initial Time"), ("TFINAL", "Final Time"),
                     ("INTEGSTP", "Integration Step"), ("PRINTINT", "Print-Integer"),
                     ("ABSERR", "Absolute Error"), ("RELERR", "Relative Error"))


class MDynamicsProgram(MProgram):
    """The text of one DynamicsPlan's Matlab program: Autolev's driver loop calling
    ode45 over every INTEGSTP (as `autolev run` integrates a .m CODE file)."""

    def __init__(self, plan):
        self.plan = plan
        self.name = program_name(plan.filename)
        self.function = function_name(plan.filename)
        rename_clashes(plan, LANGUAGE_NAMES | OWN_NAMES | _DYNAMICS_NAMES | {self.function},
                       "Matlab")
        self.stem = self.name.rpartition(".")[0]
        self.n, self.m = len(plan.states), len(plan.unknowns)
        self.names = dynamics_names(plan, plan.name_of)
        self.z_size = 0

    def text(self) -> str:
        p = self.plan
        parts = print_dynamics(p, self.names, MatlabPrinter, lambda k: f"z({k})", p.name_of)
        constants, outputs = parts.constants, parts.outputs
        self.z_size = parts.z_size
        g = self._globals()
        lines = [f"function {self.function}", "SolveOrdinaryDifferentialEquations",
                 f"% File  {self.name}  created by autolev {__version__} in the layout "
                 "of Autolev 4.1's programs"]
        lines += self._function("VAR = ReadUserInput", g, self._table() + [
            "", "% Unit conversions", "Pi       = 3.141592653589793;",
            "DEGtoRAD = Pi/180.0;", "RADtoDEG = 180.0/Pi;"]
            + [f"{p.name_of(s)} = {p.name_of(s)}*DEGtoRAD;" for s in p.degree_inputs]
            + ["", "% Reserve space and initialize matrices", f"z = zeros({self.z_size},1);",
               "", "% Evaluate constants"] + self._lines(constants)
            + ["", "% Set the initial values of the states"]
            + [f"VAR({k}) = {p.name_of(x)};" for k, x in enumerate(p.states, 1)])
        if p.files:
            lines += self._function("OpenOutputFilesAndWriteHeadings", [], self._headings())
        lines += ["", "", "", "%" + "=" * 75,
                  "% Main driver loop for numerical integration of differential equations"]
        lines += self._function("SolveOrdinaryDifferentialEquations", g, (
            ["OpenOutputFilesAndWriteHeadings"] if p.files else []) + [
            "VAR = ReadUserInput;",
            "OdeMatlabOptions = odeset( 'RelTol',RELERR, 'AbsTol',ABSERR, "
            "'MaxStep',INTEGSTP );",
            "T = TINITIAL;", "PrintCounter = 0;", "mdlDerivatives(T,VAR,0);",
            "while 1,",
            "  if( TFINAL>=TINITIAL & T+0.01*INTEGSTP>=TFINAL ) PrintCounter = -1; end",
            "  if( TFINAL<=TINITIAL & T+0.01*INTEGSTP<=TFINAL ) PrintCounter = -1; end",
            "  if( PrintCounter <= 0.01 ),",
            "     mdlOutputs(T,VAR,0);",
            "     if( PrintCounter == -1 ) break; end",
            "     PrintCounter = PRINTINT;", "  end",
            "  [TimeOdeArray,VarOdeArray] = ode45( @mdlDerivatives, [T T+INTEGSTP], VAR, "
            "OdeMatlabOptions, 0 );",
            "  TimeAtEndOfArray = TimeOdeArray( length(TimeOdeArray) );",
            "  if( abs(TimeAtEndOfArray - (T+INTEGSTP) ) >= abs(0.001*INTEGSTP) ) "
            "warning('numerical integration failed'); break;  end",
            "  T = TimeAtEndOfArray;",
            "  VAR = VarOdeArray( length(TimeOdeArray), : );",
            "  PrintCounter = PrintCounter - 1;", "end", "mdlTerminate(T,VAR,0);"])
        lines += ["", "", "", "%" + "=" * 75,
                  "% mdlDerivatives: Calculates and returns the derivatives of the "
                  "continuous states"]
        lines += self._function("sys = mdlDerivatives(T,VAR,u)", g,
                                self._derivatives(self._lines(parts.equations), parts))
        lines += ["", "", "", "%" + "=" * 75, "% mdlOutputs: Calculates and return the outputs"]
        lines += self._function("Output = mdlOutputs(T,VAR,u)", g,
                                ["% Evaluate output quantities"] + self._lines(outputs)
                                + _showing(p, outputs.values))
        lines += self._function("WriteOutput( fileIdentifier, Output )", [], _WRITE_OUTPUT)
        lines += ["", "", "", "%" + "=" * 75,
                  "% mdlTerminate: Perform end of simulation tasks and set sys=[]"]
        lines += self._function("sys = mdlTerminate(T,VAR,u)", [],
                                self._closing() + ["sys = [];"])
        return "\n".join(lines) + "\n"

    def _lines(self, part) -> list[str]:
        return _m_lines(part.statements, self.plan.sources)

    def _globals(self) -> list[str]:
        p = self.plan
        derivatives = p.derivatives
        algebraic = derivatives + sorted((s for s in p.named if s not in derivatives),
                                         key=lambda s: (c_name(s).lower(), c_name(s)))
        groups = [p.constants, p.specified, p.states, algebraic]
        lines = [f"global   {' '.join(p.name_of(s) for s in g)};" for g in groups if g]
        misc = ["DEGtoRAD", "RADtoDEG", "z"] + [e.name for e in p.encoded] + \
            (["Encode"] if p.encoded else [])
        return lines + [f"global   {' '.join(misc)};",
                        "global   TINITIAL TFINAL INTEGSTP PRINTINT ABSERR RELERR;"]

    def _table(self) -> list[str]:
        p = self.plan
        rows = [_RULE, f"% {'Quantity':<30}| {'Value':<25}| {'Units':<18}| Description",
                _RULE.replace("+", "|")]
        for group, what in ((p.constants, "Constant"), (p.states, "Initial Value")):
            for s in group:
                value = p.values[s]
                rows.append(f"{p.name_of(s):<32}= {format_value(value.given) + ';':<25}"
                            f"% {value.unit or 'UNITS':<20}{what}")
            rows.append("")
        time_unit = p.time_unit or "UNITS"
        for key, what in _INTEGRATION_ROWS:
            given = p.values[key].given
            text = f" {int(given)}" if key == "PRINTINT" else format_value(given)
            unit = {"PRINTINT": "Positive Integer", "ABSERR": "", "RELERR": ""}.get(
                key, time_unit)
            rows.append(f"{key:<32}= {text + ';':<25}% {unit:<20}{what}")
        return rows + [_RULE]

    def _derivatives(self, statements, parts) -> list[str]:
        p = self.plan
        lines = ["% Update variables after integration step"]
        lines += [f"{p.name_of(x)} = VAR({k});" for k, x in enumerate(p.states, 1)]
        if p.specified:
            lines += ["", "% Quantities to be specified"]
            lines += [f"{p.name_of(s)} = 0;" for s in p.specified]
        lines += [""] + statements
        lines += [f"{target} = {text};" for target, text in parts.rates]
        mass, forcing = parts.mass, parts.forcing
        if self.m:
            lines.append(f"COEF = zeros({self.m},{self.m});")
            for i in range(self.m):
                lines += [f"COEF({i + 1},{j + 1}) = {mass[i * self.m + j]};"
                          for j in range(self.m)]
            lines += [f"RHS({i + 1}) = {forcing[i]};" for i in range(self.m)]
            lines.append("SolutionToAxEqualsB = COEF\\RHS';")
            lines += ["", "% Update variables after uncoupling equations"]
            lines += [f"{p.name_of(u)} = SolutionToAxEqualsB({i});"
                      for i, u in enumerate(p.unknowns, 1)]
        lines += ["", "% Update derivative array prior to integration step"]
        lines += [f"VARp({k}) = {p.name_of(S.derivative(x))};"
                  for k, x in enumerate(p.states, 1)]
        return lines + ["", "sys = VARp';"]


def write_m_dynamics(plan) -> dict:
    """{file name: text}: the program (its input values are in its ReadUserInput)."""
    return {plan.filename: MDynamicsProgram(plan).text()}


__all__ = ["write_m", "write_m_dynamics", "m_string", "MatlabPrinter"]
