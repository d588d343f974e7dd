"""bench/oracle.py's fixed-seed handful: random models written both as Autolev text and as
sympy.physics.mechanics built directly from the same description must give the same state
derivatives (and KANE's unknowns); the comparison is shown to fail on a wrong answer and a
case over its time limit to be a timeout; and the smallest model of issue 49 item 9 (an
auxiliary constraint on a speed the motion has) agrees with the oracle."""
import importlib.util
import re
import sys

import pytest

from helpers import ROOT
from helpers.differences import assert_same_jacobians

spec = importlib.util.spec_from_file_location("oracle", ROOT / "bench" / "oracle.py")
oracle = importlib.util.module_from_spec(spec)
sys.modules["oracle"] = oracle          # its dataclasses look their module up there
spec.loader.exec_module(oracle)
models = oracle.models

SEED = 11
# two or more per family, each a few seconds at most: SIMPROT about axes and vectors, W
# written or implied, V2PTS, V1PT and DT velocities, DIRCOS and KINDIFFS, springs, forces
# and torques alone and in pairs, DEPENDENT constraints (fixed in N and in a body: a knife
# edge), a rolling disc, auxiliary speeds with KANE's reactions (34: with a DEPENDENT
# constraint through a slack speed, the fourbar's pattern), auxiliary constraints (8, 17)
FAST = [1, 3, 4, 5, 6, 7, 8, 9, 13, 14, 16, 17, 18, 20, 22, 23, 25, 28, 30, 33, 34, 46, 91]
# DIRCOS and KINDIFFS of more links, Euler parameters: sympy takes 10-60 s on each
SLOW = [2, 38, 47, 56, 39, 138]


def _id(index: int) -> str:
    return f"{SEED}:{index}-{oracle.FAMILIES[index % len(oracle.FAMILIES)]}"


@pytest.mark.parametrize("index", FAST, ids=_id)
def test_our_rates_are_the_oracles(index):
    outcome = oracle.run_case(SEED, index)
    assert outcome.status == "agree", oracle.describe(outcome, full=True)
    assert len(outcome.samples) == oracle.STATES


@pytest.mark.slow
@pytest.mark.parametrize("index", SLOW, ids=_id)
def test_our_rates_are_the_oracles_for_larger_rotations(index):
    outcome = oracle.run_case(SEED, index)
    assert outcome.status == "agree", oracle.describe(outcome, full=True)


def test_the_cases_are_reproducible_and_cycle_the_families():
    a, b = oracle.make_case(SEED, 9), oracle.make_case(SEED, 9)
    assert (a.autolev, a.sympy) == (b.autolev, b.sympy)
    assert oracle.make_case(SEED + 1, 9).autolev != a.autolev
    assert [oracle.make_case(SEED, i).family for i in range(9)] == oracle.FAMILIES


def _negated(text: str, statement: str) -> str:
    """`text` with the vector of its first `statement` line (FORCE, GRAVITY) negated."""
    pattern = re.compile(rf"^({statement}\((?:[A-Z0-9/]+, )?)(.*)\)$", re.M)
    assert pattern.search(text), f"no {statement} line to change"
    return pattern.sub(r"\1-(\2))", text, count=1)


def test_a_force_of_the_opposite_sign_is_a_disagreement():
    # 11:9 has a spring and a force pair; the pair's sign flipped in the Autolev text
    assert "FORCE(" in oracle.make_case(SEED, 9).autolev
    outcome = oracle.run_case(SEED, 9, mutate=lambda text: _negated(text, "FORCE"))
    assert outcome.status == "disagree"
    assert outcome.error > 1e-3


def test_gravity_of_the_opposite_sign_is_a_disagreement():
    outcome = oracle.run_case(SEED, 5, mutate=lambda text: _negated(text, "GRAVITY"))
    assert outcome.status == "disagree"


def test_a_reaction_of_the_opposite_sign_is_a_disagreement_in_it_alone():
    # KANE's reaction at a joint of 11:34 given a slack speed: the motion is unchanged
    unknown = oracle.make_case(SEED, 34).description.unknowns()[0]
    outcome = oracle.run_case(SEED, 34, mutate=lambda text: text.replace(
        f", {unknown}*", f", -{unknown}*", 1))
    assert outcome.status == "disagree"
    assert outcome.detail.startswith(f"differs in {unknown}")


def test_a_case_over_its_time_limit_is_a_timeout_of_its_side():
    # 11:2 takes sympy 10-60 s; our side is under 0.5 s only once this process's caches
    # are warm: the limit is charged to whichever side was running when it ran out
    outcomes = oracle.run_all([(SEED, 2)], jobs=1, timeout=0.5, report=lambda o: None)
    assert [o.status for o in outcomes] in (["our-timeout"], ["oracle-timeout"])
    spent = outcomes[0].our_seconds if outcomes[0].status == "our-timeout" \
        else outcomes[0].oracle_seconds
    assert 0.5 <= spent < 5


def test_the_table_counts_each_family():
    outcomes = [oracle.Outcome(1, 0, "planar", "agree"), oracle.Outcome(1, 9, "planar", "agree"),
                oracle.Outcome(1, 8, "aux_constraint", "disagree")]
    lines = oracle.table(outcomes).splitlines()
    assert lines[0].split()[:4] == ["family", "cases", "agree", "DISAGREE"]
    assert lines[1].split()[:4] == ["planar", "2", "2", "0"]
    assert lines[2].split()[:4] == ["aux_constraint", "1", "0", "1"]
    assert lines[3].split()[:4] == ["all", "3", "2", "1"]


def incline() -> models.Description:
    """A particle in N's plane (Q1, Q2 along N1>, N2>) under gravity -G*N2>, its velocity
    along N1> - N2> zero by an auxiliary constraint solved for U1 (so U1 = U2), with the
    constraint force FC1 as KANE's unknown."""
    d = models.Description("aux_constraint", constants={"M1": "1.000", "G": "9.810"},
                           nq=2, nu=2)
    d.ranges = dict.fromkeys(("Q1", "Q2", "U1", "U2"), (-1.0, 1.0))
    d.links = [models.Link(1, "particle", 0, offset=(), slides=((1, 1, 1), (2, 2, 2)),
                           velocity="dt")]
    d.gravity = ((("neg", ("c", "G")), "N", 2),)
    along = ((None, "N", 1), (("n", "-1"), "N", 2))
    d.constraints = [models.Constraint("auxiliary", "P1", along, 1, force="FC1")]
    return d


def test_an_auxiliary_constraint_moves_the_speed_it_is_solved_for():
    # issue 49 item 9: the run held Q1 (Q1' = 0) where the constraint makes U1 = U2, so
    # the particle fell straight down while U2' = -G/2 was the incline's
    d = incline()
    d.multipliers = True
    case = oracle.described_case(0, 0, d)
    assert "AUXILIARY[1] = DOT(V_P1_N>, N1> - 1*N2>)" in case.autolev
    outcome = oracle.check_case(case)
    assert outcome.status == "agree", oracle.describe(outcome)
    t, state, ours, theirs = outcome.samples[0]
    assert ours["Q1"] == pytest.approx(state["U2"])
    assert ours["U2"] == pytest.approx(-9.81 / 2)
    # the incline's normal force along N1> - N2>: m*a = m*g + FC1*(N1> - N2>) gives -G/2
    assert ours["FC1"] == pytest.approx(-9.81 / 2)


def pendulum_with_products() -> models.Description:
    """A body turning about N3> alone, its products of inertia written as numbers:
    INERTIA B1, IXX1, IYY1, IZZ1, 0.100, 0, 0 (only IZZ1 enters its equations)."""
    d = models.Description("spatial", constants={"D1X": "0.500", "M1": "1.000",
                                                 "IXX1": "1.000", "IYY1": "1.200",
                                                 "IZZ1": "1.400", "G": "9.810"})
    d.links = [models.Link(1, "body", 0, offset=(),
                           rotation=models.Rotation("simprot", 3, q=(1,), u=(1,)),
                           mass_offset=((("c", "D1X"), "B1", 1),), velocity="dt",
                           inertia=("IXX1", "IYY1", "IZZ1", "0.100", "0", "0"))]
    d.nq = d.nu = 1
    d.ranges = {"Q1": (-1.0, 1.0), "U1": (-1.0, 1.0)}
    d.gravity = ((("neg", ("c", "G")), "N", 2),)
    return d


def test_products_of_inertia_written_as_numbers_are_not_refused():
    outcome = oracle.check_case(oracle.described_case(0, 0, pendulum_with_products()))
    assert outcome.status == "agree", oracle.describe(outcome)


# random trees of the planar, spatial, DIRCOS and KINDIFFS families (the others have
# constraints, or are not trees: mass matrix alone): 2, 11 and 29 take 10-30 s each
TREES = [1, 3, 9, 18, 20, 28]
LARGER_TREES = [2, 11, 29]


@pytest.mark.parametrize("index", TREES + [pytest.param(i, marks=pytest.mark.slow)
                                           for i in LARGER_TREES], ids=_id)
def test_a_random_trees_residual_jacobians_by_newton_euler_are_kanes(index, tmp_path):
    # r's Jacobians by the Newton-Euler recursion over the tree, against those of M a - F
    # as Kane's equations form them (whose rates the test above holds to sympy's)
    import warnings

    import numpy as np

    import autolev
    path = tmp_path / "case.al"
    path.write_text(oracle.make_case(SEED, index).autolev)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = autolev.load(path)
        tree, mass = model.dynamics(), model.dynamics(recursion=False)
        rng = np.random.default_rng(index)
        x = rng.uniform(-1.0, 1.0, size=(2, len(tree.states)))
        xdot, u = rng.normal(size=x.shape), rng.normal(size=(2, len(tree.controls)))
        by_tree, by_mass = tree.residual_jacobians(x, xdot, u), mass.residual_jacobians(x, xdot, u)
    assert (by_tree.by, by_mass.by) == ("recursion", "mass matrix")
    assert_same_jacobians(by_tree, by_mass, 1e-12)
