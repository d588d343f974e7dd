"""The cache never destroys nor trusts what autolev did not make (issue 31, items 1, 4
and 8): only its own files are removed, only in a folder marked as its cache; entries
are authenticated with a key kept outside the cache; a cache that cannot be written
costs the run nothing and leaves nothing."""
import errno
import hashlib
import os
import pickle
import subprocess
import sys

import pytest

import autolev
from autolev.engine import cachekeys
from autolev import modelcache
from autolev.engine import diskcache
from helpers import EXAMPLES


@pytest.fixture
def cache(tmp_path, monkeypatch):
    folder = tmp_path / "cache"
    monkeypatch.setenv("AUTOLEV_CACHE", str(folder))
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    monkeypatch.delenv(cachekeys.DISABLE_VARIABLE, raising=False)
    return folder


def cli(*args, env=None):
    return subprocess.run([sys.executable, "-m", "autolev", *map(str, args)],
                          capture_output=True, text=True, env=env)


def test_cache_clear_of_a_folder_of_the_users_files_removes_nothing(tmp_path):
    docs = tmp_path / "docs"
    docs.mkdir(mode=0o700)
    for name in ("report.md", "model_notes.txt", "data.pickle"):
        (docs / name).write_text("the user's own")
    env = dict(os.environ, AUTOLEV_CACHE=str(docs), XDG_CONFIG_HOME=str(tmp_path / "cfg"))
    r = cli("cache", "clear", env=env)
    assert r.returncode == 1 and "is not marked as autolev's cache" in r.stderr
    assert sorted(p.name for p in docs.iterdir()) == ["data.pickle", "model_notes.txt",
                                                       "report.md"]


def test_a_run_does_not_use_a_folder_of_other_files_as_its_cache(tmp_path):
    docs = tmp_path / "docs"
    docs.mkdir(mode=0o700)
    (docs / "measurement.csv").write_bytes(b"1,2\n" * 1000)
    env = dict(os.environ, AUTOLEV_CACHE=str(docs), AUTOLEV_CACHE_LIMIT_MB="0",
               XDG_CONFIG_HOME=str(tmp_path / "cfg"), AUTOLEV_NO_MODEL_CACHE="0")
    r = cli("run", EXAMPLES / "simple_pendulum.al", "--out", tmp_path / "o", "-q", env=env)
    assert r.returncode == 0, r.stderr
    assert "holds files autolev did not make (measurement.csv)" in r.stderr
    assert [p.name for p in docs.iterdir()] == ["measurement.csv"]


def test_clear_removes_autolevs_files_only(cache, tmp_path):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    autolev.load(model)
    (cache / "notes.txt").write_text("kept")
    (cache / (modelcache.PREFIX + "0" * 40 + ".pickle.123.tmp")).write_text("left over")
    count, _ = modelcache.clear()
    assert count == 2          # the model and its translation
    assert sorted(p.name for p in cache.iterdir()) == [diskcache.MARKER, "notes.txt"]


def test_the_names_autolev_calls_its_own():
    entry = "model_" + "a" * 40 + ".pickle"
    for name in (entry, entry + ".mac", entry + ".sha256", entry + ".77.tmp",
                 entry + ".mac.77.0a1b.tmp", "." + entry + ".mac.77.0a1b.autolev-part",
                 "al_" + "0" * 24 + ".so", diskcache.MARKER):
        assert diskcache.is_ours(name), name
    for name in ("model_notes.pickle", entry + ".bak", "al_x.so", "report.md",
                 ".report.md.77.0a1b.autolev-part",
                 "al_" + "0" * 24 + ".so.d", entry[:-1]):
        assert not diskcache.is_ours(name), name


class _Planted:
    """A pickle that runs code when it is read."""

    def __init__(self, marker):
        self.marker = str(marker)

    def __reduce__(self):
        return (open, (self.marker, "w"))


def test_a_cache_that_arrives_with_a_project_runs_no_code(cache, tmp_path):
    # a clone: files the user owns, 0600 in a private folder, with SHA-256 digests
    # anyone can compute, under the very names our runs would read
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    autolev.load(model)
    marker = tmp_path / "PLANTED-CODE-RAN"
    data = pickle.dumps(_Planted(marker))
    planted = list(cache.glob("*.pickle"))
    assert len(planted) == 2
    for entry in planted:
        entry.write_bytes(data)
        diskcache.digest_file(entry).write_text(hashlib.sha256(data).hexdigest() + "\n")
    env = dict(os.environ)
    code = f"import autolev; print(autolev.load({str(model)!r})['X'])"
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "A**2" and not marker.exists()


def test_the_key_is_private_and_made_once(cache, tmp_path):
    autolev.load(EXAMPLES / "simple_pendulum.al")
    key = tmp_path / "config" / "autolev" / "cache.key"
    assert oct(key.stat().st_mode & 0o777) == "0o600"
    before = key.read_bytes()
    assert len(before) == 64
    diskcache._SECRET.clear()
    autolev.load(EXAMPLES / "double_pendulum.al")
    assert key.read_bytes() == before


def test_a_relative_cache_setting_is_ignored(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("AUTOLEV_CACHE", "project/cache")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    with pytest.warns(UserWarning, match="AUTOLEV_CACHE=project/cache is not an absolute"):
        folder = diskcache.configured_dir()
    assert folder == tmp_path / "xdg" / "autolev" / "build"


def test_a_cache_that_cannot_be_written_costs_the_run_nothing(cache, monkeypatch):
    real = os.replace

    def full(src, dst):
        if str(dst).startswith(str(cache)):
            raise OSError(errno.ENOSPC, "No space left on device")
        return real(src, dst)
    monkeypatch.setattr(diskcache.os, "replace", full)
    with pytest.warns(UserWarning, match="No space left on device"):
        r = autolev.load(EXAMPLES / "simple_pendulum.al").simulate(TFINAL=0.5)
    assert r.ok and len(r.t) > 1
    left = [p.name for p in cache.iterdir()] if cache.exists() else []
    assert not [n for n in left if n.endswith(".tmp")]
    assert not [n for n in left if n != diskcache.MARKER]


def test_a_fresh_cache_tagged_meanwhile_by_another_thread_is_used(cache, monkeypatch):
    # a cold run's C compiles on a thread while the run goes on: both may tag the folder
    write_new = diskcache._write_new

    def the_other_first(path, data):
        write_new(path, data)            # the other thread's tag, just before ours
        write_new(path, data)
    monkeypatch.setattr(diskcache, "_write_new", the_other_first)
    cache.mkdir(mode=0o700)
    assert diskcache._problem_with(cache) is None
    assert (cache / diskcache.MARKER).is_file()


@pytest.mark.parametrize("spoilt", ["a file where the folder goes", "a key cut short"])
def test_a_key_that_cannot_be_had_costs_the_run_nothing(tmp_path, spoilt):
    # the cache falls back to a private folder, whose entries this process keys itself
    # (it was exit 70 and a traceback: the fallback still asked for the user's key)
    config = tmp_path / "config"
    if spoilt == "a file where the folder goes":
        config.write_text("not a folder")
    else:
        (config / "autolev").mkdir(parents=True, mode=0o700)
        (config / "autolev" / "cache.key").write_text("abc\n")
        (config / "autolev" / "cache.key").chmod(0o600)
    model = EXAMPLES / "simple_pendulum.al"
    env = dict(os.environ, AUTOLEV_CACHE=str(tmp_path / "cache"), AUTOLEV_NO_MODEL_CACHE="0",
               XDG_CONFIG_HOME=str(config))
    spoilt_run = cli("run", model, "--out", tmp_path / "spoilt", "-q", env=env)
    assert spoilt_run.returncode == 0, spoilt_run.stderr
    assert "cannot be trusted: its key" in spoilt_run.stderr
    assert "internal error" not in spoilt_run.stderr and "Traceback" not in spoilt_run.stderr
    # nothing kept where the key that would authenticate it is not had
    assert not (tmp_path / "cache").exists() or not any(
        n.endswith(".pickle") for n in os.listdir(tmp_path / "cache"))
    fine = cli("run", model, "--out", tmp_path / "fine", "-q",
               env=dict(env, XDG_CONFIG_HOME=str(tmp_path / "fine-config")))
    assert fine.returncode == 0, fine.stderr
    assert (tmp_path / "spoilt" / "simple_pendulum.1").read_bytes() == \
        (tmp_path / "fine" / "simple_pendulum.1").read_bytes()
