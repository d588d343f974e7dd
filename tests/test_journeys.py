"""bench/journeys.py: every command a user runs, on every model, in a user's order.
CI runs the journey of two shipped examples; the corpus's journeys are marked `corpus`."""
import math
import sys

import numpy as np
import pytest

from helpers import CORPUS, EXAMPLES, ROOT, SHARED
from helpers.programs import compiler

sys.path.insert(0, str(ROOT / "bench"))
import journeys as J  # noqa: E402

EVERY_COMMAND_RUNS = ["double_pendulum", "simple_pendulum"]


# -- classifying a command's process -----------------------------------------------------
def outcome(code, stderr="", stdout=""):
    return J.Outcome(code, stdout, stderr, 1.5, limit=600)


def test_an_internal_error_is_a_failure_whatever_the_table_says():
    cell = J.classify("m", "run", outcome(70, "m.al: internal error: running `autolev run`"
                                               "\nautolev: note: AUTOLEV_TRACEBACK=1"),
                      genuine={("m", "run"): "the model is wrong"})
    assert cell.status == "FAIL"
    assert cell.reason == "exit 70: m.al: internal error: running `autolev run`"


def test_a_traceback_is_a_failure_even_with_exit_0():
    text = "Traceback (most recent call last):\n  File \"x.py\"\nKeyError: 'Q1'\n"
    cell = J.classify("m", "check", outcome(0, text))
    assert (cell.status, cell.reason) == ("FAIL", "exit 0 with a Python traceback: "
                                                  "KeyError: 'Q1'")


def test_an_exit_1_named_in_the_table_is_genuine_with_the_tables_reason():
    cell = J.classify("m", "check", outcome(1, "m.al:3:1: error: X is not declared"),
                      genuine={("m", "check"): "line 3 uses X, declared nowhere"})
    assert (cell.status, cell.reason) == ("genuine", "line 3 uses X, declared nowhere")


def test_an_exit_1_not_named_is_a_failure_saying_the_first_error():
    said = "autolev: warning: an old unit\nm.al:3:1: error: X is not declared\nm.al: not run"
    for table in ({}, {("m", "check"): "named for another command"}, {("n", "run"): "x"}):
        cell = J.classify("m", "run", outcome(1, said), genuine=table)
        assert (cell.status, cell.reason) == ("FAIL", "exit 1: m.al:3:1: error: X is not "
                                                      "declared")


def test_a_failure_without_the_word_error_is_said_by_its_first_line_not_a_warning():
    said = ("autolev: warning: inputs in DEG/S are used as radian rates\n"
            "m.al:9: Numerical integration failed to converge at T = 0.5\n")
    assert J.classify("m", "run", outcome(1, said)).reason == \
        "exit 1: m.al:9: Numerical integration failed to converge at T = 0.5"


def test_every_genuine_entry_names_a_command_and_quotes_the_models_line():
    for (ident, command), reason in J.GENUINE.items():
        assert command in J.COMMANDS and ident
        assert "line" in reason and "`" in reason, (ident, command)


def test_exit_0_is_ok_and_the_time_limit_and_a_signal_are_failures():
    assert J.classify("m", "run", outcome(0, "autolev: warning: slow")).status == "ok"
    assert J.classify("m", "run", outcome(None)).reason == "did not finish in 600 s"
    assert J.classify("m", "run", outcome(-11)).reason == "killed by signal 11"


# -- values by rule ----------------------------------------------------------------------
MESSAGE = ("m.al:9: error: CODE DYNAMICS: 14 constants of m.c have no value: G, IA, IB, "
           "IC, I12, I23, I31, L1, L2, L3, M1, M2, ... and 2 more.  Autolev's program read "
           "them from its .in file; give them with --in FILE")


def test_the_missing_names_are_read_from_the_runs_message_without_the_count():
    names = J.missing_names(MESSAGE + "\nm.al:12: error: CODE ALGEBRAIC: 1 constant of "
                            "a.c has no value: K.  Autolev's program read it")
    assert names == ["G", "IA", "IB", "IC", "I12", "I23", "I31", "L1", "L2", "L3", "M1",
                     "M2", "K"]


def test_the_rule_gives_1_to_constants_and_0_to_products_of_inertia():
    assert J.rule_values(["M", "IXX", "ixy", "L"], {"IXY"}) == {
        "M": "1", "IXX": "1", "ixy": "0", "L": "1"}


RULE_MODEL = """\
NEWTONIAN N
FRAMES A
BODIES B
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS M, L, G, I11, I22, I33, I12, I23, I31
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_N> = U2*A1> + W_A_N>
P_NO_BO> = L*B3>
V_BO_N> = DT(P_NO_BO>, N)
MASS B = M
INERTIA B, I11, I22, I33, I12, I23, I31
GRAVITY(G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT Q1 = 10 DEG, Q2 = 30 DEG, U1 = 1, U2 = 0, TFINAL = 1, INTEGSTP = 0.5
OUTPUT Q1, Q2
CODE DYNAMICS() top.c
"""


def test_a_model_without_values_runs_with_values_by_rule(tmp_path):
    """The products of inertia are the model's 4th-6th INERTIA arguments: 0; the other
    constants 1, as the .in the run wrote shows."""
    path = tmp_path / "top.al"
    path.write_text(RULE_MODEL)
    cell, values = J.run_with_values("top", path, J.read_model(path), None, tmp_path, 300,
                                     {})
    assert cell.status == "ok", cell.reason
    assert values.by_rule and cell.reason == "values INPUT; by rule: 6 constants 1, " \
                                             "3 products of inertia 0"
    given = {k: float(v) for k, v in J.in_values(tmp_path / "run" / "top.in").items()}
    assert {k: given[k] for k in ("M", "L", "G", "I11", "I22", "I33", "I12", "I23", "I31")} \
        == {"M": 1, "L": 1, "G": 1, "I11": 1, "I22": 1, "I33": 1, "I12": 0, "I23": 0, "I31": 0}
    # the values are given as a user gives them on the command line
    assert values.options.count("--set") == 9 and "I23=0" in values.options


# -- comparing a program's rows with the run's -------------------------------------------
def test_tables_part_where_a_difference_exceeds_a_millionth_of_the_columns_largest():
    run = np.array([[0.0, 10.0, 1e-3], [1.0, -20.0, 2e-3], [2.0, 5.0, 0.0]])
    near = run + np.array([[0, 1.5e-5, 1e-9], [0, -1.9e-5, 0], [0, 0, 1.9e-9]])
    assert J.first_parting(near, run) is None
    far = run.copy()
    far[2, 1] += 2.1e-5                       # 1.05e-6 of the column's 20
    row, col, diff = J.first_parting(far, run)
    assert (row, col) == (2, 1) and math.isclose(diff, 1.05e-6, rel_tol=1e-6)
    lost = run.copy()
    lost[1, 2] = float("nan")
    assert J.first_parting(lost, run)[:2] == (1, 2)


# -- comparing two reports ---------------------------------------------------------------
def _report(cells):
    return {"models": {m: {"cells": {c: {"status": s, "reason": r}
                                     for c, (s, r) in by.items()}} for m, by in cells.items()}}


def test_a_comparison_lists_new_failures_and_fixed_cells():
    old = _report({"a": {c: ("ok", "") for c in J.COMMANDS},
                   "b": dict({c: ("ok", "") for c in J.COMMANDS}, run=("FAIL", "exit 1: x"))})
    new = _report({"a": dict({c: ("ok", "") for c in J.COMMANDS}, verify=("FAIL", "exit 1")),
                   "b": {c: ("ok", "") for c in J.COMMANDS}})
    assert J.changes(old, new) == ["new failures: 1", "  a verify: ok -> FAIL: exit 1",
                                   "fixed: 1", "  b run: FAIL -> ok (was: exit 1: x)",
                                   "other changes: 0"]


# -- the journeys themselves -------------------------------------------------------------
@pytest.mark.skipif(compiler() is None, reason="no C compiler on this machine")
def test_every_command_is_ok_on_shipped_examples(tmp_path):
    models = [(name, EXAMPLES / f"{name}.al", None) for name in EVERY_COMMAND_RUNS]
    done = J.run_all(models, limit=300, jobs=2, keep=tmp_path)
    for journey in done:
        assert {c: journey.cells[c].status for c in J.COMMANDS} == \
            {c: "ok" for c in J.COMMANDS}, journey.cells
        # the C program was compiled, run and its files compared with the run's
        assert journey.cells["code"].detail.endswith("files equal to 1e-06"), journey.cells
        assert (tmp_path / journey.ident / "anim" / f"{journey.ident}.html").exists()


@pytest.mark.corpus
@pytest.mark.slow
def test_no_corpus_model_fails_a_command_but_the_named_genuine_ones():
    listing = SHARED / "corpus" / "visible.tsv"
    if not listing.exists() or not CORPUS.exists():
        pytest.skip("the corpus is not materialized")
    ns = J.parse_args(["--listing", str(listing), "--corpus", str(CORPUS)])
    done = J.run_all(J.chosen_models(ns), limit=ns.limit, jobs=ns.jobs)
    failures = [f"{j.ident} {c}: {j.cells[c].reason}" for j in done for c in J.COMMANDS
                if j.cells[c].status == "FAIL"]
    assert failures == []



def _tables(folder, columns):
    """Files m.1, m.2 ... of rows (t, y) at t = 0, 1, 2, 3, one per list of y's."""
    folder.mkdir(parents=True, exist_ok=True)
    for k, ys in enumerate(columns, 1):
        (folder / f"m.{k}").write_text(
            "% t y\n" + "".join(f"{t:.6e} {y:.6e}\n" for t, y in enumerate(ys)))


@pytest.mark.parametrize("tight_state, differs", [
    # the state parts from the tighter run at row 3 (t = 2): the energy's later rows
    # depend on the integration error too, though the run's energy stays near the
    # tighter one's (sprintjl 9seg's Fortran: its .6 of energies and momenta)
    ([1.0, 1.1, 1.3, 1.6], False),
    # the state never parts from the tighter run: the energy must agree to its end
    ([1.0, 1.1, 1.2, 1.3], True),
])
def test_a_commands_files_are_trusted_up_to_where_any_of_them_parts_from_a_tighter_run(
        tmp_path, tight_state, differs):
    run = J.RunToMatch(tmp_path / "m.al", tmp_path / "work", None, None, 60)
    state, energy = [1.0, 1.1, 1.2, 1.3], [50.0, 50.0, 50.0, 50.0]
    _tables(run.folder, [state, energy])
    _tables(tmp_path / "program", [state, [50.0, 50.0, 50.0, 50.1]])
    run.tight_folder, run.tight_status = tmp_path / "work" / "run-tight", 0
    _tables(run.tight_folder, [tight_state, energy])
    check = J.ProgramCheck()
    J.compare_files(check, tmp_path / "program", "m", run, integrated=True)
    assert bool(check.problem) == differs, check
    if differs:
        assert check.problem.startswith("m.2 column 2 differs") and "row 4" in check.problem
    else:
        assert "row 3 at the earliest" in " ".join(check.remarks)
