"""No lock-in (issue 33): a model handed to sympy.physics.mechanics as frames, points,
bodies, loads and kinematical equations, with Kane's equations formed by sympy's own
KanesMethod (a second derivation, independent of ours): its rates equal our compiled
ones at random states and constants; PyDy integrates it as `simulate` does."""
import importlib.util

import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.export_mechanics import export_sympy
from autolev.engine.errors import AutolevModelError
from autolev.runtime.numerics.prepare import prepare_command
from helpers import EXAMPLES

# fourbar has dependent and auxiliary speeds, rolling_disc dependent ones
HANDED = ["simple_pendulum", "double_pendulum", "cart_pendulum", "mass_spring_damper",
          "block_pendulums", "nlink_pendulum", "euler_parameters_body", "fourbar",
          "rolling_disc"]


@pytest.mark.parametrize("name", HANDED)
def test_sympys_kanes_method_gives_our_rates(name):
    import sympy.physics.mechanics as me
    model = autolev.load(EXAMPLES / f"{name}.al")
    h = model.to_mechanics()
    assert isinstance(h.kane, me.KanesMethod)
    command = next(c for c in model.code_commands if c.kind.integrates)
    system = prepare_command(model.snapshot_for(command), command).system
    time = me.dynamicsymbols._t
    x = [h.states[s] for s in system.states]            # our state order
    sympy_state = h.coordinates + h.speeds + h.dependent
    assert [u.name for u in model.dependent_speeds] == [str(u.func) for u in h.dependent]
    # sympy's velocity constraints read the auxiliary speeds, zero in motion
    full = [m.xreplace({u.diff(time): 0 for u in h.auxiliary}).xreplace(
        dict.fromkeys(h.auxiliary, 0)) for m in (h.kane.mass_matrix_full, h.kane.forcing_full)]
    order = [sympy_state.index(v) for v in x]
    specified = {s: 0 for s in h.specified}
    rng = np.random.default_rng(11)
    dummy = sm.symbols(f"x0:{len(sympy_state)}")
    # constants are plain symbols of their names, as a SymPy user writes them
    params = [sm.Symbol(str(c)) for c in system.params]
    assert full[1].free_symbols - {time} <= set(params)
    fn = sm.lambdify([dummy, params, time],
                     [m.xreplace(dict(zip(sympy_state, dummy))).xreplace(specified)
                      for m in full])
    for _ in range(5):
        p = rng.uniform(0.5, 1.5, len(system.params))
        state = rng.uniform(-1.0, 1.0, len(x))
        system.set_parameters(p)
        ours = system.derivatives(0.3, state)
        at = dict(zip(x, state)) | dict(zip(params, p)) | specified | {time: 0.3}
        # the dependent speeds where the constraints hold, as our run computes them
        held = h.dependent_speeds_at(at)
        values = dict(zip(x, state)) | held
        mass, forcing = fn([values[v] for v in sympy_state], p, 0.3)
        theirs = np.linalg.solve(mass, np.asarray(forcing, dtype=float).ravel())[order]
        assert np.allclose(theirs, ours, atol=1e-9 * max(1.0, np.abs(ours).max()))


def test_the_dependent_speeds_are_sympys_with_the_models_velocity_constraints():
    model = autolev.load(EXAMPLES / "fourbar.al")
    h = model.to_mechanics()
    assert [str(u.func) for u in h.dependent] == ["U2", "U3"]
    assert [str(u.func) for u in h.auxiliary] == ["UA1", "UA2"]
    assert [str(f.func) for f in h.unknowns] == ["F1", "F2"]
    # CONSTRAIN(DEPENDENT[U2, U3]) of the closing point P5: by hand, its velocity in N
    q1, q2, q3 = h.coordinates
    u1, (u2, u3), (ua1, ua2) = h.speeds[0], h.dependent, h.auxiliary
    l2, l3, l4 = sm.symbols("L2 L3 L4")
    x = l2 * sm.cos(q1) + l3 * sm.cos(q1 + q2) + l4 * sm.cos(q1 + q2 + q3)
    y = l2 * sm.sin(q1) + l3 * sm.sin(q1 + q2) + l4 * sm.sin(q1 + q2 + q3)
    time = q1.args[0]
    by_hand = [x.diff(time) + ua1, y.diff(time) + ua2]
    rates = {q.diff(time): u for q, u in zip(h.coordinates, (u1, u2, u3))}
    for ours, theirs in zip(h.velocity_constraints, by_hand):
        assert sm.simplify(ours - theirs.subs(rates)) == 0


def test_an_auxiliary_speed_not_zero_in_motion_is_refused(tmp_path):
    path = tmp_path / "aux.al"
    path.write_text("NEWTONIAN N\nPARTICLES P\nMOTIONVARIABLES' Q', U', UA'\nCONSTANTS M\n"
                    "MASS P = M\nQ' = U\nV_P_N> = (U + UA)*N1>\nAUXILIARY[1] = UA - U\n"
                    "CONSTRAIN(AUXILIARY[UA])\nVARIABLES R\nFORCE_P> = R*N1>\n"
                    "ZERO = FR() + FRSTAR()\nKANE(R)\n")
    model = autolev.load(path)
    with pytest.raises(AutolevModelError, match="the auxiliary speed UA is U in motion"):
        model.to_mechanics()


@pytest.mark.skipif(importlib.util.find_spec("pydy") is None,
                    reason="PyDy is an optional extra (pip install pydy)")
@pytest.mark.parametrize("name, tfinal", [("double_pendulum", 2), ("fourbar", 0.5),
                                          ("rolling_disc", 1)])
def test_pydy_integrates_the_handed_model_as_simulate_does(name, tfinal):
    # fourbar: PyDy integrates the dependent speeds too, from where the constraints hold
    model = autolev.load(EXAMPLES / f"{name}.al")
    system = model.to_pydy(TFINAL=tfinal)
    rows = system.integrate()
    result = model.simulate(TFINAL=tfinal, method="dop853", RELERR=1e-10, ABSERR=1e-10)
    h = model.to_mechanics()
    ours = {name: result.states[:, k] for k, name in enumerate(result.state_names)}
    assert rows.shape == (len(result.t), len(result.state_names) + len(h.dependent))
    for j, state in enumerate(system.states[:len(result.state_names)]):
        ours_name = next(str(s) for s, v in h.states.items() if v == state)
        assert np.allclose(rows[:, j], ours[ours_name], atol=1e-5), ours_name


INCLINE = """NEWTONIAN N
FRAMES P
PARTICLES B
MOTIONVARIABLES' X''
CONSTANTS THETA, G, M
SIMPROT(N, P, 3, THETA)
P_NO_B> = X*P1>
V_B_N> = DT(P_NO_B>, N)
MASS B = M
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT THETA = 30 DEG, G = 9.81, M = 2
CODE DYNAMICS() incline.c
"""


def test_a_constant_in_an_orientation_is_the_same_plain_symbol_everywhere(tmp_path):
    # a block sliding down a plane tilted by THETA: by hand, X'' = -G sin(THETA)
    path = tmp_path / "incline.al"
    path.write_text(INCLINE)
    h = autolev.load(path).to_mechanics()
    theta, g = sm.Symbol("THETA"), sm.Symbol("G")
    rates = h.kane.mass_matrix_full.LUsolve(h.kane.forcing_full)
    assert sm.simplify(rates[1] + g * sm.sin(theta)) == 0
    assert {s.name for s in rates.free_symbols} == {"THETA", "G", "t"}   # M cancels


def test_a_frame_goes_over_turned_the_way_the_model_turns_it(tmp_path):
    # SIMPROT(N, A, 3, Q): by the right-hand rule A1> = cos(Q) N1> + sin(Q) N2>
    path = tmp_path / "turned.al"
    path.write_text("NEWTONIAN N\nFRAMES A\nVARIABLES Q\nSIMPROT(N, A, 3, Q)\n")
    model = autolev.load(path)
    a = model.to_sympy(model.entity("A").unit(1))
    n = model.entity("N").to_sympy()
    q = sm.Function("Q")(sm.Symbol("t"))
    assert sm.simplify(a.dot(n.x) - sm.cos(q)) == 0
    assert sm.simplify(a.dot(n.y) - sm.sin(q)) == 0


def test_an_inertia_in_a_frame_not_oriented_in_n_is_named_once(tmp_path):
    # the message said "frame A or A" for a body's own inertia
    path = tmp_path / "spin.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' U'\nW_A_N> = U*A3>\n"
                    "V_AO_N> = 0>\nMASS A = 1\nINERTIA A, 1, 1, 2\n"
                    "ZERO = FR() + FRSTAR()\nKANE()\n")
    model = autolev.load(path)
    with pytest.raises(AutolevModelError) as caught:
        model.to_mechanics()
    assert str(caught.value) == ("an inertia is given in frame A, not oriented in the "
                                 "Newtonian frame")


def test_a_sympy_users_symbol_reaches_the_models_constant_everywhere():
    # symbolic_system() kept the model's own real=True symbols: sm.Symbol('G') and
    # subs silently did nothing there, though to_mechanics() took plain symbols
    model = autolev.load(EXAMPLES / "simple_pendulum.al")
    g, m, length = sm.symbols("G M L")
    theta = sm.Function("THETA")(sm.Symbol("t"))
    system = model.symbolic_system("combined")
    rate = system.comb_implicit_mat.LUsolve(system.comb_implicit_rhs)[1]
    assert sm.simplify(rate + g / length * sm.sin(theta)) == 0          # by hand
    assert sm.simplify(rate.subs(g, 0)) == 0
    assert {g, length} <= rate.free_symbols
    # the model's own symbols (model["G"]) go over as the user's
    weight = model.to_sympy(model["M"] * model["G"] * model["L"])
    assert weight == m * g * length and weight.subs({m: 2, g: 3, length: 5}) == 30
    assert {s for s in model.to_mechanics().kane.forcing_full.free_symbols
            if not s.name == "t"} <= {g, m, length}


def test_a_variable_nothing_defines_is_a_constant_as_in_the_run(tmp_path):
    # VARIABLES O with INPUT O = 2 and no definition: the run takes it as a constant (as
    # sympy's test mass_spring_damper.al does); handed over as O(t), sympy's equations
    # had a function of time the run does not have
    path = tmp_path / "push.al"
    path.write_text("NEWTONIAN N\nPARTICLES P\nMOTIONVARIABLES' X', V'\nVARIABLES O\n"
                    "CONSTANTS M\nMASS P = M\nV_P_N> = V*N1>\nX' = V\n"
                    "FORCE_P> = O*SIN(T)*N1>\nZERO = FR() + FRSTAR()\nKANE()\n"
                    "INPUT M = 2, O = 3, X = 0, V = 0\nCODE DYNAMICS() push.c\n")
    model = autolev.load(path)
    h = model.to_mechanics()
    o = sm.Symbol("O")
    assert o in h.constants
    time = h.coordinates[0].args[0]
    # by hand: M V' = O sin(t)
    assert sm.simplify(h.kane.forcing_full[1] - o * sm.sin(time)) == 0
    text = export_sympy(model, "push.al")
    assert "\nLevel: mechanics." in text and "O = sm.Symbol('O')" in text


def test_kinematical_equations_not_linear_in_the_speeds_are_refused_by_name(tmp_path):
    # sympy's KanesMethod raised its own ValueError (SSOpt's CellSimplifiedModV4)
    path = tmp_path / "square.al"
    path.write_text("NEWTONIAN N\nPARTICLES P\nMOTIONVARIABLES' Q', U'\nCONSTANTS M\n"
                    "MASS P = M\nQ' = U^2\nV_P_N> = Q'*N1>\nZERO = FR() + FRSTAR()\nKANE()\n")
    model = autolev.load(path)
    with pytest.raises(AutolevModelError, match="the kinematical equation of Q' is not "
                                                "linear in the speeds"):
        model.to_mechanics()


@pytest.mark.skipif(importlib.util.find_spec("pydy") is None,
                    reason="PyDy is an optional extra (pip install pydy)")
@pytest.mark.parametrize("given, message", [
    (dict(TFINAL=-5), "must have the sign of TFINAL - TINITIAL"),
    (dict(INTEGSTP=0), "INTEGSTP must be a nonzero number"),
    (dict(INTEGSTP=1e-300), "too small to advance the time"),
])
def test_to_pydy_refuses_the_integration_a_run_refuses(given, message):
    # it took TFINAL = -5 and raised a raw ZeroDivisionError or MemoryError for these
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    with pytest.raises(AutolevModelError, match=message):
        model.to_pydy(**given)


@pytest.mark.skipif(importlib.util.find_spec("pydy") is None,
                    reason="PyDy is an optional extra (pip install pydy)")
def test_to_pydy_times_are_the_runs_printed_times():
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    system = model.to_pydy(TFINAL=1, PRINTINT=3)
    result = model.simulate(TFINAL=1, PRINTINT=3)
    assert np.array_equal(np.asarray(system.times), result.t)
