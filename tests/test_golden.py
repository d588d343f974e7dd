"""Each example's translation equals its golden file (tests/golden/NAME.py), and its SymPy
script its own (tests/golden/sympy/NAME_sympy.py).

Update goldens only with `python tools/update_goldens.py`, and read the diff."""
import difflib

import pytest

import autolev
from helpers import EXAMPLES, ROOT

GOLDEN = ROOT / "tests" / "golden"
MODELS = sorted(EXAMPLES.glob("*.al"))


def test_every_example_has_a_golden():
    assert MODELS
    assert {m.stem for m in MODELS} == {g.stem for g in GOLDEN.glob("*.py")}


@pytest.mark.parametrize("model", MODELS, ids=lambda p: p.stem)
def test_translation_matches_golden(model):
    expected = (GOLDEN / (model.stem + ".py")).read_text()
    got = autolev.transpile(model)
    if got != expected:
        diff = "".join(difflib.unified_diff(expected.splitlines(True), got.splitlines(True),
                                            "golden", "now"))
        pytest.fail("translation differs from the golden file; if intended, run "
                    "python tools/update_goldens.py and read the diff\n" + diff)


@pytest.mark.parametrize("model", MODELS, ids=lambda p: p.stem)
def test_golden_module_builds_its_model(model):
    """The golden text itself runs (imports) and forms the equations."""
    namespace = {"__name__": "golden_" + model.stem}
    exec(compile((GOLDEN / (model.stem + ".py")).read_text(), str(model), "exec"), namespace)
    m = namespace["model"]
    assert m.kane_equations is not None
    assert m.mass_matrix.shape[0] == len(m.speeds) > 0


@pytest.mark.parametrize("model", MODELS, ids=lambda p: p.stem)
def test_the_sympy_script_matches_its_golden(model):
    """`autolev convert --to sympy`'s script of each example (tests/golden/sympy)."""
    expected = (GOLDEN / "sympy" / (model.stem + "_sympy.py")).read_text()
    got = autolev.export_sympy(autolev.load(model), model.name)
    if got != expected:
        diff = "".join(difflib.unified_diff(expected.splitlines(True), got.splitlines(True),
                                            "golden", "now"))
        pytest.fail("the SymPy script differs from its golden file; if intended, run "
                    "python tools/update_goldens.py and read the diff\n" + diff)
