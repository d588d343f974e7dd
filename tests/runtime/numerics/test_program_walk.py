"""A program walked (numerics/interpret.py) gives the compiled Python's numbers to the
last bit: each construct the printer writes, at random values; and where the Python
raises, the walk raises too (its caller then compiles, whose fallback gives C's nan)."""
import math

import numpy as np
import pytest
import sympy as sm

from autolev.runtime import Int, Round
from autolev.runtime.calculus import Definitions
from autolev.runtime.numerics import codegen
from autolev.runtime.numerics.compiled import WalkedFirst
from autolev.runtime.numerics.interpret import ProgramWalk

a, b, c, x, y = sm.symbols("a b c x y")
Z = sm.Symbol("z")


def constructs() -> list:
    """Every construct of printer.PythonPrinter, in sums, products and powers."""
    shared = sm.cos(x) + a
    return [
        a * b * x - 3 * c * y + 2.5 - x / (a * b) + y / 3 - sm.Rational(2, 7) * x,
        -(a + b) * x, -x, (a - b) ** 2 + (a + x) ** 3 + x ** -3 + (b * b + 1) ** 1.5,
        sm.sqrt(a * a + b * b) + 1 / sm.sqrt(1 + x * x) + 1 / (a + y) + (a + 2) ** y,
        sm.sin(x) * sm.cos(y) + sm.tan(x / 3) + sm.asin(x / 4) + sm.acos(y / 5)
        + sm.atan(a) + sm.atan2(y, x) + sm.sinh(x) + sm.cosh(y) + sm.tanh(a),
        sm.asinh(x) + sm.acosh(2 + y * y) + sm.atanh(x / 3) + sm.exp(-x * x)
        + sm.log(1 + a * a) + sm.log(2 + b * b, 3) + sm.erf(x) + sm.gamma(2.5 + x * x),
        sm.Abs(x - y) + sm.sign(x - y) + sm.Heaviside(x) + sm.floor(3 * x)
        + sm.ceiling(3 * y) + Int(3 * x) + Round(5 * y) + sm.factorial(3),
        sm.Max(x, y, a) - sm.Min(x, b) + sm.sec(x) + sm.csc(1 + x * x) + sm.cot(1 + y * y),
        sm.Piecewise((x, x > y), (y * 2, sm.And(x < 0, y >= -1)), (a, sm.Or(x < y, b > 0)),
                     (0, True)),
        sm.Piecewise((1, sm.Not(x <= a)), (2, sm.Eq(x, y)), (3, sm.Ne(x, y))),
        shared * b + shared * c + sm.pi * x + sm.E * y + Z * 2,
    ]


@pytest.mark.parametrize("factored", [True, False])
def test_every_construct_walked_is_the_compiled_pythons_to_the_bit(factored):
    defs = Definitions()
    defs.rhs[Z] = a * x + sm.sin(b)          # a definition the program evaluates first
    outputs = constructs()
    prog = codegen.Program({"v": [x, y], "c": [a, b, c]}, outputs, defs).build(factored)
    compiled = codegen.compile_python(prog)[0]
    rng = np.random.default_rng(7)
    for _ in range(200):
        v, k = rng.uniform(-0.9, 0.9, 2), rng.uniform(0.1, 2.0, 3)
        want, got = np.zeros(len(outputs)), np.zeros(len(outputs))
        compiled(v, k, want)
        ProgramWalk(prog).evaluate(v, k, got)
        assert np.array_equal(got, want), (v, k)
    assert len(prog.bound) >= 1          # cos(x) held in a variable: walked once too


def test_the_walk_raises_where_the_compiled_python_raises():
    prog = codegen.Program({"v": [x, y]}, [x / y, sm.sqrt(x - 1)], Definitions()).build()
    with pytest.raises(ZeroDivisionError):
        ProgramWalk(prog).evaluate(np.array([1.0, 0.0]), np.zeros(2))


def test_a_constants_program_is_walked_once_then_compiled():
    prog = codegen.Program({"p": [a, b]}, [a / b, a * b + 1], Definitions())
    constants = WalkedFirst(prog, "autolev_constants")
    first, second = np.zeros(2), np.zeros(2)
    constants.call(np.array([3.0, 4.0]), first)
    assert constants._function is None             # nothing printed nor compiled
    constants.call(np.array([3.0, 4.0]), second)
    assert constants._function is not None and "def autolev_constants" in \
        constants.compiled().source
    assert first.tolist() == second.tolist() == [0.75, 13.0]
    # a first call the math module refuses: compiled, and C's inf and nan
    failing = WalkedFirst(codegen.Program({"p": [a, b]}, [a / b, sm.sqrt(b)],
                                          Definitions()), "autolev_constants")
    out = np.zeros(2)
    failing.call(np.array([1.0, 0.0]), out)
    assert out[0] == math.inf and out[1] == 0.0
    failing.call(np.array([1.0, -4.0]), out)
    assert out[0] == -0.25 and math.isnan(out[1])


def test_conditions_joined_by_and_or_not_compile_in_both_languages():
    # sympy's And, Or and Not are Functions too: the printer once refused them as such
    from autolev.engine import clibrary
    outputs = constructs()[9:11]
    prog = codegen.Program({"v": [x, y], "c": [a, b, c]}, outputs, Definitions()).build()
    python = codegen.compile_python(prog)[0]
    backends = [python] + ([codegen.compile_c(prog)[0]] if clibrary.compiler() else [])
    for v in ([0.5, 0.2], [-0.5, -0.2], [-0.5, 0.3], [0.3, 0.3]):
        k = np.array([0.4, -1.0, 2.0])
        got = []
        for fn in backends:
            out = np.zeros(2)
            fn(np.array(v), k, out)
            got.append(out)
        # by hand: the first condition that holds
        vx, vy = v
        first = vx if vx > vy else 2 * vy if (vx < 0 and vy >= -1) else 0.4 if vx < vy \
            else 0.0
        second = 1 if not vx <= 0.4 else 2 if vx == vy else 3
        for out in got:
            assert out.tolist() == [first, second]


def test_a_walked_program_reads_the_definitions_as_they_stood_when_it_was_made():
    # a value given to a specified quantity defines it only while the programs are made
    defs = Definitions()
    defs.rhs[Z] = 2 * a
    constants = WalkedFirst(codegen.Program({"p": [a]}, [Z + 1], defs), "autolev_constants")
    del defs.rhs[Z]
    walked, compiled = np.zeros(1), np.zeros(1)
    constants.call(np.array([3.0]), walked)
    constants.compiled().call(np.array([3.0]), compiled)
    assert walked.tolist() == compiled.tolist() == [7.0]


def test_a_definition_that_is_anothers_negative_is_read_as_it():
    # signed: Z2 = b - a is -Z1, Z4 = Z1 again, Z3 built from Z2 meets -Z1 too; the
    # program keeps Z1 and Z3, gives the numbers of the program without it to their
    # rounding (z1 - y*z1 is then printed z1*(1 - y)), and its C those of its Python
    from autolev.engine import clibrary
    z1, z2, z3, z4 = sm.symbols("z1 z2 z3 z4")
    defs = Definitions()
    defs.rhs[z1] = a - b * x
    defs.rhs[z2] = b * x - a
    defs.rhs[z3] = z2 * y + z1
    defs.rhs[z4] = a - b * x
    outputs = [z2, z3 * z4, z1 + z2 + z4]
    plain = codegen.Program({"v": [x, y], "c": [a, b, c]}, outputs, defs).build()
    signed = codegen.Program({"v": [x, y], "c": [a, b, c]}, outputs, defs).build(signed=True)
    assert len(plain.assignments) == 4 and len(signed.assignments) == 2
    tiers = [codegen.compile_python(signed)[0]] + (
        [codegen.compile_c(signed, "aliased")[0]] if clibrary.compiler() else [])
    rng = np.random.default_rng(5)
    for _ in range(50):
        v, k = rng.uniform(-2, 2, 2), rng.uniform(-2, 2, 3)
        want = np.zeros(3)
        codegen.compile_python(plain)[0](v, k, want)
        got = []
        for tier in tiers:
            got.append(np.zeros(3))
            tier(v, k, got[-1])
        assert np.allclose(got[0], want, rtol=1e-13, atol=1e-13)
        assert all(np.array_equal(g, got[0]) for g in got)
