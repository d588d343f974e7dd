"""A CODE DYNAMICS() program in Fortran 77, in the layout of the programs Autolev 3.2
wrote (the Fortran of the corpus: TomRottier's sprinting and dogtail models): fixed
form cut at column 72, the quantities shared through COMMON blocks (CONSTNTS, VARIBLES,
ALGBRAIC, MISCLLNS), a main program that reads the .in file with FORMATs 7000/7010/7011
and integrates with KUTTA, EQNS1 for the derivatives (COEF x = RHS solved by SOLVE), IO
for the output rows (1PE14.6E3), and KUTTA and SOLVE themselves unless NOSUBS."""
from __future__ import annotations

import re

import sympy as sm

from .. import __version__
from ..runtime import symbols as S
from ..runtime import units
from ..engine.errors import AutolevModelError
from ..engine.files import dir_text
from ..runtime.printer import ADD, ATOM, POW, UNARY, CPrinter
from .f_subroutines import kutta_and_solve
from .plan import (DynamicsPlan, check_names, dynamics_names, input_file_name, print_dynamics,
                   program_name, with_sources)

# the names the program itself uses (an intrinsic function's name is refused only
# where the program calls that function: Fortran has no reserved words)
RESERVED = frozenset("""
t var varp boundary iloop iprint printint message eqns1 io kutta solve pi degtorad
radtodeg z coef rhs tinitial tfinal integstp abserr relerr
""".split())
_CALL = re.compile(r"(?<![A-Za-z0-9_])([A-Za-z][A-Za-z0-9_]*)\(")

LONGEST_NAME = 63        # what gfortran accepts (Fortran 77 itself allowed 6)
FIRST_UNIT = 21          # NAME.1 is unit 21, NAME.2 unit 22, ...; the .in file is 20

_RELATIONS = {"<": ".LT.", "<=": ".LE.", ">": ".GT.", ">=": ".GE.", "==": ".EQ.",
              "!=": ".NE."}


def f_name(sym) -> str:
    """A quantity's name in Autolev 3.2's Fortran: upper case, X' is Xp, X'' is Xpp."""
    base, order = S.base_and_order(sym)
    return base.name.upper() + "p" * order


def double(value: float) -> str:
    """A double precision literal (`0.5D0`, `1.0D-8`): the shortest decimal that reads
    back as the same double."""
    text = repr(float(value))
    mantissa, _, exponent = text.partition("e")
    if "." not in mantissa:
        mantissa += ".0"
    return f"{mantissa}D{int(exponent) if exponent else 0}"


class FortranPrinter(CPrinter):
    """The C printer's walk, in Fortran: `**`, upper-case intrinsics, D exponents, and
    a unary minus only where Fortran allows one (never right after an operator)."""

    ONE = "1"               # an INTEGER numerator: X is DOUBLE PRECISION in 1/X
    LANGUAGE, LANGUAGE_NAME = "fortran", "Fortran"
    GENERATES = "Fortran"

    def _atom(self, e):
        if e is sm.true or e is sm.false:
            return (".TRUE." if e is sm.true else ".FALSE."), ATOM
        return _binary(*super()._atom(e))

    def _compound(self, e):
        if isinstance(e, (sm.And, sm.Or)):
            op = " .AND. " if isinstance(e, sm.And) else " .OR. "
            return "(" + op.join(self._p(a)[0] for a in e.args) + ")", ATOM
        if isinstance(e, sm.Not):
            return f"(.NOT. {self._p(e.args[0])[0]})", ATOM
        return _binary(*super()._compound(e))

    def _number(self, e):
        if e is sm.nan or e is sm.zoo or e in (sm.oo, -sm.oo):
            raise AutolevModelError(f"{e} has no literal in Fortran 77: write the "
                                    "program in C")
        # integers as Autolev printed them (2*X, X**2) while they fit an INTEGER
        if e.is_Integer and abs(int(e)) < 2 ** 31:
            return str(int(e)), (ADD if e < 0 else ATOM)
        return double(float(e)), (ADD if e < 0 else ATOM)

    def _argument(self, e) -> str:
        """`e` where Fortran needs a DOUBLE PRECISION value (an intrinsic's argument)."""
        if e.is_Integer:
            return double(float(e))
        return self._p(e)[0]

    def _constant(self, e):
        if e is sm.E:
            return "EXP(1.0D0)", ATOM
        return double(float(e)), ATOM

    def _power(self, base, exp):
        return f"{self._wrap(base, ATOM)}**{self._wrap(exp, ATOM)}", POW

    def _piecewise(self, e):
        pieces = list(e.args)
        if pieces[-1][1] is not sm.true:
            raise AutolevModelError("a piecewise quantity without a value for every case "
                                    "has no Fortran 77 form: write the program in C")
        text = self._argument(pieces[-1][0])
        for value, cond in reversed(pieces[:-1]):
            text = f"MERGE({self._argument(value)}, {text}, {self._p(cond)[0]})"
        return text, ATOM

    def _relational(self, e):
        return (f"({self._p(e.lhs)[0]} {_RELATIONS[e.rel_op]} {self._p(e.rhs)[0]})",
                ATOM)


def _binary(text: str, prec: int) -> tuple[str, int]:
    # Fortran has no unary minus after an operator (A*-B): a negated term is
    # parenthesised wherever a sum would be
    return text, (ADD if prec == UNARY else prec)


# -- fixed form ---------------------------------------------------------------------------
def statement(text: str, label: str | int = "") -> list[str]:
    """A statement in fixed form: its label in columns 1-5, its text from column 7,
    cut at column 72 (anywhere, as Autolev cut them) and continued on lines with `&`
    in column 6."""
    line = f"{str(label):<6}{text}"
    lines = [line[:72]]
    for start in range(72, len(line), 66):
        lines.append("     &" + line[start:start + 66])
    return lines


def comment(text: str) -> list[str]:
    return ["C**   " + text]


def f_string(text: str) -> str:
    """`text` as a Fortran character constant: quoted, quotes doubled, printable ASCII."""
    return "'" + "".join(ch if " " <= ch <= "~" else "?" for ch in text).replace(
        "'", "''") + "'"


def _centred(labels: list[str]) -> list[str]:
    """FORMAT items that print the labels centred in 15-character columns (the first
    after a blank), as the headings of Autolev's output files."""
    items, column = [], 0
    for k, label in enumerate(labels):
        start = max(column, 1 + 15 * k + max(0, -(-(14 - len(label)) // 2)))
        if column and start == column:
            start += 1
        if start > column:
            items.append(f"{start - column}X")
        items.append(f_string(label))
        column = start + len(label)
    return items


class FortranDynamicsProgram:
    """The text of one DynamicsPlan's Fortran program."""

    def __init__(self, plan: DynamicsPlan, subroutines: bool):
        check_names(plan, RESERVED, "Fortran")
        self.plan = plan
        self.subroutines = subroutines
        self.name = program_name(plan.filename)
        self.stem = self.name.rpartition(".")[0] or self.name
        self.infile = input_file_name(plan.filename)
        self.n, self.m = len(plan.states), len(plan.unknowns)
        if plan.encoded:
            raise AutolevModelError(
                f"{plan.filename}: ENCODE in a Fortran program: no program Autolev wrote "
                "in Fortran with ENCODE is known; write it in C or Matlab")
        if len(plan.files) > 99 - FIRST_UNIT:
            raise AutolevModelError(f"{plan.filename}: at most {99 - FIRST_UNIT} OUTPUT "
                                    "files in a Fortran program (units 21 to 99)")
        self.names = dynamics_names(plan, f_name)
        self._check_names()
        self.z_size = 0

    def _check_names(self) -> None:
        seen: dict = {}
        for name in self.names.values():
            if len(name) > LONGEST_NAME:
                raise AutolevModelError(f"{self.plan.filename}: the name {name} is longer "
                                        f"than Fortran allows ({LONGEST_NAME} characters)")
            other = seen.setdefault(name.upper(), name)
            if other != name:
                raise AutolevModelError(f"{self.plan.filename}: {other} and {name} are one "
                                        "name in Fortran, which ignores case")

    def _check_calls(self, parts: list) -> None:
        """A quantity named as an intrinsic function the program calls (EXP, with the
        model's EXP(X)) would make the call an array reference: refused."""
        texts = ["ATAN(1.0D0)"] + [t for part in parts for pair in part.statements
                                   for t in pair] + [v for part in parts for v in part.values]
        called = {m.group(1).upper() for text in texts for m in _CALL.finditer(text)}
        clashes = sorted(name for name in set(self.names.values())
                         if name.upper() in called)
        if clashes:
            raise AutolevModelError(
                f"{self.plan.filename}: {', '.join(clashes)} cannot be a name in the "
                "Fortran program, which calls the intrinsic function of that name; "
                "rename it in the model")

    def text(self) -> str:
        parts = print_dynamics(self.plan, self.names, FortranPrinter, lambda k: f"Z({k})",
                               name_of=f_name)
        self.z_size = parts.z_size
        self._check_calls([parts.constants, parts.equations, parts.outputs])
        lines = (self._main(self._lines(parts.constants)) + _BETWEEN
                 + self._eqns1(self._lines(parts.equations), parts) + _BETWEEN
                 + self._io(self._lines(parts.outputs), parts.outputs.values))
        if self.subroutines:
            lines += _BETWEEN + kutta_and_solve(self.n)
        return "\n".join(lines) + "\n"

    def _lines(self, part) -> list[str]:
        return with_sources(part.statements, self.plan.sources,
                            lambda source: "C**   " + "".join(
                                ch if " " <= ch <= "~" else "?" for ch in source)[:66],
                            lambda target, text: statement(f"{target} = {text}"))

    # -- declarations, the same in every program unit -------------------------------------
    def _commons(self) -> list[str]:
        p = self.plan
        # a second-order variable's X' is a state already (in VARIBLES)
        derivatives = [d for d in p.derivatives if d not in p.states]
        others = sorted((s for s in set(p.named) | set(p.specified) if s not in derivatives),
                        key=lambda s: f_name(s).upper())
        # as Autolev's: the quantities, the states' derivatives, other derivatives
        plain = [s for s in others if not S.base_and_order(s)[1]]
        higher = [s for s in others if S.base_and_order(s)[1]]
        misc = ["PI", "DEGtoRAD", "RADtoDEG"]
        if self.z_size:
            misc.append(f"Z({self.z_size})")
        if self.m > 1:
            misc += [f"COEF({self.m},{self.m})", f"RHS({self.m})"]
        lines = []
        for block, group in (("CONSTNTS", [f_name(s) for s in p.constants]),
                             ("VARIBLES", [f_name(s) for s in p.states]),
                             ("ALGBRAIC", [f_name(s) for s in plain + derivatives
                                           + higher]),
                             ("MISCLLNS", misc)):
            if group:
                lines += statement(f"COMMON/{block}/ " + ",".join(group))
        return lines

    # -- the program units -----------------------------------------------------------------
    def _main(self, constants: list) -> list[str]:
        p, nfiles = self.plan, len(self.plan.files)
        lines = [f"C**   The name of this program is {self.name}",
                 f"C**   Created by autolev {__version__} in the layout of Autolev 3.2's "
                 "programs", ""]
        lines += statement("IMPLICIT         DOUBLE PRECISION (A - Z)")
        lines += statement("INTEGER          ILOOP, IPRINT, PRINTINT")
        lines += statement("CHARACTER        MESSAGE(99)")
        lines += statement("EXTERNAL         EQNS1")
        lines += statement(f"DIMENSION        VAR({self.n})")
        lines += self._commons() + [""] + comment("Open input and output files")
        lines += statement(f"OPEN(UNIT=20, FILE={f_string(self.infile)}, STATUS='OLD')")
        for k in range(1, nfiles + 1):
            lines += statement(f"OPEN(UNIT={FIRST_UNIT + k - 1}, "
                               f"FILE={f_string(f'{self.stem}.{k}')},  STATUS='UNKNOWN')")
        lines += [""] + comment("Read message from input file")
        lines += statement("READ(20,7000,END=7100,ERR=7101) (MESSAGE(ILOOP),ILOOP = 1,99)")
        for what, group, fmt in (("values of constants", p.constants, 7010),
                                 ("the initial value of each variable", p.states, 7010)):
            if group:
                lines += [""] + comment(f"Read {what} from input file")
                lines += statement(f"READ(20,{fmt},END=7100,ERR=7101) "
                                   + ",".join(f_name(s) for s in group))
        lines += [""] + comment("Read integration parameters from input file")
        lines += statement("READ(20,7011,END=7100,ERR=7101) TINITIAL,TFINAL,INTEGSTP,"
                           "PRINTINT,ABSERR,RELERR")
        if nfiles:
            lines += [""] + comment("Write heading(s) to output file(s)")
            for k in range(1, nfiles + 1):
                for unit in (["*, ", f"{FIRST_UNIT},"] if k == 1
                             else [f"{FIRST_UNIT + k - 1},"]):
                    lines += statement(f"WRITE({unit}{6020 + k}) (MESSAGE(ILOOP), "
                                       "ILOOP = 1,99)")
        lines += [""] + comment("Degree to radian conversion")
        lines += ["      PI       = 4*ATAN(1.0D0)", "      DEGtoRAD = PI/180.0D0",
                  "      RADtoDEG = 180.0D0/PI"]
        for s in p.degree_inputs:
            lines += statement(f"{f_name(s)} = {f_name(s)}*DEGtoRAD")
        if constants:
            lines += [""] + comment("Evaluate constants") + constants
        lines += [""] + comment("Initialize time, print counter, variables array for "
                                "integrator")
        lines += ["      T      = TINITIAL", "      IPRINT = 0"]
        lines += [f"      VAR({k}) = {f_name(x)}" for k, x in enumerate(p.states, 1)]
        call = f"CALL KUTTA(EQNS1, {self.n}, VAR, T, INTEGSTP, ABSERR, RELERR, {{}}, *5920)"
        lines += [""] + comment("Initalize numerical integrator with call to EQNS1 at "
                                "T=TINITIAL")
        lines += statement(call.format(0))
        lines += [""] + comment("Numerically integrate; print results")
        lines += statement("IF( TFINAL.GE.TINITIAL .AND. T+.01D0*INTEGSTP.GE.TFINAL) "
                           "IPRINT=-7", 5900)
        lines += statement("IF( TFINAL.LE.TINITIAL .AND. T+.01D0*INTEGSTP.LE.TFINAL) "
                           "IPRINT=-7")
        lines += ["      IF( IPRINT .LE. 0 ) THEN", "        CALL IO(T)",
                  "        IF( IPRINT .EQ. -7 ) GOTO 5930", "        IPRINT = PRINTINT",
                  "      ENDIF"]
        lines += statement(call.format(1))
        lines += ["      IPRINT = IPRINT - 1", "      GOTO 5900", ""]
        lines += comment("Print message if numerical integration fails to converge")
        lines += statement("CALL IO(T)", 5920)
        lines += [f"      WRITE({u},6997)" for u in
                  ["*"] + [str(FIRST_UNIT + k) for k in range(nfiles)]]
        lines += [""] + comment("Inform user of input and output filename(s)")
        lines += statement("WRITE(*,6999)", 5930) + [""]
        lines += self._formats()
        lines += ["      STOP"]
        lines += statement(f"WRITE(*,*) 'Premature end of file while reading "
                           f"{f_string(self.infile)[1:-1]}'", 7100)
        lines += ["      STOP"]
        lines += statement(f"WRITE(*,*) 'Error while reading a number from "
                           f"{f_string(self.infile)[1:-1]}'", 7101)
        return lines + ["      STOP", "      END"]

    def _formats(self) -> list[str]:
        p, lines = self.plan, []
        for k, cols in enumerate(p.files, 1):
            labels = [label[:14].upper() for _, label, _ in cols]
            brackets = [f"({(unit or 'UNITS').upper()})" for _, _, unit in cols]
            items = ([f"1X,{f_string(f'FILE: {self.stem}.{k} ')}", "//1X", "'*** '",
                      "99A1", "///"] + _centred(labels) + ["/"] + _centred(brackets)
                     + ["/"])
            lines += statement(f"FORMAT({','.join(items)})", 6020 + k)
        lines += statement("FORMAT(/7X,'Error: Numerical integration failed to converge',/)",
                           6997)
        told = [f"//1X,{f_string('Input is in the file ' + self.infile)}"]
        if p.files:
            what = (f"file {self.stem}.1" if len(p.files) == 1
                    else f"files {self.stem}.i  (i=1,...,{len(p.files)})")
            told += [f"//1X,{f_string('Output is in the ' + what)}",
                     "//1X," + f_string("The output quantities and associated files are "
                                        f"listed in file {self.stem}.dir")]
        lines += statement(f"FORMAT({','.join(told)},/)", 6999)
        lines += statement("FORMAT(//,99A1,///)", 7000)
        lines += statement("FORMAT( 1000(59X,E30.0,/) )", 7010)
        lines += statement("FORMAT( 3(59X,E30.0,/), 1(59X,I30,/), 2(59X,E30.0,/) )", 7011)
        return lines

    def _head(self, signature: str, integers: str = "") -> list[str]:
        lines = ["C" + "*" * 70] + statement(f"SUBROUTINE       {signature}")
        lines += statement("IMPLICIT         DOUBLE PRECISION (A - Z)")
        if integers:
            lines += statement(f"INTEGER          {integers}")
        return lines

    def _eqns1(self, statements: list, parts) -> list[str]:
        p = self.plan
        lines = self._head("EQNS1(T, VAR, VARp, BOUNDARY)", "BOUNDARY")
        lines += statement("DIMENSION        VAR(*), VARp(*)") + self._commons() + [""]
        lines += comment("Update variables after integration step")
        lines += [f"      {f_name(x)} = VAR({k})" for k, x in enumerate(p.states, 1)]
        if p.specified:
            lines += [""] + comment("Quantities which were specified")
            lines += [f"      {f_name(s)} = 0" for s in p.specified]
        lines += [""] + statements
        for target, text in parts.rates:
            lines += statement(f"{target} = {text}")
        mass, forcing = parts.mass, parts.forcing
        if self.m == 1:
            lines += statement(f"{f_name(p.unknowns[0])} = ({forcing[0]})/({mass[0]})")
        elif self.m > 1:
            lines.append("")
            for i in range(self.m):
                for j in range(self.m):
                    lines += statement(f"COEF({i + 1},{j + 1}) = {mass[i * self.m + j]}")
            for i in range(self.m):
                lines += statement(f"RHS({i + 1}) = {forcing[i]}")
            lines += statement(f"CALL SOLVE({self.m},COEF,RHS,VARp)")
            lines += [""] + comment("Update variables after uncoupling equations")
            lines += [f"      {f_name(u)} = VARp({i})" for i, u in enumerate(p.unknowns, 1)]
        lines += [""] + comment("Update derivative array prior to integration step")
        lines += [f"      VARp({k}) = {f_name(S.derivative(x))}"
                  for k, x in enumerate(p.states, 1)]
        return lines + ["", "      RETURN", "      END"]

    def _io(self, statements: list, values: list) -> list[str]:
        p = self.plan
        lines = self._head("IO(T)") + self._commons() + [""]
        lines += comment("Evaluate output quantities") + statements
        if p.files:
            lines += [""] + comment("Write output to screen and to output file(s)")
            values = list(values)
            widest = 99
            for k, cols in enumerate(p.files, 1):
                row = []
                for _, _, unit in cols:
                    text = values.pop(0)
                    if re.fullmatch(r"-?[0-9]+", text):    # the WRITE's format is real
                        text = double(int(text))
                    row.append(f"({text})*RADtoDEG" if units.is_degrees(unit) else text)
                widest = max(widest, len(row))
                for unit in (["*, ", str(FIRST_UNIT) + ","] if k == 1
                             else [f"{FIRST_UNIT + k - 1},"]):
                    lines += statement(f"WRITE({unit}6020) " + ",".join(row))
            lines += [""] + statement(f"FORMAT( {widest}(1X, 1PE14.6E3) )", 6020)
        return lines + ["", "      RETURN", "      END"]


_BETWEEN = ["", ""]


def dir_file_name(filename: str) -> str:
    return input_file_name(filename)[:-3] + ".dir"


def write_f_dynamics(plan: DynamicsPlan) -> dict:
    """{file name: text}: the program, the .in file it reads and the .dir file that
    lists its output files (Autolev wrote it with the program)."""
    nosubs = "NOSUBS" in {o.upper() for o in plan.options}
    program = FortranDynamicsProgram(plan, subroutines=not nosubs)
    text = program.text()
    labels = [[label[:14].upper() for _, label, _ in cols] for cols in plan.files]
    stem = program.stem
    return {plan.filename: text, input_file_name(plan.filename): plan.input_text,
            dir_file_name(plan.filename): dir_text(stem, program.name, labels)}
