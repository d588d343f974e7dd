#!/usr/bin/env python3
"""Conformance over the public corpus: how many models each stage accepts.

    python bench/corpus.py [--corpus DIR] [--list]

Reads shared/corpus/visible.tsv, finds the files that shared/corpus/materialize.py
copied (default ~/.cache/autolev-corpus, or $AUTOLEV_CORPUS), and reports per model
the outcome of each stage: parse (syntax, macros and RUN files), translate (to
Python), build (the generated module runs and forms its equations).  Every model
that stops is listed with its first diagnostic; --list lists them all.
"""
from __future__ import annotations

import argparse
import csv
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev  # noqa: E402


def corpus_models(corpus: Path, listing: Path | None = None) -> list[tuple[str, Path]]:
    """(id, path) of every model row (kind `al`, not a .a macro) found in the corpus.

    `listing`: a TSV with columns repo, path, kind (and id, commit) -- visible.tsv by
    default, or another set's manifest laid out the same way under `corpus`.
    A row pinned to an older commit whose files differ from the newest ones lives in
    `OWNER+NAME@commit/` (materialize.py); it is read from an overlay folder that puts
    those files over the newest ones, so its RUN files and macros are of its commit."""
    listing = listing or ROOT.parent / "shared" / "corpus" / "visible.tsv"
    out, seen = [], set()
    for row in csv.DictReader(open(listing), delimiter="\t"):
        if row["kind"] != "al" or row["path"].lower().endswith(".a"):
            continue
        ident = row.get("id") or f"{row['repo']}:{row['path']}"
        commit = row.get("commit") or ""
        base = corpus / row["repo"].replace("/", "+")
        pinned_root = corpus / (row["repo"].replace("/", "+") + "@" + commit[:8])
        p = base / row["path"]
        if commit and pinned_root.is_dir() and ident.endswith(commit[:8]):
            p = _overlay(base, pinned_root) / row["path"]
        if p.exists() and p not in seen:
            seen.add(p)
            out.append((ident, p))
    return out


def _overlay(base: Path, pinned: Path) -> Path:
    """A copy of `base` with the files of `pinned` over it (made once, in the cache)."""
    import shutil
    target = base.parent / ".overlay" / pinned.name
    if not target.exists():
        shutil.copytree(base, target)
        for f in pinned.rglob("*"):
            if f.is_file():
                dest = target / f.relative_to(pinned)
                dest.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(f, dest)
    return target


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout()


def run_model(args) -> dict:
    """Every stage for one model, in a worker process (with a time limit)."""
    import signal
    import time
    ident, path, limit, run_code = args
    out = {"id": ident, "path": str(path), "stage": "ok", "detail": "", "seconds": 0.0}
    try:
        out["code"] = len(autolev.parse(path).of_kind("code"))
    except autolev.AutolevError:
        out["code"] = 0
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(limit)
    t0 = time.perf_counter()
    try:
        result = autolev.translation(path)
        model = autolev.load(path)
        out["speeds"] = len(model.kane_equations.speeds) if model.kane_equations else 0
        out["warnings"] = sum(d.severity == "warning" for d in result.diagnostics)
        if run_code:
            _run_code(model, out)
    except autolev.AutolevSyntaxError as exc:
        out.update(stage="parse", detail=_first(exc.diagnostics))
    except autolev.AutolevTranslationError as exc:
        out.update(stage="translate", detail=_first(exc.diagnostics))
        if run_code:
            _run_after_errors(path, out)
    except autolev.AutolevRuntimeError as exc:
        out.update(stage="build", detail=_first(exc.diagnostics))
        if run_code:
            _run_after_errors(path, out)
    except _Timeout:
        out.update(stage="build", detail=f"did not finish in {limit} s")
    finally:
        signal.alarm(0)
    out["seconds"] = time.perf_counter() - t0
    return out


def _run_code(model, out: dict) -> None:
    """Perform the model's CODE commands with its INPUT values (files into a temporary
    folder): 'ok', or why not, said to be 'before the build' (nothing was compiled for
    the command) or 'after the build' (its numeric system was built: a failure found
    that late cost the user the build)."""
    import tempfile
    import warnings

    from autolev.engine.errors import AutolevModelError
    from autolev.runtime.numerics.run import run_command
    if not model.code_commands:
        return
    outcomes = []
    with tempfile.TemporaryDirectory() as tmp, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for command in model.code_commands:
            systems = model.__dict__.setdefault("_numeric_systems", {})
            try:
                r = run_command(model.snapshot_for(command), out_dir=tmp)
            except AutolevModelError as exc:
                when = ("after the build" if any(k[0] == id(command) for k in systems)
                        else "before the build")
                outcomes.append(f"error {when}: {str(exc).splitlines()[0][:160]}")
                continue
            except _Timeout:
                outcomes.append("did not finish in the time limit")
                break
            outcomes.append("ok" if r.ok else
                            f"integration failed after the build: {r.failure[:120]}")
    out["run"] = outcomes


def _run_after_errors(path, out: dict) -> None:
    """Statements after the last CODE command may fail and still leave it runnable (as
    `autolev run` does)."""
    from autolev.loader import load_for_run
    try:
        model, _ = load_for_run(path)
    except autolev.AutolevError:
        return
    _run_code(model, out)


def _first(diagnostics) -> str:
    d = next(d for d in diagnostics if d.severity == "error")
    return d.format(context=False).splitlines()[0]


def main() -> int:
    from concurrent.futures import ProcessPoolExecutor
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--listing", type=Path, default=None,
                    help="a TSV of models (repo, path, kind) under --corpus; default "
                    "shared/corpus/visible.tsv")
    ap.add_argument("--list", action="store_true", help="list every model and its outcome")
    ap.add_argument("--limit", type=int, default=120, help="seconds per model")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-run", action="store_true",
                    help="stop after building: do not perform the CODE commands")
    ns = ap.parse_args()
    models = corpus_models(ns.corpus, ns.listing)
    if not models:
        print(f"no corpus under {ns.corpus}: see shared/corpus/materialize.py")
        return 1
    with ProcessPoolExecutor(ns.jobs) as pool:
        results = list(pool.map(run_model, [(i, p, ns.limit, not ns.no_run)
                                            for i, p in models]))
    total = len(results)
    order = ["parse", "translate", "build"]
    passed = total
    for stage in order:
        failed = sum(r["stage"] == stage for r in results)
        passed -= failed
        passed = total - sum(r['stage'] in order[:order.index(stage) + 1] for r in results)
        print(f"{stage:9s}: {passed}"
              f"/{total} models get past it ({failed} stop here)")
    ok = sum(r["stage"] == "ok" for r in results)
    print(f"translate and build without a diagnostic: {ok}/{total} ({100 * ok / total:.1f} %)")
    coded = [r for r in results if r.get("code")]
    if not ns.no_run:
        done = [r for r in coded if r.get("run") and all(o == "ok" for o in r["run"])]
        failed = [r for r in coded if r.get("run") and any(o.startswith("integration")
                                                           for o in r["run"])]
        late = [r for r in coded if r.get("run") and any("after the build" in o
                                                          for o in r["run"])]
        early = [r for r in coded if r.get("run") and any("before the build" in o
                                                           for o in r["run"])]
        print(f"run      : {len(done)}/{len(coded)} models with a CODE command run every "
              f"one to completion; {len(failed)} stop with Autolev's integration failure; "
              f"{len(late)} fail after the build, {len(early)} are stopped before it")
        for r in coded:
            if r not in done:
                print(f"  {r['id']}: run: " + "; ".join(r.get("run") or ["not built"]))
    slow = sorted(results, key=lambda r: -r["seconds"])[:5]
    print("slowest: " + ", ".join(f"{r['id']} {r['seconds']:.1f} s" for r in slow))
    for r in results:
        if ns.list or r["stage"] != "ok":
            print(f"  {r['id']}: {r['stage']}: {r['detail'] or 'ok'} ({r['seconds']:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
