"""Outputs never follow planted links, never leave their folder, and are whole or
absent (issue 31, item 5; issue 30, item 8: one writer of files)."""
import subprocess
import sys

import pytest

from autolev.engine import outputs
from helpers import EXAMPLES

PENDULUM = EXAMPLES / "simple_pendulum.al"


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "autolev", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd)


@pytest.fixture
def victim(tmp_path):
    """A file of the user's outside the output folder, e.g. their .bashrc."""
    path = tmp_path / "home" / ".bashrc"
    path.parent.mkdir()
    path.write_text("export PATH=$PATH:~/bin\n")
    return path


def planted(out, name, victim):
    out.mkdir(exist_ok=True)
    (out / name).symlink_to(victim)
    return out / name


def unharmed(victim, link):
    assert victim.read_text() == "export PATH=$PATH:~/bin\n"
    assert link.is_file() and not link.is_symlink()


def test_the_writer_replaces_a_link_instead_of_writing_through_it(tmp_path, victim):
    link = planted(tmp_path / "out", "a.csv", victim)
    outputs.write_whole(link, "1,2\n")
    unharmed(victim, link)
    assert link.read_text() == "1,2\n"


def test_a_failed_write_leaves_neither_file_nor_temporary(tmp_path, monkeypatch):
    target = tmp_path / "m.py"
    target.write_text("old\n")

    def refuse(src, dst):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(outputs.os, "replace", refuse)
    with pytest.raises(OSError):
        outputs.write_whole(target, "new\n")
    assert target.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.py"]


def test_a_name_may_not_lead_outside_its_folder(tmp_path, victim):
    out = tmp_path / "out"
    out.mkdir()
    (out / "sub").symlink_to(victim.parent, target_is_directory=True)
    for name in ("sub/prog.c", "../prog.c", "new/../../prog.c"):
        with pytest.raises(outputs.OutsideFolder):
            outputs.inside(out, name)
    assert outputs.inside(out, "deep/er/prog.c") == out / "deep" / "er" / "prog.c"
    assert (out / "deep" / "er").is_dir()


def test_plots_and_the_run_replace_planted_links(tmp_path, victim):
    pytest.importorskip("matplotlib")
    out = tmp_path / "out"
    links = [planted(out, name, victim) for name in
             ("simple_pendulum.1", "simple_pendulum.1.png", "simple_pendulum.dir")]
    r = cli("run", PENDULUM, "--out", out, "--plot", "-q")
    assert r.returncode == 0, r.stderr
    for link in links:
        unharmed(victim, link)


def test_linearize_out_replaces_a_planted_link(tmp_path, victim):
    out = tmp_path / "out"
    link = planted(out, "double_pendulum-eigenvalues.csv", victim)
    r = cli("linearize", EXAMPLES / "double_pendulum.al", "--out", out)
    assert r.returncode == 0, r.stderr
    unharmed(victim, link)
    assert link.read_text().startswith("real,imaginary")


def test_transcript_and_convert_replace_planted_links(tmp_path, victim):
    out = tmp_path / "out"
    link = planted(out, "simple_pendulum.all", victim)
    assert cli("transcript", PENDULUM, "--out", out).returncode == 0
    unharmed(victim, link)
    module = planted(out, "m.py", victim)
    assert cli("convert", PENDULUM, "-o", module).returncode == 0
    unharmed(victim, module)


def test_code_refuses_a_linked_sub_folder_and_writes_nothing(tmp_path, victim):
    model = tmp_path / "m.al"
    model.write_text(PENDULUM.read_text().replace("CODE DYNAMICS() simple_pendulum.c",
                                                  "CODE DYNAMICS() sub/prog.c"))
    assert "sub/prog.c" in model.read_text()
    out = tmp_path / "out"
    out.mkdir()
    (out / "sub").symlink_to(victim.parent, target_is_directory=True)
    r = cli("code", model, "--out", out)
    assert r.returncode == 1 and "leads outside" in r.stderr
    assert sorted(p.name for p in victim.parent.iterdir()) == [".bashrc"]


@pytest.mark.parametrize("args, message", [
    (["-o", "{tmp}/a_file/x.py"], "cannot write"),
    (["-o", "{tmp}"], "is a folder"),
])
def test_convert_into_a_place_it_cannot_write_is_a_clear_error(tmp_path, args, message):
    (tmp_path / "a_file").write_text("a file where -o names a folder\n")
    r = cli("convert", PENDULUM, *[a.format(tmp=tmp_path) for a in args])
    assert r.returncode in (1, 2) and message in r.stderr
    assert "internal error" not in r.stderr


def test_a_run_never_replaces_an_in_file_the_user_edited(tmp_path):
    # Autolev's workflow edits NAME.in; the next run keeps it unless told otherwise
    out = tmp_path / "out"
    assert cli("run", PENDULUM, "--out", out, "-q").returncode == 0
    again = cli("run", PENDULUM, "--out", out, "-q")        # its own files: replaced
    assert again.returncode == 0, again.stderr
    edited = (out / "simple_pendulum.in").read_text().replace("| 1.0", "| 2.0", 1)
    (out / "simple_pendulum.in").write_text(edited)
    refused = cli("run", PENDULUM, "--out", out, "-q")
    assert refused.returncode == 1
    assert "simple_pendulum.in in" in refused.stderr and "--overwrite" in refused.stderr
    assert (out / "simple_pendulum.in").read_text() == edited
    with_it = cli("run", PENDULUM, "--out", out, "--in", out / "simple_pendulum.in", "-q")
    assert with_it.returncode == 0, with_it.stderr
    assert (out / "simple_pendulum.in").read_text() == edited
    replaced = cli("run", PENDULUM, "--out", out, "-q", "--overwrite")
    assert replaced.returncode == 0 and (out / "simple_pendulum.in").read_text() != edited
    # the record of what autolev wrote is kept with the user's state, not in the folder
    assert sorted(p.name for p in out.iterdir()) == [
        "simple_pendulum.1", "simple_pendulum.dir", "simple_pendulum.in"]


def test_transcript_never_replaces_autolevs_own_session(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    session = out / "simple_pendulum.all"
    session.write_text("   (1) NEWTONIAN N\n")            # Autolev's own, saved by SAVE
    r = cli("transcript", PENDULUM, "--out", out)
    assert r.returncode == 1 and "not written by autolev" in r.stderr
    assert session.read_text() == "   (1) NEWTONIAN N\n"
    assert cli("transcript", PENDULUM, "--out", out, "--overwrite").returncode == 0
    assert session.read_text() != "   (1) NEWTONIAN N\n"
    assert cli("transcript", PENDULUM, "--out", out).returncode == 0     # now ours


def test_code_never_replaces_a_program_the_user_edited(tmp_path):
    out = tmp_path / "out"
    assert cli("code", PENDULUM, "--out", out).returncode == 0
    program = out / "simple_pendulum.c"
    program.write_text(program.read_text() + "/* my change */\n")
    r = cli("code", PENDULUM, "--out", out)
    assert r.returncode == 1 and "--overwrite" in r.stderr
    assert program.read_text().endswith("/* my change */\n")


def test_animate_replaces_a_planted_link_but_not_a_users_page(tmp_path, victim):
    out = tmp_path / "out"
    link = planted(out, "simple_pendulum.html", victim)
    r = cli("animate", PENDULUM, "--format", "html", "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    unharmed(victim, link)
    (out / "simple_pendulum.html").write_text("<p>my page</p>")
    r = cli("animate", PENDULUM, "--format", "html", "--out", out, "-q")
    assert r.returncode == 1 and "--overwrite" in r.stderr
    assert (out / "simple_pendulum.html").read_text() == "<p>my page</p>"


def test_a_record_a_killed_process_was_writing_leaves_no_temporary(tmp_path, monkeypatch):
    # a background child killed (SIGKILL) as it wrote the record of its output folder
    # left `.<record>.<pid>.<hex>.autolev-part` in the state folder for good
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    out = tmp_path / "out"
    out.mkdir()
    outputs.write_output(out, "a.1", "1\n")
    record = outputs.Written(out).path
    gone = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)
    dead = record.with_name(f".{record.name}.{gone.stdout.strip()}.0a1b2c3d"
                            f"{outputs.TEMPORARY_SUFFIX}")
    living = outputs.temporary_beside(record)      # this process's: being written
    dead.write_text("{")
    living.write_text("{")
    outputs.write_output(out, "a.2", "2\n")
    assert not dead.exists() and living.exists()


def test_a_record_another_run_drops_meanwhile_is_no_error(tmp_path, monkeypatch):
    # two runs at once, each a new folder past RECORDS_KEPT: one listed the records,
    # the other dropped one of them, and the first's write said "cannot write into
    # <its folder>: No such file or directory (<that record>)"
    state = tmp_path / "state"
    monkeypatch.setenv("XDG_STATE_HOME", str(state))
    monkeypatch.setattr(outputs, "RECORDS_KEPT", 1)
    old = tmp_path / "old"
    old.mkdir()
    outputs.write_output(old, "a.1", "1\n")
    records = outputs.records_dir()
    listing = type(records).glob

    def with_one_dropped(self, pattern):
        found = list(listing(self, pattern))
        return iter(found + [records / "dropped-meanwhile.json"] if pattern == "*.json"
                    else found)
    monkeypatch.setattr(type(records), "glob", with_one_dropped)
    old_record = outputs.Written(old).path
    old.joinpath("a.1").unlink()
    old.rmdir()
    new = tmp_path / "new"
    new.mkdir()
    assert outputs.write_output(new, "b.1", "2\n").read_text() == "2\n"
    assert not old_record.exists()          # the folder gone: its record dropped
