"""What a program Autolev's CODE command wrote contains, apart from its language: the
inputs in the order its main() reads them, the quantities it declares, the statements
of its computation (Z's and named quantities) and the encoded arrays it fills.

The layout rules come from the programs Autolev 4.1 wrote (docs/language.md, "CODE
programs"): names sorted ignoring case, constants then variables then their
derivatives, z[] slots for intermediates, ENCODE arrays in ENCODE order.
"""
from __future__ import annotations

import heapq
import re
from dataclasses import dataclass, field

from ..runtime import symbols as S
from ..runtime import units
from ..engine.errors import AutolevModelError
from ..runtime.io import CodeKind
from ..runtime.numerics import codegen
from ..runtime.numerics.inputs import Inputs
from ..runtime.numerics.command import (encoded_values, equations_and_unknowns,
                                         hidden_in_outputs, output_columns,
                                         program_file_name, solution_columns,
                                         solver_expressions, sweep_of, take_time,
                                         time_dependence)
from ..runtime.numerics.system import NumericSystem, lower_derivative, read_order


@dataclass
class Encoded:
    """One ENCODE'd quantity: its name, shape (() for a scalar; (n,) for a column) and
    its elements row by row."""

    name: str
    shape: tuple
    elements: list


@dataclass
class Statement:
    """`target = expr`: target is a named quantity (a sympy symbol), or None for an
    intermediate (a z slot); `defines`: the symbol the statement gives a value (None
    for a repeated subexpression, whose expression `holds_call`)."""

    target: object
    expr: object
    defines: object = None
    holds_call: bool = False


@dataclass
class Plan:
    """One CODE command's program, before it is written in a language."""

    kind: str
    filename: str               # as the CODE statement names it
    inputs: list                # symbols, in the order main() reads them
    input_text: str             # the NAME.in file main() reads
    specified: list             # specified quantities without a definition (0)
    named: list                 # user quantities the computation assigns
    statements: list            # Statement, in evaluation order
    encoded: list               # Encoded, in ENCODE order
    files: list                 # per OUTPUT file: [(expression, label, unit)]
    degree_inputs: list = field(default_factory=list)
    values: dict = field(default_factory=dict)     # input -> its Value (given, unit)
    solving: "Solving | None" = None
    sweep: "Sweep | None" = None
    # {NAME (upper case, as the program spells it): "file:line: statement"}
    sources: dict = field(default_factory=dict)
    # the model's quantities Autolev's output routine hid (computed as 0 there)
    hidden: list = field(default_factory=list)
    # {symbol: its name in the program} where the model's name is the language's or the
    # program's own (rename_clashes), and what the user is told of it
    renamed: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)

    def name_of(self, sym) -> str:
        """A quantity's name in this program: c_name's, unless renamed."""
        return self.renamed.get(sym) or c_name(sym)

    @property
    def unknowns(self) -> list:
        """What the program solves for (empty unless it solves equations)."""
        return list(self.solving.unknowns) if self.solving is not None else []

    @property
    def computed(self) -> list:
        """What the program sets that it neither reads nor defines by name: the linear
        equations' unknowns (the nonlinear ones' guesses are read) and a swept input
        (set by main's loop)."""
        found = [u for u in self.unknowns if u not in self.inputs]
        if self.sweep is not None and self.sweep.target is not None:
            found.append(self.sweep.target)
        return found

    def solves_or_sweeps(self) -> bool:
        return self.solving is not None or self.sweep is not None


@dataclass
class Solving:
    """The equations a CODE ALGEBRAIC(EQ, x, ...) or NONLINEAR(EQ, x, ...) program
    solves before its outputs: `statements` compute the `matrix` (n x n, row by row)
    and `right` (n): the coefficients and constant terms of the linear equations
    (A x + b = 0), or the Jacobian and the residuals at the current unknowns (Newton's
    method from the guesses read, steps until each is within max(ABSERR,
    RELERR*|x|), as `autolev run`)."""

    method: str                 # "linear" or "newton"
    unknowns: list
    statements: list
    matrix: list
    right: list

    ITERATIONS = 50             # Newton's steps at most (autolev run's)


@dataclass
class Sweep:
    """CODE ALGEBRAIC() [Q UNIT = start, stop, step]: the program writes a row per
    value of Q, start + step*k for k = 0 .. count-1."""

    target: object              # the swept input (None: it enters no output)
    start: float
    step: float
    count: int
    degrees: bool


def with_sources(pairs, sources: dict, comment, line) -> list[str]:
    """The lines of (target, text) assignments, each named one after a comment that
    says which statement of the model defines it."""
    out = []
    for target, text in pairs:
        source = sources.get(target.upper())
        if source is not None:
            out.append(comment(source))
        out += line(target, text)
    return out


def program_name(filename: str) -> str:
    """The program's name as Autolev printed it: the CODE file as written, with '/'."""
    return filename.replace("\\", "/")


def input_file_name(filename: str) -> str:
    """The .in file a program reads: its own name with the extension replaced."""
    name = program_name(filename)
    stem, dot, _ = name.rpartition(".")
    return (stem if dot else name) + ".in"


def is_fortran(filename: str) -> bool:
    """A CODE file Autolev wrote in Fortran (its .in file has the Fortran layout)."""
    return filename.lower().endswith((".f", ".for"))


def plan_algebraic(model, command, quirks: bool = True) -> Plan:
    """The plan of a CODE ALGEBRAIC() program (every ENCODE and OUTPUT quantity
    evaluated once from the values its .in file gives, or once per value of a swept
    input), of a CODE ALGEBRAIC(EQ, x, ...) one (the linear equations solved first) and
    of a CODE NONLINEAR(EQ, x, ...) one (Newton's method from the guesses read).
    `quirks`: its outputs as Autolev's program computed them (as `autolev run` does)."""
    kind = command.kind
    equations, unknowns = equations_and_unknowns(command.args, kind.upper())
    snapshot = model.snapshot_for(command)
    files = solution_columns(command, output_columns(snapshot, command), unknowns)
    encoded = encoded_values(snapshot)
    defs = model.defs
    with defs.as_of(command.definitions):
        system = NumericSystem(snapshot, files, encoded, integrate=False, solved=unknowns,
                               extra=solver_expressions(defs, kind, equations, unknowns),
                               hidden_in_outputs=hidden_in_outputs(command) if quirks
                               else (), compile_functions=False)
        extra = system.extra_exprs
        timed = time_dependence(system)
        fixed = dict(system.aux_fixed)
        inputs = read_order(system.params, system.symbols) + ([S.TIME] if timed else [])
        given = {"in": inputs, "s": list(system.specified), "u": list(system.solved)}
        prog = codegen.Program(given, system.output_exprs, defs, fixed).build(shared="all")
        solving, solver_named = None, []
        if extra:
            n = len(unknowns)
            solver = codegen.Program(given, [e for v in extra.values() for e in v], defs,
                                     fixed).build(shared="all")
            solver_statements, solver_named = statements_of(solver)
            found = list(solver.outputs)
            if "linear" in extra:       # the coefficients, then the constant terms
                solving = Solving("linear", list(unknowns), solver_statements,
                                  found[:n * n], found[n * n:])
            else:                       # the residuals, then their Jacobian
                solving = Solving("newton", list(unknowns), solver_statements, found[n:],
                                  found[:n])
    statements, named = statements_of(prog)
    named = list(dict.fromkeys(solver_named + named))
    out_files, encoded_plan = _shown(system, prog.outputs)
    read = [s for s in inputs if command.sweep is None or s != command.sweep[0]]
    guesses = list(unknowns) if kind.from_guesses else []
    values = Inputs(model.defs, read + guesses, command.inputs,
                    {**model.unit_of, **command.units},
                    integration=("ABSERR", "RELERR") if guesses else ())
    if timed:
        take_time(command, values, timed)
    values.fill_missing(read + guesses, "0 (no INPUT)")
    text = values.file_text(input_file_name(command.filename),
                            {**{s: "Constant" for s in read},
                             **{u: "Initial Guess" for u in guesses}})
    degrees = [s for s in read + guesses if units.is_degrees(values.unit_of(s))]
    sweep = _sweep_of(command, inputs, values)
    return Plan(kind=kind, filename=command.filename, inputs=read + guesses, input_text=text,
                specified=list(system.specified), named=named, statements=statements,
                encoded=encoded_plan, files=out_files, degree_inputs=degrees,
                values={s: values.values[s] for s in values.names}, solving=solving,
                sweep=sweep, hidden=[s.name for s in system.hidden_in_outputs])


def _sweep_of(command, inputs: list, values: Inputs) -> Sweep | None:
    """The sweep of CODE ALGEBRAIC() [Q = start, stop, step] (its values as
    `autolev run` takes them)."""
    found = sweep_of(command, values)
    if found is None:
        return None
    target, start, step, count, unit = found
    return Sweep(target if target in inputs else None, start, step, count,
                 units.is_degrees(unit))


@dataclass
class DynamicsPlan:
    """A CODE DYNAMICS() program: main evaluates the constants once and integrates
    the states with Kutta-Merson; eqns1 gives the states' derivatives (the unknown
    ones from M x = F), output the OUTPUT and ENCODE quantities at print times."""

    kind: str
    filename: str
    constants: list             # read first, sorted
    states: list                # VAR[] order (sorted), read as initial values
    input_text: str
    values: dict                # input -> Value
    specified: list             # without a definition: 0
    constant_statements: list   # main's "Evaluate constants"
    defined_constants: list     # the symbols they define, as eqns1 and output read them
    rhs_statements: list        # eqns1
    rates: list                 # per state: its derivative's expression (None: solved)
    mass: list                  # m x m, row by row (M x = F)
    forcing: list
    unknowns: list              # the derivatives x solves for, in M's column order
    output_statements: list
    files: list
    encoded: list
    named: list
    degree_inputs: list
    time_unit: str | None = None
    options: tuple = ()         # SUBS / NOSUBS
    sources: dict = field(default_factory=dict)     # as Plan's
    hidden: list = field(default_factory=list)      # as Plan's
    renamed: dict = field(default_factory=dict)     # as Plan's
    notes: list = field(default_factory=list)       # as Plan's

    def name_of(self, sym) -> str:
        """A quantity's name in this program: c_name's, unless renamed."""
        return self.renamed.get(sym) or c_name(sym)

    @property
    def derivatives(self) -> list:
        """The states' derivatives, but those the program reads as constants (a
        derivative CODE ODE() finds declared and never defined)."""
        return [d for d in map(S.derivative, self.states) if d not in self.constants]


def plan_dynamics(model, command, quirks: bool = True) -> DynamicsPlan:
    """The plan of a CODE DYNAMICS() program, or of a CODE ODE(EQ, x'', ...) one: the
    same program, the unknown derivatives solved from the equations in place of
    Kane's (as `autolev run` integrates it).  `quirks`: as plan_algebraic's."""
    what = command.kind.upper()
    equations, unknowns = equations_and_unknowns(command.args, what)
    if command.kind is CodeKind.DYNAMICS and command.args:
        raise AutolevModelError("CODE DYNAMICS with arguments is not written as a "
                                "program yet")
    ode = (equations, unknowns) if command.kind is CodeKind.ODE else None
    snapshot = model.snapshot_for(command)
    files = output_columns(snapshot, command)
    encoded = encoded_values(snapshot)
    defs = model.defs
    filename = program_file_name(command.filename)
    with defs.as_of(command.definitions):
        system = NumericSystem(snapshot, files, encoded, integrate=True, solving=ode,
                               zero=command.zero if command.kind is CodeKind.DYNAMICS else None,
                               hidden_in_outputs=hidden_in_outputs(command) if quirks
                               else (), compile_functions=False)
        if not system.nstate:
            raise AutolevModelError(f"CODE {what}: the model has no state to integrate "
                                    "(no speeds or variables with derivatives)")
        fixed = dict(system.aux_fixed)
        constants_prog = codegen.Program({"c": list(system.params)},
                                         list(system.constant_defs), defs).build(
                                             factored=False, shared="all")
        c_inputs = list(system.params) + list(system.constant_defs)
        inputs = {"t": [S.TIME], "x": list(system.states), "c": c_inputs,
                  "s": list(system.specified)}
        rhs_prog = codegen.Program(inputs, list(system.rhs_exprs), defs, fixed).build(
            shared="all")
        out_prog = codegen.Program(dict(inputs, a=list(system.accel_inputs)),
                                   list(system.output_exprs), defs, fixed).build(
                                       shared="all")
    const_statements, const_named = statements_of(constants_prog)
    rhs_statements, rhs_named = statements_of(rhs_prog)
    out_statements, out_named = statements_of(out_prog)
    n, unknowns = system.nstate, list(system.implicit_unknowns)
    solved = {lower_derivative(d) for d in unknowns}
    rhs = list(rhs_prog.outputs)
    rates = [None if x in solved else rhs[k] for k, x in enumerate(system.states)]
    m = len(unknowns)
    mass, forcing = rhs[n:n + m * m], rhs[n + m * m:n + m * m + m]
    out_files, encoded_plan = _shown(system, out_prog.outputs)
    constants, states = list(system.params), list(system.states)
    values = Inputs(model.defs, constants + states, command.inputs,
                    {**model.unit_of, **command.units})
    values.fill_missing(constants + states, "0 (no INPUT)")
    kinds = {**{c: "Constant" for c in constants}, **{x: "Initial Value" for x in states}}
    text = values.file_text(input_file_name(filename), kinds,
                            fortran=is_fortran(filename))
    degrees = [q for q in constants + states if units.is_degrees(values.unit_of(q))]
    named = list(dict.fromkeys(const_named + rhs_named + out_named))
    return DynamicsPlan(
        kind=command.kind, filename=filename, constants=constants, states=states,
        input_text=text, values=dict(values.values), specified=list(system.specified),
        constant_statements=const_statements, defined_constants=list(system.constant_defs),
        rhs_statements=rhs_statements, rates=rates, mass=mass, forcing=forcing,
        unknowns=unknowns, output_statements=out_statements, files=out_files,
        encoded=encoded_plan, named=named, degree_inputs=degrees,
        time_unit=values.unit_of("T"), options=tuple(command.options),
        hidden=[s.name for s in system.hidden_in_outputs])


def _shown(system, outputs: list) -> tuple[list, list]:
    """(per OUTPUT file [(expression, label, unit)], [Encoded]) from a program's
    outputs, in the order the numeric system lists them (files, then ENCODE)."""
    outputs = list(outputs)
    files = [[(outputs.pop(0), c.label, c.unit) for c in cols] for cols in system.files]
    encoded = []
    for name, shape in system.encode_shapes:
        size = shape[0] * shape[1] if len(shape) == 2 else 1
        elements = [outputs.pop(0) for _ in range(size)]
        encoded.append(Encoded(encode_name(name), (shape[0],) if shape[1:] == (1,) else shape,
                               elements))
    return files, encoded


_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def encode_name(text: str) -> str:
    """The program's name of an ENCODE'd quantity: its own, a derivative's primes as p
    (THETA' is THETAp, as every program names it); refused for what has no name."""
    base = text.rstrip("'")
    if _IDENTIFIER.fullmatch(base) is None:
        raise AutolevModelError(f"ENCODE {text}: a program names each ENCODE array by the "
                                "quantity's name: give the expression a name first "
                                "(NAME = ..., then ENCODE NAME)")
    return base + "p" * (len(text) - len(base))


def statements_of(prog: codegen.Program) -> tuple[list, list]:
    """The program's assignments as Statements: a definition of a quantity the user
    named keeps its name (target: the symbol); Autolev's Z's, the engine's
    intermediates and repeated subexpressions go to z slots (target None), which the
    writer of each language numbers from what its printed text reads (assign_slots)."""
    by_ident = {ident: sym for sym, ident in prog.names.items()}
    named, statements = [], []
    for ident, expr in prog.assignments:
        sym = by_ident.get(ident)
        user = sym is not None and not isinstance(sym, S.Z) and ident.startswith("w")
        if user:
            named.append(sym)
        statements.append(Statement(sym if user else None, expr, sym, ident in prog.bound))
    return statements, named


def assign_slots(reads: list, intermediate: list) -> dict:
    """{statement: z slot} for the statements that are intermediate (`intermediate[k]`),
    numbered from 1; `reads[k]`: the statements whose values text k reads (one text per
    statement, then the texts after them, which keep what they read).  A slot is used
    again once the last text that reads its value has been computed."""
    n = len(intermediate)
    last_read: dict = {}
    for k, read in enumerate(reads):
        for j in read:
            if j != k:
                last_read[j] = k
    frees_after: dict = {}
    for j, k in last_read.items():
        if intermediate[j] and k < n:
            frees_after.setdefault(k, []).append(j)
    free: list = []
    slots: dict = {}
    next_slot = 1
    for k in range(n):
        if intermediate[k]:
            if free:
                slots[k] = heapq.heappop(free)
            else:
                slots[k] = next_slot
                next_slot += 1
        for j in frees_after.get(k, ()):
            heapq.heappush(free, slots[j])
    return slots


# -- printing a plan's computation (any language) ----------------------------------------
_MARK = re.compile(r"@(\d+)@")


def marked_statements(statements: list, printer, where: dict,
                      name_of) -> list[tuple[str, str]]:
    """(target, text) of each statement, printed with the mark `@k@` for the value of
    statement k wherever a later text reads it (through its symbol, or through the
    text of a repeated subexpression the printer reuses, negated terms included), so
    that what each text reads is what was written.  `where` is the printer's names."""
    out = []
    for k, st in enumerate(statements):
        text = printer(st.expr)
        if st.target is None:
            mark = f"@{k}@"
            if st.defines is not None:          # later statements read it from there
                where[st.defines] = mark
            if st.holds_call:                   # a repeated subexpression, computed once
                printer.bind(st.expr, mark)
            out.append((mark, text))
        else:
            out.append((name_of(st.target), text))
    return out


def slots_of(planned: list, statements: list, later: list, order=None) -> dict:
    """The z slot of each intermediate statement of `planned`, from the marked texts
    of the statements and of what is printed after them; `order`: the order in which
    the program runs the statements (default: as planned)."""
    order = list(range(len(statements))) if order is None else list(order)
    place = {k: i for i, k in enumerate(order)}
    reads = [{place[j] for j in _marks(statements[k][1])} for k in order]
    reads.append({place[j] for text in later for j in _marks(text)})
    slots = assign_slots(reads, [planned[k].target is None for k in order])
    return {order[i]: slot for i, slot in slots.items()}


def unmarked(text: str, slots: dict, slot_text) -> str:
    """`text` with each mark replaced by slot_text(its slot)."""
    return _MARK.sub(lambda m: slot_text(slots[int(m.group(1))]), text)


@dataclass
class Printed:
    """One part of a program, printed: its statements as (target, text), the texts of
    the values printed after them, where each symbol it defines is kept, and the
    highest z slot it uses."""

    statements: list
    values: list
    kept: dict
    top: int


def printed(statements: list, values: list, names: dict, printer_of, slot_text,
            offset: int = 0, persistent: bool = False, order=None,
            name_of=None) -> Printed:
    """`statements` and then `values` (expressions; "0" for an exact zero) printed by
    printer_of(names), the intermediates in z slots from offset+1 written by
    slot_text(slot), the named ones as name_of(symbol); `persistent`: every value
    stays readable by later parts (main's constants); `order`: the order the program
    runs the statements in."""
    name_of = name_of or c_name
    where = dict(names)
    printer = printer_of(where)
    assigned = marked_statements(statements, printer, where, name_of)
    texts = ["0" if v == 0 else printer(v) for v in values]
    later = list(texts)
    if persistent:
        later.append(" ".join(f"@{k}@" for k in range(len(statements))))
    slots = slots_of(statements, assigned, later, order)

    def put(text):
        return unmarked(text, slots, lambda k: slot_text(k + offset))
    kept = {st.defines: (name_of(st.target) if st.target is not None
                         else slot_text(slots[k] + offset))
            for k, st in enumerate(statements) if st.defines is not None}
    return Printed([(put(t), put(x)) for t, x in assigned], [put(t) for t in texts], kept,
                   max(slots.values(), default=0) + offset)


@dataclass
class DynamicsParts:
    """A DYNAMICS program's computation, printed in its three parts: the constants
    (evaluated once, their z slots kept for the whole run), the derivatives and the
    outputs (their slots above the constants'); the states' derivatives that have an
    expression as (name, text), and the texts of M and F (M x = F)."""

    constants: Printed
    equations: Printed
    outputs: Printed
    rates: list
    mass: list
    forcing: list
    z_size: int


def print_dynamics(plan, names: dict, printer_of, slot_text, name_of=None) -> DynamicsParts:
    """The plan's computation printed by printer_of(names) (`names` gets where each
    constant is kept, as the derivatives and outputs read it)."""
    name_of = name_of or c_name
    constants = printed(plan.constant_statements, [], names, printer_of, slot_text, 0,
                        persistent=True, name_of=name_of)
    for sym, text in constants.kept.items():
        names.setdefault(sym, text)
    rhs = [r for r in plan.rates if r is not None] + list(plan.mass) + list(plan.forcing)
    equations = printed(plan.rhs_statements, rhs, names, printer_of, slot_text,
                        constants.top, name_of=name_of)
    outputs = printed(plan.output_statements, shown_values(plan), names, printer_of,
                      slot_text, constants.top, name_of=name_of)
    values, rates = list(equations.values), []
    for x, rate in zip(plan.states, plan.rates):
        if rate is not None:
            target, text = name_of(S.derivative(x)), values.pop(0)
            if text != target:              # X' of a second-order X is a state itself
                rates.append((target, text))
    m = len(plan.unknowns)
    return DynamicsParts(constants, equations, outputs, rates, values[:m * m],
                         values[m * m:], max(equations.top, outputs.top, constants.top))


def shown_values(plan) -> list:
    """The expressions output() shows: the OUTPUT columns, file by file, then the
    elements of the ENCODE arrays."""
    return [e for cols in plan.files for e, _, _ in cols] + \
        [x for e in plan.encoded for x in e.elements]


def dynamics_names(plan, name_of=None) -> dict:
    """{symbol: name_of(symbol)} (default c_name) of what a DYNAMICS program keeps in
    named variables: constants, states and their derivatives, specified quantities,
    named definitions, the unknowns of M x = F; and T."""
    name_of = name_of or c_name
    names = {s: name_of(s) for s in plan.constants + plan.states + plan.specified
             + plan.named + list(plan.unknowns)}
    names[S.TIME] = "T"
    for x in plan.states:
        names[S.derivative(x)] = name_of(S.derivative(x))
    return names


def _marks(text: str) -> set:
    return {int(k) for k in _MARK.findall(text)}


def element_indices(shape: tuple) -> list[tuple]:
    """The 0-based indices of an ENCODE quantity's elements, row by row."""
    if not shape:
        return [()]
    if len(shape) == 1:
        return [(i,) for i in range(shape[0])]
    return [(i, j) for i in range(shape[0]) for j in range(shape[1])]


def c_name(sym) -> str:
    """A quantity's name in Autolev's programs: X' is Xp, X'' is Xpp; time is T."""
    if sym == S.TIME:
        return "T"
    base, order = S.base_and_order(sym)
    return base.name + "p" * order


def check_names(plan, reserved: frozenset, language: str,
                exact: frozenset = frozenset()) -> None:
    """Autolev printed the user's names as they are: a name the program's own text
    uses (or the language reserves) would change its meaning, so it is refused (the
    Fortran programs; C and Matlab rename: rename_clashes).  `reserved`: in lower
    case, met in any case; `exact`: met as spelt."""
    symbols = [s for group in ("inputs", "constants", "states", "named", "specified")
               for s in getattr(plan, group, []) if s != S.TIME]    # T is the program's
    names = [c_name(s) for s in symbols] + [e.name for e in plan.encoded]
    clashes = sorted({n for n in names if n.lower() in reserved or n in exact})
    if clashes:
        raise AutolevModelError(
            f"{plan.filename}: {', '.join(clashes)} cannot be a name in the {language} "
            "program (the program or the language uses it); rename it in the model")


def rename_clashes(plan, taken: frozenset, language: str) -> None:
    """A model's quantity or ENCODE array named as the program or the language names
    something of its own (`taken`, as spelt: C and Matlab tell case apart) would change
    the program's meaning: it is written with underscores appended until its name is
    free, each renaming said (plan.notes)."""
    symbols = [s for group in ("inputs", "constants", "states", "named", "specified")
               for s in getattr(plan, group, []) if s != S.TIME]    # T is the program's
    used = {c_name(s) for s in symbols} | {e.name for e in plan.encoded} | set(taken)

    def free(name: str) -> str:
        new = name + "_"
        while new in used:
            new += "_"
        used.add(new)
        plan.notes.append(f"{plan.filename}: {name} is written {new} in the {language} "
                          f"program, where {name} names something of the program's or "
                          f"{language}'s own")
        return new
    for s in dict.fromkeys(symbols):
        if c_name(s) in taken:
            plan.renamed[s] = free(c_name(s))
    for e in plan.encoded:
        if e.name in taken:
            e.name = free(e.name)
