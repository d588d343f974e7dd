"""The public corpus (materialized by shared/corpus/materialize.py).

Every model reads without a syntax error except the genuine errors in the users'
files listed here; and (slow) the models that translate and build are at least those
they were, the rest failing only for the reasons listed."""
import sys

import pytest

from helpers import ROOT

pytestmark = pytest.mark.corpus

sys.path.insert(0, str(ROOT / "bench"))
import corpus as corpus_bench  # noqa: E402  (bench/corpus.py; workers import it too)

# (model id, diagnostic code, line): errors that are really in the user's file
GENUINE = {
    # `P_O_P>=R*D1>D_Q1_B>=D(P_O_P>,Q1,B)`: two statements run together on one line
    ("mae223-chapter-1-1-9-2", "E002", 16),
    # `RUN gait2d_kin.al`: no such file in the repository, at HEAD or at 427b529d
    ("biomac-acc-427b529d", "E022", 18),
}

# models that cannot be built, and why (the stage and the start of the message)
NOT_BUILDING = {
    "mae223-chapter-1-1-9-2": ("parse", "unexpected 'D_Q1_B>'"),
    "biomac-acc-427b529d": ("parse", "RUN gait2d_kin.al"),
    # undeclared names in the users' files
    "mae223-bicycledyn-bicycle2": ("translate", "'D1O' is not declared"),
    "mae223-bicycledyn-bike": ("translate", "'Z12' is not declared"),    # a Z of a session
    "mae223-bicycledyn-bicycle11": ("translate", "'U5P' is not declared"),  # commented out
    "swingbike-linearize-swing-bike": ("translate", "'Q4' is not declared"),  # a fragment
    "npparser-example5-2": ("translate", "'EigenVec' is not declared"),   # EigenVecs
    # the model asks for the impossible
    "ridermodel-leanangle": ("build", "INV needs a square matrix"),       # ROWS(B,3:4) is 2x5
    "npparser-example5-7": ("build", "cannot solve the DEPENDENT constraints"),  # qA' for all
    "sympy-ruletest10": ("build", "the velocity of O in N is not defined"),
}


def test_every_corpus_model_parses_except_genuine_errors(corpus):
    import autolev
    failures = set()
    models = corpus_bench.corpus_models(corpus)
    assert len(models) >= 120
    for ident, path in models:
        try:
            autolev.parse(path)
        except autolev.AutolevSyntaxError as exc:
            for d in exc.diagnostics:
                if d.severity == "error":
                    failures.add((ident, d.code, d.line))
    assert failures == GENUINE


def test_check_reports_an_error_exactly_when_convert_fails(corpus):
    import autolev
    from autolev.cli.check import check_file
    disagree = []
    models = corpus_bench.corpus_models(corpus)
    for ident, path in models:
        checked = sum(d.severity == "error" for d in check_file(path))
        try:
            autolev.transpile(path)
            converts = True
        except autolev.AutolevError:
            converts = False
        if converts != (checked == 0):
            disagree.append((ident, checked, converts))
    assert disagree == []


@pytest.mark.slow
def test_corpus_models_translate_and_build(corpus):
    from concurrent.futures import ProcessPoolExecutor
    models = corpus_bench.corpus_models(corpus)
    with ProcessPoolExecutor(2) as pool:
        results = list(pool.map(corpus_bench.run_model, [(i, p, 120, False) for i, p in models]))
    failing = {r["id"]: r for r in results if r["stage"] != "ok"}
    unexplained = {k: (v["stage"], v["detail"]) for k, v in failing.items()
                   if k not in NOT_BUILDING or NOT_BUILDING[k][0] != v["stage"]
                   or NOT_BUILDING[k][1] not in v["detail"]}
    assert not unexplained
    assert len(results) - len(failing) >= 110
