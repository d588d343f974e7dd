"""Simulations with Autolev's contract: schedule, integrators, files, inputs, and
end-to-end runs checked against closed forms and physical invariants."""
import math
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

import autolev
from helpers import EXAMPLES, load_model
from autolev.engine import clibrary, files, integrate
from autolev.runtime.numerics import codegen
from autolev.runtime.numerics.inputs import InputFileError



load = load_model


def quiet_simulate(model, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return model.simulate(**kw)


# -- the print schedule -------------------------------------------------------------------
def test_default_schedule_has_eleven_rows_with_both_ends():
    s = integrate.Schedule(0.0, 1.0, 0.1, 1)
    times = s.print_times()
    assert len(times) == 11
    assert times[0] == 0.0 and abs(times[-1] - 1.0) < 1e-12


def test_printint_prints_every_kth_step_and_the_last():
    times = integrate.Schedule(0.0, 1.0, 0.1, 3).print_times()
    assert np.allclose(times, [0.0, 0.3, 0.6, 0.9, 1.0])


def test_last_row_may_pass_tfinal_as_autolevs_loop_did():
    # TFINAL = 0.25 is not on the grid: the loop stops at the first T >= TFINAL - 0.01h
    times = integrate.Schedule(0.0, 0.25, 0.1, 1).print_times()
    assert np.allclose(times, [0.0, 0.1, 0.2, 0.3])


def test_backward_integration_with_negative_step():
    times = integrate.Schedule(1.0, 0.0, -0.25, 1).print_times()
    assert np.allclose(times, [1.0, 0.75, 0.5, 0.25, 0.0])


@pytest.mark.parametrize("h, t1, printint", [(0.0, 1.0, 1), (0.1, -1.0, 1), (0.1, 1.0, 0)])
def test_inconsistent_schedules_are_refused(h, t1, printint):
    with pytest.raises(ValueError):
        integrate.Schedule(0.0, t1, h, printint).check()


# -- Kutta-Merson ---------------------------------------------------------------------------
def test_kutta_merson_integrates_exponential_decay_to_tolerance():
    rows = []
    stats = integrate.integrate(lambda t, y: -y, np.array([1.0]),
                                integrate.Schedule(0.0, 2.0, 0.1, 1), "kutta-merson",
                                1e-10, 1e-10, lambda t, y: rows.append((t, y[0])))
    t, y = np.array(rows).T
    assert len(rows) == 21
    assert np.max(np.abs(y - np.exp(-t))) < 1e-9
    assert stats["steps"] >= 20


@pytest.mark.parametrize("fresh", [False, True])
def test_kutta_merson_as_c_and_as_fortran_programs(fresh):
    # Autolev 4.1's C programs (kutta(..., 2)) evaluate f at every step's start: one
    # evaluation more per step than 3.2's Fortran (kutta(..., 1)), which reuses the
    # last stage's f there; both integrate y' = y cos(t) (y = exp(sin t)) to tolerance
    calls = []

    def f(t, y):
        calls.append(t)
        return y * np.cos(t)
    rows = []
    sched = integrate.Schedule(0.0, 1.0, 0.5, 1, fresh_derivatives=fresh)
    stats = integrate.integrate(f, np.array([1.0]), sched, "kutta-merson", 1e-9, 1e-9,
                                lambda t, y: rows.append((t, y[0])))
    t, y = np.array(rows).T
    assert np.max(np.abs(y - np.exp(np.sin(t)))) < 1e-8
    advances = 2
    # 1 check at T0, 1 at each advance's start, 4 per attempted step, and 1 more per
    # accepted step that is not the last of its advance when fresh
    attempts = stats["steps"] + stats["rejected"]
    expected = 1 + advances + 4 * attempts + (stats["steps"] - advances) * fresh
    assert len(calls) == expected
    assert stats["steps"] > 4


def test_kutta_merson_takes_smaller_steps_for_tighter_tolerance():
    def count(tol):
        return integrate.integrate(lambda t, y: np.array([y[1], -50 * y[0]]),
                                   np.array([1.0, 0.0]), integrate.Schedule(0, 1, 0.1, 1),
                                   "kutta-merson", tol, tol, lambda t, y: None)["steps"]
    assert count(1e-12) > 2 * count(1e-6)


def test_kutta_merson_halves_too_many_times_and_reports_time_and_state():
    rows = []
    with pytest.raises(integrate.IntegrationFailure) as info:
        integrate.integrate(lambda t, y: -1e9 * y, np.array([1.0]),
                            integrate.Schedule(0.0, 1.0, 0.1, 1), "kutta-merson", 1e-8, 1e-7,
                            lambda t, y: rows.append(t))
    assert "halved too many times" in str(info.value)
    assert info.value.t == 0.0 and info.value.y[0] == 1.0
    assert rows == [0.0]


@pytest.mark.parametrize("method", ["rk45", "dop853", "radau", "lsoda"])
def test_scipy_methods_give_rows_on_the_print_grid(method):
    rows = []
    integrate.integrate(lambda t, y: np.array([y[1], -y[0]]), np.array([0.0, 1.0]),
                        integrate.Schedule(0.0, 3.0, 0.05, 4), method, 1e-10, 1e-10,
                        lambda t, y: rows.append((t, y[0])))
    t, y = np.array(rows).T
    assert np.allclose(t, integrate.Schedule(0.0, 3.0, 0.05, 4).print_times())
    assert np.max(np.abs(y - np.sin(t))) < 1e-7


@pytest.mark.parametrize("method", ["kutta-merson", "rk45", "dop853", "radau"])
def test_rows_do_not_depend_on_the_schedules_blocks(method, monkeypatch):
    """A long run takes its schedule in blocks (bounded memory): any block size gives
    the same rows."""
    def rows_with(block):
        monkeypatch.setattr(integrate.Schedule, "BLOCK", block)
        rows = []
        integrate.integrate(lambda t, y: np.array([y[1], -y[0] - 0.1 * y[1] ** 3]),
                            np.array([0.0, 1.0]), integrate.Schedule(0.0, 3.0, 0.05, 4),
                            method, 1e-9, 1e-9, lambda t, y: rows.append((t, *y)))
        return np.array(rows)
    whole = rows_with(1 << 16)
    assert len(whole) == 16                    # T0, then every fourth of 60 steps
    for block in (1, 3, 8):
        assert np.array_equal(rows_with(block), whole)


def test_a_long_schedule_is_not_walked_before_the_first_step():
    """TFINAL = 1e15 (1e16 steps): under Autolev's Kutta-Merson and the compiled DOP853
    the first rows come at once, from the first block (scipy's solvers need their end
    first, a walk over the schedule)."""
    made = []

    class Counted(integrate.Schedule):
        def blocks(self, size=None):
            for block in super().blocks(size):
                made.append(len(block[0]))
                yield block

    class Enough(Exception):
        pass

    def on_row(t, y):
        if t > 1.0:
            raise Enough
    system = quiet_simulate(load("double_pendulum"), TFINAL=0.1).system
    system.compiled_loop(wait=True)       # a first run steps in Python while C compiles
    y0 = np.array([0.5, 1.0, 0.0, 0.0])
    for method, loop in (("kutta-merson", None), ("kutta-merson", system.loop),
                         ("dop853", system.loop)):
        made.clear()
        with pytest.raises(Enough):
            integrate.integrate(system.derivatives, y0, Counted(0.0, 1e15, 0.1, 1), method,
                                1e-8, 1e-8, on_row, loop=loop)
        assert 1 <= len(made) <= 3, method


def test_unknown_method_is_refused():
    with pytest.raises(ValueError, match="unknown integrator"):
        integrate.integrate(lambda t, y: -y, np.array([1.0]), integrate.Schedule(0, 1, .1, 1),
                            "euler", 1e-8, 1e-7, lambda t, y: None)


# -- file layouts ---------------------------------------------------------------------------
def test_output_header_centres_labels_in_15_character_columns():
    text = files.header("PEND.1", ["T", "Q1", "ENERGY"], ["sec", "deg", None])
    lines = text.splitlines()
    assert lines[0] == "% FILE: PEND.1"
    assert lines[1] == "%"
    assert lines[2] == "%       T             Q1           ENERGY"
    # units as the model wrote them, as Autolev's C programs print them
    # ("(radian/sec)" in AutolevToolKit's PendulumDynamics.c)
    assert lines[3] == "%     (sec)          (deg)         (UNITS)"
    assert lines[4] == ""


def test_output_header_keeps_the_spelling_and_cuts_labels_to_14_characters():
    text = files.header("X.1", ["omega", "dot(v_bhat_n>,cross(p_ahat_bhat>,n3>))"],
                        ["radian/sec", None])
    lines = text.splitlines()
    assert lines[2] == "%     omega     dot(v_bhat_n>,"
    assert lines[3] == "% (radian/sec)      (UNITS)"


def test_rows_are_written_with_autolevs_format():
    assert files.row([0.0, -0.25, 12345.678]) == \
        "  0.000000E+00  -2.500000E-01   1.234568E+04 \n"


def test_output_file_names_never_leave_the_output_folder():
    assert files.safe_stem("model/arms/model_angle.f") == "model_angle"
    assert files.safe_stem(r"gait10dof18musc\gait_FK_raw.c") == "gait_FK_raw"
    assert files.safe_stem("../../etc/passwd.c") == "passwd"
    with pytest.raises(autolev.engine.errors.AutolevModelError):
        files.safe_stem("../..")


# -- end to end against closed forms and invariants -----------------------------------------
@pytest.mark.parametrize("method", ["kutta-merson", "dop853"])
def test_harmonic_oscillator_matches_its_closed_form(method):
    r = quiet_simulate(load("harmonic"), method=method)
    w = 2.0                                   # sqrt(K/M)
    x = 0.2 * np.cos(w * r.t) + 0.3 / w * np.sin(w * r.t)
    v = -0.2 * w * np.sin(w * r.t) + 0.3 * np.cos(w * r.t)
    assert np.allclose(r.t, np.arange(0, 3.0001, 0.1))       # PRINTINT 2 of 0.05
    assert np.max(np.abs(r["X"] - x)) < 1e-6
    assert np.max(np.abs(r["V"] - v)) < 1e-6
    assert np.max(np.abs(r.outputs[0]["V'"] + 4 * r["X"])) < 1e-9    # V' = -K/M X


def test_small_angle_pendulum_matches_harmonic_motion():
    r = quiet_simulate(load("simple_pendulum"), THETA=1.0)     # degrees, as the INPUT is
    theta0 = math.radians(1.0)
    w = math.sqrt(9.81 / 1.0)
    exact_small = theta0 * np.cos(w * r.t)
    # the nonlinear period is longer by theta0^2/16: the phase error stays below 3e-4 rad*t
    assert np.max(np.abs(r["THETA"] - exact_small)) < theta0 * 2e-4 * 5 * w
    assert abs(r.outputs[0].data[0, 1] - 1.0) < 1e-12         # printed in degrees


def test_double_pendulum_conserves_energy():
    r = quiet_simulate(load("double_pendulum"))
    energy = r.outputs[1]["ENERGY"]
    assert len(energy) == 1001
    assert np.max(np.abs(energy - energy[0])) < 1e-6 * abs(energy[0])


def test_four_bar_keeps_its_loop_closed():
    r = quiet_simulate(load("fourbar"))
    q1, q2, q3 = r["Q1"], r["Q2"], r["Q3"]
    a1, a2, a3 = q1, q1 + q2, q1 + q2 + q3                # link angles in N
    px = 2 + np.cos(a1) + 2 * np.cos(a2) + np.cos(a3)      # P5 from NO, by hand
    py = np.sin(a1) + 2 * np.sin(a2) + np.sin(a3)
    assert r.ok and len(r.t) == 201
    assert np.max(np.hypot(px, py)) < 1e-6
    assert np.ptp(q1) > 0.3                                # it did move


def test_rolling_disc_rolls_without_slipping():
    r = quiet_simulate(load("rolling_disc"))
    names = r.state_names
    for t, x in zip(r.t[::10], r.states[::10]):
        d = dict(zip(names, r.system.derivatives(t, x)))
        # the contact point (Q4, Q5) moves at the rim speed R*Q3'
        assert abs(math.hypot(d["Q4"], d["Q5"]) - 0.3 * abs(d["Q3"])) < 1e-9


def test_c_and_python_back_ends_give_identical_numbers():
    if clibrary.compiler() is None:
        pytest.skip("no C compiler on this machine: only the Python back end exists")
    m = load("double_pendulum")
    a = quiet_simulate(m, TFINAL=2, backend="c")
    b = quiet_simulate(m, TFINAL=2, backend="python")
    assert a.system.rhs_function.backend == "c"
    assert b.system.rhs_function.backend == "python"
    assert np.array_equal(a.states, b.states)


@pytest.mark.parametrize("backend", ["python", "c"])
def test_int_and_round_in_generated_code_truncate_and_round_halves_away(backend):
    import sympy as sm
    from autolev.runtime import Int, Round
    from autolev.runtime.calculus import Definitions
    if backend == "c" and clibrary.compiler() is None:
        pytest.skip("no C compiler on this machine: only the Python back end exists")
    x = sm.Symbol("x")
    prog = codegen.Program({"x": [x]}, [Int(x), Round(x)], Definitions()).build()
    fn = (codegen.compile_c if backend == "c" else codegen.compile_python)(prog)[0]
    # by hand: toward zero, and halves away from zero (C's round)
    for v, want in ((2.5, (2, 3)), (-2.5, (-2, -3)), (-2.7, (-2, -3)), (-0.2, (0, 0)),
                    (0.49999999999999994, (0, 0)), (1e300, (1e300, 1e300))):
        out = np.zeros(2)
        fn(np.array([v]), out)
        assert tuple(out) == want


def test_a_call_met_twice_anywhere_is_computed_once_and_a_call_met_once_inline():
    import sympy as sm
    from autolev.runtime.calculus import Definitions
    a, b, c, q, r = sm.symbols("a b c q r")
    shared = a + sm.cos(q)        # one object under two outputs: cos(q) occurs twice
    outputs = [shared * b, shared * c, sm.sin(r) + a, sm.sin(sm.cos(r)) * sm.cos(r)]
    prog = codegen.Program({"v": [a, b, c, q, r]}, outputs, Definitions()).build()
    held = sorted(map(str, prog.bound.values()))
    assert held == ["cos(q)", "cos(r)"]          # sin(r) and sin(cos(r)) occur once
    # each held call is assigned before the first statement that uses it
    source = codegen.python_source(prog)
    assert source.count("math.cos(v_3)") == 1 and source.count("math.cos(v_4)") == 1
    fn = codegen.compile_python(prog)[0]
    values = np.array([0.3, 1.1, -0.7, 0.4, 2.0])
    out = np.zeros(4)
    fn(values, out)
    va, vb, vc, vq, vr = values
    want = [(va + math.cos(vq)) * vb, (va + math.cos(vq)) * vc, math.sin(vr) + va,
            math.sin(math.cos(vr)) * math.cos(vr)]
    assert np.allclose(out, want, rtol=1e-15, atol=0)


def test_parts_in_constants_alone_are_lifted_out_once_and_give_the_same_values():
    import sympy as sm
    from autolev.runtime.calculus import Definitions
    a, b, x, y = sm.symbols("a b x y")
    outputs = [a * b * x + a**2 + 3 * b + sm.cos(a) * y, sm.sin(x + a * b)]
    prog = codegen.Program({"x": [x, y], "c": [a, b]}, outputs, Definitions())
    prog = prog.build(lift_into="c")
    lifted = {str(e): s for s, e in prog.lifted}
    # a*b serves both outputs and is lifted once; x and y stay in the program
    assert sorted(lifted) == ["a**2 + 3*b", "a*b", "cos(a)"]
    assert prog.inputs["c"] == [a, b] + [s for s, _ in prog.lifted]
    va, vb, vx, vy = 0.7, -1.3, 0.4, 2.5
    # by hand, the lifted values appended to the constants in their order
    by_hand = {"a*b": va * vb, "a**2 + 3*b": va**2 + 3 * vb, "cos(a)": math.cos(va)}
    c = np.array([va, vb] + [by_hand[str(e)] for _, e in prog.lifted])
    out = np.zeros(2)
    codegen.compile_python(prog)[0](np.array([vx, vy]), c, out)
    want = [va * vb * vx + va**2 + 3 * vb + math.cos(va) * vy, math.sin(vx + va * vb)]
    assert np.allclose(out, want, rtol=1e-14, atol=0)
    assert "math.cos" not in codegen.python_source(prog)


def test_python_programs_give_nan_and_inf_as_c_does_without_a_warning_per_line():
    import sympy as sm
    from autolev.runtime.calculus import Definitions
    x, y = sm.symbols("x y")
    outputs = [x / y, 1 / y, sm.sqrt(x - 1), x + y]
    prog = codegen.Program({"v": [x, y]}, outputs, Definitions()).build()
    fn = codegen.compile_python(prog)[0]
    out = np.zeros(4)
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # numpy's "invalid value" would raise
        fn(np.array([0.0, 0.0]), out)
    assert np.isnan(out[0]) and out[1] == np.inf and np.isnan(out[2]) and out[3] == 0.0


def test_generated_code_does_not_depend_on_the_hash_seed():
    code = ("import autolev, warnings; warnings.simplefilter('ignore');"
            f"m = autolev.load({str(EXAMPLES / 'nlink_pendulum.al')!r});"
            "r = m.simulate(TFINAL=0, backend='python');"
            "print(r.system.rhs_function.source)")
    out = [subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONHASHSEED=seed), check=True).stdout
           for seed in ("1", "2")]
    assert out[0] == out[1] and "def autolev_rhs" in out[0]


def test_derivatives_return_a_fresh_array():
    r = quiet_simulate(load("harmonic"), TFINAL=0)
    a = r.system.derivatives(0.0, r.states[0])
    b = r.system.derivatives(0.0, r.states[0])
    assert a is not b
    a[:] = 99
    assert not np.any(b == 99)


# -- specified quantities ------------------------------------------------------------------
def test_unassigned_specified_is_zero_with_a_warning():
    with pytest.warns(UserWarning, match="set to 0: F"):
        r = load("forced").simulate()
    assert np.all(r["X"] == 0)


def test_specified_function_drives_the_model():
    r = quiet_simulate(load("forced"), specified={"F": lambda t: 1.0})
    # X'' = 1 - X from rest: X = 1 - cos(t)
    assert np.max(np.abs(r["X"] - (1 - np.cos(r.t)))) < 1e-6
    assert np.all(r.outputs[0]["F"] == 1.0)


# -- inputs and .in files --------------------------------------------------------------------
def test_in_file_round_trip_and_degree_units(tmp_path):
    m = load("double_pendulum")
    r = quiet_simulate(m, TFINAL=0.1, out_dir=tmp_path)
    text = (tmp_path / "double_pendulum.in").read_text().splitlines()
    row = next(line for line in text if line.startswith("Initial Value") and " Q1 " in line)
    assert row[58] == "|" and row[42:58].strip() == "DEG" and float(row[59:]) == 30.0
    edited = [line[:59] + " 45.0" if line is row else line for line in text]
    (tmp_path / "edited.in").write_text("\n".join(edited) + "\n")
    r2 = quiet_simulate(m, TFINAL=0.1, infile=tmp_path / "edited.in")
    assert abs(r2["Q1"][0] - math.radians(45)) < 1e-15
    assert r2.outputs[0].data[0, 1] == pytest.approx(45.0)
    assert abs(r.states[0][0] - math.radians(30)) < 1e-15


def test_legacy_in_files_read_by_name_with_p_suffixes_and_d_exponents(tmp_path):
    lines = ["File: x.in", "-" * 77, "message", "-" * 58 + "+" + "-" * 18,
             "Description          Quantity             Units           | Value",
             "-" * 58 + "|" + "-" * 18]

    def entry(kind, name, value):
        return f"{kind:<21}{name:<21}{'UNITS':<16}|{value}"
    lines += [entry("Constant:", "K", " 9.0D+00"), entry("Constant:", "M", " 1.0"),
              entry("Initial Value:", "X", " 0.1"), entry("Initial Value:", "V", " 0.0"),
              entry("Constant:", "OLDNAME", " 3"), entry("Final Time:", "TFINAL", " 1.0")]
    (tmp_path / "x.in").write_text("\n".join(lines) + "\n")
    with pytest.warns(UserWarning, match="OLDNAME is not an input"):
        r = load("harmonic").simulate(infile=tmp_path / "x.in")
    assert np.max(np.abs(r["X"] - 0.1 * np.cos(3.0 * r.t))) < 1e-6     # K = 9 read


def test_malformed_in_file_names_line_and_column(tmp_path):
    (tmp_path / "bad.in").write_text(
        f"{'Constant':<21}{'K':<21}{'UNITS':<16}| nine\n")
    with pytest.raises(InputFileError, match=r"bad\.in:1:60: expected a number for K"):
        quiet_simulate(load("harmonic"), infile=tmp_path / "bad.in")


def test_overrides_use_the_inputs_units_and_unknown_names_are_refused():
    m = load("simple_pendulum")
    r = quiet_simulate(m, THETA=20, TFINAL=0)
    assert r.states[0][0] == pytest.approx(math.radians(20))
    with pytest.raises(autolev.engine.errors.AutolevModelError, match="no input named"):
        quiet_simulate(m, LENGTH=2)


def test_missing_constant_stops_the_run_before_the_build_unless_zero_is_asked(tmp_path,
                                                                               monkeypatch):
    from autolev.runtime.numerics import system as numeric_system
    compiled = []
    real = numeric_system.compile_program
    monkeypatch.setattr(numeric_system, "compile_program",
                        lambda *a, **kw: compiled.append(a[2]) or real(*a, **kw))
    model = load("zero_inputs")
    with pytest.raises(autolev.runtime.MissingValues,
                       match=r"1 constant of zero_inputs.c has no value: L\.") as info:
        model.simulate(out_dir=tmp_path)
    assert info.value.names == ("L",)
    assert compiled == []                       # refused before anything was compiled
    template = tmp_path / "zero_inputs-template.in"
    assert [p.name for p in tmp_path.iterdir()] == [template.name]
    assert "Constant             L                    UNITS           | 0.0" in \
        template.read_text()
    with pytest.warns(UserWarning, match="no value for L: using 0"):
        r = model.simulate(missing_values="zero")
    assert compiled                             # now built
    assert not r.ok
    assert "constants that are 0: L" in r.failure
    assert len(r.t) == 1                        # the row where it stopped


def test_failed_run_keeps_its_rows_and_says_so_in_the_file(tmp_path):
    r = quiet_simulate(load("stiff"), out_dir=tmp_path)
    assert not r.ok and "halved too many times" in r.failure
    text = (tmp_path / "stiff.1").read_text()
    assert "1.000000E+00" in text and "% Error: Numerical integration failed" in text


# -- other CODE forms ------------------------------------------------------------------------
def test_code_algebraic_sweeps_an_input_in_degrees(tmp_path):
    r = quiet_simulate(load("linear"), out_dir=tmp_path)
    assert np.allclose(r.t, [0, 30, 60, 90])
    for c_deg, x, y in r.outputs[0].data:
        c = math.radians(c_deg)
        sol = np.linalg.solve([[3, 2], [1, -0.5]], [math.sin(c), 1])
        assert np.allclose([x, y], sol, rtol=1e-12)
    assert (tmp_path / "linear.1").read_text().count("\n") == 4 + 1 + 4


def test_code_nonlinear_solves_from_the_guesses():
    r = quiet_simulate(load("circle"))
    x, y = r.outputs[0].data[0]
    assert x == pytest.approx(2 / math.sqrt(1.25), abs=1e-9)
    assert y == pytest.approx(1 / math.sqrt(1.25), abs=1e-9)


def test_code_ode_solves_the_equation_for_the_listed_derivative():
    r = quiet_simulate(load("ode_pendulum"), method="dop853")
    k = quiet_simulate(load("simple_pendulum"), TFINAL=2, method="dop853")
    assert np.max(np.abs(r.outputs[0]["THETA"] - k.outputs[0]["THETA"])) < 1e-6


def test_encode_values_are_written_with_one_based_names(tmp_path):
    r = quiet_simulate(load("encoded"), out_dir=tmp_path)
    q = math.radians(30)
    assert np.allclose(r.encoded["R"], [[math.cos(q), -math.sin(q), 0],
                                        [math.sin(q), math.cos(q), 0], [0, 0, 1]])
    assert np.allclose(r.encoded["DR"][0], [-math.sin(q), -math.cos(q), 0])
    lines = (tmp_path / "encoded.encode").read_text().splitlines()
    assert lines[1].startswith("R[1,1]\t0.8660254037844")
    assert "encoded.encode" in (tmp_path / "encoded.dir").read_text()


def test_progress_line_appears_only_after_a_second(monkeypatch):
    import io
    from autolev.engine import progress
    clock = iter([0.0, 0.5, 1.5, 1.6, 7.0])
    monkeypatch.setattr(progress.time, "monotonic", lambda: next(clock))
    stream = io.StringIO()
    bar = progress.Progress(stream, "T", 0.0, 10.0)     # start: t = 0.0 s
    bar.update(1.0)              # 0.5 s: too early
    bar.update(2.0)              # 1.5 s: shown
    bar.update(2.5)              # 1.6 s: not a tty, next line only after 5 s
    bar.update(9.0)              # 7.0 s
    lines = stream.getvalue().splitlines()
    assert lines == ["  T = 2 of 10 (20%), 1.5 s", "  T = 9 of 10 (90%), 7.0 s"]


def test_plot_writes_a_png_per_output_file(tmp_path, capsys):
    pytest.importorskip("matplotlib", reason="--plot needs the optional matplotlib")
    from autolev.cli import main
    code = main(["run", str(EXAMPLES / "double_pendulum.al"), "--out", str(tmp_path),
                 "--tfinal", "0.2", "--plot", "-q"])
    assert code == 0
    pngs = sorted(p.name for p in tmp_path.glob("*.png"))
    assert pngs == ["double_pendulum.1.png", "double_pendulum.2.png"]
    assert (tmp_path / "double_pendulum.1.png").read_bytes()[:4] == b"\x89PNG"


def test_nonlinear_without_output_writes_its_unknowns_in_their_units(tmp_path):
    f = tmp_path / "angle.al"
    f.write_text("VARIABLES QA\nEQ = COS(QA) - 0.5\nINPUT QA = 50 DEG\n"
                 "CODE NONLINEAR(EQ, QA) angle.c\n")
    r = quiet_simulate(autolev.load(f), out_dir=tmp_path)
    assert r.outputs[0].labels == ["QA"] and r.outputs[0].units == ["DEG"]
    assert r.outputs[0].data[0, 0] == pytest.approx(60.0, abs=1e-9)
    assert r.solution["QA"][0] == pytest.approx(math.pi / 3, abs=1e-12)
    assert "(DEG)" in (tmp_path / "angle.1").read_text()


def test_generated_code_does_not_depend_on_what_the_process_built_before():
    # Z's are numbered per model: their names order the terms of sums, so a model's
    # code and its rounding must be the same whatever was loaded earlier
    def source():
        m = load("fourbar")
        r = quiet_simulate(m, TFINAL=0.1)
        r.system.compiled_loop(wait=True)     # a cold run may end before its C is built
        return r.system.rhs_function.source
    first = source()
    load("rolling_disc")
    load("nlink_pendulum")
    assert source() == first
