"""Model.dynamics over the public corpus (issue 53): for every visible model whose first
CODE DYNAMICS runs (over 1 s, with the values the journeys give it: INPUT, the .in its
repository ships, then 1 for each constant still without a value, 0 for a product of
inertia), the exact Jacobians of f and of r equal five-point central differences at
two states of that run (its first row and its middle one), by the rule of the examples'
test: each entry within 1e-8 of its row's size at the step that suits it."""
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import autolev
from autolev.engine.errors import AutolevModelError, MissingValues
from helpers import ROOT, SHARED
from helpers.differences import agrees, central

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

sys.path.insert(0, str(ROOT / "bench"))
import corpus as corpus_bench  # noqa: E402
import journeys as journeys_bench  # noqa: E402

LIMIT = 1500          # seconds for one model: build, run, form and compile its Jacobians
INPUTS = {"TFINAL": 1}


def check_model(args) -> dict:
    """One model: {'id', 'outcome' (not built / not run / agrees / failing), 'detail'}."""
    import signal
    ident, path, shipped = args
    out = {"id": ident, "outcome": "agrees", "detail": ""}
    signal.signal(signal.SIGALRM, corpus_bench._alarm)
    signal.alarm(LIMIT)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            _check(Path(path), shipped and Path(shipped), out)
    except corpus_bench._Timeout:
        out.update(outcome="failing", detail=f"did not finish in {LIMIT} s")
    except Exception as exc:     # reported with the model's name, and the test fails
        out.update(outcome="failing", detail=f"{type(exc).__name__}: {exc}"[:300])
    finally:
        signal.alarm(0)
    return out


def _run(model, path: Path, shipped: Path | None, rounds: int = 8):
    """(result, values) of `simulate` over 1 s with the journeys' values."""
    products = journeys_bench.read_model(path).products_of_inertia
    values = dict(INPUTS)
    for _ in range(rounds):
        try:
            return model.simulate(infile=shipped, **values), values
        except MissingValues as exc:
            values.update({name: float(v) for name, v in
                           journeys_bench.rule_values(exc.names, products).items()})
    raise AssertionError(f"still missing values after {rounds} rounds")


def _check(path: Path, shipped: Path | None, out: dict) -> None:
    try:
        model = autolev.load(path)
    except autolev.AutolevError as exc:
        out.update(outcome="not built", detail=str(exc).splitlines()[0][:120])
        return
    if not any(c.kind.name == "DYNAMICS" for c in model.code_commands):
        out.update(outcome="not run", detail="no CODE DYNAMICS")
        return
    try:
        result, values = _run(model, path, shipped)
    except AutolevModelError as exc:
        out.update(outcome="not run", detail=str(exc).splitlines()[0][:120])
        return
    if result.kind.name != "DYNAMICS" or len(result.t) == 0:
        out.update(outcome="not run", detail="its first program is not its CODE DYNAMICS")
        return
    dynamics = model.dynamics(infile=shipped, overrides=values)
    rows = [0, len(result.t) // 2]
    where = [result.state_names.index(name) for name in dynamics.states]
    x = result.states[rows][:, where]
    rng = np.random.default_rng(11)
    u = 0.1 * rng.normal(size=(len(rows), len(dynamics.controls)))
    p, t = dynamics.parameter_values, result.t[rows]
    xdot = dynamics.explicit(x, u, p, t)
    explicit = dynamics.explicit_jacobians(x, u, p, t)
    implicit = dynamics.residual_jacobians(x, xdot, u, p, t)
    arrays = dict(x=x, u=u, p=p, t=t)

    def f(x, u, p, t):
        return dynamics.explicit(x, u, p, t)

    def r(x, u, p, t):
        return dynamics.residual(x, xdot, u, p, t)
    wrong = []
    for block in ("x", "u", "p"):
        if arrays[block].shape[-1]:
            if not agrees(explicit.dense(block), central(f, arrays, block)):
                wrong.append(f"df/d{block}")
            if not agrees(implicit.dense(block), central(r, arrays, block)):
                wrong.append(f"dr/d{block}")
    by_rates = central(lambda xdot: dynamics.residual(x, xdot, u, p, t), {"xdot": xdot}, "xdot")
    if not agrees(implicit.dense("xdot"), by_rates):
        wrong.append("dr/dxdot")
    out["detail"] = (f"{len(dynamics.states)} states, {len(dynamics.parameters)} parameters"
                     + (f"; differ: {', '.join(wrong)}" if wrong else ""))
    if wrong:
        out["outcome"] = "failing"


def test_every_corpus_models_jacobians_are_central_differences(corpus):
    from concurrent.futures import ProcessPoolExecutor, as_completed
    listing = SHARED / "corpus" / "visible.tsv"
    models = corpus_bench.corpus_models(corpus, listing)
    shipped = journeys_bench.companions(listing)
    cases = []
    for ident, path in models:
        found = journeys_bench.nearest(path, shipped.get(ident, []))
        cases.append((ident, str(path), found and str(found)))
    results = []
    with ProcessPoolExecutor(2) as pool:
        for done in as_completed([pool.submit(check_model, case) for case in cases]):
            results.append(done.result())
            r = results[-1]
            print(f"[{len(results)}/{len(models)}] {r['outcome']} {r['id']}", flush=True)
    agreeing = [r for r in results if r["outcome"] == "agrees"]
    failing = [r for r in results if r["outcome"] == "failing"]
    print(f"\n{len(results)} models; {len(agreeing) + len(failing)} run their CODE "
          f"DYNAMICS; {len(agreeing)} agree; {len(failing)} failing")
    for r in sorted(results, key=lambda r: (r["outcome"], r["id"])):
        print(f"{r['outcome']:10} {r['id']}: {r['detail']}")
    assert not failing
    assert len(agreeing) >= 40
