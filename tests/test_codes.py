"""The registry of diagnostic codes (src/autolev/codes.py): every code the sources give
is registered, every registered code is given, each means what the registry says (a
small model that makes it), and docs/language.md's table is the registry's."""
import json
import re
from pathlib import Path

import pytest

from autolev import codes
from autolev.cli import main
from autolev.errors import AutolevRuntimeError
from autolev.loader import run_python

ROOT = Path(__file__).resolve().parent.parent
SOURCES = ROOT / "src" / "autolev"

# a model (and the files beside it) that makes each code; the codes not here are made
# by the tests named in MADE_ELSEWHERE
MAKERS = {
    "E001": ("X = $\n", {}),
    "E002": ("X = (1 +)\n", {}),
    "E003": ("X = SIN(1\n", {}),
    "E004": ("X = " + "(" * 3000 + "1" + ")" * 3000 + "\n", {}),
    "E005": ("VARIABLES\n", {}),
    "E006": ("VARIABLES Q\nX = Q '\n", {}),
    "E010": ("SIMPORT N, A, 3, Q\n", {}),
    "E011": ("CODE DYNAMIC() m.c\n", {}),
    "E012": ("CODE DYNAMICS() m.c, FAST\n", {}),
    "E013": ("CODE DYNAMICS() my file.c\n", {}),
    "E014": ("DIGITS 0.5\n", {}),
    "E021": ("RUN ../x.al\n", {}),
    "E022": ("RUN nothere.al\n", {}),
    "E023": ("RUN m.al\n", {}),
    "E030": ("two(a)\n", {"two.a": "x = #1# + #2#\n"}),
    "E031": ("X = F(1)\n", {"f.r": "F(#1#)\n"}),
    "E032": ("X = F(1)\n", {"f.r": "Y = #1#\nZ = 2\n"}),
    "E040": ("VARIABLES Q{3:1}\n", {}),
    "E041": ("VARIABLES Q{1:2000000}\n", {}),
    "E042": ("BODIES B\nMASS B=2=3\n", {}),
    "E043": ("BODIES B\nINERTIA B, 2=1, 1, 1\n", {}),
    "E044": ("BODIES B\nINERTIA B, 1, 2, 3, 4\n", {}),
    "E045": ("X = " + "9" * 5000 + "\n", {}),
    "W001": ("VARIABLES Q\nVARIABLES Q\n", {}),
    "W002": ("VARIABLES Q\nCONSTANTS Q\n", {}),
    "W101": ("NEWTONIAN N\nPOINTS P, NO\n", {}),
    "W103": ("X = 1\nEXIT\nY = 2\n", {}),
    "W104": ("INPUT ZZ = 1\n", {}),
    "W105": ("VARIABLES T\n", {}),
    "W106": ("X = COS(1)\n", {"cos.R": "#1#\n"}),
    "W107": ("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q'\nSIMPROT(N, A, 3, Q)\n"
             "X = FRSTAR()\n", {}),
    "T001": ("NEWTONIAN N\nX = 1/N1>\n", {}),
    "T002": ("X = Q9\n", {}),
    "T003": ("X = FOO(1)\n", {}),
    "T004": ("X = " + "SIN(" * 40 + "1" + ")" * 40 + "\n", {}),
    "T005": ("X = 10^(10^10)\n", {}),
    "T006": ("VARIABLES Q{2}\nM = [Q1, Q2]\nX = M'[1]\n", {}),
    "T007": ("X = SIN(1, 2)\n", {}),
    "T008": ("CONSTANTS Q\nMASS Q=1\n", {}),
    "T009": ("X = EVALUATE(1, 2)\n", {}),
    "T010": ("NEWTONIAN N\nN1> = 0>\n", {}),
}
# files 1.al .. 33.al, each RUNning the next
MAKERS["E024"] = ("RUN 1.al\n", {f"{k}.al": f"RUN {k + 1}.al\n" for k in range(1, 34)})
MADE_ELSEWHERE = {
    "E000": "test_a_file_that_cannot_be_read_is_E000 below",
    "E007": "tests/test_dispatch.py",
    "E020": "tests/test_source.py", "E025": "tests/test_source.py",
    "E033": "tests/test_include.py", "R001": "tests/runtime/test_model_faults.py",
    "R002": "test_a_python_translation_that_is_not_python_is_R002 below",
    "R003": "test_a_python_translation_without_a_model_is_R003 below",
}


def codes_in_sources() -> set[str]:
    found = set()
    for path in SOURCES.rglob("*.py"):
        if "_antlr" in path.parts or path.name == "codes.py":
            continue
        found |= set(re.findall(r"[\"']([EWTR]\d{3})[\"']", path.read_text()))
    return found


def test_every_code_given_is_registered_and_every_registered_code_is_given():
    used = codes_in_sources()
    assert used - set(codes.CODES) == set()
    assert set(codes.CODES) - used == set()


def test_every_code_has_a_maker_or_a_test_that_makes_it():
    assert set(MAKERS) | set(MADE_ELSEWHERE) == set(codes.CODES)
    assert set(MAKERS).isdisjoint(MADE_ELSEWHERE)


@pytest.mark.parametrize("code", sorted(MAKERS))
def test_the_model_of_a_code_is_given_that_code(code, tmp_path, capsys):
    text, beside = MAKERS[code]
    folder = tmp_path / "model"
    folder.mkdir()
    (folder / "m.al").write_text(text)
    for name, content in beside.items():
        (folder / name).write_text(content)
    main(["check", "--json", str(folder / "m.al")])
    (report,) = json.loads(capsys.readouterr().out)["files"]
    given = {d["code"] for d in report["diagnostics"]}
    assert code in given
    severity = {d["code"]: d["severity"] for d in report["diagnostics"]}[code]
    assert severity == ("warning" if code.startswith("W") else "error")


def test_the_table_in_the_rules_is_the_registry():
    text = (ROOT / "docs" / "language.md").read_text()
    table = text.split("<!-- codes:begin -->\n")[1].split("<!-- codes:end -->")[0]
    assert table == codes.markdown()


def test_a_pipe_in_a_meaning_does_not_break_the_table():
    assert codes._cell("a | b") == "a \\| b"


def test_a_file_that_cannot_be_read_is_E000(tmp_path, capsys):
    (tmp_path / "m.al").symlink_to(tmp_path / "nowhere.al")
    assert main(["check", "--json", str(tmp_path / "m.al")]) == 1
    (report,) = json.loads(capsys.readouterr().out)["files"]
    assert [d["code"] for d in report["diagnostics"]] == ["E000"]


def test_a_python_translation_that_is_not_python_is_R002():
    with pytest.raises(AutolevRuntimeError) as info:
        run_python("model = (\n", "m.py")
    assert info.value.diagnostics[0].code == "R002"


def test_a_python_translation_without_a_model_is_R003():
    with pytest.raises(AutolevRuntimeError) as info:
        run_python("x = 1\n", "m.py")
    assert info.value.diagnostics[0].code == "R003"
