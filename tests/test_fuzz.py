"""Fixed-seed handfuls of bench/fuzz.py's mutants and generated models: none may end in a
traceback; a case over the time limit is reported as a hang."""
import importlib.util
import random
import sys

from helpers import EXAMPLES, ROOT

spec = importlib.util.spec_from_file_location("fuzz", ROOT / "bench" / "fuzz.py")
fuzz = importlib.util.module_from_spec(spec)
sys.modules["fuzz"] = fuzz          # its dataclasses look their module up there
spec.loader.exec_module(fuzz)

SEEDS = sorted(EXAMPLES.glob("*.al")) + sorted((ROOT / "tests" / "data").glob("*.al"))


def test_mutation_is_deterministic_and_changes_the_text():
    text = SEEDS[0].read_text()
    a = fuzz.mutate(text, random.Random(7))
    b = fuzz.mutate(text, random.Random(7))
    assert a == b and a != text


def test_fixed_seed_mutants_never_crash():
    outcomes = fuzz.run(150, seed=2024, files=SEEDS, quiet=True)
    assert outcomes["crash"] == 0
    # the mutants exercise both paths
    assert outcomes["parsed"] > 0 and outcomes["diagnosed"] > 0


def test_check_one_flags_a_crash():
    # a filename that cannot be read as a folder makes a RUN unresolvable, not a crash
    assert fuzz.check_one("x = 1\n", "m.al") == ("parsed", None)
    assert fuzz.check_one("x = (\n", "m.al")[0] == "diagnosed"


# -- grammar mode -------------------------------------------------------------------
def test_grammar_cases_are_deterministic_per_seed():
    first = [fuzz.grammar_case(3, i) for i in range(60)]
    assert first == [fuzz.grammar_case(3, i) for i in range(60)]
    assert first != [fuzz.grammar_case(4, i) for i in range(60)]
    assert {c.generator for c in first} == set(fuzz.GENERATORS)
    # every case is written to a file of its own name inside the case folder
    assert all("/" not in c.filename and c.filename not in (".", "..") for c in first)


def test_fixed_seed_grammar_cases_in_a_worker_never_crash():
    cases = [fuzz.grammar_case(2024, i) for i in range(40)]
    results = fuzz.run_cases(cases, jobs=1, timeout=30)
    outcomes = {r.outcome for r in results}
    assert [r.index for r in results] == list(range(40))
    assert not outcomes & set(fuzz.FAILURES), [r for r in results if r.outcome != "ok"]
    assert {"ok", "diagnosed"} <= outcomes
    assert all(r.seconds >= 0 and r.rss_mb > 0 for r in results)


def test_a_case_over_the_time_limit_is_a_hang_and_the_next_runs_in_a_fresh_worker():
    slow = fuzz.Case(0, "model", "slow.al",
                     "CONSTANTS A, B, C, D\nE = EXPAND((A + B + C + D)^60)\n")
    quick = fuzz.Case(1, "model", "quick.al", "CONSTANTS A\nE = A^2\n")
    hang, after = fuzz.run_cases([slow, quick], jobs=1, timeout=1.0)
    assert (hang.outcome, after.outcome) == ("hang", "ok")
    assert 1.0 <= hang.seconds < 5


def test_a_file_written_outside_the_case_folder_is_an_escape(tmp_path, monkeypatch):
    (tmp_path / "cwd").mkdir()
    (tmp_path / "worker").mkdir()
    monkeypatch.chdir(tmp_path / "cwd")
    really_loads = fuzz.load_case

    def writes_into_the_cwd(path, text):
        (tmp_path / "cwd" / "escaped.c").write_text("")
        return "ok", "load", None
    monkeypatch.setattr(fuzz, "load_case", writes_into_the_cwd)
    case = fuzz.Case(0, "hostile", "m.al", "CODE DYNAMICS() escaped.c\n")
    result = fuzz.check_case(case, tmp_path / "worker")
    assert result["outcome"] == "escaped" and "escaped.c" in result["detail"]
    monkeypatch.setattr(fuzz, "load_case", really_loads)
    assert fuzz.check_case(case, tmp_path / "worker")["outcome"] == "ok"
