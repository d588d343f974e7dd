"""A bug in autolev is reported as one (AutolevInternalError; from the command line,
exit status 70 and no traceback unless AUTOLEV_TRACEBACK=1), never as the user's failed
statement; the model's own faults stay R001 diagnostics (tests/runtime/test_model_faults.py)."""
import pytest

import autolev
from autolev.cli import EXIT_INTERNAL, main

TINY = "NEWTONIAN N\nFRAMES A\nVARIABLES Q\nSIMPROT(N, A, 3, Q)\nX = DOT(A1>, N1>)\n"


@pytest.fixture
def tiny(tmp_path):
    path = tmp_path / "tiny.al"
    path.write_text(TINY)
    return path


@pytest.fixture
def broken_dot(monkeypatch):
    """A bug in the runtime: Vector.dot (which DOT calls) raises AttributeError."""
    from autolev.runtime.vectors import Vector

    def dot(self, other):
        raise AttributeError("'Frame' object has no attribute 'bogus'")
    monkeypatch.setattr(Vector, "dot", dot)


def test_a_runtime_bug_is_an_internal_error_at_the_statement(tiny, broken_dot):
    with pytest.raises(autolev.AutolevInternalError) as info:
        autolev.load(tiny)
    exc = info.value
    assert not isinstance(exc, autolev.AutolevError)      # never "the input's fault"
    assert (exc.location.file, exc.location.line) == (str(tiny), 5)
    assert exc.error == "AttributeError: 'Frame' object has no attribute 'bogus'"
    first, note = str(exc).splitlines()
    assert first == (f"{tiny}:5:1: internal error: a bug in autolev, not in the model, "
                     "while executing `X = DOT(A1>, N1>)`: AttributeError: 'Frame' object "
                     "has no attribute 'bogus'")
    assert note == (f"{tiny}:5:1: note: please report it to the autolev developers, with "
                    "the model and this message")
    assert isinstance(exc.__cause__, AttributeError)      # the traceback is kept


def test_running_out_of_memory_is_neither_the_models_fault_nor_a_bug(tiny, monkeypatch):
    from autolev.runtime.vectors import Vector

    def dot(self, other):
        raise MemoryError
    monkeypatch.setattr(Vector, "dot", dot)
    with pytest.raises(MemoryError):
        autolev.load(tiny)


@pytest.mark.parametrize("traceback_wanted", [False, True])
def test_the_cli_reports_an_internal_error_with_its_own_exit_status(
        tiny, broken_dot, capsys, monkeypatch, traceback_wanted):
    if traceback_wanted:
        monkeypatch.setenv("AUTOLEV_TRACEBACK", "1")
    else:
        monkeypatch.delenv("AUTOLEV_TRACEBACK", raising=False)
    assert main(["run", str(tiny), "--out", str(tiny.parent)]) == EXIT_INTERNAL == 70
    err = capsys.readouterr().err
    assert err.startswith(f"{tiny}:5:1: internal error: a bug in autolev, not in the model")
    assert "please report it to the autolev developers" in err
    assert ("Traceback" in err) == traceback_wanted
    assert ("AUTOLEV_TRACEBACK=1 shows where" in err) != traceback_wanted
    assert "[R001]" not in err


def test_the_exit_statuses_are_in_the_help(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "70 an internal error (a bug in autolev" in out and "AUTOLEV_TRACEBACK=1" in out


def test_a_converted_module_calling_a_broken_runtime_is_an_internal_error(
        tiny, broken_dot, tmp_path, capsys):
    converted = tmp_path / "tiny.py"
    assert main(["convert", str(tiny), "-o", str(converted), "-q"]) == 0
    line = converted.read_text().splitlines().index("X = al.dot(A.x, N.x)") + 1
    assert main(["run", str(converted), "--out", str(tmp_path)]) == EXIT_INTERNAL
    err = capsys.readouterr().err
    assert err.startswith(f"{converted}:{line}:1: internal error: a bug in autolev, not in "
                          "the model, while executing `X = DOT(A1>, N1>)`: AttributeError")


def test_a_converted_modules_own_python_that_fails_is_the_users(tiny, tmp_path, capsys):
    converted = tmp_path / "tiny.py"
    assert main(["convert", str(tiny), "-o", str(converted), "-q"]) == 0
    text = converted.read_text().replace("X = al.dot(A.x, N.x)", "X = A.x.bogus")
    converted.write_text(text)
    line = text.splitlines().index("X = A.x.bogus") + 1
    assert main(["run", str(converted), "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert (f"{converted}:{line}:1: error: this statement failed: AttributeError: 'Vector' "
            "object has no attribute 'bogus' (Autolev: X = DOT(A1>, N1>)) [R001]") in err
    assert "internal error" not in err


def test_a_bug_outside_any_statement_is_still_an_internal_error(tiny, monkeypatch, capsys):
    import autolev.cli.run

    def load_for_run(path, *options):
        raise RuntimeError("boom")
    # a model is built for its CODE commands, and only translated for its responses
    monkeypatch.setattr(autolev.cli.run, "load_model", load_for_run)
    monkeypatch.setattr(autolev.cli.run, "transcript_text", load_for_run)
    monkeypatch.delenv("AUTOLEV_TRACEBACK", raising=False)
    assert main(["run", str(tiny), "--out", str(tiny.parent)]) == EXIT_INTERNAL
    err = capsys.readouterr().err
    assert err.startswith(f"{tiny}: internal error: a bug in autolev, not in the model, "
                          "while running `autolev run`: RuntimeError: boom")
    assert "Traceback" not in err


def test_the_cli_says_out_of_memory_without_a_traceback(tiny, monkeypatch, capsys):
    import autolev.cli.run

    def load_for_run(path, *options):
        raise MemoryError
    monkeypatch.setattr(autolev.cli.run, "load_model", load_for_run)
    monkeypatch.setattr(autolev.cli.run, "transcript_text", load_for_run)
    assert main(["run", str(tiny), "--out", str(tiny.parent)]) == 1
    err = capsys.readouterr().err
    assert "out of memory" in err and "Traceback" not in err and "internal error" not in err


def test_an_internal_error_crosses_to_another_process_whole():
    # a bench's or a sweep's worker sends it back pickled: it was unreadable there
    import pickle

    from autolev.errors import AutolevInternalError
    sent = AutolevInternalError("m.al:3:1", "building the model", KeyError("Z9"))
    got = pickle.loads(pickle.dumps(sent))
    assert type(got) is AutolevInternalError
    assert (str(got), got.location, got.did, got.error) == (
        str(sent), "m.al:3:1", "building the model", "KeyError: 'Z9'")
