"""The solve of Kane's equations M u' = f: a symmetric mass matrix factored as
M = L^T D L along its branches (Featherstone's LTDL), pivoting where it is not positive
definite, the same numbers from the Python and C back ends."""
import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.engine import clibrary
from autolev.engine.massmatrix import (
    MassStructure, SingularMassMatrix, solve_mass_matrix, symmetric)


def tree_mass_matrix(parents: list, rng) -> np.ndarray:
    """J^T J summed over the bodies of a tree (`parents[k]`: the body k hangs from,
    -1 for the root): body k moves with the speeds of its path to the root only."""
    m = len(parents)
    matrix = np.zeros((m, m))
    for body in range(m):
        jacobian = np.zeros((6, m))
        k = body
        while k >= 0:
            jacobian[:, k] = rng.normal(size=6)
            k = parents[k]
        matrix += jacobian.T @ jacobian
    return matrix


def symbols_of(matrix: np.ndarray) -> list:
    """Symbolic entries, row by row: one symbol per symmetric pair, 0 where 0."""
    m = len(matrix)
    return [sm.Symbol(f"M{min(r, s)}_{max(r, s)}") if matrix[r, s] != 0 else sm.S.Zero
            for r in range(m) for s in range(m)]


@pytest.mark.parametrize("parents, expected", [
    ([-1, 0, 1, 2, 3], (-1, 0, 1, 2, 3)),                 # a chain: every row before
    ([-1, 0, 0, 1, 1, 2, 2], (-1, 0, 0, 1, 1, 2, 2)),     # a binary tree: no fill
    ([-1, 0, 1, 0, 3, 0, 5, 6], (-1, 0, 1, 0, 3, 0, 5, 6)),   # three legs on a pelvis
])
def test_a_tree_is_factored_along_its_branches(parents, expected):
    rng = np.random.default_rng(7)
    matrix = tree_mass_matrix(parents, rng)
    structure = MassStructure.of(symbols_of(matrix), len(parents))
    assert structure.order == tuple(range(len(parents)))
    assert structure.parent == expected and structure.proven
    for _ in range(5):
        f = rng.normal(size=len(parents))
        got = solve_mass_matrix(matrix, f, 0.0, structure)
        assert np.allclose(got, np.linalg.solve(matrix, f), rtol=1e-12, atol=1e-14)


def test_a_tree_numbered_from_its_leaves_is_eliminated_in_the_other_order():
    # the pelvis-and-legs tree above with its speeds numbered in reverse
    rng = np.random.default_rng(3)
    forward = [-1, 0, 1, 0, 3, 0, 5, 6]
    m = len(forward)
    back = [m - 1 - k for k in range(m)]
    reversed_parents = [-1] * m
    for k, p in enumerate(forward):
        if p >= 0:
            reversed_parents[back[k]] = back[p]
    matrix = tree_mass_matrix(forward, rng)[np.ix_(back, back)]
    structure = MassStructure.of(symbols_of(matrix), m)
    assert structure.order == tuple(back) and structure.parent == tuple(forward)
    f = rng.normal(size=m)
    assert np.allclose(solve_mass_matrix(matrix, f, 0.0, structure),
                       np.linalg.solve(matrix, f), rtol=1e-12, atol=1e-14)


def test_structure_needs_a_symmetric_pattern_and_proves_identical_entries():
    a, b, c, d = sm.symbols("a b c d")
    assert MassStructure.of([a, b, b, c], 2).proven
    assert not MassStructure.of([a, b, d, c], 2).proven    # values must show it
    assert MassStructure.of([a, b, sm.S.Zero, c], 2) is None
    assert MassStructure.of([a], 1) is None


def test_a_matrix_not_positive_definite_is_solved_by_pivoting():
    structure = MassStructure.of(symbols_of(np.ones((3, 3))), 3)
    indefinite = np.array([[1.0, 2.0, 0.0], [2.0, 1.0, 1.0], [0.0, 1.0, 3.0]])
    f = np.array([1.0, -2.0, 0.5])
    assert np.allclose(solve_mass_matrix(indefinite, f, 0.0, structure),
                       np.linalg.solve(indefinite, f), rtol=1e-13)
    # a zero leading pivot: L^T D L cannot, pivoting can
    zero_corner = np.array([[4.0, 1.0, 2.0], [1.0, 3.0, 0.0], [2.0, 0.0, 0.0]])
    assert np.allclose(solve_mass_matrix(zero_corner, f, 0.0, structure),
                       np.linalg.solve(zero_corner, f), rtol=1e-13)
    with pytest.raises(SingularMassMatrix):
        solve_mass_matrix(np.ones((3, 3)), f, 2.5, structure)


def test_symmetry_is_judged_relative_to_the_diagonal():
    light = np.array([[1e6, 1e-3], [1e-3, 1e-8]])           # a heavy body, a light rotor
    assert symmetric(light[None])
    assert not symmetric((light + np.array([[0, 1e-9], [0, 0]]))[None])
    assert not symmetric(np.array([[[1.0, 0.0], [0.0, -1.0]]]))
    assert not symmetric(np.array([[[1.0, np.nan], [np.nan, 1.0]]]))


# A planar "Y": a link pinned in N, two links pinned at its far end.  U2 moves B only
# and U3 moves C only, so no body has both: M23 = 0, the branches' zero.
Y_MODEL = """
NEWTONIAN N
BODIES A, B, C
POINTS P
MOTIONVARIABLES' Q{3}', U{3}'
CONSTANTS L, M, G
MASS A = M, B = M, C = M
INERTIA A, 0, 0, M*L^2/12
INERTIA B, 0, 0, M*L^2/12
INERTIA C, 0, 0, M*L^2/12
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
SIMPROT(A, C, 3, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
W_A_N> = U1*N3>
W_B_A> = U2*A3>
W_C_A> = U3*A3>
P_NO_AO> = L/2*A1>
V2PTS(N, A, NO, AO)
P_NO_P> = L*A1>
V2PTS(N, A, NO, P)
P_P_BO> = L/2*B1>
V2PTS(N, B, P, BO)
P_P_CO> = L/2*C1>
V2PTS(N, C, P, CO)
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.7, M = 1.3, G = 9.81
INPUT Q1 = 0.3, Q2 = -0.8, Q3 = 1.1, U1 = 0.2, U2 = -0.4, U3 = 0.9
INPUT TFINAL = 1, INTEGSTP = 0.1
OUTPUT T, Q1, Q2, Q3
CODE DYNAMICS() y.c
"""


def y_accelerations_by_lagrange(q, u, length, mass, g) -> np.ndarray:
    """The Y's q'' from Lagrange's equations (sympy, absolute angles by hand)."""
    t = sm.Symbol("t")
    qs = [sm.Function(f"q{i}")(t) for i in (1, 2, 3)]
    angle = {"A": qs[0], "B": qs[0] + qs[1], "C": qs[0] + qs[2]}

    def e(th):
        return sm.Matrix([sm.cos(th), sm.sin(th)])
    pin = length * e(angle["A"])
    centres = {"A": length / 2 * e(angle["A"]), "B": pin + length / 2 * e(angle["B"]),
               "C": pin + length / 2 * e(angle["C"])}
    inertia = mass * length ** 2 / 12
    kinetic = sum(mass / 2 * p.diff(t).dot(p.diff(t)) + inertia / 2 * angle[b].diff(t) ** 2
                  for b, p in centres.items())
    potential = -sum(mass * g * p[0] for p in centres.values())
    lagrangian = kinetic - potential
    eqs = [sm.diff(lagrangian.diff(qi.diff(t)), t) - lagrangian.diff(qi) for qi in qs]
    acc = [qi.diff(t, 2) for qi in qs]
    mass_matrix = sm.Matrix(eqs).jacobian(acc)
    rest = sm.Matrix(eqs).subs({a: 0 for a in acc})
    values = {}
    for qi, qv, uv in zip(qs, q, u):
        values[qi.diff(t)] = uv
    for qi, qv in zip(qs, q):
        values[qi] = qv
    mm = np.array(mass_matrix.subs(values).evalf(), dtype=float)
    ff = np.array(rest.subs(values).evalf(), dtype=float).ravel()
    return np.linalg.solve(mm, -ff)


@pytest.fixture(scope="module")
def y_model(tmp_path_factory):
    path = tmp_path_factory.mktemp("y") / "y.al"
    path.write_text(Y_MODEL)
    return autolev.load(path)


def test_the_branches_of_a_tree_are_zero_and_the_solve_agrees_with_lagrange(y_model):
    # the mass matrix's solve, which a tree's run leaves for the recursion unless asked
    system = y_model.simulate(backend="python", recursion=False).system
    assert system.mass_structure.parent == (-1, 0, 0)
    col = {str(s).upper(): k for k, s in enumerate(system.states)}
    rng = np.random.default_rng(11)
    for _ in range(3):
        q, u = rng.uniform(-3, 3, 3), rng.uniform(-2, 2, 3)
        x = np.zeros(6)
        for i in range(3):
            x[col[f"Q{i + 1}"]], x[col[f"U{i + 1}"]] = q[i], u[i]
        xdot = system.derivatives(0.0, x)
        assert system.last_mass_matrix()[1, 2] == 0.0
        ours = [xdot[col[f"U{i}"]] for i in (1, 2, 3)]
        assert np.allclose(ours, y_accelerations_by_lagrange(q, u, 0.7, 1.3, 9.81),
                           rtol=1e-11, atol=1e-12)


@pytest.mark.skipif(clibrary.compiler() is None, reason="needs a C compiler")
def test_python_and_c_factor_the_same_numbers(y_model):
    in_c = y_model.simulate(recursion=False).system
    assert in_c.compiled_loop(wait=True) is not None
    python = y_model.simulate(backend="python", recursion=False).system
    assert python.rhs_function.backend == "python"
    rng = np.random.default_rng(5)
    for _ in range(20):
        x = rng.uniform(-3, 3, 6)
        assert np.array_equal(in_c.derivatives(0.0, x), python.derivatives(0.0, x))


def accelerations_by_numpy(system, x) -> np.ndarray:
    """The solved accelerations at x from the mass matrix and forcing the compiled
    right-hand side wrote, solved by numpy."""
    system.derivatives(0.0, x)
    n, ns = system._n, system.nstate
    out = system.loop.out_buffer
    return np.linalg.solve(out[ns:ns + n * n].reshape(n, n), out[ns + n * n:ns + n * n + n])


@pytest.mark.skipif(clibrary.compiler() is None, reason="needs a C compiler")
def test_a_constrained_models_symmetry_is_judged_by_its_values():
    # the rolling disc's dependent speeds make each entry a sum formed in its own order
    from helpers import load_model
    system = load_model("rolling_disc").simulate(TFINAL=0.1).system
    assert system.compiled_loop(wait=True) is not None
    assert not system.mass_structure.proven
    assert system._factoring is system.mass_structure
    rng = np.random.default_rng(2)
    for _ in range(5):
        x = rng.uniform(-1, 1, system.nstate)
        got = system.derivatives(0.0, x)[system.unknown_positions]
        assert np.allclose(got, accelerations_by_numpy(system, x), rtol=1e-12, atol=1e-14)


@pytest.mark.skipif(clibrary.compiler() is None, reason="needs a C compiler")
def test_a_zero_changed_after_kane_into_no_symmetry_is_solved_by_pivoting(tmp_path):
    # U2' added to the first row only: M12 is no longer M21
    path = tmp_path / "skew.al"
    path.write_text(Y_MODEL.replace("KANE()\n", "KANE()\nZERO[1] = ZERO[1] + M*L^2*U2'\n"))
    system = autolev.load(path).simulate().system
    assert system.compiled_loop(wait=True) is not None
    assert system.mass_structure is not None and system._factoring is None
    rng = np.random.default_rng(4)
    for _ in range(5):
        x = rng.uniform(-2, 2, 6)
        got = system.derivatives(0.0, x)[system.unknown_positions]
        mm = system.last_mass_matrix()
        assert abs(mm[0, 1] - mm[1, 0]) > 0.1
        assert np.allclose(got, accelerations_by_numpy(system, x), rtol=1e-12, atol=1e-14)
