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
    fn = sm.lambdify([*dummy, *system.params, time],
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
