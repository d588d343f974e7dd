"""A fixed-seed handful of bench/fuzz.py's mutants: none may end in a traceback."""
import importlib.util
import random

from conftest import EXAMPLES, ROOT

spec = importlib.util.spec_from_file_location("fuzz", ROOT / "bench" / "fuzz.py")
fuzz = importlib.util.module_from_spec(spec)
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
