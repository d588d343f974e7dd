#!/usr/bin/env python3
"""`autolev convert --to sympy` on every corpus model as it stands (its own INPUT values
only: no .in, no values by rule), and each script imported by a Python that has sympy,
numpy and scipy but not autolev (issue 49: the way out works without values, and
without us).

    python bench/exports.py [--python PY] [--only ID ...] [--limit S] [--json FILE]

--python: the interpreter that imports the scripts (a venv of sympy, numpy and scipy
alone; default this one, with autolev made unimportable).  Per model: converted (its
level, mechanics or equations, and how many constants the script leaves None), refused
(exit 1 with autolev's reason: a model with no equations of motion to export, an error
in the model), or FAIL (an internal error, a traceback, the time limit, or a script that
does not import).  Exit status 1 when any model FAILs.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import journeys  # noqa: E402

# the script imported with autolev out of reach: what a user without autolev has
IMPORT = ("import runpy, sys\n"
          "sys.modules['autolev'] = None\n"
          "runpy.run_path(sys.argv[1], run_name='exported')\n")


def one(ident: str, path: Path, python: str, limit: float) -> dict:
    with tempfile.TemporaryDirectory(prefix="autolev-export-") as tmp:
        work = Path(tmp)
        script = work / "model_sympy.py"
        start = time.monotonic()
        made = journeys.run_process(journeys.autolev_cli(
            "convert", path, "--to", "sympy", "-q", "-o", script), work, limit,
            journeys.process_env(AUTOLEV_CACHE=str(work / "cache")))
        row = {"id": ident, "seconds": 0.0, "level": "", "lacking": 0}
        if made.returncode is None:
            row.update(outcome="FAIL", detail=f"convert took over {limit:g} s")
        elif made.returncode in (1, 2) and "internal error" not in made.stderr \
                and "Traceback" not in made.stderr:
            row.update(outcome="refused", detail=_reason(made.stderr))
        elif made.returncode != 0:
            row.update(outcome="FAIL", detail=journeys._last_line(made.stderr))
        else:
            text = script.read_text()
            level = re.search(r"^Level: (\w+)\.", text, re.MULTILINE)
            row["level"] = level.group(1) if level else "?"
            values = re.search(r"^constants = \{(.*)\}$", text, re.MULTILINE)
            row["lacking"] = values.group(1).count(": None") if values else 0
            imported = journeys.run_process([python, "-c", IMPORT, script], work, limit,
                                            journeys.process_env())
            if imported.returncode == 0:
                row.update(outcome="converted", detail="")
            else:
                row.update(outcome="FAIL", detail="the script does not import: "
                           + journeys._last_line(imported.stderr))
        row["seconds"] = round(time.monotonic() - start, 1)
        return row


def _reason(stderr: str) -> str:
    """A refusal's first error line (its last says only "FILE: not converted")."""
    errors = [line for line in stderr.splitlines() if "error:" in line]
    return errors[0] if errors else journeys._last_line(stderr)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--python", default=sys.executable,
                    help="the interpreter importing the scripts (sympy, numpy, scipy)")
    ap.add_argument("--only", action="append", metavar="ID")
    ap.add_argument("--limit", type=float, default=1200, help="seconds per step")
    ap.add_argument("--json", type=Path, metavar="FILE")
    ns = ap.parse_args(argv)
    ns.corpus, ns.listing, ns.examples = journeys.CORPUS, journeys.LISTING, False
    rows = []
    for ident, path, _ in journeys.chosen_models(ns):
        rows.append(one(ident, path, ns.python, ns.limit))
        r = rows[-1]
        print(f"  {ident}: {r['outcome']} {r['level']} ({r['seconds']:.0f} s) {r['detail']}",
              file=sys.stderr, flush=True)
        if ns.json:
            ns.json.write_text(json.dumps(rows, indent=1))
    width = max([len(r["id"]) for r in rows] + [5])
    print(f"{'model':{width}}  outcome    level       None  seconds  detail")
    for r in rows:
        print(f"{r['id']:{width}}  {r['outcome']:10} {r['level']:11} {r['lacking']:4d} "
              f"{r['seconds']:8.1f}  {r['detail']}")
    tally: dict = {}
    for r in rows:
        tally[r["outcome"]] = tally.get(r["outcome"], 0) + 1
    print("\n" + ", ".join(f"{k} {v}" for k, v in sorted(tally.items())))
    return 1 if tally.get("FAIL") else 0


if __name__ == "__main__":
    sys.exit(main())
