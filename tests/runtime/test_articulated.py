"""The articulated-body recursion (runtime/articulated.py) solves a tree's Kane's
equations: its accelerations equal those of sympy's KanesMethod built from scratch
(tests/runtime/test_chain_equations.py's systems), loads on points and frames that no body
carries equal Kane's own Fr, and a model that is not such a tree is refused, so that
its mass matrix is solved instead (with the same rows in a run)."""
from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.runtime import articulated
from autolev.runtime.symbols import TIME
from helpers import ROOT, load_model
from helpers.mechanics import symbols, value
from test_chain_equations import chains, kanes_chain3d, kanes_planar


def recursion_and_mass_matrix(model, values: dict) -> tuple[np.ndarray, np.ndarray]:
    """(u' of the recursion, u' solved from the model's M and f) at `values`."""
    speeds = model.generalized_speeds()[0]
    rates = articulated.accelerations(model.kane_system(), speeds).rates
    ours = np.array(value(model, sm.Matrix(rates), values), dtype=float).ravel()
    mm = np.array(value(model, model.mass_matrix, values), dtype=float)
    f = np.array(value(model, model.forcing, values), dtype=float).ravel()
    return ours, np.linalg.solve(mm, f)


@pytest.mark.parametrize("kind, n", [("planar", 1), ("planar", 2), ("planar", 4),
                                     ("chain3d", 1), ("chain3d", 2)])
def test_a_chains_accelerations_are_sympys(kind, n, tmp_path):
    model = autolev.load(chains.write(kind, n, tmp_path))
    M, f, q, u, constants = {"planar": kanes_planar, "chain3d": kanes_chain3d}[kind](n)
    theirs = sm.lambdify((q, u, list(constants.values())), [M, f])
    speeds = model.generalized_speeds()[0]
    rates = sm.Matrix(articulated.accelerations(model.kane_system(), speeds).rates)
    order = [int(s.name[1:]) - 1 for s in speeds]
    rng = random.Random(f"{kind}{n}")
    for _ in range(3):
        qv = [rng.uniform(-1.0, 1.0) for _ in u]
        uv = [rng.uniform(-1.0, 1.0) for _ in u]
        cv = {name: rng.uniform(0.5, 2.0) for name in constants}
        values = {symbols(model, f"Q{i}"): v for i, v in enumerate(qv, 1)}
        values.update((symbols(model, f"U{i}"), v) for i, v in enumerate(uv, 1))
        values.update((symbols(model, name), v) for name, v in cv.items())
        ours = np.array(value(model, rates, values), dtype=float).ravel()
        mm, ff = theirs(qv, uv, list(cv.values()))
        expected = np.linalg.solve(np.asarray(mm, float), np.asarray(ff, float).ravel())
        assert np.allclose(ours, expected[order], rtol=1e-11, atol=1e-11), (ours, expected)


LOADS = """NEWTONIAN N
BODIES A, B
FRAMES F
POINTS P, E
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS L, M, K, C, G
MASS A = M, B = 2*M
INERTIA A, 0, 0, M*L^2/12
INERTIA B, 0, 0, M*L^2/6
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
SIMPROT(A, F, 3, Q2/2)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_A> = U2*A3>
W_F_A> = U2/2*A3>
P_NO_AO> = L/2*A1>
P_NO_P> = L*A1>
P_P_BO> = L/2*B1>
P_BO_E> = L/4*B2>
V2PTS(N, A, NO, AO)
V2PTS(N, A, NO, P)
V2PTS(N, B, P, BO)
V2PTS(N, B, BO, E)
GRAVITY(G*N1>)
FORCE_E> = -K*Q1*N2> + C*T*B1>
TORQUE_F> = -C*U2*N3>
TORQUE(A/B, -K*Q2*N3>)
ZERO = FR() + FRSTAR()
KANE()
"""


def test_loads_on_points_and_frames_no_body_carries_are_kanes(tmp_path):
    # E is fixed in B away from its mass centre; F turns with half of B's joint
    # angle, so its torque enters through its partial angular velocities
    path = tmp_path / "loads.al"
    path.write_text(LOADS)
    model = autolev.load(path)
    rng = random.Random(5)
    for _ in range(3):
        values = {symbols(model, name): rng.uniform(-1.0, 1.0)
                  for name in ("Q1", "Q2", "U1", "U2")}
        values[TIME] = rng.uniform(0.0, 2.0)
        values.update((symbols(model, name), rng.uniform(0.5, 2.0))
                      for name in ("L", "M", "K", "C", "G"))
        ours, expected = recursion_and_mass_matrix(model, values)
        assert np.allclose(ours, expected, rtol=1e-11, atol=1e-11)


def refusal(text: str, tmp_path) -> str:
    path = tmp_path / "model.al"
    path.write_text(text)
    model = autolev.load(path)
    with pytest.raises(articulated.NotATree) as caught:
        articulated.accelerations(model.kane_system(), model.generalized_speeds()[0])
    return str(caught.value)


PENDULUM = """NEWTONIAN N
BODIES A, B
MOTIONVARIABLES' Q1', U1'
CONSTANTS L, M
MASS A = M, B = M
INERTIA A, 0, 0, {inertia_a}
INERTIA B, 0, 0, M*L^2
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, {angle_b})
Q1' = U1
W_A_N> = U1*N3>
W_B_N> = {rate_b}*N3>
ALF_B_N> = {alf_b}*N3>
P_NO_AO> = 0>
P_NO_BO> = 0>
V_AO_N> = 0>
V_BO_N> = 0>
ZERO = FR() + FRSTAR()
KANE()
"""


def test_two_bodies_turned_by_one_speed_but_not_joined_are_refused(tmp_path):
    # B turns twice as fast as A, about the same axis: not carried by A
    text = PENDULUM.format(inertia_a="M*L^2", angle_b="2*Q1", rate_b="2*U1",
                           alf_b="2*U1'")
    assert "of B is not the one" in refusal(text, tmp_path)


def test_an_angular_acceleration_the_velocity_does_not_give_is_refused(tmp_path):
    text = PENDULUM.format(inertia_a="M*L^2", angle_b="Q1", rate_b="U1", alf_b="3*U1'")
    assert "angular acceleration of B" in refusal(text, tmp_path)


def test_a_singular_mass_matrix_stops_the_run_as_one(tmp_path):
    # no inertia about the axis: the recursion's pivot is 0, as the mass matrix's is
    text = PENDULUM.format(inertia_a="0", angle_b="Q1", rate_b="U1",
                           alf_b="U1'").replace("INERTIA B, 0, 0, M*L^2", "INERTIA B, 0, 0, 0")
    path = tmp_path / "model.al"
    path.write_text(text + "INPUT L = 1, M = 1, Q1 = 0.1, U1 = 0, TFINAL = 1\n")
    model = autolev.load(path)
    recursion = articulated.accelerations(model.kane_system(), model.generalized_speeds()[0])
    assert recursion.pivots == [0]
    for recursion in (True, False):
        result = model.simulate(recursion=recursion)
        assert "mass matrix is singular at T = 0" in result.failure


@pytest.mark.parametrize("name", ["simple_pendulum", "double_pendulum", "cart_pendulum",
                                  "mass_spring_damper", "nlink_pendulum"])
def test_particles_and_bodies_of_the_examples_are_solved_as_their_mass_matrix(name):
    # a particle turns with its parent: the cart carries its pendulum's bob, a bob the
    # next one when each link's angle is measured from N
    model = load_model(name)
    rng = random.Random(name)
    speeds = model.generalized_speeds()[0]
    for _ in range(3):
        values = {s: rng.uniform(-1.0, 1.0) for s in speeds + model.coordinates}
        ours, expected = recursion_and_mass_matrix(model, values)
        assert np.allclose(ours, expected, rtol=1e-11, atol=1e-11)


def test_a_particle_turned_by_its_parents_speed_is_refused(tmp_path):
    # P2's link turns relative to P1's: a particle has no frame to carry that turning
    text = """NEWTONIAN N
FRAMES A, B
PARTICLES P1, P2
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS L, M
MASS P1 = M, P2 = M
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_A> = U2*A3>
P_NO_P1> = L*A1>
P_P1_P2> = L*B1>
V_NO_N> = 0>
V2PTS(N, A, NO, P1)
V2PTS(N, B, P1, P2)
ZERO = FR() + FRSTAR()
KANE()
"""
    assert "velocity of P2 is not the one" in refusal(text, tmp_path)


def test_a_run_integrates_the_recursions_accelerations(tmp_path):
    # the run's system solves u' = f with f the recursion's (an identity mass matrix),
    # and its rates at a state are sympy's
    model = autolev.load(chains.write("planar", 3, tmp_path))
    result = model.simulate(TFINAL=0.2)
    system = result.system
    assert system.last_mass_matrix() is None or np.array_equal(
        system.last_mass_matrix(), np.eye(3))
    M, f, q, u, constants = kanes_planar(3)
    theirs = sm.lambdify((q, u, list(constants.values())), [M, f])
    state = np.array([0.3, -0.4, 0.5, 0.2, -0.1, 0.7])    # Q1..Q3, U1..U3
    x = np.array([state[["Q1", "Q2", "Q3", "U1", "U2", "U3"].index(s.name)]
                  for s in system.states])
    xdot = system.derivatives(0.0, x)
    mm, ff = theirs(state[:3], state[3:], [0.5, 1.0, 9.81])
    expected = np.linalg.solve(np.asarray(mm, float), np.asarray(ff, float).ravel())
    got = [xdot[[s.name for s in system.states].index(f"U{i}")] for i in (1, 2, 3)]
    assert np.allclose(got, expected, rtol=1e-12, atol=1e-12)
    assert np.allclose(system.rhs_exprs[system.nstate:system.nstate + 9],
                       np.eye(3).ravel())


def test_a_model_keeps_its_tree_of_joints_once_and_pickles_without_it(tmp_path):
    # the run's recursion and the Newton-Euler rows read one tree for the revision;
    # pickled (a study's workers, the cache of built models) the model keeps its
    # numeric systems only, whichever part (model, scene) holds the derived tables
    import pickle
    model = autolev.load(ROOT / "autolev_examples" / "nlink_pendulum.al")
    model.dynamics().explicit_jacobians(np.zeros(8))
    trees = model.derived.table("trees of joints")
    assert len(trees) == 1 and next(iter(trees.values()))[0] is not None
    back = pickle.loads(pickle.dumps(model))
    assert back.scene.derived is back.derived
    assert "trees of joints" not in back.derived._tables
    assert "numeric systems" in back.derived._tables
    assert np.array_equal(back.simulate()["Q1"], model.simulate()["Q1"])
