"""The emitter's layout of long lines (translate/emit.py) and how wide the goldens are."""
from autolev.translate.emit import MAX_WIDTH, assign_names, call_lines, quoted_names
from helpers import ROOT

GOLDEN = ROOT / "tests" / "golden"


def test_a_long_assignment_wraps_its_names_within_the_width():
    names = [f"NAME{i}" for i in range(40)]
    lines = assign_names(names, "model.constants('...')").split("\n")
    assert len(lines) > 1 and all(len(line) <= MAX_WIDTH for line in lines)
    assert lines[0].startswith("(NAME0, ") and lines[-1].endswith(") = model.constants('...')")


def test_an_assignment_whose_names_fit_one_line_stays_one_line():
    # wrapping would only put the names in parentheses: the long part is the call
    line = assign_names(["A", "B"], "f(" + "x" * MAX_WIDTH + ")")
    assert line == "A, B = f(" + "x" * MAX_WIDTH + ")"


def test_long_quoted_names_are_adjacent_literals_of_the_same_text():
    names = [f"NAME{i}" for i in range(40)]
    text = quoted_names(names)
    assert text.startswith("('") and eval(text) == " ".join(names)
    assert quoted_names(["A", "B"]) == "'A B'"


def test_a_long_call_puts_one_item_per_line():
    assert call_lines("f(", ["a", "b"]) == "f(a, b)"
    items = [f"item{i}" for i in range(30)]
    assert call_lines("f(", items).split("\n") == ["f(", *(f"    {i}," for i in items), ")"]
    assert call_lines("m([", items, "])").split("\n")[-1] == "])"


def test_the_goldens_over_the_width_are_only_those_known():
    # (the examples' translations are the goldens, test_golden.py) one-line declarations
    # whose names fit (the call is the long part), the model's own long lines echoed as
    # comments, and INERTIA's expressions: none of these is broken today
    over = {g.stem: sum(len(line) > MAX_WIDTH for line in g.read_text().splitlines())
            for g in GOLDEN.glob("*.py")}
    assert {k: n for k, n in over.items() if n} == {"fourbar": 1, "rolling_disc": 1,
                                                   "whipple_benchmark": 7}
