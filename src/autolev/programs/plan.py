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

import sympy as sm

from ..runtime import symbols as S
from ..runtime import units
from ..runtime.errors import AutolevModelError
from ..runtime.numerics import codegen
from ..runtime.numerics.inputs import Inputs
from ..runtime.numerics.run import encoded_values, equations_and_unknowns, output_columns
from ..runtime.numerics.system import NumericSystem, read_order


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


def program_name(filename: str) -> str:
    """The program's name as Autolev printed it: the CODE file as written, with '/'."""
    return filename.replace("\\", "/")


def input_file_name(filename: str) -> str:
    """The .in file a program reads: its own name with the extension replaced."""
    name = program_name(filename)
    stem, dot, _ = name.rpartition(".")
    return (stem if dot else name) + ".in"


def plan_algebraic(model, command) -> Plan:
    """The plan of a CODE ALGEBRAIC() program: every ENCODE and OUTPUT quantity
    evaluated once from the values its .in file gives."""
    equations, unknowns = equations_and_unknowns(command.args, "ALGEBRAIC")
    if equations:
        raise AutolevModelError("CODE ALGEBRAIC with equations to solve is not written "
                                "as a program yet (only CODE ALGEBRAIC() file)")
    if command.sweep:
        raise AutolevModelError("CODE ALGEBRAIC over a range of an input: no program "
                                "Autolev wrote for one is known, so its layout is not")
    files = output_columns(model, command)
    encoded = encoded_values(model, command)
    with model.defs.as_of(command.definitions):
        system = NumericSystem(model, files, encoded, integrate=False,
                               compile_functions=False)
        if S.TIME in _free(system.output_exprs, model):
            raise AutolevModelError("CODE ALGEBRAIC: its quantities depend on T, which "
                                    "a CODE ALGEBRAIC program has no value for")
        inputs = read_order(system.params, model)
        prog = codegen.Program({"in": inputs, "s": list(system.specified)},
                               system.output_exprs, model.defs,
                               dict(system.aux_fixed)).build(shared="all")
    statements, named = statements_of(prog)
    outputs = list(prog.outputs)
    out_files = []
    for cols in system.files:
        out_files.append([(outputs.pop(0), c.label, c.unit) for c in cols])
    encoded_plan = []
    for name, shape in system.encode_shapes:
        size = 1
        for d in shape:
            size *= d
        elements = [outputs.pop(0) for _ in range(size)]
        if len(shape) == 2 and shape[1] == 1:
            shape = (shape[0],)
        encoded_plan.append(Encoded(name, shape, elements))
    values = Inputs(model, inputs, integration=(), given=command.inputs,
                    unit_table={**model.unit_of, **command.units})
    values.fill_missing(inputs, "0 (no INPUT)")
    text = values.file_text(input_file_name(command.filename),
                            {s: "Constant" for s in inputs})
    degrees = [s for s in inputs if units.is_degrees(values.unit_of(s))]
    return Plan("algebraic", command.filename, inputs, text, list(system.specified),
                named, statements, encoded_plan, out_files, degrees,
                {s: values.values[s] for s in inputs})


def _free(exprs, model) -> set:
    found: set = set()
    for e in exprs:
        found |= sm.sympify(e).free_symbols
    order = model.defs.evaluation_order(found, set())
    for s in order:
        found |= model.defs.free(s)
    return found


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


def marked_statements(plan: Plan, printer, where: dict, name_of) -> list[tuple[str, str]]:
    """(target, text) of each statement, printed with the mark `@k@` for the value of
    statement k wherever a later text reads it (through its symbol, or through the
    text of a repeated subexpression the printer reuses, negated terms included), so
    that what each text reads is what was written.  `where` is the printer's names."""
    out = []
    for k, st in enumerate(plan.statements):
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


def slots_of(plan: Plan, statements: list, later: list, order=None) -> dict:
    """The z slot of each intermediate statement, from the marked texts of the
    statements and of what is printed after them; `order`: the order in which the
    program runs the statements (default: as planned)."""
    order = list(range(len(statements))) if order is None else list(order)
    place = {k: i for i, k in enumerate(order)}
    reads = [{place[j] for j in _marks(statements[k][1])} for k in order]
    reads.append({place[j] for text in later for j in _marks(text)})
    slots = assign_slots(reads, [plan.statements[k].target is None for k in order])
    return {order[i]: slot for i, slot in slots.items()}


def unmarked(text: str, slots: dict, slot_text) -> str:
    """`text` with each mark replaced by slot_text(its slot)."""
    return _MARK.sub(lambda m: slot_text(slots[int(m.group(1))]), text)


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
    """A quantity's name in Autolev's programs: X' is Xp, X'' is Xpp."""
    base, order = S.base_and_order(sym)
    return base.name + "p" * order


def check_names(plan: Plan, reserved: frozenset, language: str) -> None:
    """Autolev printed the user's names as they are: a name the program's own text
    uses (or the language reserves) would change its meaning, so it is refused."""
    clashes = sorted({c_name(s) for s in plan.inputs + plan.named + plan.specified
                      if c_name(s).lower() in reserved}
                     | {e.name for e in plan.encoded if e.name.lower() in reserved})
    if clashes:
        raise AutolevModelError(
            f"{plan.filename}: {', '.join(clashes)} cannot be a name in the {language} "
            "program (the program or the language uses it); rename it in the model")
