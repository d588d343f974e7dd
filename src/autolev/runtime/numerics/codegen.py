"""Straight-line numeric code from a model's definitions.

A `Program` is what one numeric function computes: given input vectors (time, state,
parameters, ...), every definition the outputs need, once, in dependency order (the
Z variables are already the common subexpressions), then the outputs.  It is printed
as Python (always available) or as C (compiled with the system's compiler when there
is one, cached on disk by a hash of the source, called through ctypes).  Both give
the same numbers: the same operations in the same order, in double precision.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sm

from ..calculus import Definitions, symbols_in
from ...engine.errors import AutolevModelError
from ...engine.clibrary import UNIT_MARK, UNIT_STATEMENTS, CompileError, c_function, cpus
from ..printer import LANES, CLanesPrinter, CPrinter, LanesUnsupported, PythonPrinter
from ..sympy_functions import SPEC_OF_FUNCTION
from ...engine.pyfunction import python_function


def _factor_out(add):
    """add with the symbols (positive integer powers) common to all its terms taken
    out as a product, or add itself."""
    terms = [t.as_powers_dict() for t in add.args]
    common = None
    for d in terms:
        here = {b: e for b, e in d.items()
                if b.is_Symbol and e.is_Integer and e > 0}
        if common is None:
            common = here
        else:
            common = {b: min(e, here[b]) for b, e in common.items() if b in here}
        if not common:
            return add
    rest = []
    for t, d in zip(add.args, terms):
        factors = []
        for b, e in d.items():
            k = e - common.get(b, 0)
            if k != 0:
                factors.append(b ** k if k != 1 else b)
        rest.append(sm.Mul(*factors))
    outer = [b ** e if e != 1 else b for b, e in common.items()]
    return sm.Mul(*outer, sm.Add(*rest), evaluate=False) if len(rest) > 1 else add


# elementary functions whose repeated calls are computed once
_HOISTED = tuple(f for f, s in SPEC_OF_FUNCTION.items() if s.hoisted)


@dataclass
class Program:
    """inputs: {name: [symbols]} (each a vector argument); outputs: [expressions].

    Every symbol an output needs must be an input, a `fixed` symbol (a number that
    replaces a definition, e.g. an auxiliary speed set to zero), or defined in `defs`
    (its definition is then evaluated here, after what it needs)."""

    inputs: dict[str, list]
    outputs: list
    defs: Definitions
    fixed: dict = field(default_factory=dict)
    assignments: list = field(default_factory=list)   # (identifier, expression)
    names: dict = field(default_factory=dict)         # symbol -> identifier
    # identifier -> the function call it holds: printed as that call at its own
    # assignment and as the identifier everywhere after (see CodePrinter.bind)
    bound: dict = field(default_factory=dict)
    # (symbol, expression) of the parts lifted out (see build's lift_into)
    lifted: list = field(default_factory=list)
    named: bool = False         # name_all done: the definitions ordered as they stood
    # expression -> with its common factors taken out (build's `factored`): one memo may
    # serve several programs of the same definitions (it depends on the expression alone)
    factored_memo: dict = field(default_factory=dict)
    built: bool = False         # build done (a second build returns it as it is)

    def build(self, factored: bool = True, lift_into: str | None = None,
              shared: str = "calls", signed: bool = False) -> "Program":
        """Order the definitions the outputs need and name everything; `factored`:
        take common factors out of sums (worth it for a program evaluated many times,
        not for one evaluated once per parameter set or solution).  `lift_into`: the
        input holding the values fixed for a parameter set; every part of the program
        computed from those alone is lifted out (`lifted`), to be evaluated once per
        parameter set and passed in as new entries appended to that input.  `shared`:
        what occurs more than once gets a variable of its own: "calls" (elementary
        function calls; gcc finds the rest in the functions it compiles) or "all"
        (sums and products too: a program for a user's compiler, in one function).
        `signed`: a definition that is another's negative is computed as that one
        negated (see _alias_negations)."""
        if self.built:
            return self
        self.built = True
        self._shared = shared
        self.name_all()
        if signed:
            self._alias_negations()
        if factored:
            self._pull_common_factors()
        if lift_into is not None:
            self._lift_constant_parts(lift_into)
        exprs = [a[1] for a in self.assignments] + self.outputs
        seen: set = set()
        # one walk, for the check and the hoisting: each one's nodes not met before
        new_nodes = [post_order([e], seen) for e in exprs]
        missing = {s for nodes in new_nodes for node in nodes for s in node.args
                   if s.is_Symbol and s not in self.names}
        missing |= {e for e in self.outputs if e.is_Symbol and e not in self.names}
        if missing:
            raise AutolevModelError("no value for " + ", ".join(sorted(map(str, missing))))
        self._hoist_calls(exprs, new_nodes)
        return self

    def name_all(self) -> "Program":
        """Name the inputs, the fixed symbols and the definitions the outputs need (as the
        definitions stand now), the definitions assigned in their evaluation order; once.
        Named only, the program is what a walk evaluates (interpret.py), with the numbers
        of build(factored=False), whose hoisting and check of every node cost more than
        one evaluation; the rest of build reads no definition."""
        if self.named:
            return self
        self.named = True
        self.inputs = {arg: list(syms) for arg, syms in self.inputs.items()}
        for arg, syms in self.inputs.items():
            for i, s in enumerate(syms):
                self.names[s] = f"{arg}_{i}"
        given = set(self.names)
        self.outputs = [sm.sympify(o) for o in self.outputs]
        roots = symbols_in(*self.outputs)
        for n, (s, v) in enumerate(self.fixed.items()):
            if s not in given:
                self.names[s] = f"f{n}"
                self.assignments.append((self.names[s], sm.Float(v)))
        given |= set(self.fixed)
        needed = self.defs.evaluation_order(roots, given)
        for n, s in enumerate(needed):
            self.names[s] = f"w{n}"
            self.assignments.append((self.names[s], self.defs.rhs[s]))
        return self

    def _alias_negations(self) -> None:
        """Each definition whose expression is an earlier one's, or its negative, is read
        as that one (negated) wherever it is used, in order, so that what is built from
        it meets its twins too: a derivative of a direction cosine is often another one
        negated (d cos(q1 + q2)/dq1 is -sin(q1 + q2)), and the Jacobians' definitions
        repeat in sign-flipped copies.  Both back ends print the program so changed."""
        symbol_of = {ident: s for s, ident in self.names.items()}
        first: dict = {}            # expression -> the symbol defined by it first
        read_as: dict = {}          # symbol -> the earlier symbol, or its negative
        kept = []
        for ident, expr in self.assignments:
            symbol = symbol_of[ident]
            if read_as and symbol in self.defs.rhs \
                    and not self.defs.free(symbol).isdisjoint(read_as):
                expr = expr.xreplace(read_as)
            twin = first.get(expr)
            if twin is None:
                twin = first.get(-expr)
                twin = None if twin is None else -twin
            if twin is None:
                first[expr] = symbol
                kept.append((ident, expr))
            else:
                read_as[symbol] = twin
        self.assignments = kept
        self.outputs = [e.xreplace(read_as) if read_as else e for e in self.outputs]

    def _pull_common_factors(self) -> None:
        """Sums whose terms share symbolic factors are written with the factors taken
        out (c1*w1 + c1*w2 + ... as c1*(w1 + w2 + ...)): Kane's rows are long sums of
        mass or length times an intermediate, and the multiplications were most of the
        arithmetic.  Both back ends print the same expressions, so their numbers stay
        identical."""
        memo = self.factored_memo

        def pull(e):
            if e.is_Atom:
                return e
            r = memo.get(e)
            if r is not None:
                return r
            args = [pull(a) for a in e.args]
            r = e.func(*args) if any(a is not b for a, b in zip(args, e.args)) else e
            if r.is_Add:
                r = _factor_out(r)
            memo[e] = r
            return r
        self.assignments = [(ident, pull(expr)) for ident, expr in self.assignments]
        self.outputs = [pull(e) for e in self.outputs]

    def _lift_constant_parts(self, arg: str) -> None:
        """Subexpressions of the inputs in `arg` and numbers alone (a sum's constant
        terms, a product's constant factors, cos of an angle constant) become new
        inputs of `arg`, as Autolev's programs evaluate such Z's once with the
        constants."""
        constant = set(self.inputs[arg])
        memo: dict = {}
        lifted: dict = {}

        def lift(e):
            symbol = lifted.get(e)
            if symbol is None:
                symbol = lifted[e] = sm.Dummy(f"k{len(lifted)}")
                self.lifted.append((symbol, e))
            return symbol

        def fixed(e) -> bool:
            return e.is_number or e in constant

        def walk(e):
            """(e with its constant parts lifted, whether e is constant itself)"""
            if e.is_Atom:
                return e, fixed(e)
            kept = memo.get(e)
            if kept is not None:
                return kept
            parts = [walk(a) for a in e.args]
            if all(c for _, c in parts):
                kept = (e, True)
            elif (e.is_Add or e.is_Mul) and sum(c for _, c in parts) > 1:
                const = e.func(*[a for a, c in parts if c])
                kept = (e.func(lift(const), *[a for a, c in parts if not c]), False)
            else:
                args = [lift(a) if c and not a.is_Atom else a for a, c in parts]
                same = all(a is b for a, b in zip(args, e.args))
                kept = (e if same else e.func(*args), False)
            memo[e] = kept
            return kept

        def top(e):
            e, const = walk(e)
            return lift(e) if const and not e.is_Atom else e
        self.assignments = [(ident, top(expr)) for ident, expr in self.assignments]
        self.outputs = [top(e) for e in self.outputs]
        for n, (symbol, _) in enumerate(self.lifted, len(self.inputs[arg])):
            self.names[symbol] = f"{arg}_{n}"
        self.inputs[arg] += [symbol for symbol, _ in self.lifted]

    def _hoist_calls(self, roots: list, new_nodes: list) -> None:
        """Every elementary function call (with shared="all": every subexpression
        worth it) that occurs more than once in the program (cos(q1) in every entry of
        a mass matrix: small expressions stay inline in the definitions) is computed
        once, into its own variable assigned just before its first use.  `roots`: the
        assignments' expressions and the outputs; `new_nodes`: for each, the compound
        nodes under it not under an earlier one, each after its arguments."""
        shared = _repeated(roots, [n for nodes in new_nodes for n in nodes],
                           _worth_a_variable if self._shared == "all"
                           else lambda n: isinstance(n, _HOISTED))
        if not shared:
            return
        new: list = []

        def hoist(nodes):
            # inner calls first; a subtree met before has its calls assigned already
            for c in nodes:
                if c in shared:
                    ident = f"h{len(self.bound)}"
                    new.append((ident, c))
                    self.bound[ident] = c
        for (ident, expr), nodes in zip(self.assignments, new_nodes):
            hoist(nodes)
            new.append((ident, expr))
        for nodes in new_nodes[len(self.assignments):]:
            hoist(nodes)
        self.assignments = new


def post_order(roots: list, seen: set) -> list:
    """The distinct compound nodes under `roots` not in `seen`, each after its
    arguments (walked once as a DAG: the trees share most of their subexpressions);
    adds them to `seen`."""
    out: list = []
    stack = [(r, False) for r in reversed(roots)]
    while stack:
        node, expanded = stack.pop()
        if expanded:
            out.append(node)
        elif not node.is_Atom and node not in seen:
            seen.add(node)
            stack.append((node, True))
            stack.extend((a, False) for a in reversed(node.args))
    return out


def _worth_a_variable(node) -> bool:
    """A call, or a sum or product of more than a number and one factor."""
    if isinstance(node, _HOISTED) or node.is_Add:
        return True
    if node.is_Mul:
        return not (len(node.args) == 2 and node.args[0].is_Number)
    return node.is_Pow or node.is_Function


def _repeated(roots: list, nodes: list, wanted) -> set:
    """The nodes `wanted` picks that occur more than once in the trees of `roots`
    (`nodes`: their compound nodes, each after its arguments): occurrences flow from
    each node to its arguments in topological order (counted up to 2), so shared
    subtrees are not walked again."""
    count: dict = {}
    for r in roots:
        count[r] = min(2, count.get(r, 0) + 1)
    for node in reversed(nodes):
        k = count[node]
        for a in node.args:
            if not a.is_Atom:
                count[a] = min(2, count.get(a, 0) + k)
    return {n for n, k in count.items() if k > 1 and wanted(n)}


# -- Python ---------------------------------------------------------------------------
def python_source(prog: Program, name: str = "compute", printer=PythonPrinter) -> str:
    """The program as a Python function name(*inputs, out) filling `out`; `printer`: the
    printer class of its expressions (CasadiPrinter: building CasADi's)."""
    args = ", ".join(prog.inputs)
    lines = [f"def {name}({args}{', ' if args else ''}out):"]
    for arg, syms in prog.inputs.items():
        for i in range(len(syms)):
            lines.append(f"    {arg}_{i} = {arg}[{i}]")
    p = printer(prog.names)
    for ident, expr in prog.assignments:
        lines.append(f"    {ident} = {p(expr)}")
        if ident in prog.bound:
            p.bind(expr, ident)
    for k, e in enumerate(prog.outputs):
        lines.append(f"    out[{k}] = {p(e)}")
    lines.append("    return out")
    return "\n".join(lines) + "\n"


def compile_python(prog: Program, name: str = "compute"):
    """A Python function for the program: math-module speed, and where Python raises
    (division by zero, a domain error, a complex power) the same code evaluated with
    numpy scalars, which gives inf or nan like compiled C."""
    source = python_source(prog, name)
    recipe = (name, len(prog.inputs))
    return python_function(source, *recipe), source, recipe


# -- C ---------------------------------------------------------------------------------
CHUNK = 100     # statements per C function: gcc's time grows faster than the function's size
                # (planar 16-link: 100 compiles in 0.9 s against 1.05 s for 400, runs as fast)


def c_source(prog: Program, name: str = "compute", lanes: int = 1) -> str:
    """C for the program: inputs read from their arrays, intermediates kept in a work
    array `w` (so that no function is huge: gcc -O2 takes minutes and gigabytes on
    one function of ten thousand locals), the statements split into functions of
    CHUNK statements called in order.  `lanes` (LANES): the statements compute that
    many nodes at once (CLanesPrinter; LanesUnsupported where it prints not), and
    name_rows packs each group of nodes into the vectors and back."""
    where = {}
    for arg, syms in prog.inputs.items():
        for i, s in enumerate(syms):
            where[s] = f"{arg}[{i}]"
    index = {ident: k for k, (ident, _) in enumerate(prog.assignments)}
    for s, ident in prog.names.items():
        if ident in index:
            where[s] = f"w[{index[ident]}]"
    c = CLanesPrinter(where) if lanes > 1 else CPrinter(where)

    def value(expr) -> str:
        text = c(expr)
        return f"AL_SPLAT({text})" if lanes > 1 and not c.varies(expr) else text
    statements = []
    for k, (ident, expr) in enumerate(prog.assignments):
        statements.append(f"w[{k}] = {value(expr)};")
        if ident in prog.bound:
            c.bind(expr, f"w[{k}]")
    statements += [f"out[{k}] = {value(sm.sympify(e))};" for k, e in enumerate(prog.outputs)]
    # restrict: no array is another, so gcc may keep what it read in registers across
    # the stores to w (else every store could change an input and forces reloads)
    number = "al_v" if lanes > 1 else "double"
    params = ", ".join(f"const {number} *restrict {a}" for a in prog.inputs)
    params = (params + ", " if params else "") + \
        f"{number} *restrict w, {number} *restrict out"
    call_args = ", ".join(list(prog.inputs) + ["w", "out"])
    header = ["#include <math.h>", "#ifndef M_PI", "#define M_PI 3.14159265358979323846",
              "#endif", "#ifndef M_E", "#define M_E 2.71828182845904523536", "#endif", ""]
    if lanes > 1:       # aligned(8): read and written wherever the caller's doubles are
        header[-1:] = [f"typedef double al_v __attribute__((vector_size({8 * lanes}), "
                       "aligned(8)));",
                       "#define AL_SPLAT(e) ({ double _s = (e); (al_v){"
                       + ", ".join(["_s"] * lanes) + "}; })", ""]
    # big programs go to several translation units of about equal size (the compiler's
    # time follows the text), compiled in parallel; each unit in functions of at most
    # CHUNK statements
    units = max(1, min(cpus(), len(statements) // UNIT_STATEMENTS))
    total = sum(len(st) for st in statements)
    groups: list = [[] for _ in range(units)]
    done = 0
    for st in statements:
        groups[min(units - 1, done * units // max(1, total))].append(st)
        done += len(st)
    parts, unit_of_part = [], []
    for u, group in enumerate(groups):
        for i in range(0, len(group), CHUNK):
            parts.append(group[i:i + CHUNK])
            unit_of_part.append(u)
    if not parts:
        parts, unit_of_part = [[]], [0]
    lines: list = []
    for u in range(units):
        if u:
            lines.append(UNIT_MARK)
        lines += header
        for n in (k for k in range(len(parts)) if unit_of_part[k] == u):
            lines.append(f"{'static ' if units == 1 else ''}void {name}_part{n}({params})")
            lines.append("{")
            for arg in prog.inputs:
                lines.append(f"    (void){arg};")
            lines.append("    (void)w; (void)out;")
            lines += ["    " + st for st in parts[n]]
            lines.append("}")
            lines.append("")
    if units > 1:
        lines.append(UNIT_MARK)
        lines += header
        lines += [f"void {name}_part{n}({params});" for n in range(len(parts))]
    lines.append(f"void {name}{'_lanes' if lanes > 1 else ''}({params})")
    lines.append("{")
    lines += [f"    {name}_part{n}({call_args});" for n in range(len(parts))]
    lines.append("}")
    if lanes > 1:
        return "\n".join(lines + _lanes_entries(prog, name, lanes)) + "\n"
    # many rows in one call (a run's print rows): input k advances by step[k] doubles
    # a row (0: the same for every row), out by out_step
    row_args = ", ".join([f"{a} + i * step[{k}]" for k, a in enumerate(prog.inputs)]
                         + ["w", "out + i * out_step"])
    lines += ["", f"void {name}_rows(long count, const long *step, {params}, long out_step)",
              "{", "    long i;", f"    for (i = 0; i < count; i++) {name}({row_args});",
              "}"]
    return "\n".join(lines) + "\n"


def _lanes_entries(prog: Program, name: str, lanes: int) -> list:
    """name_rows and name (one node) of a lanes program, as a one-node program's: the
    work array holds each input packed (a vector per entry), the program's own work,
    then its outputs; a group short of `lanes` nodes repeats its last node."""
    params = ", ".join(f"const double *restrict {a}" for a in prog.inputs)
    params = (params + ", " if params else "") + "double *restrict w, double *restrict out"
    # its own names begin al_ (the inputs' are the project's: t, x, p, s, a)
    lines = ["", f"void {name}_rows(long count, const long *step, {params}, long out_step)",
             "{", "    al_v *al_packed = (al_v *)w;", "    long al_i, al_j, al_l;"]
    at = 0
    for arg, syms in prog.inputs.items():
        lines.append(f"    al_v *al_in_{arg} = al_packed + {at};")
        at += len(syms)
    lines += [f"    al_v *al_work = al_packed + {at}, *al_res = al_work + {len(prog.assignments)};",
              f"    for (al_i = 0; al_i < count; al_i += {lanes}) {{",
              f"        for (al_l = 0; al_l < {lanes}; al_l++) {{",
              "            long al_node = al_i + al_l < count ? al_i + al_l : count - 1;"]
    for k, (arg, syms) in enumerate(prog.inputs.items()):
        if syms:
            lines.append(f"            for (al_j = 0; al_j < {len(syms)}; al_j++) "
                         f"al_in_{arg}[al_j][al_l] = {arg}[al_node * step[{k}] + al_j];")
    lines += ["        }",
              f"        {name}_lanes({', '.join(f'al_in_{a}' for a in prog.inputs)}"
              f"{', ' if prog.inputs else ''}al_work, al_res);",
              f"        for (al_l = 0; al_l < {lanes} && al_i + al_l < count; al_l++)",
              f"            for (al_j = 0; al_j < {len(prog.outputs)}; al_j++) "
              "out[(al_i + al_l) * out_step + al_j] = al_res[al_j][al_l];",
              "    }", "}", "",
              f"void {name}({params})", "{",
              f"    static const long step[{max(1, len(prog.inputs))}];",
              f"    {name}_rows(1, step, {', '.join(list(prog.inputs) + ['w', 'out'])}, 0);",
              "}"]
    return lines


def lanes_work(prog: Program, lanes: int) -> int:
    """The doubles of work a lanes program's entries need (see _lanes_entries)."""
    return lanes * (sum(len(s) for s in prog.inputs.values()) + len(prog.assignments)
                    + len(prog.outputs))


def compile_c(prog: Program, name: str = "compute", extra_source: str = "",
              extra_flags: tuple = (), lanes: bool = False):
    """A Python callable f(*input_arrays, out) running the compiled C, and the source.
    `extra_source`: C that is the same for many programs (the integration loop),
    compiled once into a cached object and linked into the same library (reachable as
    `call.lib`).  `lanes`: LANES nodes at once where the program and the compiler allow
    (the same numbers; called over many rows, it reads its text once per group)."""
    source, recipe = c_program(prog, name, extra_source, extra_flags, lanes)
    try:
        return c_function(source, *recipe), source, recipe
    except CompileError:
        if recipe[-1] == 1:
            raise
    source, recipe = c_program(prog, name, extra_source, extra_flags)  # without vectors
    return c_function(source, *recipe), source, recipe


def c_program(prog: Program, name: str = "compute", extra_source: str = "",
              extra_flags: tuple = (), lanes: bool = False) -> tuple[str, tuple]:
    """(C source, recipe): what clibrary.c_function compiles and loads."""
    if lanes:
        try:
            source = c_source(prog, name, LANES)
            return source, (name, len(prog.inputs), lanes_work(prog, LANES), extra_source,
                            tuple(extra_flags), LANES)
        except LanesUnsupported:
            pass
    source = c_source(prog, name)
    return source, (name, len(prog.inputs), len(prog.assignments), extra_source,
                    tuple(extra_flags), 1)
