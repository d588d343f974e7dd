"""The compiled integration loop (loop.c): the same steps, rows and failures as the
Python loops, stiffness detection, and the C solve of Kane's equations."""
import re
import warnings

import numpy as np
import pytest

import autolev
from helpers import EXAMPLES, load_model
from autolev.engine import clibrary


pytestmark = pytest.mark.skipif(clibrary.compiler() is None, reason="needs a C compiler")


load = load_model


def run(model, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return model.simulate(**kw)


def compiled(model):
    """The model, its right-hand side's C compiled (a first run steps in Python while it
    compiles) and its loop there."""
    run(model, TFINAL=0.1).system.compiled_loop(wait=True)
    return model


@pytest.mark.parametrize("name", ["double_pendulum", "fourbar", "rolling_disc",
                                  "euler_parameters_body"])
def test_kutta_merson_in_c_takes_exactly_the_python_steps(name):
    m = compiled(load(name))
    a = run(m, TFINAL=2, compiled=True)
    b = run(m, TFINAL=2, compiled=False)
    assert a.stats.get("compiled") and not b.stats.get("compiled")
    assert a.stats["evaluations"] == b.stats["evaluations"]
    assert a.stats["steps"] == b.stats["steps"]
    assert np.array_equal(a.t, b.t)
    assert np.array_equal(a.states, b.states)
    for ta, tb in zip(a.outputs, b.outputs):
        assert np.array_equal(ta.data, tb.data)


@pytest.mark.parametrize("name", ["double_pendulum", "rolling_disc"])
def test_rk45_afresh_every_step_is_the_same_in_c_and_python(name, tmp_path):
    """A Matlab program's run (ode45 over each INTEGSTP) in the compiled loop and in
    Python: the same steps and the same numbers, to the last bit (Python's RK45 follows
    the loop's order of operations; scipy's sums in another order gave rows that
    depended on when a cold run's C arrived)."""
    source = (EXAMPLES / f"{name}.al").read_text()
    matlab = tmp_path / f"{name}.al"
    matlab.write_text(re.sub(r"(CODE\s+DYNAMICS\(\)\s+\w+)\.\w+", r"\1.m", source,
                             flags=re.IGNORECASE))
    m = compiled(autolev.load(matlab))
    kw = dict(TFINAL=3, ABSERR=1e-7, RELERR=1e-7)
    a = run(m, compiled=True, **kw)
    b = run(m, compiled=False, **kw)
    assert a.stats["method"] == b.stats["method"] == "rk45"
    assert a.stats.get("compiled") and not b.stats.get("compiled")
    assert a.stats["evaluations"] == b.stats["evaluations"]
    assert a.stats["steps"] == b.stats["steps"]
    assert np.array_equal(a.t, b.t)
    assert np.array_equal(a.states, b.states)


def test_rk45_afresh_is_scipys_rk45_step_for_step():
    # the loop's RK45 (and its Python twin) against scipy's own, over one INTEGSTP
    import scipy.integrate

    from autolev.engine.integrate import RK45Interval

    def f(t, y):                       # a van der Pol oscillator, forced
        return np.array([y[1], 2.0 * (1 - y[0] ** 2) * y[1] - y[0] + np.cos(1.3 * t)])
    y = np.array([1.2, -0.4])
    for t0, t1 in ((0.0, 0.5), (0.5, 2.0), (2.0, 2.01)):
        ours = RK45Interval(f, 1e-7, 1e-9, abs(t1 - t0))
        got = ours(t0, y, t1)
        theirs = scipy.integrate.RK45(f, t0, y, t1, max_step=abs(t1 - t0), rtol=1e-7,
                                      atol=1e-9)
        steps = 0
        while theirs.status == "running":
            theirs.step()
            steps += 1
        assert ours.steps == steps and ours.evaluations == theirs.nfev
        assert np.allclose(got, theirs.y, rtol=1e-13, atol=1e-15)
        y = got


@pytest.mark.parametrize("name", ["double_pendulum", "nlink_pendulum", "rolling_disc"])
def test_dop853_in_c_takes_scipys_steps(name):
    m = load(name)
    kw = dict(TFINAL=3, ABSERR=1e-9, RELERR=1e-9, method="dop853")
    a = run(m, compiled=True, **kw)
    b = run(m, compiled=False, **kw)
    assert a.stats["evaluations"] == b.stats["evaluations"]
    assert a.stats["steps"] == b.stats["steps"]
    assert np.array_equal(a.t, b.t)
    # the same formulas summed in another order: differences at rounding level
    scale = np.abs(b.states).max()
    assert np.abs(a.states - b.states).max() < 1e-10 * scale


def test_c_solve_of_kanes_equations_matches_the_python_solve():
    m = compiled(load("nlink_pendulum"))
    system = run(m, TFINAL=0.1).system
    ns, n = system.nstate, system._n
    rng = np.random.default_rng(1)
    for _ in range(5):
        x = rng.uniform(-2, 2, ns)
        c_dot = system.derivatives(0.3, x)
        loop = system.loop
        system.loop = None
        try:
            py_dot = system.derivatives(0.3, x)
        finally:
            system.loop = loop
        assert np.array_equal(c_dot, py_dot)
        # and both solve M u' = f (M and f as the generated function gives them)
        out = np.empty(system.n_rhs)
        system.rhs_function.call(np.array([0.3]), x, system.constant_values,
                                 system.specified_values, out)
        mm, f = out[ns:ns + n * n].reshape(n, n), out[ns + n * n:ns + n * n + n]
        assert np.allclose(mm @ c_dot[system.unknown_positions], f, rtol=1e-12, atol=1e-12)


def test_halving_failure_is_the_same_in_c_and_python():
    m = load("stiff")
    a = run(m, compiled=True)
    b = run(m, compiled=False)
    assert not a.ok and not b.ok
    assert a.failure == b.failure
    assert a.failure_time == b.failure_time
    assert np.array_equal(a.states, b.states)


def test_singular_mass_matrix_stops_both_loops_at_the_same_place():
    m = load("zero_inputs")               # L = 0: M = m L^2 = 0
    a = run(m, compiled=True, missing_values="zero")
    b = run(m, compiled=False, missing_values="zero")
    assert not a.ok and "singular" in a.failure
    assert a.failure == b.failure
    assert np.array_equal(a.states, b.states)


@pytest.mark.parametrize("method", ["kutta-merson", "dop853"])
def test_slices_and_blocks_of_a_long_run_continue_exactly_where_they_stopped(method):
    """Budget slices of one call and blocks of the schedule (what keeps a long run's
    memory bounded) both resume the integrator's exact state."""
    m = compiled(load("double_pendulum"))
    system = run(m, TFINAL=0.1).system
    y0 = np.array([0.5, 1.0, 0.0, 0.0])
    sched = autolev.engine.integrate.Schedule(0.0, 20.0, 0.1, 3)
    opts = dict(t0=0.0, rtol=1e-10, atol=1e-10, integstp=0.1, max_step=0.1)

    def blocks(size):
        if method == "kutta-merson":
            return ((times, printed, None) for times, printed in sched.blocks(size))
        return ((times, None, end) for times, end in sched.bounded_print_blocks(size))

    def collect(budget, size):
        got = []
        out = system.loop.run(method, y0, blocks(size), opts,
                              lambda ts, rows: got.append((ts, rows)), budget=budget,
                              adapt=False)
        assert out["status"] == 0
        return got, out
    sliced, a = collect(50.0, 1 << 16)
    blocked, c = collect(1e9, 7)
    whole, b = collect(1e9, 1 << 16)
    assert len(sliced) > 20 and len(whole) == 1
    # 200 steps in blocks of 7; DOP853 is bounded beyond the end until the blocks
    # ahead show the last print time, and still steps exactly as with it known
    assert len(blocked) == 29 if method == "kutta-merson" else len(blocked) >= 10
    for parts, out in ((sliced, a), (blocked, c)):
        assert np.array_equal(np.concatenate([ts for ts, _ in parts]), whole[0][0])
        assert np.array_equal(np.concatenate([r for _, r in parts]), whole[0][1])
        assert out["stats"] == b["stats"]
    assert len(whole[0][0]) == 67             # every third of 200 steps, and the last


def test_the_schedule_in_blocks_is_autolevs_loop():
    """Blocks of any size give the T of repeated addition and the print flags of
    Autolev's counter, the last step printed (a loop written out here as reference)."""
    from autolev.engine.integrate import Schedule

    def reference(t0, t1, h, printint):
        out, t, counter = [], t0, printint
        while not (t + 0.01 * h >= t1 if t1 >= t0 else t + 0.01 * h <= t1):
            t += h
            counter -= 1
            last = t + 0.01 * h >= t1 if t1 >= t0 else t + 0.01 * h <= t1
            out.append((t, counter <= 0 or last))
            if counter <= 0 or last:
                counter = printint
        return out
    for t0, t1, h, printint in [(0.0, 1.0, 0.1, 1), (0.0, 2.37, 0.1, 4),
                                (1.0, -0.5, -0.07, 3), (0.3, 0.3, 0.1, 1),
                                (0.0, 1e3, 0.01, 7)]:
        expected = reference(t0, t1, h, printint)
        for size in (1, 5, 64, 1 << 16):
            got = [(t, bool(p)) for times, printed in Schedule(t0, t1, h, printint)
                   .blocks(size) for t, p in zip(times.tolist(), printed.tolist())]
            assert got == expected, (t0, t1, h, printint, size)


def test_stiff_equations_are_detected_and_handed_to_an_implicit_method():
    m = load("stiff_forced")
    with pytest.warns(UserWarning, match=r"stiff from T = .*Radau"):
        r = m.simulate(method="dop853")
    assert r.ok
    assert r.stats["switched_to"] == "radau"
    assert r.stats["stiff_t"] < 0.01            # found within the first steps
    assert np.abs(r.states[:, 0] - np.cos(r.t)).max() < 1e-6
    # DOP853 alone would need about LAMBDA/6 steps per second; the switch keeps the
    # whole run far below that
    assert r.stats["evaluations"] < 20000


def test_kutta_merson_names_the_stiffness_it_crawls_through_in_both_loops():
    m = load("stiff_forced")
    kw = dict(TFINAL=0.002, INTEGSTP=0.0005)
    with pytest.warns(UserWarning, match=r"stiff from T = .*lsoda or radau"):
        a = m.simulate(compiled=True, **kw)
    with pytest.warns(UserWarning, match=r"stiff from T = "):
        b = m.simulate(compiled=False, **kw)
    assert a.stats["stiff_t"] == b.stats["stiff_t"] < 1e-3
    assert np.array_equal(a.states, b.states)


@pytest.mark.parametrize("name", ["double_pendulum", "nlink_pendulum", "rolling_disc"])
@pytest.mark.parametrize("method", ["kutta-merson", "dop853"])
def test_no_stiffness_is_reported_for_ordinary_models(name, method):
    with warnings.catch_warnings():
        warnings.simplefilter("error")           # any warning fails the test
        r = load(name).simulate(method=method)
    assert r.ok and "stiff_t" not in r.stats


def test_cpython_entry_point_gives_the_ctypes_numbers():
    from autolev.engine.cloop import python_include
    system = run(compiled(load("rolling_disc")), TFINAL=0.1).system
    loop = system.loop
    if python_include() is None:
        assert loop.python_entry is None                 # no headers: the ctypes route only
        return
    assert loop.python_entry is not None
    rng = np.random.default_rng(3)
    for _ in range(5):
        x = rng.uniform(-1, 1, system.nstate)
        fast, status = loop.derivatives(0.2, x)
        saved, loop.python_entry = loop.python_entry, None
        try:
            slow, status2 = loop.derivatives(0.2, x)
        finally:
            loop.python_entry = saved
        assert status == status2 == 0
        assert np.array_equal(fast, slow)
    # anything but a float64 state array is converted, not refused
    fast, _ = loop.derivatives(0.2, [0.1] * system.nstate)
    slow, _ = loop.derivatives(0.2, np.full(system.nstate, 0.1))
    assert np.array_equal(fast, slow)


@pytest.mark.parametrize("method", ["radau", "bdf", "lsoda"])
def test_implicit_methods_run_on_the_compiled_right_hand_side(method):
    # their numerical Jacobians evaluate the right-hand side on strided columns
    m = load("double_pendulum")
    r = run(m, method=method, TFINAL=1, RELERR=1e-8, ABSERR=1e-8)
    ref = run(m, method="dop853", TFINAL=1, RELERR=1e-11, ABSERR=1e-11)
    assert r.ok and np.abs(r.states - ref.states).max() < 1e-5
    x = np.zeros((r.system.nstate, 3))
    x[:, 1] = r.states[-1]
    assert np.array_equal(r.system.derivatives(0.0, x[:, 1]),
                          r.system.derivatives(0.0, r.states[-1]))


def test_fast_path_returns_fresh_arrays_and_reports_singularity():
    system = run(compiled(load("double_pendulum")), TFINAL=0.1).system
    x = np.array([0.5, 1.0, 0.1, -0.2])
    a = system.derivatives(0.0, x)
    b = system.derivatives(0.0, x)
    assert a is not b and np.array_equal(a, b)
    a[:] = 0.0                                # the caller may keep or change it
    assert np.array_equal(system.derivatives(0.0, x), b)
    from autolev.engine.massmatrix import SingularMassMatrix
    zero = load("zero_inputs")                # L = 0: a singular mass matrix
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = zero.simulate(missing_values="zero").system
    with pytest.raises(SingularMassMatrix):
        s.derivatives(0.0, np.array([0.1, 0.0]))


def handed_over(method: str, schedule, python_steps: int) -> dict:
    """The double pendulum integrated with `method` on `schedule`: in Python alone, in
    the compiled loop alone, and in Python for `python_steps` steps (a cold run while
    its C compiles) then handed to the loop; each (rows, stats)."""
    from autolev.engine.integrate import integrate
    m = load("double_pendulum")
    in_c = run(m, TFINAL=0.1).system
    loop = in_c.compiled_loop(wait=True)
    python = run(m, TFINAL=0.1, backend="python").system
    assert loop is not None and python.rhs_function.backend == "python"
    y0 = np.array([0.5, 1.0, 0.0, 0.0])

    def rows(f, **how):
        got = []
        stats = integrate(f, y0, schedule, method, 1e-9, 1e-9,
                          lambda t, y: got.append(np.r_[t, y]), **how)
        return np.array(got), stats
    asked = []

    def loop_when_built():
        asked.append(1)
        return loop if len(asked) > python_steps else None
    return {"python": rows(python.derivatives), "c": rows(in_c.derivatives, loop=loop),
            "handed": rows(python.derivatives, loop_when_built=loop_when_built)}


@pytest.mark.parametrize("python_steps", [0, 7, 150, 200])
def test_kutta_merson_goes_on_in_c_from_where_python_stepped(python_steps):
    """A cold run steps in Python while its C compiles, then hands T, the state and its
    step to the compiled loop: the rows are those of either alone, to the last bit."""
    from autolev.engine.integrate import Schedule
    runs = handed_over("kutta-merson", Schedule(0.0, 20.0, 0.1, 3), python_steps)
    (in_python, only_python), (in_c, only_c) = runs["python"], runs["c"]
    handed, both = runs["handed"]
    assert np.array_equal(in_python, in_c) and np.array_equal(handed, in_c)
    # 200 steps: the compiler never finished, Python did them all
    if 0 < python_steps < 200:
        assert both["python_until"] == pytest.approx(0.1 * python_steps)
    else:
        assert "python_until" not in both
    assert both.get("python_only", False) == (python_steps == 200)
    assert both.get("compiled", False) == (python_steps < 200)
    assert "compiled" not in only_python
    for count in ("evaluations", "steps", "rejected"):
        assert both[count] == only_c[count] == only_python[count]


@pytest.mark.parametrize("python_steps", [0, 7, 150, 200])
def test_rk45_afresh_each_step_goes_on_in_c_from_where_python_stepped(python_steps):
    """Autolev's Matlab loop (ode45 started afresh over each INTEGSTP) in a cold run:
    Python's steps while the C compiles, then the compiled loop from that T and state
    (nothing else carries over a step): the rows are those of either alone, to the
    last bit, whenever the C arrived."""
    from autolev.engine.integrate import Schedule
    runs = handed_over("rk45", Schedule(0.0, 20.0, 0.1, 3, restart_each_step=True),
                       python_steps)
    (in_python, only_python), (in_loop, only_c) = runs["python"], runs["c"]
    handed, both = runs["handed"]
    assert len(handed) == len(in_loop) == len(in_python)
    assert np.array_equal(handed, in_loop) and np.array_equal(in_python, in_loop)
    if 0 < python_steps < 200:
        assert both["python_until"] == pytest.approx(0.1 * python_steps)
    assert both.get("python_only", False) == (python_steps == 200)
    assert both.get("compiled", False) == (python_steps < 200)
    assert both["steps"] > 200 and "compiled" not in only_python and only_c["compiled"]


@pytest.mark.parametrize("method", ["kutta-merson", "rk45"])
def test_a_cold_run_does_not_wait_for_its_c_and_keeps_it_for_the_next(tmp_path,
                                                                     monkeypatch, method):
    monkeypatch.setenv("AUTOLEV_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("AUTOLEV_NO_MODEL_CACHE", "0")
    path = tmp_path / "pendulum.al"
    # a model nothing has cached
    path.write_text((EXAMPLES / "double_pendulum.al").read_text() + f"\n% {tmp_path}\n")
    cold = run(autolev.load(path), TFINAL=5, method=method)
    tiers = {"python_until", "python_only"}
    assert tiers & set(cold.stats)
    system = cold.system
    assert system.compiled_loop(wait=True) is not None
    assert system.rhs_function.backend == "c" and system.rhs_compiling is None
    compiled_first = run(autolev.load(path), TFINAL=5, backend="c", method=method)
    assert not tiers & set(compiled_first.stats)
    assert np.array_equal(cold.states, compiled_first.states)
    # the model kept is the compiled one: read back, its run is C from the first step
    again = run(autolev.load(path), TFINAL=5, method=method)
    assert again.system.rhs_function.backend == "c" and not tiers & set(again.stats)


@pytest.mark.parametrize("backend", ["auto", "python"])
def test_the_outputs_of_many_rows_are_those_of_each_row(backend):
    """A run's print rows have their outputs computed in one call (outputs_rows): the
    numbers of one call per row, to the last bit, and what each row's conditioning is
    judged by (the mass matrix, or the recursion's pivot ratios)."""
    m = compiled(load("double_pendulum"))
    r = run(m, TFINAL=2, backend=backend)
    system = r.system
    assert (system.output_function.backend == "c") == (backend == "auto")
    values, matrices = system.outputs_rows(r.t, r.states)
    for i, (t, x) in enumerate(zip(r.t, r.states)):
        assert np.array_equal(values[i], system.outputs(t, x))
        assert np.array_equal(matrices[i], system.last_conditioning())
    # the run's own table (its rows from the loop a slice at a time): these numbers
    first = r.outputs[0].data
    degrees = np.array(system.degree_columns[0])
    raw = values[:, :first.shape[1]]
    assert len(first) == len(values) > 10
    assert np.array_equal(first, np.where(degrees, raw * 180 / np.pi, raw))


def test_rows_whose_specified_quantities_are_functions_go_one_by_one():
    # F = sin(t) changes from row to row: one call for all rows would read one F
    r = run(load("forced"), TFINAL=2, specified={"F": lambda t: np.sin(t)})
    system = r.system
    values, _ = system.outputs_rows(r.t, r.states)
    for i, (t, x) in enumerate(zip(r.t, r.states)):
        assert np.array_equal(values[i], system.outputs(t, x))
    first = r.outputs[0].data
    degrees = np.array(system.degree_columns[0])
    raw = values[:, :first.shape[1]]
    assert len(set(raw[:, r.outputs[0].labels.index("F")])) > 10
    assert np.array_equal(first, np.where(degrees, raw * 180 / np.pi, raw))


def test_rows_formatted_in_c_are_the_characters_pythons_percent_writes():
    from autolev.engine import rowtext
    rng = np.random.default_rng(7)
    mantissas = rng.uniform(1, 10, 4000) * rng.choice([-1, 1], 4000)
    exponents = rng.integers(-320, 309, 4000).astype(float)
    with np.errstate(over="ignore", under="ignore"):
        spread = mantissas * 10.0 ** exponents
    edges = [0.0, -0.0, np.inf, -np.inf, np.nan, -np.nan, 5e-324, 2.2250738585072014e-308,
             1.7976931348623157e308, 12345675.0, 1234567.5, 0.5, 9999999.5, 999999.95,
             0.99999995, 9.9999995e22, 1e22, 1e23, 1e-16, 123456789012.0, -2.5e-7,
             1 / 3, 2 / 3, np.pi * 1e5, 100.0, 1e6, 1e7]
    values = np.concatenate([spread, edges, rng.standard_normal(4000)])
    values = values[: len(values) // 9 * 9].reshape(-1, 9)
    assert rowtext._formatter() is not None
    text = rowtext.rows_text(values)
    assert text == rowtext.python_rows_text(values.tolist())
    assert text.splitlines()[0] == "".join(" " + ("%- 14.6E" % v) for v in values[0])
