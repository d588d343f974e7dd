"""What the corpus-wide tests share (the sympy export's, the Jacobians'): every visible
model with the .in its repository ships, each checked in a worker process under a time
limit, and a run of it with the journeys' values."""
import signal
import sys
import warnings
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

from autolev.engine.errors import MissingValues
from helpers import ROOT, SHARED

sys.path.insert(0, str(ROOT / "bench"))
import corpus as corpus_bench  # noqa: E402
import journeys as journeys_bench  # noqa: E402


def corpus_cases(corpus: Path) -> list[tuple]:
    """(id, model's path, the .in shipped nearest it or None) of every visible model."""
    listing = SHARED / "corpus" / "visible.tsv"
    shipped = journeys_bench.companions(listing)
    cases = []
    for ident, path in corpus_bench.corpus_models(corpus, listing):
        found = journeys_bench.nearest(path, shipped.get(ident, []))
        cases.append((ident, str(path), found and str(found)))
    return cases


def guarded(check, case: tuple, out: dict, limit: int) -> dict:
    """`out` after check(model's path, shipped .in, out) within `limit` seconds, its
    warnings silenced; a timeout or an exception is the model's failure, named."""
    _, path, shipped = case
    signal.signal(signal.SIGALRM, corpus_bench._alarm)
    signal.alarm(limit)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            check(Path(path), shipped and Path(shipped), out)
    except corpus_bench._Timeout:
        out.update(outcome="failing", detail=f"did not finish in {limit} s")
    except Exception as exc:     # reported with the model's name, and the test fails
        out.update(outcome="failing", detail=f"{type(exc).__name__}: {exc}"[:300])
    finally:
        signal.alarm(0)
    return out


def results_of(worker, cases: list) -> list[dict]:
    """worker(case) of every case on two processes, each printed as it comes."""
    results = []
    with ProcessPoolExecutor(2) as pool:
        for done in as_completed([pool.submit(worker, case) for case in cases]):
            results.append(done.result())
            r = results[-1]
            said = " ".join(part for part in (r["outcome"], r.get("level"), r["id"]) if part)
            print(f"[{len(results)}/{len(cases)}] {said}", flush=True)
    return results


def run_with_values(model, path: Path, shipped: Path | None, inputs: dict,
                    rounds: int = 8, **options):
    """(result, values) of `simulate` with the journeys' values: INPUT, the shipped .in,
    then by rule for the constants the run names as having none; `inputs` first."""
    products = journeys_bench.read_model(path).products_of_inertia   # (it parses)
    values = dict(inputs)
    for _ in range(rounds):
        try:
            return model.simulate(infile=shipped, **options, **values), values
        except MissingValues as exc:
            values.update({name: float(v) for name, v in
                           journeys_bench.rule_values(exc.names, products).items()})
    raise AssertionError(f"still missing values after {rounds} rounds")
