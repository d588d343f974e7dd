"""Model.dynamics: the explicit and implicit equations of motion with exact sparse
Jacobians, against a pendulum worked by hand, central finite differences on every
shipped example, and sympy's own derivatives of the mass matrix and forcing."""
import math

import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.engine.errors import AutolevModelError
from helpers import EXAMPLES, ROOT
from helpers.differences import agrees, assert_same_jacobians, central
from helpers.models import PENDULUM


@pytest.fixture
def pendulum(tmp_path):
    path = tmp_path / "pendulum.al"
    path.write_text(PENDULUM)
    return autolev.load(path).dynamics()


def test_the_pendulum_by_hand(pendulum):
    # M L^2 U' = TQ - M G L sin(Q), Q' = U; G, L, M = 9.81, 2, 3 from INPUT
    g, L, m = 9.81, 2.0, 3.0
    q, u, tq, qd, ud = 0.3, -0.2, 0.7, 0.1, 0.5
    assert (pendulum.states, pendulum.controls, pendulum.parameters) == (
        ["Q", "U"], ["TQ"], ["G", "L", "M"])
    accel = (tq - m * g * L * math.sin(q)) / (m * L ** 2)
    assert np.allclose(pendulum.explicit([q, u], [tq]), [[u, accel]], rtol=1e-14)
    r = pendulum.residual([q, u], [qd, ud], [tq])
    assert np.allclose(r, [[qd - u, m * L ** 2 * ud - tq + m * g * L * math.sin(q)]],
                       rtol=1e-14)
    assert np.allclose(pendulum.mass_matrix([q, u], [tq]), [[[m * L ** 2]]], rtol=1e-14)
    jac = pendulum.residual_jacobians([q, u], [qd, ud], [tq])
    assert np.allclose(jac.dense("x")[0], [[0, -1], [m * g * L * math.cos(q), 0]])
    assert np.allclose(jac.dense("xdot")[0], [[1, 0], [0, m * L ** 2]])
    assert np.allclose(jac.dense("u")[0], [[0], [-1]])
    assert np.allclose(jac.dense("p")[0], [[0, 0, 0], [
        m * L * math.sin(q), 2 * m * L * ud + m * g * math.sin(q),
        L ** 2 * ud + g * L * math.sin(q)]])
    # sparse: Q's row depends on U alone, and nothing on p
    assert jac.patterns["p"].nnz == 3 and jac.patterns["x"].nnz == 2


def test_nodes_in_one_call_are_each_nodes_answer(pendulum):
    rng = np.random.default_rng(3)
    x, u, t = rng.normal(size=(6, 2)), rng.normal(size=(6, 1)), rng.uniform(size=6)
    together = pendulum.explicit_jacobians(x, u, t=t).values["x"]
    apart = [pendulum.explicit_jacobians(x[k], u[k], t=t[k]).values["x"][0] for k in range(6)]
    assert np.array_equal(together, np.array(apart))


@pytest.mark.parametrize("model", sorted(EXAMPLES.glob("*.al")), ids=lambda p: p.stem)
def test_jacobians_are_central_differences_on_every_example(model):
    dynamics = autolev.load(model).dynamics()
    rng = np.random.default_rng(7)
    nx, nu = len(dynamics.states), len(dynamics.controls)
    x, u = 0.5 * rng.normal(size=(3, nx)), rng.normal(size=(3, nu))
    p = dynamics.parameter_values * rng.uniform(0.8, 1.2, size=len(dynamics.parameters))
    t = rng.uniform(size=3)
    xdot = dynamics.explicit(x, u, p, t)
    assert np.allclose(dynamics.residual(x, xdot, u, p, t), 0,
                       atol=1e-9 * max(1.0, np.abs(xdot).max()))
    explicit = dynamics.explicit_jacobians(x, u, p, t)
    implicit = dynamics.residual_jacobians(x, xdot, u, p, t)
    arrays = dict(x=x, u=u, p=p, t=t)

    def f(x, u, p, t):
        return dynamics.explicit(x, u, p, t)

    def r(x, u, p, t, xdot=xdot):
        return dynamics.residual(x, xdot, u, p, t)
    for block in ("x", "u", "p"):
        if arrays[block].shape[-1]:
            assert agrees(explicit.dense(block), central(f, arrays, block)), block
            assert agrees(implicit.dense(block), central(r, arrays, block)), block
    by_rates = central(lambda xdot: dynamics.residual(x, xdot, u, p, t), {"xdot": xdot},
                        "xdot")
    assert agrees(implicit.dense("xdot"), by_rates)


def test_sympys_derivatives_of_the_mass_matrix_and_forcing():
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    dynamics = model.dynamics()
    # a second differentiation: sympy's own, of the model's M and F as expressions
    expand = model.defs.explicit                # the Z's written out
    mass, forcing = model.mass_matrix.applyfunc(expand), model.forcing.applyfunc(expand)
    names = {str(s): s for s in (mass.free_symbols | forcing.free_symbols)}
    states = [names.get(n, sm.Symbol(n)) for n in dynamics.states]
    params = [names.get(n, sm.Symbol(n)) for n in dynamics.parameters]
    speeds = [s for s in states if str(s).startswith("U")]
    rates = sm.Matrix(sm.symbols(f"a1:{len(speeds) + 1}"))
    residual = mass * rates - forcing
    point = dict(zip(states, [0.4, -0.3, 0.8, 1.1]))
    point.update(zip(params, dynamics.parameter_values))
    point.update(zip(rates, [0.2, -0.5]))
    jac = dynamics.residual_jacobians([[point[s] for s in states]],
                                      [[0.8, 1.1, 0.2, -0.5]])
    rows = [dynamics.states.index(str(s)) for s in speeds]
    by_sympy = np.array(residual.jacobian(states).subs(point), dtype=float)
    assert np.allclose(jac.dense("x")[0][rows], by_sympy, rtol=1e-12, atol=1e-12)
    by_sympy_p = np.array(residual.jacobian(params).subs(point), dtype=float)
    assert np.allclose(jac.dense("p")[0][rows], by_sympy_p, rtol=1e-12, atol=1e-12)


TREES = ["cart_pendulum", "double_pendulum", "mass_spring_damper", "nlink_pendulum",
         "simple_pendulum"]


def both_routes(name: str, seed: int) -> tuple:
    """(the example's Dynamics by its tree's recursions, by Kane's M and F, the random
    generator, five random states drawn from it)."""
    model = autolev.load(EXAMPLES / f"{name}.al")
    tree, mass = model.dynamics(), model.dynamics(recursion=False)
    rng = np.random.default_rng(seed)
    return tree, mass, rng, 0.7 * rng.normal(size=(5, len(tree.states)))


@pytest.mark.parametrize("name", TREES)
def test_a_trees_jacobians_by_its_recursion_are_those_of_the_mass_matrix(name):
    # two derivations of f's Jacobians, each -M^-1 times the Jacobian of M a - F: formed
    # by the Newton-Euler recursion and solved in the program, or as Kane's equations
    # form M and F and solved by numpy at each node
    tree, mass, rng, x = both_routes(name, 29)
    u = rng.normal(size=(5, len(tree.controls)))
    for parameters in (True, False):
        by_tree = tree.explicit_jacobians(x, u, parameters=parameters)
        by_mass = mass.explicit_jacobians(x, u, parameters=parameters)
        assert (by_tree.by, by_mass.by) == ("recursion", "mass matrix")
        assert_same_jacobians(by_tree, by_mass, 1e-11)


@pytest.mark.parametrize("name", TREES)
def test_a_trees_residual_jacobians_by_newton_euler_are_those_of_kanes_m_and_f(name):
    # two derivations of r's Jacobians: the rows M a - F by the Newton-Euler recursion
    # over the tree, and M and F as Kane's equations form them (x': M's entries)
    tree, mass, rng, x = both_routes(name, 31)
    xdot = rng.normal(size=x.shape)
    u = rng.normal(size=(5, len(tree.controls)))
    for parameters in (True, False):
        by_tree = tree.residual_jacobians(x, xdot, u, parameters=parameters)
        by_mass = mass.residual_jacobians(x, xdot, u, parameters=parameters)
        assert (by_tree.by, by_mass.by) == ("recursion", "mass matrix")
        assert set(by_tree.values) == set(by_mass.values)
        assert_same_jacobians(by_tree, by_mass, 1e-12)


@pytest.mark.parametrize("first", ["explicit", "explicit without p", "residual without p"])
def test_a_trees_jacobians_are_the_same_numbers_whichever_is_asked_for_first(first):
    # each Z's name depends on what was formed before it, and a generated sum's order on
    # the names: the tree's Jacobians are formed together, in one order, whatever comes first
    rng = np.random.default_rng(37)
    asked = {}
    for order in ("residual", first):
        dynamics = autolev.load(EXAMPLES / "nlink_pendulum.al").dynamics()
        x = rng.normal(size=(3, len(dynamics.states))) if not asked else asked["x"]
        xdot = rng.normal(size=x.shape) if not asked else asked["xdot"]
        if order != "residual":
            getattr(dynamics, f"{order.split()[0]}_jacobians")(
                *((x, xdot) if order.startswith("residual") else (x,)),
                parameters="without p" not in order)
        got = {"r": dynamics.residual_jacobians(x, xdot), "f": dynamics.explicit_jacobians(x)}
        if asked:
            for form, jac in got.items():
                assert jac.by == "recursion"
                for block in jac.values:
                    assert np.array_equal(jac.values[block], asked[form].values[block]), \
                        (form, block)
        asked = got | {"x": x, "xdot": xdot}


@pytest.mark.parametrize("parents", [[-1, 0, 1, 2, 3, 4], [-1, 0, 0, 1, 1, 2, 5, -1, 7]])
def test_the_solve_of_a_trees_mass_matrix_is_numpys(parents):
    # M's nonzeros where one speed's joint is the other's ancestor, eliminated from the
    # leaves (as a tree's Jacobian program is) and from the root (a chain fills in
    # nothing either way; the branched tree fills in): M^-1 B at three nodes as numpy
    # solves it, by ltdl.c and by its numpy twin, the same bits; a node whose M is not
    # positive definite is named
    import ctypes
    from autolev.engine import clibrary
    from autolev.engine.massmatrix import (LTDL_SOURCE, CompactRows, MassStructure,
                                           compiled_ltdl_columns, ltdl_columns)
    n, nodes, w = len(parents), 3, 35      # w: two of ltdl.c's blocks and a rest

    def ancestors(i):
        return {i} | (ancestors(parents[i]) if parents[i] >= 0 else set())
    rng = np.random.default_rng(41)
    masses, rhs = [], rng.normal(size=(nodes, n, w))
    for _ in range(nodes):
        columns = [np.array([rng.normal() if k in ancestors(i) else 0.0 for k in range(n)])
                   for i in range(n)]
        masses.append(sum(np.outer(c, c) for c in columns) + np.eye(n))
    nonzero = [[j for j in range(n) if j != k and masses[0][k, j]] for k in range(n)]
    leaves_last = sorted(range(n), key=lambda i: len(ancestors(i)))
    # linked in as a tree's Jacobian program links it (at -O3: its loops vectorized)
    lib = (ctypes.CDLL(str(clibrary.build_shared_library("", shared_source=LTDL_SOURCE)))
           if clibrary.compiler() else None)
    for order in (leaves_last, list(range(n))[::-1]):
        structure = MassStructure.eliminated(nonzero, order)
        compact = [[mass[structure.order[k], structure.order[j]]
                    for k, j in zip(structure.rows, structure.columns)] for mass in masses]
        rows = np.hstack([np.array(compact), rhs[:, structure.order].reshape(nodes, -1)])
        args = (0, len(compact[0]), n, w, CompactRows.of(structure))
        twin = rows.copy()
        assert ltdl_columns(twin, *args) == 0
        got = np.empty((nodes, n, w))
        got[:, structure.order] = twin[:, args[1]:].reshape(nodes, n, w)
        assert np.allclose(got, np.linalg.solve(np.array(masses), rhs), rtol=1e-13,
                           atol=1e-13)
        if lib is not None:
            compiled = rows.copy()
            assert compiled_ltdl_columns(lib, compiled, *args) == 0
            assert np.array_equal(compiled, twin)
        rows[1, 0] = -1.0                       # the second node's first pivot
        assert ltdl_columns(rows.copy(), *args) == 2
        if lib is not None:
            assert compiled_ltdl_columns(lib, rows.copy(), *args) == 2


def test_a_trees_singular_mass_matrix_is_named_by_both_derivations():
    model = autolev.load(EXAMPLES / "simple_pendulum.al")
    for dynamics in (model.dynamics(), model.dynamics(recursion=False)):
        massless = np.where(np.array(dynamics.parameters) == "M", 0.0,
                            dynamics.parameter_values)
        with pytest.raises(AutolevModelError, match="mass matrix is singular at a node"):
            dynamics.explicit_jacobians([[0.3, 0.1]], p=massless)


def test_the_python_tier_gives_the_c_tiers_numbers(tmp_path):
    from autolev.engine import clibrary
    if clibrary.compiler() is None:
        pytest.skip("no C compiler: one tier")
    model = autolev.load(EXAMPLES / "block_pendulums.al")
    c, python = model.dynamics(), model.dynamics(backend="python")
    assert (c.backend, python.backend) == ("c", "python")
    rng = np.random.default_rng(5)
    x, u = rng.normal(size=(4, len(c.states))), rng.normal(size=(4, len(c.controls)))
    a, b = c.explicit_jacobians(x, u), python.explicit_jacobians(x, u)
    for block in ("x", "u", "p"):
        assert np.allclose(a.values[block], b.values[block], rtol=1e-12, atol=1e-12)


def test_controls_are_named_and_the_others_held_at_zero(tmp_path):
    model = autolev.load(EXAMPLES / "block_pendulums.al")
    both = model.dynamics()
    assert both.controls == ["F", "TQ"]
    one = model.dynamics(controls=["tq"])
    x = np.full((1, len(one.states)), 0.2)
    assert one.controls == ["TQ"]
    assert np.array_equal(one.explicit(x, [[0.5]]), both.explicit(x, [[0.0, 0.5]]))
    with pytest.raises(AutolevModelError, match="'Q1' is not a specified quantity"):
        model.dynamics(controls=["Q1"])


def test_arrays_of_the_wrong_size_are_named(pendulum):
    with pytest.raises(ValueError, match=r"x: 2 states per node \(Q, U\), not 3"):
        pendulum.explicit(np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"p: 3 parameters \(G, L, M\)"):
        pendulum.explicit(np.zeros((4, 2)), p=[1.0])


@pytest.mark.parametrize("model", sorted(EXAMPLES.glob("*.al")), ids=lambda p: p.stem)
def test_the_casadi_form_is_the_same_equations_and_derivatives(model):
    ca = pytest.importorskip("casadi", reason="the CasADi form needs casadi (an extra)")
    dynamics = autolev.load(model).dynamics()
    form = dynamics.casadi()
    rng = np.random.default_rng(11)
    nx, nu, npar = len(dynamics.states), len(dynamics.controls), len(dynamics.parameters)
    x, u = 0.5 * rng.normal(size=nx), rng.normal(size=nu)
    p, t = dynamics.parameter_values, 0.4
    xdot = dynamics.explicit(x, u, p, t)[0] + 0.1
    # their M a = F solved by CasADi's QR, ours by LU: apart by the solves' rounding
    rates = dynamics.explicit(x, u, p, t)[0]
    assert np.allclose(np.array(form.f(x, u, p, t)).ravel(), rates, rtol=0,
                       atol=1e-10 * max(1.0, np.abs(rates).max()))
    # CasADi's own derivatives of its graph against ours
    X, XD, U, P = (ca.SX.sym(name, size) for name, size in
                   (("x", nx), ("xdot", nx), ("u", nu), ("p", npar)))
    r = form.residual(X, XD, U, P, t)
    blocks = ca.Function("blocks", [X, XD, U, P], [ca.jacobian(r, X), ca.jacobian(r, XD),
                                                  ca.jacobian(r, U), ca.jacobian(r, P)])
    ours = dynamics.residual_jacobians(x, xdot, u, p, t)
    for block, theirs in zip(("x", "xdot", "u", "p"), blocks(x, xdot, u, p)):
        scale = max(1.0, np.abs(ours.dense(block)).max(initial=0.0))
        assert np.allclose(np.array(theirs), ours.dense(block)[0], rtol=0,
                           atol=1e-12 * scale), block


def test_a_parameter_named_as_a_control_varies_from_node_to_node():
    model = autolev.load(EXAMPLES / "block_pendulums.al")
    fixed = model.dynamics()
    k = fixed.parameters.index("K")
    varying = model.dynamics(controls=["F", "TQ", "K"])
    assert varying.controls == ["F", "TQ", "K"] and "K" not in varying.parameters
    rng = np.random.default_rng(13)
    x, u = rng.normal(size=(3, len(fixed.states))), rng.normal(size=(3, 2))
    with_k = np.column_stack([u, np.full(3, fixed.parameter_values[k])])
    assert np.allclose(varying.explicit(x, with_k), fixed.explicit(x, u), rtol=1e-14)
    # d/dK as a control is d/dK as a parameter
    assert np.allclose(varying.explicit_jacobians(x, with_k).dense("u")[:, :, 2],
                       fixed.explicit_jacobians(x, u).dense("p")[:, :, k], rtol=1e-14)
    other = with_k.copy()
    other[1, 2] *= 2                                   # another K at the second node only
    moved = varying.explicit(x, other) != varying.explicit(x, with_k)
    assert not moved[0].any() and moved[1].any() and not moved[2].any()


@pytest.mark.parametrize("form", ["residual", "explicit"])
def test_jacobians_without_the_parameters_columns_are_the_same_numbers(form):
    model = autolev.load(EXAMPLES / "block_pendulums.al")
    dynamics = model.dynamics()
    rng = np.random.default_rng(23)
    x = rng.normal(size=(4, len(dynamics.states)))
    u = rng.normal(size=(4, len(dynamics.controls)))
    args = (x, rng.normal(size=x.shape), u) if form == "residual" else (x, u)
    full = getattr(dynamics, f"{form}_jacobians")(*args)
    fixed = getattr(dynamics, f"{form}_jacobians")(*args, parameters=False)
    assert "p" in full.values and "p" not in fixed.values and full.patterns["p"].nnz
    for block in fixed.values:
        assert np.array_equal(fixed.dense(block), full.dense(block)), block


def test_a_control_needs_no_value(tmp_path):
    # gait2d declares its joint moments VARIABLES with no value, for the optimizer to
    # choose: naming them controls is their value, node by node
    path = tmp_path / "moment.al"
    path.write_text(PENDULUM.replace("SPECIFIED TQ", "VARIABLES TQ"))
    model = autolev.load(path)
    with pytest.raises(AutolevModelError, match="TQ"):
        model.dynamics()
    dynamics = model.dynamics(controls=["TQ"])
    g, L, m = 9.81, 2.0, 3.0
    assert dynamics.controls == ["TQ"] and "TQ" not in dynamics.parameters
    assert np.allclose(dynamics.explicit([0.3, -0.2], [0.7]),
                       [[-0.2, (0.7 - m * g * L * math.sin(0.3)) / (m * L ** 2)]], rtol=1e-14)
    # opty's form: TQ a trajectory of its own, not a known parameter
    parts = model.to_opty(controls=["TQ"])
    (tq,) = parts.controls
    assert str(tq.func) == "TQ" and tq.args == (parts.time,)
    assert all(str(c) != "TQ" for c in parts.parameters)
    q, u = parts.states
    at = {q: 0.3, u: -0.2, tq: 0.7, q.diff(parts.time): -0.2,
          u.diff(parts.time): (0.7 - m * g * L * math.sin(0.3)) / (m * L ** 2)}
    on_motion = parts.equations_of_motion.xreplace(parts.parameters).xreplace(at)
    assert np.allclose(np.array(on_motion, dtype=float), 0, atol=1e-12)


@pytest.mark.parametrize("name", ["block_pendulums", "double_pendulum", "nlink_pendulum"])
def test_the_opty_equations_hold_on_the_motion_of_the_dynamics(name):
    # opty's form comes from sympy's own KanesMethod: a second derivation of the motion
    model = autolev.load(EXAMPLES / f"{name}.al")
    parts, dynamics = model.to_opty(), model.dynamics()
    rng = np.random.default_rng(17)
    x, u = 0.5 * rng.normal(size=len(dynamics.states)), rng.normal(size=len(dynamics.controls))
    rates = dynamics.explicit(x, u)[0]
    by_name = {str(s.func): s for s in parts.states + parts.controls}
    point = {by_name[n]: v for n, v in zip(dynamics.states, x)}
    point |= {by_name[n]: v for n, v in zip(dynamics.controls, u)}
    point |= parts.parameters
    derivatives = {by_name[n].diff(parts.time): v for n, v in zip(dynamics.states, rates)}
    eom = parts.equations_of_motion
    on_motion = np.array(eom.xreplace(derivatives).xreplace(point), dtype=float)
    assert np.allclose(on_motion, 0, atol=1e-10 * max(1.0, np.abs(rates).max()))
    off = {d: v + 0.1 for d, v in derivatives.items()}
    assert np.abs(np.array(eom.xreplace(off).xreplace(point), dtype=float)).max() > 1e-3


def test_opty_is_refused_a_model_with_dependent_speeds():
    with pytest.raises(AutolevModelError, match="dependent or auxiliary speeds"):
        autolev.load(EXAMPLES / "fourbar.al").to_opty()


def test_a_planar_chains_jacobians_are_pinocchios_aba_derivatives(tmp_path):
    # a third derivation: Pinocchio's analytical derivatives of its articulated-body
    # algorithm, on the same chain built from its own joints and inertias
    pin = pytest.importorskip("pinocchio", reason="Pinocchio is the bench extra's anchor")
    import sys
    sys.path.insert(0, str(ROOT / "bench"))
    import chains
    n = 5
    path = tmp_path / "planar.al"
    path.write_text(chains.planar(n))
    dynamics = autolev.load(path).dynamics()
    model = chains.planar_pinocchio(pin, n)
    data = model.createData()
    rng = np.random.default_rng(19)
    x = rng.normal(size=len(dynamics.states))
    q = [dynamics.states.index(f"Q{i}") for i in range(1, n + 1)]
    u = [dynamics.states.index(f"U{i}") for i in range(1, n + 1)]
    pin.computeABADerivatives(model, data, x[q], x[u], np.zeros(n))
    ours = dynamics.explicit_jacobians(x).dense("x")[0]
    assert np.allclose(dynamics.explicit(x)[0][u], data.ddq, rtol=1e-12, atol=1e-12)
    assert np.allclose(ours[np.ix_(u, q)], data.ddq_dq, rtol=1e-11, atol=1e-11)
    assert np.allclose(ours[np.ix_(u, u)], data.ddq_dv, rtol=1e-11, atol=1e-11)
