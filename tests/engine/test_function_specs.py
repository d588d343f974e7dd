"""Every record of engine/functions.py in every place that reads one (issue 52): its call
translates; it prints in C, Python, numpy, Fortran and Matlab, and the C, Fortran and
Matlab programs compute it (where a compiler and Octave are); its derivative through
the record's rule, fastdiff and the dual numbers is sympy's; its values in double and
complex precision are sympy's.  And the records are the only table of function names
in the package."""
import ast
import math
import subprocess

import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.engine.dual import DualJacobian, NotDifferentiable
from autolev.engine.errors import AutolevModelError
from autolev.engine.functions import FUNCTION_SPECS
from autolev.engine.pyfunction import fast_namespace, safe_namespace
from autolev.programs.f import FortranPrinter, double, statement
from autolev.programs.m import MatlabPrinter
from autolev.runtime import functions as al
from autolev.runtime import fastdiff
from autolev.runtime.calculus import Definitions
from autolev.runtime.floats import NotElementary, complex_value
from autolev.runtime.numerics import codegen
from autolev.runtime.numerics.interpret import ProgramWalk
from autolev.runtime.printer import CasadiPrinter, CPrinter, PythonPrinter
from autolev.runtime.sympy_functions import sympy_function
from autolev.translate import translate
from autolev.translate.functions.table import FUNCTIONS
from helpers import ROOT
from helpers.programs import GFORTRAN, compiler, needs_cc, needs_gfortran, needs_octave, run_octave

# each record's test line: points of its domain, away from its jumps and poles (a point
# is the arguments of one call)
POINTS = {
    "SIN": [(0.3,), (-1.2,), (2.5,)],
    "COS": [(0.3,), (-1.2,), (2.5,)],
    "TAN": [(0.3,), (-1.2,), (1.0,)],
    "SEC": [(0.3,), (-1.2,), (2.5,)],
    "CSC": [(0.3,), (-1.2,), (2.5,)],
    "COT": [(0.3,), (-1.2,), (2.5,)],
    "ASIN": [(0.3,), (-0.7,), (0.95,)],
    "ACOS": [(0.3,), (-0.7,), (0.95,)],
    "ATAN": [(0.3,), (-2.0,), (10.0,)],
    "ATAN2": [(0.4, -1.1), (-2.0, 0.5), (1.0, 3.0)],
    "SINH": [(0.3,), (-1.2,), (3.0,)],
    "COSH": [(0.3,), (-1.2,), (3.0,)],
    "TANH": [(0.3,), (-1.2,), (3.0,)],
    "ASINH": [(0.3,), (-1.2,), (30.0,)],
    "ACOSH": [(1.5,), (3.0,), (20.0,)],
    "ATANH": [(0.3,), (-0.7,), (0.9,)],
    "EXP": [(0.3,), (-1.2,), (5.0,)],
    "LOG": [(0.3,), (1.7,), (40.0,)],
    "LOG10": [(0.3,), (1.7,), (40.0,)],
    "SQRT": [(0.3,), (1.7,), (40.0,)],
    "SQR": [(0.3,), (-1.7,), (4.0,)],
    "ABS": [(0.3,), (-1.7,)],
    "SIGN": [(0.3,), (-1.7,)],
    "Heaviside": [(0.3,), (-1.7,)],
    "FLOOR": [(0.3,), (-1.7,), (2.5,), (3.0e10 + 0.5,)],
    "CEIL": [(0.3,), (-1.7,), (2.5,), (-3.0e10 - 0.5,)],
    "INT": [(0.3,), (-1.7,), (2.5,)],
    "ROUND": [(0.3,), (-1.7,), (2.5,), (-2.5,)],
    "MAX": [(0.3, -1.7), (0.3, 2.0, -1.0)],
    "MIN": [(0.3, -1.7), (0.3, 2.0, -1.0)],
    "FACTORIAL": [(0.3,), (2.0,), (4.5,)],
    "gamma": [(0.3,), (2.5,), (-1.5,)],
    "erf": [(0.3,), (-1.2,), (2.0,)],
}
# where the complex values are compared: off and on the branch cuts of the real axis
# and the imaginary one
COMPLEX_POINTS = [0.3 + 0.4j, -1.2 + 0.5j, 0.5 - 1.5j, 2.0, -3.0, 0.5, 2j, -2j, 0.5j]
SYMBOLS = sm.symbols("x1 x2 x3", real=True)
RECORDS = {spec.name: spec for spec in FUNCTION_SPECS}
LANGUAGES = ("c", "python", "numpy", "fortran", "matlab", "casadi")


def _close(got, want, rel=1e-12) -> bool:
    return abs(complex(got) - complex(want)) <= rel * max(abs(complex(want)), 1e-3)


def expression(spec, n: int):
    """The record's function of n of SYMBOLS as a model holds it: an Autolev call
    translated and its Python evaluated; sympy's own for one only sympy writes."""
    args = SYMBOLS[:n]
    if spec.autolev is None:
        return sympy_function(spec)(*args)
    names = [s.name.upper() for s in args]
    text = f"VARIABLES {', '.join(names)}\nE = {spec.autolev}({', '.join(names)})\n"
    translation = translate(autolev.parse(text, "call.al"))
    assert not translation.diagnostics, translation.diagnostics
    (line,) = [t for t in translation.code.splitlines() if t.startswith("E = ")]
    return eval(line[4:], {"sm": sm, "al": al, **dict(zip(names, args))})


def want(expr, point) -> complex:
    return complex(expr.subs(dict(zip(SYMBOLS, point))).evalf(30))


def derivative_wanted(expr, x, point) -> complex:
    """sympy's derivative at the point; where sympy keeps it unevaluated (floor's), a
    central difference in exact numbers."""
    exact = sm.diff(expr, x).subs(dict(zip(SYMBOLS, point)))
    if not exact.has(sm.Derivative, sm.Subs):
        return complex(exact.evalf(30))
    at = {s: sm.Rational(repr(v)) for s, v in zip(SYMBOLS, point)}
    h = sm.Rational(1, 10 ** 6)          # the points are farther from a jump
    ahead, behind = expr.subs({**at, x: at[x] + h}), expr.subs({**at, x: at[x] - h})
    return complex(((ahead - behind) / (2 * h)).evalf(30))


def cases():
    return [pytest.param(RECORDS[name], points, id=name) for name, points in POINTS.items()]


def test_every_record_has_its_test_line():
    assert sorted(POINTS) == sorted(RECORDS)


@pytest.mark.parametrize("spec", [s for s in FUNCTION_SPECS if s.autolev is not None],
                         ids=lambda s: s.name)
def test_every_autolev_name_is_a_function_of_the_translator(spec):
    assert FUNCTIONS.get(spec.autolev) is not None


@pytest.mark.parametrize("spec", [s for s in FUNCTION_SPECS if s.sympy is not None],
                         ids=lambda s: s.name)
def test_every_sympy_name_is_a_function(spec):
    assert callable(sympy_function(spec))


@pytest.mark.parametrize("spec, points", cases())
def test_it_prints_in_every_language(spec, points):
    for n in sorted({len(p) for p in points}):
        expr = expression(spec, n)
        names = {s: s.name for s in SYMBOLS}
        for printer in (CPrinter, PythonPrinter, FortranPrinter, MatlabPrinter, CasadiPrinter):
            if spec.sympy is not None and spec.spelling(printer.LANGUAGE) is None:
                with pytest.raises(AutolevModelError, match=f"{spec.sympy} has no "):
                    printer(names)(expr)
                continue
            text = printer(names)(expr)
            if spec.sympy is not None:      # its own spelling (LOG10's is LOG's)
                for called in spec.calls(printer.LANGUAGE):
                    assert called + "(" in text, (printer.LANGUAGE, text)


@pytest.mark.parametrize("spec, points", cases())
def test_the_printed_python_its_numpy_fallback_and_the_walk_compute_it(spec, points):
    for point in points:
        expr = expression(spec, len(point))
        prog = codegen.Program({"v": list(SYMBOLS[:len(point)])}, [expr],
                               Definitions()).build()
        source = codegen.python_source(prog, "compute")
        code = compile(source, "<test>", "exec")
        fast, safe = fast_namespace(), safe_namespace()
        exec(code, fast)
        exec(code, safe)
        by_python, by_numpy, walked = np.zeros(1), np.zeros(1), np.zeros(1)
        fast["compute"](list(point), by_python)
        safe["compute"](np.array(point, dtype=float), by_numpy)
        ProgramWalk(prog).evaluate(np.array(point), walked)
        value = want(expr, point)
        assert _close(by_python[0], value), (point, by_python[0], value)
        assert _close(by_numpy[0], value), (point, by_numpy[0], value)
        assert walked[0] == by_python[0]


@pytest.mark.parametrize("spec, points", cases())
def test_its_double_and_complex_values_are_sympys(spec, points):
    if spec.double is not None:
        for point in points:
            assert _close(spec.double(*point), want(expression(spec, len(point)), point))
    if spec.complex_double is None:
        return
    x = SYMBOLS[0]
    f = sympy_function(spec)
    for z in COMPLEX_POINTS:
        exact = complex(sm.N(f(sm.sympify(z)), 30))
        if spec.branch_cut is not None and spec.branch_cut(z):
            with pytest.raises(NotElementary):      # sympy's side of the cut, not cmath's
                complex_value(f(x), {x: sm.sympify(z)}, {})
            continue
        assert _close(spec.complex_double(z), exact), (z, spec.complex_double(z), exact)
        assert _close(complex_value(f(x), {x: sm.sympify(z)}, {}), exact)


@pytest.mark.parametrize("spec, points", cases())
def test_its_derivative_is_sympys(spec, points):
    for point in points:
        n = len(point)
        expr = expression(spec, n)
        at = dict(zip(SYMBOLS, point))
        prog = codegen.Program({"v": list(SYMBOLS[:n])}, [expr], Definitions()).build()
        duals = DualJacobian(codegen.python_source(prog, "compute"), "compute", 1,
                             {0: list(range(n))}, with_values=True)
        out = np.zeros(1 + n)
        try:
            duals.call(np.array(point), out)
        except NotDifferentiable:
            assert spec.differential is None and not spec.steps
            out = None
        gradient = fastdiff.gradient(expr, SYMBOLS[:n])
        value, at_point = fastdiff.value_and_gradient(
            expr, {s: sm.Float(v) for s, v in at.items()},
            {s: {s: sm.S.One} for s in at})
        assert _close(value, want(expr, point))
        if out is not None:
            assert _close(out[0], value)
        for k, x in enumerate(SYMBOLS[:n]):
            wanted = derivative_wanted(expr, x, point)
            assert _close(fastdiff.diff(expr, x).subs(at).evalf(30), wanted), (point, x)
            assert _close(gradient.get(x, sm.S.Zero).subs(at).evalf(30), wanted), (point, x)
            assert _close(at_point.get(x, 0), wanted), (point, x)
            if out is not None:
                assert _close(out[1 + k], wanted), (point, x, out[1 + k], wanted)
            if spec.differential is not None and spec.sympy is not None:
                changes = [sm.S.One if j == k else sm.S.Zero for j in range(n)]
                rule = spec.differential(sm, *SYMBOLS[:n], *changes)
                assert _close(rule.subs(at).evalf(30), wanted), (point, x)


@pytest.mark.parametrize("spec, points", cases())
def test_the_casadi_expression_computes_it_and_its_derivative(spec, points):
    ca = pytest.importorskip("casadi", reason="the CasADi form needs casadi (an extra)")
    if spec.sympy is not None and spec.casadi is None:
        pytest.skip(f"{spec.name} has no CasADi form (refused: tested above)")
    for point in points:
        n = len(point)
        expr = expression(spec, n)
        prog = codegen.Program({"v": list(SYMBOLS[:n])}, [expr], Definitions()).build()
        namespace = {"ca": ca, "math": math}
        exec(codegen.python_source(prog, "compute", printer=CasadiPrinter), namespace)
        v = ca.SX.sym("v", n)
        out = [None]
        namespace["compute"]([v[i] for i in range(n)], out)
        value, gradient = ca.Function("f", [v], [out[0], ca.gradient(out[0], v)])(point)
        assert _close(float(value), want(expr, point)), (point, float(value))
        for k, x in enumerate(SYMBOLS[:n]):
            wanted = derivative_wanted(expr, x, point)
            assert _close(float(gradient[k]), wanted), (point, x, float(gradient[k]), wanted)


def _points_and_wanted(spec, points):
    """(point, expression, its value there) of the record's function in a quotient (an
    integer a language's spelling left would divide as one)."""
    for point in points:
        expr = expression(spec, len(point)) / 3
        yield point, expr, want(expr, point).real


@needs_cc
@pytest.mark.parametrize("spec, points", cases())
def test_the_c_program_computes_it(spec, points, tmp_path):
    lines = ["#include <math.h>", "#include <stdio.h>", "int main(void)", "{"]
    wanted = []
    for k, (point, expr, value) in enumerate(_points_and_wanted(spec, points)):
        names = {s: f"{s.name}_{k}" for s in SYMBOLS}
        lines += [f"    double {names[s]} = {v!r};" for s, v in zip(SYMBOLS, point)]
        lines.append(f'    printf("%.17g\\n", (double)({CPrinter(names)(expr)}));')
        wanted.append(value)
    (tmp_path / "f.c").write_text("\n".join(lines + ["    return 0;", "}"]) + "\n")
    built = subprocess.run([compiler(), "-O2", "-Wall", "-o", "f", "f.c", "-lm"],
                           cwd=tmp_path, capture_output=True, text=True)
    assert built.returncode == 0 and built.stderr == "", built.stderr
    got = subprocess.run(["./f"], cwd=tmp_path, capture_output=True, text=True).stdout
    assert all(_close(float(g), w) for g, w in zip(got.split(), wanted, strict=True)), got


@needs_gfortran
@pytest.mark.parametrize("spec, points", cases())
def test_the_fortran_program_computes_it(spec, points, tmp_path):
    lines = ["      IMPLICIT DOUBLE PRECISION (A - Z)"]
    wanted = []
    names = {s: s.name.upper() for s in SYMBOLS}
    for point, expr, value in _points_and_wanted(spec, points):
        lines += [f"      {names[s]} = {double(v)}" for s, v in zip(SYMBOLS, point)]
        lines += statement(f"R = {FortranPrinter(names)(expr)}")
        lines.append("      WRITE(*,'(ES25.17)') R")
        wanted.append(value)
    (tmp_path / "f.f").write_text("\n".join(lines + ["      END"]) + "\n")
    built = subprocess.run([GFORTRAN, "-O2", "-o", "f", "f.f"], cwd=tmp_path,
                           capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    got = subprocess.run(["./f"], cwd=tmp_path, capture_output=True, text=True).stdout
    assert all(_close(float(g), w) for g, w in zip(got.split(), wanted, strict=True)), got


@needs_octave
def test_the_matlab_programs_compute_them(tmp_path):
    script, wanted = [], []
    for spec in FUNCTION_SPECS:
        if spec.sympy is not None and spec.matlab is None:
            continue                        # refused as it is printed (above)
        for point, expr, value in _points_and_wanted(spec, POINTS[spec.name]):
            names = {s: s.name for s in SYMBOLS}
            script += [f"{s.name} = {v!r};" for s, v in zip(SYMBOLS, point)]
            script.append(f"printf('%.17g\\n', {MatlabPrinter(names)(expr)});")
            wanted.append((spec.name, point, value))
    ran = run_octave(" ".join(script), tmp_path, timeout=300)
    got = ran.stdout.split()
    assert len(got) == len(wanted), ran.stderr
    wrong = [(name, point, g, w) for g, (name, point, w) in zip(got, wanted)
             if not _close(float(g), w)]
    assert wrong == []


def _spelt_names() -> set:
    """Every name a record gives its function, in Autolev, sympy and each language."""
    names = set()
    for spec in FUNCTION_SPECS:
        names |= {spec.autolev, spec.sympy, spec.numpy, spec.callee} - {None}
        for language in LANGUAGES:
            names |= set(spec.calls(language))
    return names


def tables_of_function_names(tree: ast.AST, names: set) -> list[int]:
    """The lines of `tree` that spell a function's name as a string, or list two or
    more functions as attributes (sm.sin, cmath.sin) in one display; a module's
    `__all__` names what it exports (al.Int), not a function."""
    exports = {id(part) for node in ast.walk(tree) if isinstance(node, ast.Assign)
               and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets)
               for part in ast.walk(node.value)}
    lines = []
    for node in ast.walk(tree):
        if id(node) in exports:
            continue
        if isinstance(node, ast.Constant) and node.value in names:
            lines.append(node.lineno)
        elif isinstance(node, (ast.Dict, ast.Set, ast.List, ast.Tuple)):
            items = (node.keys + node.values) if isinstance(node, ast.Dict) else node.elts
            named = [e for e in items if isinstance(e, ast.Attribute) and e.attr in names]
            if len(named) >= 2:
                lines.append(node.lineno)
    return lines


def test_no_table_of_function_names_outside_the_records():
    names = _spelt_names()
    package = ROOT / "src" / "autolev"
    records = package / "engine" / "functions.py"
    found = []
    for path in sorted(package.rglob("*.py")):
        if path == records or "_antlr" in path.parts:
            continue
        lines = tables_of_function_names(ast.parse(path.read_text()), names)
        found += [f"{path.relative_to(package)}:{line}" for line in lines]
    assert found == []


def test_the_scan_finds_a_table_of_function_names():
    table = ast.parse('_C = {"sin": "sin", "Abs": "fabs"}\n_H = (sm.sin, sm.cos)\n'
                      'if name == "Heaviside": pass\n')
    assert sorted(tables_of_function_names(table, _spelt_names())) == [1, 1, 1, 1, 2, 3]
