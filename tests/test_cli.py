"""The `autolev` command line: check, --version, --help."""
import json
import subprocess
import sys

import pytest

import autolev
from autolev.cli import main
from conftest import EXAMPLES


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_check_clean_file(capsys):
    code, out, _ = run(capsys, "check", str(EXAMPLES / "double_pendulum.al"))
    assert code == 0
    assert out.strip() == "checked 1 file: 0 errors, 0 warnings"


def test_check_reports_file_line_col_and_exits_1(tmp_path, capsys):
    f = tmp_path / "bad.al"
    f.write_text("x = 1\ny = (2\nFOO BAR\n")
    code, out, _ = run(capsys, "check", str(f))
    assert code == 1
    lines = out.splitlines()
    assert lines[0] == f"{f}:2:7: error: unexpected end of line; expected ')' [E003]"
    assert any(line.startswith(f"{f}:3:1: error: unknown setting or command 'FOO'")
               for line in lines)
    assert lines[-1] == "checked 1 file: 2 errors, 0 warnings (1 file with errors)"


def test_check_json(tmp_path, capsys):
    f = tmp_path / "bad.al"
    f.write_text("x = )\nVARIABLES v\nVARIABLES v\n")
    code, out, _ = run(capsys, "check", "--json", str(f))
    assert code == 1
    data = json.loads(out)
    assert data["summary"] == {"files": 1, "files_with_errors": 1, "errors": 1, "warnings": 1}
    diags = data["files"][0]["diagnostics"]
    assert [(d["line"], d["col"], d["severity"], d["code"]) for d in diags] == [
        (1, 5, "error", "E002"), (3, 11, "warning", "W001")]


def test_check_several_files_and_a_folder(tmp_path, capsys):
    (tmp_path / "a.al").write_text("x = 1\n")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "B.AL").write_text("y = )\n")
    (tmp_path / "notes.txt").write_text("not a model")
    code, out, _ = run(capsys, "check", "--no-context", str(tmp_path))
    assert code == 1
    assert "B.AL:1:5: error" in out
    assert out.splitlines()[-1] == "checked 2 files: 1 error, 0 warnings (1 file with errors)"


def test_check_missing_file(tmp_path, capsys):
    code, out, _ = run(capsys, "check", str(tmp_path / "none.al"))
    assert code == 1
    assert "cannot read" in out


def test_check_a_macro_file_on_its_own(tmp_path, capsys):
    (tmp_path / "contact.a").write_text("y#1# = dot(P_O_#1#>, N2>)\nF#1#> = y#1#*N2>\n")
    code, out, _ = run(capsys, "check", str(tmp_path / "contact.a"))
    assert code == 0, out
    (tmp_path / "bad.a").write_text("y#1# = (\n")
    code, out, _ = run(capsys, "check", str(tmp_path / "bad.a"))
    assert code == 1 and "bad.a:1:9: error" in out


def test_quiet_hides_warnings(tmp_path, capsys):
    f = tmp_path / "w.al"
    f.write_text("VARIABLES v\nVARIABLES v\n")
    code, out, _ = run(capsys, "check", "-q", str(f))
    assert code == 0 and "warning:" not in out.split("\n")[0]


def test_version_and_help():
    r = subprocess.run([sys.executable, "-m", "autolev.cli", "--version"],
                       capture_output=True, text=True)
    assert r.returncode == 0 and r.stdout.strip() == f"autolev {autolev.__version__}"
    r = subprocess.run([sys.executable, "-m", "autolev.cli", "--help"],
                       capture_output=True, text=True)
    assert r.returncode == 0 and "check" in r.stdout
    r = subprocess.run([sys.executable, "-m", "autolev.cli", "check", "--help"],
                       capture_output=True, text=True)
    assert r.returncode == 0 and "--json" in r.stdout


def test_no_command_prints_help_and_exits_2(capsys):
    code, out, _ = run(capsys)
    assert code == 2 and "usage:" in out


def test_no_traceback_for_a_bad_model(tmp_path):
    f = tmp_path / "m.al"
    f.write_bytes(b"\x00\xff\xfe x = ((((\n" + b"(" * 5000 + b"\n")
    r = subprocess.run([sys.executable, "-m", "autolev.cli", "check", str(f)],
                       capture_output=True, text=True)
    assert r.returncode == 1
    assert "Traceback" not in r.stdout + r.stderr
