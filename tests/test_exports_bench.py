"""bench/exports.py: a model converted as it stands, its script imported without autolev;
a model with nothing to export refused with autolev's reason."""
import importlib.util
import sys

from helpers import EXAMPLES, ROOT

sys.path.insert(0, str(ROOT / "bench"))
spec = importlib.util.spec_from_file_location("exports", ROOT / "bench" / "exports.py")
exports = importlib.util.module_from_spec(spec)
spec.loader.exec_module(exports)


def test_a_model_is_converted_and_its_script_imported_without_autolev(tmp_path):
    row = exports.one("simple_pendulum", EXAMPLES / "simple_pendulum.al", sys.executable, 300)
    assert (row["outcome"], row["level"], row["lacking"]) == ("converted", "mechanics", 0)
    # without values: converted all the same, its constants None in the script
    bare = tmp_path / "bare.al"
    bare.write_text("\n".join(line for line in (EXAMPLES / "simple_pendulum.al")
                              .read_text().splitlines()
                              if not line.upper().startswith("INPUT")) + "\n")
    row = exports.one("bare", bare, sys.executable, 300)
    assert row["outcome"] == "converted" and row["lacking"] > 0, row


def test_a_model_without_equations_of_motion_is_refused_with_the_reason(tmp_path):
    path = tmp_path / "kinematics.al"
    path.write_text("NEWTONIAN N\nFRAMES A\nVARIABLES Q\nSIMPROT(N, A, 3, Q)\n")
    row = exports.one("kinematics", path, sys.executable, 300)
    assert row["outcome"] == "refused" and "no CODE DYNAMICS or ODE" in row["detail"], row


def test_a_model_error_is_the_refusals_reason_not_its_last_line(tmp_path):
    path = tmp_path / "dangling.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q', U'\nCONSTANTS M\n"
                    "MASS A = M\nINERTIA A, 1, 1, 1\nSIMPROT(N, A, 3, Q)\nQ' = U\n"
                    "ZERO = FR() + FRSTAR()\nKANE()\nCODE DYNAMICS() d.c\n")
    row = exports.one("dangling", path, sys.executable, 300)
    assert row["outcome"] == "refused" and "velocity of AO in N is not defined" \
        in row["detail"], row
