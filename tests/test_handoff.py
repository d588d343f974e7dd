"""No lock-in (issue 33): a model handed to sympy.physics.mechanics as frames, points,
bodies, loads and kinematical equations, with Kane's equations formed by sympy's own
KanesMethod (a second derivation, independent of ours): its rates equal our compiled
ones at random states and constants; PyDy integrates it as `simulate` does."""
import importlib.util

import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.runtime.errors import AutolevModelError
from autolev.runtime.numerics.prepare import prepare_command
from helpers import EXAMPLES

HANDED = ["simple_pendulum", "double_pendulum", "cart_pendulum", "mass_spring_damper",
          "block_pendulums", "nlink_pendulum", "euler_parameters_body"]


@pytest.mark.parametrize("name", HANDED)
def test_sympys_kanes_method_gives_our_rates(name):
    import sympy.physics.mechanics as me
    model = autolev.load(EXAMPLES / f"{name}.al")
    h = model.to_mechanics()
    assert isinstance(h.kane, me.KanesMethod)
    command = next(c for c in model.code_commands if c.kind.integrates)
    system = prepare_command(model, command).system
    time = me.dynamicsymbols._t
    x = [h.states[s] for s in system.states]            # our state order
    sympy_state = h.coordinates + h.speeds
    rates = h.kane.mass_matrix_full.LUsolve(h.kane.forcing_full)
    order = [sympy_state.index(v) for v in x]
    specified = {s: 0 for s in h.specified}
    rng = np.random.default_rng(11)
    dummy = sm.symbols(f"x0:{len(x)}")
    # constants are plain symbols of their names, as a SymPy user writes them
    params = [sm.Symbol(str(c)) for c in system.params]
    assert h.kane.forcing_full.free_symbols - {time} <= set(params)
    fn = sm.lambdify([*dummy, *params, time],
                     sm.Matrix(rates).xreplace(dict(zip(x, dummy))).xreplace(specified))
    for _ in range(5):
        p = rng.uniform(0.5, 1.5, len(system.params))
        state = rng.uniform(-1.0, 1.0, len(x))
        system.set_parameters(p)
        ours = system.derivatives(0.3, state)
        theirs = np.asarray(fn(*state, *p, 0.3), dtype=float).ravel()[order]
        assert np.allclose(theirs, ours, atol=1e-9 * max(1.0, np.abs(ours).max()))


def test_a_model_with_constrained_speeds_is_refused_with_the_way_out():
    model = autolev.load(EXAMPLES / "rolling_disc.al")
    with pytest.raises(AutolevModelError) as refused:
        model.to_mechanics()
    assert "equations level (autolev convert --to sympy" in str(refused.value)


@pytest.mark.skipif(importlib.util.find_spec("pydy") is None,
                    reason="PyDy is an optional extra (pip install pydy)")
def test_pydy_integrates_the_handed_model_as_simulate_does():
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    system = model.to_pydy(TFINAL=2)
    rows = system.integrate()
    result = model.simulate(TFINAL=2, method="dop853", RELERR=1e-10, ABSERR=1e-10)
    h = model.to_mechanics()
    ours = {name: result.states[:, k] for k, name in enumerate(result.state_names)}
    assert rows.shape == (len(result.t), 4)
    for j, state in enumerate(system.states):
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
