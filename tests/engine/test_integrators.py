"""The integrators' registry (engine/integrators.py, issue 52): no module but it names an
integrator, and every integrator it holds follows x'' = -x, whose solution is cos(t),
to its tolerance: in Python on both of Autolev's schedules, and in the compiled loop
wherever the loop runs it."""
import ast
import warnings

import numpy as np
import pytest

import autolev
from autolev.engine import clibrary
from autolev.engine.integrate import Integration, Schedule
from autolev.engine.integrators import INTEGRATORS, integrator_named
from helpers import ROOT

SOURCE = ROOT / "src" / "autolev"
REGISTRY = SOURCE / "engine" / "integrators.py"
# the names the issue lists, and whatever the registry holds besides (scipy's too)
NAMES = ({"kutta-merson", "dop853", "rk45", "radau", "bdf", "lsoda", "rk23"}
         | {i.name for i in INTEGRATORS}
         | {i.scipy_name.lower() for i in INTEGRATORS if i.scipy_name is not None})
TOLERANCE = 1e-9
# ABSERR and RELERR bound each step's error, not the run's: over 20 steps the worst
# (scipy's BDF started afresh at every INTEGSTP, its first steps of low order) is 52
# times the tolerance
REACHED = 100 * TOLERANCE


def integrator_literals(text: str, where: str) -> list[str]:
    """Where `text` has a string literal that is an integrator's name (any case, an
    f-string's constant part too)."""
    found = [node for node in ast.walk(ast.parse(text)) if isinstance(node, ast.Constant)
             and isinstance(node.value, str) and node.value.lower() in NAMES]
    return [f"{where}:{node.lineno}: {node.value!r}"
            for node in sorted(found, key=lambda node: (node.lineno, node.col_offset))]


def test_the_scan_sees_a_name_compared_keyed_or_formatted():
    text = ('if method == "dop853": pass\ncodes = {"Kutta-Merson": 0}\n'
            'f"{x}rk45"\n"run with rk45 here"\n')
    assert integrator_literals(text, "x.py") == ["x.py:1: 'dop853'",
                                                 "x.py:2: 'Kutta-Merson'", "x.py:3: 'rk45'"]


def test_no_integrator_is_named_outside_the_registry():
    found = [hit for path in sorted(SOURCE.rglob("*.py")) if path != REGISTRY
             for hit in integrator_literals(path.read_text(), str(path.relative_to(SOURCE)))]
    assert found == [], ("integrators named outside engine/integrators.py (use its "
                         "records):\n" + "\n".join(found))


def test_a_name_is_found_in_any_case_and_an_unknown_one_names_the_others():
    assert integrator_named("DOP853") is integrator_named("dop853")
    with pytest.raises(ValueError, match=r"unknown integrator 'euler' \(one of "
                       r"kutta-merson, rk45, dop853, radau, bdf, lsoda, rk23\)"):
        integrator_named("euler")


def oscillator(t, y):
    return np.array([y[1], -y[0]])


def assert_cosine(t, x, v):
    """x = cos(t), v = -sin(t) at 21 rows from 0 to 2 s, within REACHED."""
    assert len(t) == 21 and t[0] == 0.0 and t[-1] == pytest.approx(2.0)
    assert np.max(np.abs(x - np.cos(t))) < REACHED
    assert np.max(np.abs(v + np.sin(t))) < REACHED


@pytest.mark.parametrize("afresh", [False, True], ids=["carried-on", "afresh-each-step"])
@pytest.mark.parametrize("integrator", INTEGRATORS, ids=lambda i: i.name)
def test_every_integrator_follows_the_harmonic_oscillator_in_python(integrator, afresh):
    # afresh: Autolev's Matlab programs, which start their integrator over each INTEGSTP
    rows = []
    schedule = Schedule(0.0, 2.0, 0.1, 1, restart_each_step=afresh)
    stats = Integration(oscillator, schedule, integrator, TOLERANCE, TOLERANCE,
                        lambda t, y: rows.append((t, *y))).run(np.array([1.0, 0.0]))
    assert stats["method"] == integrator.name and "compiled" not in stats
    assert_cosine(*np.array(rows).T)


OSCILLATOR = """\
% x'' = -x from x = 1 at rest: x = cos(t)
NEWTONIAN N
PARTICLES P
MOTIONVARIABLES' X', V'
MASS P = 1
X' = V
P_NO_P> = X*N1>
V_P_N> = V*N1>
FORCE_P> = -X*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT X = 1, V = 0
INPUT TFINAL = 2, INTEGSTP = 0.1, PRINTINT = 1, ABSERR = 1E-9, RELERR = 1E-9
OUTPUT T, X, V
CODE DYNAMICS() oscillator.c
CODE DYNAMICS() oscillator.m
"""


def simulate(model, **given):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return model.simulate(**given)


@pytest.fixture(scope="module")
def oscillator_model(tmp_path_factory):
    """The oscillator as a model, each program's compiled loop built (a first run
    steps in Python while its C compiles)."""
    path = tmp_path_factory.mktemp("oscillator") / "oscillator.al"
    path.write_text(OSCILLATOR)
    model = autolev.load(path)
    for code in ("oscillator.c", "oscillator.m"):
        assert simulate(model, code=code, TFINAL=0.1).system.compiled_loop(wait=True)
    return model


@pytest.mark.skipif(clibrary.compiler() is None, reason="needs a C compiler")
@pytest.mark.parametrize("code", ["oscillator.c", "oscillator.m"])
@pytest.mark.parametrize("integrator", INTEGRATORS, ids=lambda i: i.name)
def test_every_integrator_follows_the_harmonic_oscillator_in_a_run(oscillator_model,
                                                                   integrator, code):
    # the .m program's schedule restarts each step (RK45 in the loop); the .c one's not
    r = simulate(oscillator_model, code=code, method=integrator.name)
    assert r.ok and r.stats["method"] == integrator.name
    in_loop = integrator.in_loop(Schedule(0.0, 2.0, 0.1, 1,
                                          restart_each_step=code.endswith(".m")))
    assert r.stats.get("compiled", False) == in_loop
    assert_cosine(r.t, *(r.states[:, r.state_names.index(name)] for name in ("X", "V")))
