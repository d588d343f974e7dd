"""A kept answer's key: every field of its request, and the files it names as they
were read (request.py); what a command read, noted when it read it
(runtime/reading.py)."""
import dataclasses

import pytest

from autolev.engine import keeping, runplan
from autolev.engine.request import (
    LinearizeRequest, Request, RunRequest, TranscriptRequest, ValuesRequest)
from autolev.engine import reading
from autolev.source import find_file

REQUESTS = [RunRequest, LinearizeRequest, TranscriptRequest]


def _a_request(kind, model, infile):
    """A request of `kind` with a value of each field's type."""
    values = {"model": str(model), "folder": ""}
    for field in dataclasses.fields(kind):
        if field.name in values:
            continue
        if field.name == "infile":
            values[field.name] = str(infile)
        elif field.name == "environment":
            values[field.name] = (("CC", ""),)
        elif field.name in ("backend", "method", "inputs", "code") and \
                field.type in ("str", "str | None"):
            values[field.name] = "c"
        elif field.type == "bool":
            values[field.name] = False
        elif field.type == "float | None":
            values[field.name] = 1.5
        else:
            values[field.name] = ("A=1",)
    return kind(**values)


def _changed(value):
    if isinstance(value, bool):
        return not value
    if isinstance(value, float):
        return value * 2
    if isinstance(value, tuple):
        return value + (("X", "1"),)
    return value + "x"


@pytest.fixture
def files(tmp_path):
    model, infile = tmp_path / "m.al", tmp_path / "m.in"
    model.write_text("CONSTANTS A\n")
    infile.write_text("values\n")
    # the same contents under the changed names (_changed): only the field differs
    (tmp_path / "m.alx").write_text("CONSTANTS A\n")
    (tmp_path / "m.inx").write_text("values\n")
    return model, infile


@pytest.mark.parametrize("kind", REQUESTS, ids=lambda k: k.__name__)
def test_every_field_of_a_request_is_in_its_key(kind, files):
    # a field added to a request changes the key without anyone remembering to
    base = _a_request(kind, *files)
    key = base.key(reading.Reads())
    assert key is not None
    for field in dataclasses.fields(kind):
        other = dataclasses.replace(base, **{field.name: _changed(getattr(base, field.name))})
        changed = other.key(reading.Reads())
        assert changed is not None and changed != key, field.name


def test_the_requests_are_the_commands_that_keep_answers():
    # each kept answer's command has its request, and nothing else derives a key
    assert {k.__name__ for k in REQUESTS} == {k.__name__ for k in _subclasses(Request)
                                             if k is not ValuesRequest}


def _subclasses(kind):
    found = set()
    for sub in kind.__subclasses__():
        found |= {sub} | _subclasses(sub)
    return found


@pytest.mark.parametrize("which", [0, 1], ids=["model", "infile"])
def test_a_named_files_content_is_in_the_key_as_first_read(which, files):
    request = _a_request(RunRequest, *files)
    reads = reading.Reads()
    key = request.key(reads)
    files[which].write_text("edited\n")
    assert request.key(reads) == key                   # as read, not as it is now
    assert request.key(reading.Reads()) != key         # read afresh: another key


def test_a_file_read_twice_with_other_bytes_tears_the_record(tmp_path):
    path = tmp_path / "x.in"
    path.write_text("one")
    with reading.recording() as reads:
        reading.read_bytes(path)
        reading.read_bytes(path)
        assert reads.torn == []
        path.write_text("two")
        reading.read_bytes(path)
    assert reads.torn == [str(path)]


def test_a_nested_record_passes_its_reads_out(tmp_path):
    path = tmp_path / "x.in"
    path.write_text("one")
    with reading.recording() as outer:
        with reading.recording() as inner:
            reading.read_bytes(path)
        assert inner.has_read(path) and outer.has_read(path)
        path.write_text("two")
        reading.read_bytes(path)
    assert outer.torn == [str(path)] and inner.torn == []


def test_a_snapshot_holds_while_files_and_searches_answer_as_they_did(tmp_path):
    model = tmp_path / "m.al"
    model.write_text("A")
    with reading.recording() as reads:
        reading.read_bytes(model)
        assert find_file(tmp_path, "mac.a") is None
        unreadable = tmp_path / "gone.al"
        with pytest.raises(OSError):
            reading.read_bytes(unreadable)
    snapshot = reads.snapshot()
    assert snapshot.holds()
    (tmp_path / "MAC.A").write_text("X = 1\n")       # the search now finds a file
    assert not snapshot.holds()
    (tmp_path / "MAC.A").unlink()
    assert snapshot.holds()
    unreadable.write_text("now here")                 # a file that was missing
    assert not snapshot.holds()
    unreadable.unlink()
    model.write_text("B")
    assert not snapshot.holds()


def test_a_kept_answer_is_filed_under_the_files_as_read_not_as_at_keeping(files, tmp_path,
                                                                         monkeypatch):
    # the background compile keeps a plan seconds after the run read its files: an
    # edit in between must not file the old answer under the new content
    monkeypatch.setenv("AUTOLEV_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("AUTOLEV_NO_MODEL_CACHE", raising=False)
    model, infile = files
    request = _a_request(RunRequest, model, infile)
    with reading.recording() as reads:
        assert keeping.kept(request, reads, lambda: runplan.KeptOutcome) is None
        reading.read_bytes(model)
    infile.write_text("edited\n")                        # before the answer is kept
    keeping.keep(request, reads, lambda r: runplan.KeptOutcome(r, "", "old", 0))
    assert keeping.kept(request, reading.Reads(), lambda: runplan.KeptOutcome) is None
    infile.write_text("values\n")                        # as the answer read it
    found = keeping.kept(request, reading.Reads(), lambda: runplan.KeptOutcome)
    assert found is not None and found.transcript == "old"


def test_nothing_is_kept_of_work_that_read_two_states_of_a_file(files, tmp_path,
                                                               monkeypatch):
    monkeypatch.setenv("AUTOLEV_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("AUTOLEV_NO_MODEL_CACHE", raising=False)
    model, infile = files
    request = _a_request(RunRequest, model, infile)
    with reading.recording() as reads:
        assert keeping.kept(request, reads, lambda: runplan.KeptOutcome) is None
        model.write_text("CONSTANTS B\n")
        reading.read_bytes(model)                        # the translation read another
    assert reads.torn
    keeping.keep(request, reads, lambda r: runplan.KeptOutcome(r, "", "mixed", 0))
    for text in ("CONSTANTS A\n", "CONSTANTS B\n"):
        model.write_text(text)
        assert keeping.kept(request, reading.Reads(), lambda: runplan.KeptOutcome) is None
