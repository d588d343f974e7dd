"""The cache of built models: an unchanged model is read back, not built again, and
gives the same rows; anything changed, damaged or turned off builds it afresh."""
import math
import os
import subprocess
import sys
import warnings

import numpy as np

import pytest

import autolev
from autolev.engine import cachekeys
from autolev import loader, modelcache, pipeline
from autolev.cli import main
from autolev.engine import diskcache
from autolev.runtime.model import Model
from helpers import EXAMPLES

PENDULUM = EXAMPLES / "double_pendulum.al"


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """A fresh cache folder, with built models kept."""
    folder = tmp_path / "cache"
    monkeypatch.setenv("AUTOLEV_CACHE", str(folder))
    monkeypatch.delenv(cachekeys.DISABLE_VARIABLE, raising=False)
    return folder


def models_in(folder):
    return sorted(p.name for p in folder.glob(modelcache.PREFIX + "*.pickle"))


def run_in_a_new_process(model, out, env, refuse_building=False, options=()):
    """`autolev run` in a fresh Python (no state shared with the building process);
    with refuse_building, building the model (executing its module) or its numeric
    system (generating its code) is an error."""
    code = ("import sys\nfrom autolev import loader\n"
            "from autolev.runtime.numerics.system import NumericSystem\n"
            + ("def refuse(*a, **k):\n    raise SystemExit('built again')\n"
               "loader._execute = refuse\nNumericSystem.__init__ = refuse\n"
               if refuse_building else "")
            + "from autolev.cli import main\n"
            f"sys.exit(main(['run', {str(model)!r}, '--out', {str(out)!r}, '-q', "
            f"*{list(options)!r}]))\n")
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                          text=True, timeout=300)


def test_a_model_read_back_gives_the_rows_of_one_built_afresh(cache, tmp_path):
    env = dict(os.environ)
    cold = run_in_a_new_process(PENDULUM, tmp_path / "cold", env)
    assert cold.returncode == 0, cold.stderr
    assert len(models_in(cache)) == 1
    # an option a run plan does not repeat: the model is read back
    warm = run_in_a_new_process(PENDULUM, tmp_path / "warm", env, refuse_building=True,
                                options=["--method", "kutta-merson"])
    assert warm.returncode == 0, warm.stderr
    files = sorted(p.name for p in (tmp_path / "cold").iterdir())
    assert files and files == sorted(p.name for p in (tmp_path / "warm").iterdir())
    for name in files:
        assert (tmp_path / "cold" / name).read_bytes() == (tmp_path / "warm" / name).read_bytes()


def test_a_changed_model_is_another_entry(cache, tmp_path):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    assert autolev.load(model)["X"] == autolev.load(model)["X"]
    assert len(models_in(cache)) == 1
    model.write_text("CONSTANTS A\nX = A^3\n")
    x = autolev.load(model)["X"]
    assert str(x) == "A**3" and len(models_in(cache)) == 2


def test_a_damaged_entry_is_built_again(cache, tmp_path, monkeypatch):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    autolev.load(model)
    (entry,) = cache.glob(modelcache.PREFIX + "*.pickle")
    entry.write_bytes(b"not a pickle")
    built = []
    original = loader._execute
    monkeypatch.setattr(loader, "_execute", lambda *a: built.append(1) or original(*a))
    assert str(autolev.load(model)["X"]) == "A**2"
    assert built == [1] and diskcache.verified(entry)        # and written again


def test_turned_off_nothing_is_kept(cache, tmp_path, monkeypatch):
    monkeypatch.setenv(cachekeys.DISABLE_VARIABLE, "1")
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    autolev.load(model)
    assert not cache.exists() or models_in(cache) == []


def test_the_warnings_of_building_are_given_again(cache, tmp_path, monkeypatch):
    original = Model.constants

    def constants(self, *args, **kwargs):
        warnings.warn("a warning while building")
        return original(self, *args, **kwargs)
    monkeypatch.setattr(Model, "constants", constants)
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    for _ in range(2):                        # built, then read back
        with pytest.warns(UserWarning, match="a warning while building"):
            autolev.load(model)
    assert len(models_in(cache)) == 1


def test_the_cache_keeps_under_its_limit_oldest_first(tmp_path):
    folder = tmp_path / "c"
    folder.mkdir(mode=0o700)
    names = [f"model_{n:040x}.pickle" for n in range(6)]
    for n, name in enumerate(names):
        (folder / name).write_bytes(b"x" * 1000)
        os.utime(folder / name, (n, n))
    # the newest was written just now: another process may be reading it
    os.utime(folder / names[5], None)
    (folder / "measurements.csv").write_bytes(b"y" * 3_000_000)   # not autolev's
    assert diskcache.trim(folder, limit=2500) == 4
    assert sorted(p.name for p in folder.iterdir()) == ["measurements.csv", *names[4:]]
    # over the limit still, the entry just written stays
    assert diskcache.trim(folder, limit=500) == 1
    assert sorted(p.name for p in folder.iterdir()) == ["measurements.csv", names[5]]


def test_cache_info_and_clear(cache, tmp_path, capsys):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    autolev.load(model)
    assert main(["cache", "info"]) == 0
    out = capsys.readouterr().out
    assert f"cache: {cache}" in out and "built models:      1" in out
    assert "translations:      1" in out
    assert main(["cache", "clear"]) == 0
    assert capsys.readouterr().out.startswith("removed 2 entries")
    assert models_in(cache) == []


class _Planted:
    """A pickle that runs code when it is read."""

    def __init__(self, marker):
        self.marker = str(marker)

    def __reduce__(self):
        return (open, (self.marker, "w"))


def test_a_model_planted_in_a_cache_others_can_write_is_not_read(cache, tmp_path):
    import hashlib
    import pickle
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = A^2\n")
    autolev.load(model)
    (entry,) = cache.glob(modelcache.PREFIX + "*.pickle")
    marker = tmp_path / "PLANTED-CODE-RAN"
    data = pickle.dumps(_Planted(marker))
    entry.write_bytes(data)                 # whoever can write the folder can write both
    diskcache.digest_file(entry).write_text(hashlib.sha256(data).hexdigest() + "\n")
    os.chmod(cache, 0o777)
    env = dict(os.environ, TMPDIR=str(tmp_path))
    code = f"import autolev; print(autolev.load({str(model)!r})['X'])"
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "A**2" and not marker.exists()
    assert "writable by others" in done.stderr


def test_expressions_read_back_are_the_same_trees(cache):
    import sympy as sm
    from autolev.pipeline import translation
    built = loader.load_translation(translation(PENDULUM), str(PENDULUM))
    read = modelcache.read(modelcache.key(translation(PENDULUM).code, str(PENDULUM)))
    assert read is not None and len(read.model.defs.rhs) == len(built.defs.rhs) >= 10
    for symbol, value in built.defs.rhs.items():
        again = read.model.defs.rhs[symbol]
        # the same tree, term for term in the same order (not just equal after sorting)
        assert sm.srepr(again) == sm.srepr(value) and hash(again) == hash(value)
    x, y = sm.symbols("x y", real=True)
    unevaluated = sm.Mul(2, sm.Add(x, y, evaluate=False), sm.Pow(x, 2, evaluate=False),
                         evaluate=False)
    modelcache.write("k" * 64, modelcache.Built(unevaluated, []))
    assert sm.srepr(modelcache.read("k" * 64).model) == sm.srepr(unevaluated)


def test_a_model_changed_after_loading_is_not_written_back(cache, tmp_path):
    model = autolev.load(PENDULUM)
    model.output((model["Q1"], "Q1 again"))          # changed by its user
    model.simulate(TFINAL=0.1, out_dir=tmp_path)      # builds a numeric system
    again = autolev.load(PENDULUM)
    assert len(again.outputs) == len(model.outputs) - 1


def test_a_translation_is_read_back_until_a_file_it_read_or_a_folder_changes(
        cache, tmp_path, monkeypatch):
    folder = tmp_path / "m"
    folder.mkdir()
    (folder / "kin.al").write_text("CONSTANTS A\n")
    model = folder / "m.al"
    model.write_text("RUN kin.al\nX = sq(A)\n")
    translated = []
    real = pipeline.translation      # the loader imports it when a text is to be translated
    monkeypatch.setattr(pipeline, "translation", lambda p: translated.append(p) or real(p))
    with pytest.raises(autolev.AutolevTranslationError):
        autolev.load(model)                     # sq is not a function: nothing kept
    (folder / "sq.r").write_text("#1#^2\n")     # a folder it looked in changed
    assert str(autolev.load(model)["X"]) == "A**2"
    assert str(autolev.load(model)["X"]) == "A**2"
    assert len(translated) == 2                 # the third load read it back
    (folder / "kin.al").write_text("CONSTANTS A, B\n")   # a file it read changed
    assert autolev.load(model).quantity("B") is not None
    assert len(translated) == 3
    (folder / "sq.r").write_text("#1#^3\n")     # and the function's file
    assert str(autolev.load(model)["X"]) == "A**3"
    assert len(translated) == 4


def test_outputs_written_beside_the_model_keep_its_translation(cache, tmp_path,
                                                              monkeypatch):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nX = 2*A\n")
    translated = []
    real = pipeline.translation      # the loader imports it when a text is to be translated
    monkeypatch.setattr(pipeline, "translation", lambda p: translated.append(p) or real(p))
    autolev.load(model)
    for name in ("m.1", "m.dir", "m.in", "m-plot.png"):
        (tmp_path / name).write_text("written by a run\n")
    (tmp_path / "o1").mkdir()                    # an --out folder beside it
    assert str(autolev.load(model)["X"]) == "2*A"
    assert len(translated) == 1                 # read back: no macro or function added
    (tmp_path / "M.A").write_text("Z = 1\n")     # a macro no statement calls: not read
    autolev.load(model)
    assert len(translated) == 1
    (tmp_path / "TWICE.r").write_text("2*#1#\n")  # a function file, any case: looked at
    autolev.load(model)
    assert len(translated) == 2


def test_a_macro_file_added_for_a_statement_that_calls_it_is_seen(cache, tmp_path):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nPLACE(3)\n")
    (tmp_path / "place.a").write_text("X = #1#*A\n")
    assert str(autolev.load(model)["X"]) == "3*A"
    (tmp_path / "PLACE.A").write_text("X = #1#+A\n")   # the name in its case: found first
    assert str(autolev.load(model)["X"]) == "A + 3"


def test_a_file_added_where_the_translation_looked_is_seen(cache, tmp_path):
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nsin(A)\n")
    assert loader.load_for_run(model)[1] == []      # a statement showing SIN(A): kept
    (tmp_path / "sin.a").write_text("Z = 2*#1#\n")  # not read, but said (W106)
    notes = loader.load_for_run(model)[1]
    assert len(notes) == 1 and "sin.a has the name of Autolev's own command SIN" in notes[0]


TWO_PROGRAMS = """\
NEWTONIAN N
BODIES A
POINTS O
VARIABLES Q', U'
CONSTANTS G, L, M, K
MASS A = M
INERTIA A, 0, 0, M*L^2/12
SIMPROT(N, A, 3, Q)
Q' = U
P_O_AO> = L/2*A1>
W_A_N> = U*N3>
V_AO_N> = DT(P_O_AO>, N)
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT G = 9.81, L = 1, M = 2, K = 3, Q = 30 DEG, U = 0
INPUT TFINAL = 0.5, INTEGSTP = 0.1
OUTPUT Q, U
CODE DYNAMICS() swing.c
ENERGY = M*G*L/2*COS(Q) + K
OUTPUT ENERGY
CODE ALGEBRAIC() energy.c
"""


def test_a_cold_run_writes_its_entry_once_with_every_program(cache, tmp_path, monkeypatch):
    model = tmp_path / "two.al"
    model.write_text(TWO_PROGRAMS)
    # in the foreground: a compile over 2 s (a loaded machine) would leave the entry to
    # the background child, whose writes this process cannot count
    monkeypatch.setenv("AUTOLEV_FOREGROUND", "1")
    writes = []
    real = modelcache.write
    monkeypatch.setattr(modelcache, "write", lambda k, b: writes.append(k) or real(k, b))
    assert main(["run", str(model), "--out", str(tmp_path / "cold"), "-q"]) == 0
    assert len(writes) == 1 and len(models_in(cache)) == 1
    # both CODE commands' numeric systems are in that one entry: nothing is built warm
    warm = run_in_a_new_process(model, tmp_path / "warm", dict(os.environ),
                                refuse_building=True)
    assert warm.returncode == 0, warm.stderr
    assert {p.name for p in (tmp_path / "warm").iterdir()} >= {"swing.1", "energy.1"}


# -- run plans: a plain warm run without the model --------------------------------------
PUSHED = """
NEWTONIAN N
FRAMES A
PARTICLES P
MOTIONVARIABLES' Q', U'
CONSTANTS L, M, G
SPECIFIED TQ
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*A3>
P_NO_P> = L*A1>
V_P_N> = L*U*A2>
MASS P = M
GRAVITY(G*N1>)
TORQUE(A, TQ*A3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L=2, M=3, G=9.81, Q=30 DEG, U=0, TFINAL=2, INTEGSTP=0.05
OUTPUT Q, U
CODE DYNAMICS() pushed.c
"""


def run_cli(args, env) -> subprocess.CompletedProcess:
    code = (f"import sys\nfrom autolev.cli import main\nstatus = main({list(args)!r})\n"
            "print('imported:', sorted(m for m in ('sympy', 'scipy') if m in sys.modules))\n"
            "sys.exit(status)\n")
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                          text=True, timeout=300)


def test_a_plain_run_repeats_from_its_plan_the_same_files_and_messages(cache, tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED)
    env = dict(os.environ)
    first = run_cli(["run", str(model), "--out", str(tmp_path / "first")], env)
    assert first.returncode == 0, first.stderr
    assert "its run plan" not in first.stdout and "'sympy'" in first.stdout
    again = run_cli(["run", str(model), "--out", str(tmp_path / "again")], env)
    assert again.returncode == 0, again.stderr
    assert "built in 0.0 s (its run plan)" in again.stdout
    # neither the model nor sympy: the plan's numbers and compiled code alone
    assert "imported: []" in again.stdout
    # the warning of the first run (TQ is 0) said again; not its progress (compiling)
    warned = [line for line in first.stderr.splitlines() if "warning" in line]
    assert "set to 0: TQ" in warned[0] and again.stderr.splitlines() == warned
    names = sorted(p.name for p in (tmp_path / "first").iterdir())
    assert names == ["pushed.1", "pushed.dir", "pushed.in"]
    assert names == sorted(p.name for p in (tmp_path / "again").iterdir())
    for name in names:
        assert (tmp_path / "first" / name).read_bytes() == \
            (tmp_path / "again" / name).read_bytes(), name
    rows = np.loadtxt(tmp_path / "again" / "pushed.1", comments="%")
    assert rows.shape == (41, 2) and abs(rows[0, 0] - math.radians(30)) < 1e-6


def test_a_plan_is_the_runs_with_its_options_and_model(cache, tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED)
    env = dict(os.environ)
    assert run_cli(["run", str(model), "--out", str(tmp_path / "a")], env).returncode == 0
    for out in ("b", "c"):              # other values: their own plan, then repeated
        other = run_cli(["run", str(model), "--out", str(tmp_path / out), "--set", "Q=10"],
                        env)
        assert other.returncode == 0 and ("its run plan" in other.stdout) == (out == "c")
        assert abs(np.loadtxt(tmp_path / out / "pushed.1", comments="%")[0, 0]
                   - math.radians(10)) < 1e-6
    model.write_text(PUSHED.replace("Q=30 DEG", "Q=20 DEG"))
    changed = run_cli(["run", str(model), "--out", str(tmp_path / "d")], env)
    assert changed.returncode == 0 and "its run plan" not in changed.stdout
    assert abs(np.loadtxt(tmp_path / "d" / "pushed.1", comments="%")[0, 0]
               - math.radians(20)) < 1e-6


def test_a_plan_is_not_used_when_a_file_the_model_reads_changes(cache, tmp_path):
    (tmp_path / "values.al").write_text("INPUT L=2, M=3, G=9.81, Q=30 DEG, U=0\n")
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED.replace("INPUT L=2, M=3, G=9.81, Q=30 DEG, U=0,",
                                    "RUN values.al\nINPUT"))
    env = dict(os.environ)
    assert run_cli(["run", str(model), "--out", str(tmp_path / "a")], env).returncode == 0
    planned = run_cli(["run", str(model), "--out", str(tmp_path / "b")], env)
    assert "its run plan" in planned.stdout
    (tmp_path / "values.al").write_text("INPUT L=2, M=3, G=9.81, Q=45 DEG, U=0\n")
    changed = run_cli(["run", str(model), "--out", str(tmp_path / "c")], env)
    assert changed.returncode == 0 and "its run plan" not in changed.stdout
    assert abs(np.loadtxt(tmp_path / "c" / "pushed.1", comments="%")[0, 0]
               - math.radians(45)) < 1e-6


def test_a_plan_with_an_in_file_is_that_files_content(cache, tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED)
    env = dict(os.environ)
    assert run_cli(["run", str(model), "--out", str(tmp_path / "a")], env).returncode == 0
    values = tmp_path / "values.in"
    values.write_text((tmp_path / "a" / "pushed.in").read_text())
    runs = [run_cli(["run", str(model), "--out", str(tmp_path / out), "--in", str(values)],
                    env) for out in ("b", "c")]
    assert [r.returncode for r in runs] == [0, 0]
    assert "its run plan" not in runs[0].stdout and "its run plan" in runs[1].stdout
    values.write_text(values.read_text().replace("| 30.0", "| 40.0"))
    edited = run_cli(["run", str(model), "--out", str(tmp_path / "d"), "--in", str(values)],
                     env)
    assert edited.returncode == 0 and "its run plan" not in edited.stdout
    assert abs(np.loadtxt(tmp_path / "d" / "pushed.1", comments="%")[0, 0]
               - math.radians(40)) < 1e-6


def test_a_run_from_its_plan_refuses_a_file_it_did_not_write_as_a_run_does(cache,
                                                                           tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED)
    env = dict(os.environ)
    assert run_cli(["run", str(model), "--out", str(tmp_path / "a")], env).returncode == 0
    refusals = []
    for planned, folder in ((True, tmp_path / "b"), (False, tmp_path / "c")):
        folder.mkdir()
        (folder / "pushed.1").write_text("the user's own\n")
        r = run_cli(["run", str(model), "--out", str(folder)],
                    dict(env, AUTOLEV_NO_MODEL_CACHE="0" if planned else "1"))
        assert r.returncode == 1 and ("its run plan" in r.stdout) == planned
        assert (folder / "pushed.1").read_text() == "the user's own\n"
        refusals.append(r.stderr.splitlines()[-1].replace(str(folder), "OUT"))
    assert refusals[0] == refusals[1]
    assert "error: CODE DYNAMICS: cannot write the output files into OUT" in refusals[0]


# programs that solve or sweep before they write, with their rows by hand
SOLVED = {
    "linear": ("VARIABLES X, Y\nCONSTANTS A, B\nEQ[1] = A*X + 2*Y - 3\n"
               "EQ[2] = X - B*Y + 1\nINPUT A = 2, B = 3\nOUTPUT X, Y\n"
               "CODE ALGEBRAIC(EQ, X, Y) linear.c\n", [[0.875, 0.625]]),
    "newton": ("VARIABLES U, V\nCONSTANTS R\nNL[1] = U^2 + V^2 - R^2\nNL[2] = V - U\n"
               "INPUT R = 2, U = 1, V = 2, ABSERR = 1.0E-10, RELERR = 1.0E-10\n"
               "OUTPUT U, V\nCODE NONLINEAR(NL, U, V) newton.c\n", [[2 ** 0.5] * 2]),
    "swept": ("CONSTANTS L, Q\nPX = L*COS(Q)\nPY = L*SIN(Q)\nINPUT L = 2\n"
              "OUTPUT Q DEG, PX, PY\nCODE ALGEBRAIC() [Q DEG = 0, 90, 15] swept.c\n",
              [[q, 2 * math.cos(math.radians(q)), 2 * math.sin(math.radians(q))]
               for q in range(0, 91, 15)]),
}


@pytest.mark.parametrize("name", sorted(SOLVED))
def test_algebraic_and_nonlinear_programs_repeat_from_their_plan(cache, tmp_path, name):
    text, expected = SOLVED[name]
    model = tmp_path / f"{name}.al"
    model.write_text(text)
    env = dict(os.environ)
    first = run_cli(["run", str(model), "--out", str(tmp_path / "first")], env)
    assert first.returncode == 0, first.stderr
    again = run_cli(["run", str(model), "--out", str(tmp_path / "again")], env)
    assert again.returncode == 0, again.stderr
    assert "built in 0.0 s (its run plan)" in again.stdout
    imported = again.stdout.split("imported: ")[1]
    assert "sympy" not in imported and "scipy" not in imported   # (numpy's LU)
    names = sorted(p.name for p in (tmp_path / "first").iterdir())
    assert names == [f"{name}.1", f"{name}.dir", f"{name}.in"]
    for file in names:
        assert (tmp_path / "first" / file).read_bytes() == \
            (tmp_path / "again" / file).read_bytes(), file
    rows = np.loadtxt(tmp_path / "again" / f"{name}.1", comments="%", ndmin=2)
    assert np.allclose(rows, expected, atol=1e-5)


def test_tables_and_plots_are_drawn_from_a_plans_rows(cache, tmp_path):
    # the plan of a plain run serves a run asking for tables: they are its rows
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED)
    env = dict(os.environ)
    plain = run_cli(["run", str(model), "--out", str(tmp_path / "plain")], env)
    assert plain.returncode == 0, plain.stderr
    tables = run_cli(["run", str(model), "--out", str(tmp_path / "tables"), "--csv"], env)
    assert tables.returncode == 0, tables.stderr
    assert "built in 0.0 s (its run plan)" in tables.stdout
    assert "sympy" not in tables.stdout.split("imported: ")[1]
    csv = np.loadtxt(tmp_path / "tables" / "pushed.csv", delimiter=",", skiprows=1)
    rows = np.loadtxt(tmp_path / "plain" / "pushed.1", comments="%")
    assert csv.shape == rows.shape == (41, 2)
    assert np.allclose(csv, rows, rtol=1e-6, atol=1e-12)
    # a column it does not write is refused before anything runs, as from the model
    wrong = run_cli(["run", str(model), "--out", str(tmp_path / "wrong"), "--plot", "Q,W"],
                    env)
    if "--plot needs matplotlib" not in wrong.stderr:
        assert wrong.returncode == 2
        assert "--plot: no output column W; the runs write Q, U" in wrong.stderr
        assert not (tmp_path / "wrong").exists()


# -- kept linearizations: a plain warm `autolev linearize` without the model ----------
def test_a_linearization_is_kept_for_its_file_and_options(cache, tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED)
    env = dict(os.environ)
    args = ["linearize", str(model), "--at", "Q=0.3"]
    first = run_cli(args + ["--out", str(tmp_path / "first")], env)
    assert first.returncode == 0, first.stderr
    assert "as before" not in first.stderr and "'sympy'" in first.stdout
    again = run_cli(args + ["--out", str(tmp_path / "again")], env)
    assert again.returncode == 0 and "linearized as before" in again.stderr
    # neither the model nor sympy (scipy only to write the .mat file)
    assert "imported: ['scipy']" in again.stdout
    assert again.stdout == first.stdout.replace("'scipy', 'sympy'", "'scipy'").replace(
        str(tmp_path / "first"), str(tmp_path / "again"))
    for name in ("pushed-A.csv", "pushed-B.csv", "pushed-eigenvalues.csv"):
        assert (tmp_path / "first" / name).read_text() == \
            (tmp_path / "again" / name).read_text()
    # by hand: a particle at L on a rod, Q'' = -(G/L) sin(Q) + TQ/(M L^2)
    a = np.loadtxt(tmp_path / "again" / "pushed-A.csv", delimiter=",", skiprows=1,
                   usecols=(1, 2))
    assert np.allclose(a, [[0, 1], [-9.81 / 2 * math.cos(0.3), 0]], rtol=1e-14)
    # another point, or the model changed: linearized afresh
    other = run_cli(["linearize", str(model), "--at", "Q=0.4"], env)
    assert other.returncode == 0 and "as before" not in other.stderr
    assert other.stdout != first.stdout and "'sympy'" in other.stdout
    model.write_text(PUSHED.replace("G=9.81", "G=9.8"))
    changed = run_cli(args, env)
    assert changed.returncode == 0 and "as before" not in changed.stderr


def test_a_failed_linearization_is_not_kept(cache, tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED.replace("MASS P = M", "MASS P = 0*M"))
    env = dict(os.environ)
    for _ in range(2):
        r = run_cli(["linearize", str(model)], env)
        assert r.returncode == 1 and "singular" in r.stderr and "as before" not in r.stderr


def _without_imported(text: str) -> str:
    return text.rsplit("imported: ", 1)[0]


def test_a_model_without_code_shows_its_responses_again_without_the_model(cache, tmp_path):
    (tmp_path / "values.al").write_text("INPUT L=2, M=3, G=9.81, Q=30 DEG, U=0\n")
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED.replace("INPUT L=2, M=3, G=9.81, Q=30 DEG, U=0,", "RUN values.al\n"
                                    "INPUT").replace("CODE DYNAMICS() pushed.c\n", "L2 = L^2\n"))
    env = dict(os.environ)
    first = run_cli(["run", str(model), "--out", str(tmp_path / "a")], env)
    assert first.returncode == 0, first.stderr
    assert "no CODE command: the responses Autolev displayed follow" in first.stderr
    assert "-> (" in first.stdout and "L2 = L^2" in first.stdout
    # the model is translated, not built, for its responses
    assert "reading and forming" not in first.stderr and "'sympy'" in first.stdout
    again = run_cli(["run", str(model), "--out", str(tmp_path / "b")], env)
    assert (again.returncode, again.stderr) == (0, first.stderr)
    assert _without_imported(again.stdout) == _without_imported(first.stdout)
    assert "imported: []" in again.stdout
    assert not (tmp_path / "a").exists() and not (tmp_path / "b").exists()
    # `autolev transcript` keeps its text too
    shown = run_cli(["transcript", str(model)], env)
    assert _without_imported(shown.stdout) == _without_imported(first.stdout)
    assert "imported: []" in run_cli(["transcript", str(model)], env).stdout
    # a file the model reads changed: its responses anew
    (tmp_path / "values.al").write_text("INPUT L=2, M=3, G=9.81, Q=45 DEG, U=0\n")
    changed = run_cli(["run", str(model), "--out", str(tmp_path / "c")], env)
    assert changed.returncode == 0 and "'sympy'" in changed.stdout
    assert _without_imported(changed.stdout) != _without_imported(first.stdout)
    assert "45" in changed.stdout


@pytest.mark.parametrize("fault, said", [
    ("Q' = U\nX = 1/0", "division by zero"),
    ("Q' = U + NOTDECLARED", "'NOTDECLARED' is not declared or defined"),
])
def test_a_refused_model_is_refused_again_without_being_built(cache, tmp_path, fault, said):
    (tmp_path / "part.al").write_text(fault + "\n")
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED.replace("Q' = U\n", "RUN part.al\n"))
    env = dict(os.environ)
    first = run_cli(["run", str(model), "--out", str(tmp_path / "a")], env)
    assert first.returncode == 1 and said in first.stderr and "not run" in first.stderr
    again = run_cli(["run", str(model), "--out", str(tmp_path / "a")], env)
    assert (again.returncode, again.stderr) == (1, first.stderr)
    assert "imported: []" in again.stdout
    # the file it reads mended: the model runs
    (tmp_path / "part.al").write_text("Q' = U\n")
    mended = run_cli(["run", str(model), "--out", str(tmp_path / "a")], env)
    assert mended.returncode == 0, mended.stderr
    assert (tmp_path / "a" / "pushed.1").is_file()


def test_a_run_that_fails_fails_again_from_its_plan_with_the_same_advice(cache, tmp_path):
    model = tmp_path / "pushed.al"
    model.write_text(PUSHED.replace("INPUT L=2, M=3,", "INPUT L=2, M=0,"))
    env = dict(os.environ)
    first = run_cli(["run", str(model), "--out", str(tmp_path / "first")], env)
    assert first.returncode == 1 and "singular at T = 0" in first.stderr
    # the advice read the model: the mass of P
    assert "mass" in first.stderr.split("singular at T = 0", 1)[1]
    again = run_cli(["run", str(model), "--out", str(tmp_path / "again")], env)
    assert again.returncode == 1 and "built in 0.0 s (its run plan)" in again.stdout
    assert "imported: []" in again.stdout
    failure = [line for line in first.stderr.splitlines() if "singular" in line]
    assert [line for line in again.stderr.splitlines() if "singular" in line] == failure
    names = sorted(p.name for p in (tmp_path / "first").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "again").iterdir())
    for name in names:
        assert (tmp_path / "first" / name).read_bytes() == \
            (tmp_path / "again" / name).read_bytes(), name


def test_a_model_built_with_c_is_not_read_back_where_c_is_refused(cache, tmp_path, monkeypatch):
    # found by bench/fuzz.py --mode stale: AUTOLEV_NO_C=1 after a run with C read the
    # built model back, whose compiled functions then failed to compile (exit 70)
    monkeypatch.setenv("AUTOLEV_FOREGROUND", "1")
    monkeypatch.delenv("AUTOLEV_NO_C", raising=False)
    assert main(["run", str(PENDULUM), "--out", str(tmp_path / "c"), "-q"]) == 0
    monkeypatch.setenv("AUTOLEV_NO_C", "1")
    assert main(["run", str(PENDULUM), "--out", str(tmp_path / "no_c"), "-q"]) == 0
    assert (tmp_path / "c" / "double_pendulum.1").read_bytes() == \
        (tmp_path / "no_c" / "double_pendulum.1").read_bytes()
