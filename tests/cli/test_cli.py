"""The `autolev` command line: check, --version, --help."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import autolev
from autolev.cli import main
from helpers import EXAMPLES


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


def test_check_reports_what_the_translation_would_refuse(tmp_path, capsys):
    f = tmp_path / "names.al"
    f.write_text("NEWTONIAM N\nCONSTANTS A\nY = A + C + D*SIN(E)\nZ = COSS(A)\n")
    code, out, _ = run(capsys, "check", str(f))
    assert code == 1
    assert "did you mean NEWTONIAN?" in out
    # the syntax first: the translation's findings come when the model reads
    f.write_text("CONSTANTS A\nY = A + C + D*SIN(E)\nZ = COSS(A)\nW> = V>\n")
    code, out, _ = run(capsys, "check", str(f))
    assert code == 1
    errors = [ln for ln in out.splitlines() if ": error: " in ln]
    assert [e.split(": error: ")[0].rsplit(":", 2)[1:] for e in errors] == \
        [["2", "9"], ["2", "13"], ["2", "19"], ["3", "5"], ["4", "6"]]
    assert "unknown function COSS(): " in errors[3] and "COS" in errors[3].split("did you mean")[1]
    assert out.splitlines()[-1].startswith("checked 1 file: 5 errors")


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


# -- autolev run -----------------------------------------------------------------------------
def test_run_writes_autolevs_files(tmp_path, capsys):
    code, out, err = run(capsys, "run", str(EXAMPLES / "double_pendulum.al"), "--out",
                         str(tmp_path), "--tfinal", "0.5", "-q")
    assert code == 0, err
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["double_pendulum.1", "double_pendulum.2", "double_pendulum.dir",
                     "double_pendulum.in"]
    rows = [line for line in (tmp_path / "double_pendulum.1").read_text().splitlines()
            if line and not line.startswith("%")]
    assert len(rows) == 51 and rows[0].split()[:3] == ["0.000000E+00", "3.000000E+01",
                                                       "6.000000E+01"]


def test_run_set_changes_an_input_in_its_unit(tmp_path, capsys):
    code, _, err = run(capsys, "run", str(EXAMPLES / "double_pendulum.al"), "--out",
                       str(tmp_path), "--tfinal", "0", "--set", "Q1=10", "-q")
    assert code == 0, err
    row = (tmp_path / "double_pendulum.1").read_text().splitlines()[5].split()
    assert row[1] == "1.000000E+01"


@pytest.mark.parametrize("argv, message", [
    (["--set", "Q1"], "--set expects NAME=VALUE"),
    (["--method", "euler"], "unknown --method euler"),
])
def test_run_refuses_bad_options(tmp_path, capsys, argv, message):
    code, _, err = run(capsys, "run", str(EXAMPLES / "double_pendulum.al"), "--out",
                       str(tmp_path), *argv)
    assert code == 2 and message in err
    assert not any(tmp_path.iterdir())


def test_run_with_a_value_that_is_not_a_number_writes_nothing(tmp_path, capsys):
    code, _, err = run(capsys, "run", str(EXAMPLES / "double_pendulum.al"), "--out",
                       str(tmp_path), "--set", "Q1=abc", "-q")
    # a usage error (issue 29): the model is not at fault
    assert code == 2 and "--set Q1=abc: abc is not a finite number" in err
    assert not any(tmp_path.iterdir())


def test_run_of_a_model_with_errors_writes_nothing(tmp_path, capsys):
    f = tmp_path / "bad.al"
    f.write_text("VARIABLES X'\nX' = -Y\nCODE DYNAMICS() bad.c\n")
    out_dir = tmp_path / "out"
    code, _, err = run(capsys, "run", str(f), "--out", str(out_dir))
    assert code == 1
    assert f"{f}:2:7: error" in err and "not run" in err
    assert not out_dir.exists()


def test_run_reports_an_integration_failure_at_the_code_line_and_keeps_rows(tmp_path,
                                                                           capsys):
    f = tmp_path / "stiff.al"
    f.write_text("VARIABLES X'\nCONSTANTS LAMBDA\nX' = -LAMBDA*X\n"
                 "INPUT LAMBDA = 1.0E+09, X = 1\nOUTPUT T, X\nCODE DYNAMICS() stiff.c\n")
    code, _, err = run(capsys, "run", str(f), "--out", str(tmp_path), "-q")
    assert code == 1
    assert f"{f}:6: Numerical integration failed to converge" in err
    assert "1.000000E+00" in (tmp_path / "stiff.1").read_text()


def test_run_reports_a_bad_code_command_at_its_line(tmp_path, capsys):
    f = tmp_path / "m.al"
    f.write_text("VARIABLES X, Y\nEQ[1] = X + Y\nCODE ALGEBRAIC(EQ, X, Y) m.c\n")
    code, _, err = run(capsys, "run", str(f), "--out", str(tmp_path), "-q")
    assert code == 1
    assert f"{f}:3: error: CODE ALGEBRAIC: 1 equations for 2 unknowns" in err


def test_run_warns_when_two_code_commands_write_the_same_files(tmp_path, capsys):
    f = tmp_path / "two.al"
    f.write_text("VARIABLES X'\nX' = -X\nINPUT X = 1\nOUTPUT X\nCODE DYNAMICS() two.c\n"
                 "CODE DYNAMICS() two.m\n")
    code, out, err = run(capsys, "run", str(f), "--out", str(tmp_path / "out"), "-q")
    assert code == 0
    assert "two.al:6: warning: CODE two.m writes the same files (two.1, ...)" in err
    assert "as CODE two.c" in err


def test_a_converted_module_without_code_says_there_is_nothing_to_run(tmp_path):
    # shanecelis/sussex-thesis-doc's frog.al has no CODE: `python frog.py` exited 2 with
    # "a transcript is made from the .al model", a usage error the user did not make
    model = tmp_path / "nocode.al"
    model.write_text("CONSTANTS K\nX = 2*K\n")
    assert main(["convert", str(model), "-o", str(tmp_path / "nocode.py"), "-q"]) == 0
    done = subprocess.run([sys.executable, str(tmp_path / "nocode.py")],
                          capture_output=True, text=True)
    assert done.returncode == 0 and done.stdout == ""
    assert "no CODE command: nothing to run" in done.stderr
    # the .al model itself still shows its responses
    shown = subprocess.run([sys.executable, "-m", "autolev", "run", str(model)],
                           capture_output=True, text=True)
    assert shown.returncode == 0 and "-> (3) X = 2*K" in shown.stdout


def test_convert_makes_the_folder_its_module_goes_into(tmp_path, capsys):
    # `-o /missing/x.py` said "leads outside /missing"
    from autolev.cli import main
    target = tmp_path / "new" / "sub" / "dp.py"
    assert main(["convert", str(EXAMPLES / "double_pendulum.al"), "-o", str(target)]) == 0
    assert target.is_file() and "leads outside" not in capsys.readouterr().err


def test_a_relative_cache_setting_is_said_once(tmp_path):
    import os
    import subprocess
    import sys
    env = dict(os.environ, AUTOLEV_CACHE="relative/cache", AUTOLEV_FOREGROUND="1")
    done = subprocess.run([sys.executable, "-m", "autolev", "run",
                           EXAMPLES / "double_pendulum.al", "--out", tmp_path, "-q"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    assert done.stderr.count("AUTOLEV_CACHE=relative/cache is not an absolute path") == 1


# Ctrl-C while the command starts, before main takes it: no traceback (issue 50)
_INTERRUPTED_IMPORT = """
import runpy, sys
interrupted = sys.argv[1]
class Interrupt:
    def find_spec(self, name, path, target=None):
        if name == interrupted:
            raise KeyboardInterrupt
sys.meta_path.insert(0, Interrupt())
sys.argv = ["autolev", "--version"]
runpy.run_module("autolev", run_name="__main__", alter_sys=True)
"""


@pytest.mark.parametrize("module", ["autolev.errors", "autolev.cli.background"])
def test_an_interrupt_while_the_command_starts_ends_it_without_a_traceback(module):
    # SIGINT while `python -m autolev` imported its package or its command line
    done = subprocess.run([sys.executable, "-c", _INTERRUPTED_IMPORT, module],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 130, done.stderr
    assert "Traceback" not in done.stderr and "KeyboardInterrupt" not in done.stderr


def test_an_interrupt_while_the_command_line_is_read_is_exit_130(monkeypatch):
    from autolev import cli

    def interrupted():
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "build_parser", interrupted)
    assert cli.entry() == 130


def test_the_command_once_over_leaves_no_fork_to_later_callers_of_main(monkeypatch):
    # a test calling entry() left it allowed: every later in-process `run` forked pytest
    from autolev import cli
    from autolev.cli import background
    monkeypatch.setattr(sys, "argv", ["autolev", "--version"])
    with pytest.raises(SystemExit):
        cli.entry()
    assert not background.allowed()
    assert background.split_off(Path(".")) is None


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full (Linux)")
@pytest.mark.parametrize("command", [["check"], ["convert"], ["run", "--out", "{tmp}"]])
@pytest.mark.parametrize("streams", ["output", "output and error"])
def test_a_full_disk_under_the_output_is_said_not_an_internal_error(command, streams,
                                                                    tmp_path):
    # `autolev check x.al > file` on a full disk was exit 70, "a bug in autolev"
    argv = [a.replace("{tmp}", str(tmp_path / "out")) for a in command]
    errors = tmp_path / "errors"
    model = tmp_path / "double_pendulum.al"
    model.write_text((EXAMPLES / "double_pendulum.al").read_text())
    with open("/dev/full", "w") as full, open(errors, "w") as said:
        done = subprocess.run([sys.executable, "-m", "autolev", argv[0], str(model),
                               *argv[1:]],
                              stdout=full, stderr=full if streams != "output" else said,
                              cwd=tmp_path, timeout=120)
    assert done.returncode == 1
    if streams == "output":
        text = errors.read_text()
        assert "cannot write its output: No space left on device" in text
        assert "internal error" not in text and "Traceback" not in text
