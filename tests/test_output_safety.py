"""Outputs never follow planted links, never leave their folder, and are whole or
absent (issue 31, item 5; issue 30, item 8: one writer of files)."""
import subprocess
import sys

import pytest

from autolev.runtime import outputs
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
    (["-o", "{tmp}/missing/x.py"], "cannot write"),
    (["-o", "{tmp}"], "is a folder"),
])
def test_convert_into_a_place_it_cannot_write_is_a_clear_error(tmp_path, args, message):
    r = cli("convert", PENDULUM, *[a.format(tmp=tmp_path) for a in args])
    assert r.returncode in (1, 2) and message in r.stderr
    assert "internal error" not in r.stderr
