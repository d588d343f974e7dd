"""The build cache of compiled right-hand sides: private, verified before loading, and
rebuilt when a cached library is damaged (issue 15, item 2)."""
import os
import stat
import subprocess
import pytest

from autolev.engine import diskcache
from autolev.engine import clibrary
from helpers import EXAMPLES

pytestmark = pytest.mark.skipif(clibrary.compiler() is None, reason="needs a C compiler")


@pytest.fixture
def cache(tmp_path, monkeypatch):
    folder = tmp_path / "home" / "cache" / "build"
    monkeypatch.setenv("AUTOLEV_CACHE", str(folder))
    return folder


RUN = f"""
import json, warnings
import autolev
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    model = autolev.load({str(EXAMPLES / "double_pendulum.al")!r})
    r = model.simulate(TFINAL=0.2)
    r.system.compiled_loop(wait=True)     # a cold run may end before its C is built
print(json.dumps({{"ok": r.ok, "backend": r.system.rhs_function.backend,
                  "states": r.states.tolist(), "said": [str(w.message) for w in caught]}}))
"""


def simulate(umask=None):
    """A run in a process of its own (a library once loaded stays mapped in a process:
    what the next run loads must be tested in a new one)."""
    import json
    import sys
    out = subprocess.run([sys.executable, "-c", RUN], capture_output=True, text=True,
                         preexec_fn=(lambda: os.umask(umask)) if umask is not None else None)
    assert out.returncode == 0, out.stderr[-2000:]
    got = json.loads(out.stdout.splitlines()[-1])
    assert got["ok"] and got["backend"] == "c"
    return got


def libraries(folder):
    return sorted(folder.glob("al_*.so"))


def test_the_cache_is_made_private_whatever_the_umask(cache):
    simulate(umask=0)
    for d in (cache, cache.parent, cache.parent.parent):
        assert stat.S_IMODE(d.stat().st_mode) == 0o700, d
    # every file 0600, digests included (they were 0666 under umask 000)
    files = [f for lib in libraries(cache) for f in (lib, diskcache.digest_file(lib))]
    assert files and all(stat.S_IMODE(f.stat().st_mode) == 0o600 for f in files)
    assert stat.S_IMODE((cache / diskcache.MARKER).stat().st_mode) == 0o600


@pytest.mark.parametrize("damage", [b"", b"garbage" * 10, "truncated"])
def test_a_damaged_cached_library_is_rebuilt(cache, damage):
    first = simulate()
    for lib in libraries(cache):
        data = lib.read_bytes()
        lib.write_bytes(data[: len(data) // 2] if damage == "truncated" else damage)
    again = simulate()
    assert again["states"] == first["states"]
    for lib in libraries(cache):
        assert diskcache.verified(lib)


def _planted_library(path, marker):
    """A shared library that creates `marker` when it is loaded."""
    src = path.with_suffix(".c")
    src.write_text('#include <stdio.h>\n__attribute__((constructor)) static void hit(void)'
                   f' {{ FILE *f = fopen("{marker}", "w"); if (f) fclose(f); }}\n')
    subprocess.run([clibrary.compiler(), "-shared", "-fPIC", "-o", str(path), str(src)],
                   check=True)
    src.unlink()


def _plant(cache, marker) -> list:
    """Replace every cached library by one that creates `marker` when loaded, with the
    digest that matches it (whoever can write the folder can write the digest too)."""
    planted = libraries(cache)
    for lib in planted:
        _planted_library(lib, marker)
        diskcache.install(lib.read_bytes(), lib)
    return planted


def test_a_library_planted_in_a_cache_others_can_write_is_not_loaded(cache, tmp_path,
                                                                    monkeypatch):
    simulate()
    marker = tmp_path / "PLANTED-CODE-RAN"
    _plant(cache, marker)
    os.chmod(cache, 0o777)
    temp = tmp_path / "temp"
    temp.mkdir()
    monkeypatch.setenv("TMPDIR", str(temp))
    said = simulate()["said"]
    assert not marker.exists()
    assert any("writable by others" in m for m in said)
    # the private folder the run built in instead is gone when the run ends
    assert not list(temp.glob("autolev-build-*"))


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0,
                    reason="giving a file to another user needs root")
def test_a_library_of_another_user_is_not_loaded(cache, tmp_path):
    simulate()
    marker = tmp_path / "PLANTED-CODE-RAN"
    for lib in _plant(cache, marker):
        os.chown(lib, 65534, 65534)              # nobody's
    simulate()
    assert not marker.exists()


MALLORY = 61002          # a uid of no account: the kernel's checks need none


def as_mallory(script: str) -> subprocess.CompletedProcess:
    """A shell command run by another user (uid MALLORY): what it cannot do, the kernel
    refuses, whatever our code believes."""
    return subprocess.run(["/bin/sh", "-c", script], user=MALLORY, group=MALLORY,
                          extra_groups=[], cwd="/", capture_output=True, text=True,
                          env={"PATH": "/usr/bin:/bin", "HOME": "/nonexistent"})


@pytest.fixture
def shared_tmp():
    """A folder every user may create files in (sticky, as /tmp)."""
    import shutil
    import tempfile
    folder = tempfile.mkdtemp(prefix="autolev-two-users-", dir="/tmp")
    os.chmod(folder, 0o1777)
    yield folder
    shutil.rmtree(folder)


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0,
                    reason="running a process as a second user needs root")
def test_a_second_user_cannot_make_our_runs_load_their_code(shared_tmp, monkeypatch):
    from pathlib import Path
    shared = Path(shared_tmp)
    ours = shared / "ours"
    monkeypatch.setenv("AUTOLEV_CACHE", str(ours))
    first = simulate()
    names = sorted(p.name for p in ours.glob("al_*") if p.suffix in (".so", ".o"))
    assert any(n.endswith(".so") for n in names) and any(n.endswith(".o") for n in names)
    # their code: a library and an object that create MARKER when loaded, with digests
    marker = shared / "PLANTED-CODE-RAN"
    planted = shared / "planted"
    planted.mkdir(mode=0o755)
    _planted_library(planted / "lib.so", marker)
    src = planted / "obj.c"
    src.write_text('#include <stdio.h>\n__attribute__((constructor)) static void hit(void)'
                   f' {{ FILE *f = fopen("{marker}", "w"); if (f) fclose(f); }}\n')
    subprocess.run([clibrary.compiler(), "-c", "-fPIC", "-o", str(planted / "obj.o"),
                    str(src)], check=True)
    for kind in ("lib.so", "obj.o"):
        diskcache.install((planted / kind).read_bytes(), planted / ("x" + kind))
        os.chmod(planted / ("x" + kind), 0o755)
        os.chmod(diskcache.digest_file(planted / ("x" + kind)), 0o644)
    copies = " && ".join(
        f"cp {planted}/x{'lib.so' if n.endswith('.so') else 'obj.o'} DIR/{n} && "
        f"cp {planted}/x{'lib.so' if n.endswith('.so') else 'obj.o'}.mac DIR/{n}.mac"
        for n in names)

    # 1. our cache: they can neither write into it, nor list it, nor move it aside
    for attempt in (copies.replace("DIR", str(ours)), f"ls {ours}",
                    f"mv {ours} {shared}/moved", f"rm -rf {ours}"):
        r = as_mallory(attempt)
        assert r.returncode != 0 and ("Permission denied" in r.stderr
                                      or "Operation not permitted" in r.stderr), attempt
    assert simulate()["states"] == first["states"] and not marker.exists()

    # 2. a cache folder they made first, at the path we were told to use, filled with
    #    their code under the names we would load, and its symlink
    theirs = shared / "theirs"
    r = as_mallory(f"mkdir -m 755 {theirs} && " + copies.replace("DIR", str(theirs))
                   + f" && ln -s {theirs} {shared}/link")
    assert r.returncode == 0, r.stderr
    assert all((theirs / n).stat().st_uid == MALLORY for n in names)
    for path in (theirs, shared / "link"):
        monkeypatch.setenv("AUTOLEV_CACHE", str(path))
        got = simulate()
        assert got["states"] == first["states"]
        assert any(f"belongs to another user (uid {MALLORY})" in m for m in got["said"])
        assert not marker.exists()
