"""Fixed-seed handfuls of bench/fuzz.py's cases in each mode: none may fail; and each
check the modes make is shown to fail on what it is there to find (a case over the time
limit is a hang, a write through a planted link an escape, rows of another model wrong)."""
import importlib.util
import os
import random
import sys

import pytest

from helpers import EXAMPLES, ROOT

spec = importlib.util.spec_from_file_location("fuzz", ROOT / "bench" / "fuzz.py")
fuzz = importlib.util.module_from_spec(spec)
sys.modules["fuzz"] = fuzz          # its dataclasses look their module up there
spec.loader.exec_module(fuzz)

SEEDS = sorted(EXAMPLES.glob("*.al")) + sorted((ROOT / "tests" / "data").glob("*.al"))


def test_mutation_is_deterministic_and_changes_the_text():
    text = SEEDS[0].read_text()
    a = fuzz.mutate(text, random.Random(7))
    b = fuzz.mutate(text, random.Random(7))
    assert a == b and a != text


def test_fixed_seed_mutants_never_crash():
    outcomes = fuzz.run(150, seed=2024, files=SEEDS, quiet=True)
    assert outcomes["crash"] == 0
    # the mutants exercise both paths
    assert outcomes["parsed"] > 0 and outcomes["diagnosed"] > 0


def test_check_one_flags_a_crash():
    # a filename that cannot be read as a folder makes a RUN unresolvable, not a crash
    assert fuzz.check_one("x = 1\n", "m.al") == ("parsed", None)
    assert fuzz.check_one("x = (\n", "m.al")[0] == "diagnosed"


# -- grammar mode -------------------------------------------------------------------
def test_grammar_cases_are_deterministic_per_seed():
    first = [fuzz.grammar_case(3, i) for i in range(60)]
    assert first == [fuzz.grammar_case(3, i) for i in range(60)]
    assert first != [fuzz.grammar_case(4, i) for i in range(60)]
    assert {c.generator for c in first} == set(fuzz.GENERATORS)
    # every case is written to a file of its own name inside the case folder
    assert all("/" not in c.filename and c.filename not in (".", "..") for c in first)


def test_fixed_seed_grammar_cases_in_a_worker_never_crash():
    cases = [fuzz.grammar_case(2024, i) for i in range(40)]
    results = fuzz.run_cases(cases, jobs=1, timeout=30)
    outcomes = {r.outcome for r in results}
    assert [r.index for r in results] == list(range(40))
    assert not outcomes & set(fuzz.FAILURES), [r for r in results if r.outcome != "ok"]
    assert {"ok", "diagnosed"} <= outcomes
    assert all(r.seconds >= 0 and r.rss_mb > 0 for r in results)


def test_a_case_over_the_time_limit_is_a_hang_and_the_next_runs_in_a_fresh_worker():
    slow = fuzz.Case(0, "model", "slow.al",
                     "CONSTANTS A, B, C, D\nE = EXPAND((A + B + C + D)^60)\n")
    quick = fuzz.Case(1, "model", "quick.al", "CONSTANTS A\nE = A^2\n")
    hang, after = fuzz.run_cases([slow, quick], jobs=1, timeout=1.0)
    assert (hang.outcome, after.outcome) == ("hang", "ok")
    assert 1.0 <= hang.seconds < 5


def test_a_file_written_outside_the_case_folder_is_an_escape(tmp_path, monkeypatch):
    (tmp_path / "cwd").mkdir()
    (tmp_path / "worker").mkdir()
    monkeypatch.chdir(tmp_path / "cwd")
    really_loads = fuzz.load_case

    def writes_into_the_cwd(path, text):
        (tmp_path / "cwd" / "escaped.c").write_text("")
        return "ok", "load", None
    monkeypatch.setattr(fuzz, "load_case", writes_into_the_cwd)
    case = fuzz.Case(0, "hostile", "m.al", "CODE DYNAMICS() escaped.c\n")
    result = fuzz.check_case(case, tmp_path / "worker")
    assert result["outcome"] == "escaped" and "escaped.c" in result["detail"]
    monkeypatch.setattr(fuzz, "load_case", really_loads)
    assert fuzz.check_case(case, tmp_path / "worker")["outcome"] == "ok"


# -- files mode ---------------------------------------------------------------------
def test_files_cases_are_deterministic_with_files_beside_the_model():
    cases = [fuzz.files_case(5, i) for i in range(60)]
    assert cases == [fuzz.files_case(5, i) for i in range(60)]
    assert {c.generator for c in cases} == set(fuzz.FILES_GENERATORS)
    assert all(c.mode == "files" and c.files for c in cases)
    assert any(c.strays for c in cases) and any(c.links for c in cases)
    # RUN files that include each other, some of them many times over
    assert any(c.files[name].count("RUN ") >= 4 for c in cases for name in c.files)


def test_fixed_seed_files_cases_in_a_worker_never_fail():
    cases = [fuzz.files_case(2024, i) for i in range(8)]
    results = fuzz.run_cases(cases, jobs=1, timeout=60)
    assert not {r.outcome for r in results} & set(fuzz.FAILURES), \
        [(r.index, r.outcome, r.detail) for r in results if r.outcome in fuzz.FAILURES]
    assert {"ok", "diagnosed"} <= {r.outcome for r in results}


def test_a_file_read_through_a_link_leading_outside_is_seen(tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "bait.al").write_text("BAIT = 1\n")
    (tmp_path / "link.al").symlink_to(outside / "bait.al")
    watch = fuzz.Watch()
    watch.start(outside, writes_only=False)
    watch("open", (str(tmp_path / "link.al"), "r", 0))
    watch("open", (str(tmp_path / "inside.al"), "r", 0))
    assert watch.stop() == [f"{tmp_path / 'link.al'} (read)"]
    watch.start(outside, writes_only=True)          # commands: only writes count
    watch("open", (str(tmp_path / "link.al"), "r", 0))
    assert watch.stop() == []


def test_a_stray_file_that_changes_the_model_is_wrong(tmp_path):
    # fx.r is the model's own function: taken for a stray file, moving it away changes
    # what the model means, which the check must call wrong
    case = fuzz.Case(0, "stray", "model.al", fuzz._FILES_HEAD + "EF = FX(Q)\n" +
                     fuzz._FILES_TAIL, mode="files", files={"fx.r": "#1# + 1\n"},
                     strays=["fx.r"])
    (tmp_path / "cwd").mkdir()
    result = fuzz.check_files_case(case, tmp_path)
    assert result["outcome"] == "wrong" and "fx.r" in result["detail"]
    case.strays = []
    assert fuzz.check_files_case(case, tmp_path)["outcome"] == "ok"


def test_a_file_written_outside_by_a_files_case_is_an_escape(tmp_path, monkeypatch):
    case = fuzz.files_case(2024, 0)
    (tmp_path / "cwd").mkdir()

    def writes_outside(path, text):
        (tmp_path / "outside" / "new.al").write_text("")
        return "ok", "load", None, ""
    monkeypatch.setattr(fuzz, "load_stages", writes_outside)
    case.commands = []
    result = fuzz.check_files_case(case, tmp_path)
    assert result["outcome"] == "escaped" and "outside/new.al new" in result["detail"]


# -- commands mode ------------------------------------------------------------------
def test_commands_cases_are_deterministic_and_plant_things_at_output_names():
    cases = [fuzz.commands_case(5, i) for i in range(40)]
    assert cases == [fuzz.commands_case(5, i) for i in range(40)]
    assert {"example", "chain", "generated"} <= {c.generator for c in cases}
    assert all(c.commands and all("{model}" in argv for argv in c.commands) for c in cases)
    kinds = {kind for c in cases for kind, _ in c.links.values()}
    assert {"symlink", "hardlink", "file"} <= kinds
    assert all(name.startswith("out/") for c in cases for name in c.links)


def pendulum_case(**planted):
    """The shipped pendulum, `autolev code` into out/, things planted at its outputs."""
    text = (EXAMPLES / "simple_pendulum.al").read_text()
    return fuzz.Case(0, "example", "simple_pendulum.al", text, mode="commands",
                     links=planted, outside=dict(fuzz._VICTIMS),
                     commands=[["code", "--out", "{out}", "-q", "{model}"]])


def careless_write(target, data, mode=0o666):
    """A writer that opens its target: through a link planted there."""
    with open(target, "w") as f:
        f.write(data if isinstance(data, str) else data.decode())
    return target


def test_a_write_through_a_planted_link_is_an_escape(tmp_path, monkeypatch):
    from autolev.engine import outputs
    case = pendulum_case(**{"out/simple_pendulum.in": ["symlink", "@OUTSIDE@/victim1"]})
    (tmp_path / "cwd").mkdir()
    assert fuzz.check_commands_case(case, tmp_path)["outcome"] == "ok"
    monkeypatch.setattr(outputs, "write_whole", careless_write)
    result = fuzz.check_commands_case(case, tmp_path)
    assert result["outcome"] == "escaped" and "outside/victim1 changed" in result["detail"]


def test_a_users_file_replaced_without_overwrite_is_clobbered(tmp_path, monkeypatch):
    from autolev.engine import outputs
    case = pendulum_case(**{"out/simple_pendulum.c": ["file", "my own program\n"]})
    (tmp_path / "cwd").mkdir()
    assert fuzz.check_commands_case(case, tmp_path)["outcome"] == "diagnosed"
    monkeypatch.setattr(outputs.Written, "check", lambda self, names, overwrite=False: None)
    result = fuzz.check_commands_case(case, tmp_path)
    assert result["outcome"] == "clobbered" and "out/simple_pendulum.c" in result["detail"]


def test_a_temporary_left_behind_is_a_failure(tmp_path, monkeypatch):
    from autolev.engine import outputs
    really_writes = outputs.write_whole

    def leaves_one(target, data, mode=0o666):
        outputs.temporary_beside(target).write_text("")
        return really_writes(target, data, mode)
    monkeypatch.setattr(outputs, "write_whole", leaves_one)
    (tmp_path / "cwd").mkdir()
    result = fuzz.check_commands_case(pendulum_case(), tmp_path)
    assert result["outcome"] == "leftover" and ".autolev-part" in result["detail"]


def test_a_c_program_that_does_not_compile_is_named(tmp_path):
    if fuzz.shutil.which("cc") is None and fuzz.shutil.which("gcc") is None:
        pytest.skip("no C compiler")
    good, bad = tmp_path / "good.c", tmp_path / "bad.c"
    good.write_text("#include <math.h>\nint main(void) { return (int) sqrt(4.0) - 2; }\n")
    bad.write_text("int main(void) { return gamma; }\n")
    assert fuzz.compile_problem(good, tmp_path) is None
    assert "bad.c does not compile" in fuzz.compile_problem(bad, tmp_path)


def test_fixed_seed_commands_cases_in_a_worker_never_fail():
    cases = [fuzz.commands_case(2024, i) for i in (0, 1, 2)]
    results = fuzz.run_cases(cases, jobs=1, timeout=120)
    assert not {r.outcome for r in results} & set(fuzz.FAILURES), \
        [(r.index, r.outcome, r.detail) for r in results if r.outcome in fuzz.FAILURES]


# -- threads mode -------------------------------------------------------------------
def test_threads_cases_sweep_different_models():
    cases = [fuzz.threads_case(5, i) for i in range(30)]
    assert cases == [fuzz.threads_case(5, i) for i in range(30)]
    assert {c.generator for c in cases} == set(fuzz.THREADS_GENERATORS)
    for c in cases:
        assert 2 <= len(c.files) <= 3 and len(set(c.files.values())) == len(c.files)
        assert all(spec["model"] in c.files and len(spec["points"]) >= 3
                   for spec in c.sweeps)


def test_rows_of_another_model_are_wrong(tmp_path):
    import autolev
    case = fuzz.threads_case(2024, 0)
    fuzz.set_up(case, tmp_path)
    specs = [s for s in case.sweeps if s["how"] != "forked"][:2]
    case.sweeps = specs
    truths = [fuzz._sweep_table(autolev.load(tmp_path / "case" / s["model"]), s, "alone")
              for s in specs]
    assert fuzz._worst(fuzz.judge_sweeps(case, truths, [None, None], truths))[0] == "ok"
    # the second sweep's points evaluated on the first model: rows of the wrong model
    swapped = dict(specs[1], model=specs[0]["model"])
    wrong = fuzz._sweep_table(autolev.load(tmp_path / "case" / specs[0]["model"]),
                              swapped, "alone")
    outcome, _, detail = fuzz._worst(fuzz.judge_sweeps(case, [truths[0], wrong],
                                                       [None, None], truths))
    assert outcome == "wrong" and specs[1]["model"] in detail
    crashed = fuzz.judge_sweeps(case, truths, [None, "Traceback ..."], truths)
    assert fuzz._worst(crashed)[0] == "crash"


def test_a_fixed_seed_threads_case_in_a_worker_never_fails():
    # case 0: two sweeps on worker processes and one on a thread pool at once, then one
    # on workers forked from the worker
    case = fuzz.threads_case(2024, 0)
    assert {s["how"] for s in case.sweeps} == {"workers", "thread-pool", "forked"}
    [result] = fuzz.run_cases([case], jobs=1, timeout=120)
    assert result.outcome == "ok", result.detail


def test_replay_writes_a_case_and_its_commands(tmp_path):
    commands = fuzz.write_case(fuzz.commands_case(2024, 0), tmp_path)
    assert commands and all(c.startswith("autolev ") for c in commands)
    case = fuzz.commands_case(2024, 0)
    assert (tmp_path / "case" / case.filename).is_file()
    for name, (kind, _) in case.links.items():
        assert (tmp_path / "case" / name).is_symlink() == (kind == "symlink")


# -- stale mode ---------------------------------------------------------------------
stale = fuzz.fuzz_stale
HARMONIC = ROOT / "tests" / "data" / "numerics" / "harmonic.al"


def test_stale_cases_are_deterministic_and_change_one_input_each():
    cases = [fuzz.make_case("stale", 5, i) for i in range(300)]
    assert cases == [fuzz.make_case("stale", 5, i) for i in range(300)]
    assert {c.generator for c in cases} == set(stale.GENERATORS)
    assert {c.change["command"] for c in cases} == set(stale.COMMAND_WEIGHTS)
    for c in cases:
        kind = c.change["kind"]
        first, after = c.commands
        knobs_first, knobs_after = c.change["knobs"]
        # the change is the kind's and no other
        assert (first != after) == (kind in ("set", "specified")), c
        assert (knobs_first != knobs_after) == (kind == "env"), c
        assert bool(c.change["edits"]) == (kind in ("model", "macro", "run-file", "added")), c
        assert (c.change["in_edit"] is not None) == (kind == "in"), c
        for name, text in c.change["edits"].items():
            files = {c.filename: c.text, **c.files}
            assert (name in files) == (kind != "added") and files.get(name) != text, c
    # the models: examples, generated chains with macros and RUN files, files added
    sources = " ".join(c.change["source"] for c in cases)
    assert "example" in sources and "macros" in sources and "run-file" in sources
    assert {"missing-variant", "missing-macro", "missing-run", "missing-function"} <= \
        set(sources.split())


def harmonic_case(moment: str = "locked") -> "fuzz.Case":
    """harmonic.al run, its spring's INPUT K = 4 made 9 at `moment`."""
    text = HARMONIC.read_text()
    edited = text.replace("INPUT K = 4", "INPUT K = 9")
    assert edited != text
    argv = ["run", "--out", "{out}", "-q", "harmonic.al"]
    change = {"kind": "model", "moment": moment, "command": "run",
              "source": "example harmonic", "edits": {"harmonic.al": edited},
              "in_file": False, "in_edit": None, "knobs": [{}, {}], "delay": 0.3,
              "write": "replace", "warm": False, "link_sleep": 0.5}
    return fuzz.Case(0, f"model@{moment}", "harmonic.al", text, mode="stale",
                     commands=[argv, list(argv)], change=change)


@pytest.fixture(scope="module")
def stale_shared(tmp_path_factory):
    """The folder a fuzz run's workers share (the fresh answers kept there)."""
    return tmp_path_factory.mktemp("stale-shared")


def test_an_answer_moved_by_the_change_is_ok(stale_shared):
    folder = stale_shared / "worker-ok"
    folder.mkdir()
    result = stale.check_stale_case(harmonic_case(), folder)
    # the first command's answer (of K = 4) is not the fresh one: a run repeating it would
    # be found
    assert (result["outcome"], result["stage"]) == ("ok", "run:moved"), result["detail"]


@pytest.mark.parametrize("second_run, outcome, said", [
    ("the first run's files", "stale", "the answer of the old inputs"),
    ("exit status 1", "error", "an exit status other than the fresh run's"),
])
def test_a_wrong_second_run_is_found(stale_shared, monkeypatch, second_run, outcome, said):
    folder = stale_shared / f"worker-{outcome}"
    folder.mkdir()
    really_finishes = stale.Running.finish

    def finishes_wrongly(self):
        ran = really_finishes(self)
        if self.label != "out2":
            return ran
        if second_run == "exit status 1":
            return stale.replace(ran, status=1)
        fuzz.shutil.rmtree(ran.out)
        fuzz.shutil.copytree(self.session.work / "out1", ran.out)
        return ran
    monkeypatch.setattr(stale.Running, "finish", finishes_wrongly)
    result = stale.check_stale_case(harmonic_case(), folder)
    assert (result["outcome"], result["stage"]) == (outcome, "out2"), result["detail"]
    assert said in result["detail"] and "timeline:" in result["detail"]


def test_a_crash_is_exit_status_70_a_signal_or_a_traceback():
    def ended(status, stderr=""):
        return stale.Ran("out2", ["run"], {}, status, "", stderr, 0.0, 1.0, None)
    assert stale.crashed(ended(0)) is None and stale.crashed(ended(1, "error: ...")) is None
    assert stale.crashed(ended(None)) is None           # over time: a hang
    assert stale.crashed(ended(70)) and stale.crashed(ended(-9))
    assert stale.crashed(ended(1, "Traceback (most recent call last):\n"))


def test_fresh_answers_are_kept_by_the_final_inputs(tmp_path, monkeypatch):
    files = {"harmonic.al": HARMONIC.read_bytes()}
    argv = ["run", "--out", "{out}", "-q", "harmonic.al"]
    answer = stale.fresh_answer(tmp_path, tmp_path / "w", files, "run", argv, {})
    assert answer["status"] == 0 and "file harmonic.1" in answer["parts"]
    runs = []

    def counted(self, label, argv, knobs):
        runs.append(argv)
        return stale.Ran(label, argv, knobs, 0, "", "", 0.0, 0.0, None)
    monkeypatch.setattr(stale.Session, "run", counted)
    assert stale.fresh_answer(tmp_path, tmp_path / "w", dict(files), "run", argv, {}) == answer
    assert runs == []
    other = {"harmonic.al": files["harmonic.al"].replace(b"K = 4", b"K = 5")}
    assert stale.fresh_answer(tmp_path, tmp_path / "w", other, "run", argv, {})["parts"] == {}
    assert len(runs) == 1


def test_a_command_over_its_time_limit_is_killed_with_its_background_child(tmp_path,
                                                                          monkeypatch):
    monkeypatch.setattr(stale, "COMMAND_SECONDS", 3.0)
    model_dir = tmp_path / "model"
    model_dir.mkdir()
    fuzz.shutil.copy(HARMONIC, model_dir)
    session = stale.Session(tmp_path, model_dir, stale.slow_compiler(tmp_path))
    # a million seconds in Python's RK45: the work goes on in the command's child
    ran = session.run("long", ["run", "--out", "{out}", "--tfinal", "1e6", "--method", "rk45",
                               "harmonic.al"], {})
    assert ran.status is None and 3 <= ran.ended - ran.began < 10
    session.end()
    assert stale.tagged(session.tag) == []


def test_a_stale_case_replays_by_hand(tmp_path):
    case = harmonic_case("during")
    commands = fuzz.write_case(case, tmp_path)
    assert (tmp_path / "model" / "harmonic.al").read_text() == case.text
    assert "INPUT K = 9" in (tmp_path / "change" / "harmonic.al").read_text()
    # the first command in the background, the file changed while it runs
    started = next(k for k, c in enumerate(commands) if c.endswith(" &"))
    assert commands[started + 1:started + 4] == ["sleep 0.3", "cp {} harmonic.al".format(
        tmp_path / "change" / "harmonic.al"), "wait"]
    assert any("AUTOLEV_FOREGROUND=1" in c and "fresh-cache" in c for c in commands)


def test_fixed_seed_stale_cases_are_never_stale():
    # an .in value edited while the background child holds the lock; a missing RUN file
    # added while a model without CODE runs (a kept outcome)
    cases = [fuzz.make_case("stale", 2024, i) for i in (24, 13)]
    assert [c.generator for c in cases] == ["in@locked", "added@during"]
    assert [c.change["command"] for c in cases] == ["run", "outcome"]
    results = fuzz.run_cases(cases, jobs=1, timeout=300)
    assert [r.outcome for r in results] == ["ok"] * 2, [r.detail for r in results]


@pytest.mark.slow
def test_more_fixed_seed_stale_cases_are_never_stale():
    cases = [fuzz.make_case("stale", 2024, i) for i in range(40)]
    results = fuzz.run_cases(cases, jobs=2, timeout=300)
    assert not [r for r in results if r.outcome != "ok"], \
        [(r.index, r.outcome, r.detail) for r in results if r.outcome != "ok"]


# -- background mode ----------------------------------------------------------------
background = fuzz.fuzz_background
hostile = fuzz.fuzz_hostile


def test_background_cases_are_deterministic_and_draw_every_fault():
    cases = [fuzz.make_case("background", 5, i) for i in range(300)]
    assert cases == [fuzz.make_case("background", 5, i) for i in range(300)]
    assert cases != [fuzz.make_case("background", 6, i) for i in range(300)]
    faults = [c.change for c in cases]
    assert {c.generator for c in cases} == set(background.GENERATORS)
    assert {f["signal"] for f in faults if "signal" in f} == set(background.SIGNALS)
    assert {f["event"] for f in faults if "event" in f} == set(background.TERMINAL_EVENTS)
    assert {(f["family"], f["action"]) for f in faults if "action" in f} == \
        {("cache", a) for a in background.CACHE_FAULTS} | \
        {("config", a) for a in background.CONFIG_FAULTS}
    assert {f["moment"] for f in faults} == set(background.MOMENTS)
    # the children are signalled while the outputs are written and while they compile
    assert {f["moment"] for f in faults if f["family"] == "signal-child"} == \
        {"early", "compiling"}
    assert {"example", "chain"} == {c.change["source"].split()[0] for c in cases}
    assert all(c.commands[0][:3] == ["run", "--out", "{out}"] for c in cases)


def background_case(family: str, **fault) -> "fuzz.Case":
    """harmonic.al run with one fault of `family` (the rest of the fault given)."""
    text = HARMONIC.read_text()
    change = {"family": family, "source": "example harmonic", "link_sleep": 0.5,
              "delay": 0.0, **fault}
    return fuzz.Case(0, family, "harmonic.al", text, mode="background",
                     commands=[["run", "--out", "{out}", "harmonic.al"]], change=change)


@pytest.fixture(scope="module")
def background_shared(tmp_path_factory):
    """The folder a fuzz run's workers share (the fresh answers and compiler there)."""
    return tmp_path_factory.mktemp("background-shared")


@pytest.fixture
def notes(monkeypatch):
    """What the cases played note (the fault sent, typed, applied)."""
    said: list[str] = []
    really_notes = background.Play.note

    def note(self, text):
        said.append(text)
        really_notes(self, text)
    monkeypatch.setattr(background.Play, "note", note)
    return said


@pytest.mark.parametrize("family, fault, landed", [
    ("signal-parent", {"signal": "SIGTERM", "moment": "early", "delay": 0.3},
     "SIGTERM sent to the parent"),
    ("signal-child", {"signal": "SIGKILL", "moment": "compiling", "delay": 0.2},
     "SIGKILL sent to the child"),
    ("terminal", {"event": "ctrl-z", "moment": "early", "delay": 0.3, "pause": 0.5},
     "ctrl-z typed"),
    ("cache", {"action": "read-only", "moment": "compiling", "delay": 0.2,
               "repair": False}, "the cache read-only"),
    ("config", {"action": "truncated", "moment": "early", "delay": 0.4,
                "key_length": 16, "repair": False}, "the cache key cut to 16 bytes"),
])
def test_a_fault_of_each_family_is_survived(background_shared, notes, family, fault,
                                            landed):
    folder = background_shared / f"worker-{family}"
    folder.mkdir()
    result = background.check_background_case(background_case(family, **fault), folder)
    assert result["outcome"] == "ok", result["detail"]
    assert [n for n in notes if n.startswith(landed)], notes
    assert "the recovery run ended, exit status 0" in notes
    if family == "signal-parent":      # it died of what it was sent
        assert result["stage"] in ("early, exit -15", "early, exit 143")


def test_the_exit_statuses_a_signal_explains():
    def allowed(*sent):
        return background.expected_statuses([{"signal": s, "to": to} for s, to in sent])
    assert allowed() == {0: False}
    assert allowed(("SIGSTOP", "child"), ("SIGCONT", "child")) == {0: False}
    # exit 1 must say why
    assert allowed(("SIGINT", "parent")) == {0: False, 1: True, 130: False, -2: False}
    assert allowed(("SIGKILL", "parent")) == {0: False, -9: False}
    assert allowed(("SIGKILL", "child")) == {0: False, 1: True}


def test_a_traceback_is_a_crash_but_an_interrupt_before_autolev_runs():
    def ended(status, text):
        return background.Ended("faulted", status, "", text, 0.0, 1.0)
    in_python = ('Traceback (most recent call last):\n  File "<frozen runpy>", line 189, in '
                 '_run_module_as_main\n  File "<frozen runpy>", line 112, in '
                 '_get_module_details\nKeyboardInterrupt\n')
    in_autolev = in_python.replace(
        "KeyboardInterrupt", '  File "/src/autolev/cli/run.py", line 3, in cmd_run\n'
        "KeyboardInterrupt")
    sigint = [{"signal": "SIGINT", "to": "parent"}]
    assert background.crash_of(ended(-2, in_python), sigint) is None
    assert background.crash_of(ended(-2, in_python), [])          # SIGINT not sent
    assert background.crash_of(ended(-2, in_autolev), sigint)
    assert background.crash_of(ended(70, ""), sigint)
    assert background.crash_of(ended(1, "autolev: internal error: ..."), sigint)
    assert background.crash_of(ended(130, ""), sigint) is None


def misbehaving(tmp_path, monkeypatch, script: str) -> None:
    """The cases' command replaced by `script` (Python; sys.argv: autolev's arguments)."""
    program = tmp_path / "misbehaving.py"
    program.write_text(script)
    monkeypatch.setattr(background, "PROGRAM", [sys.executable, str(program)])


def test_an_internal_error_is_a_crash(background_shared, tmp_path, monkeypatch):
    misbehaving(tmp_path, monkeypatch, "import sys\n"
                "print('autolev: internal error: a bug in autolev', file=sys.stderr)\n"
                "sys.exit(70)\n")
    case = background_case("config", action="truncated", moment="before", key_length=0,
                           repair=False)
    result = background.check_background_case(case, background_shared / "worker-crash")
    assert result["outcome"] == "crash" and "exit status 70" in result["detail"]


def test_a_process_left_running_is_leaked_and_killed(background_shared, tmp_path,
                                                     monkeypatch):
    # the real command, after starting a process that outlives it (with the case's tag)
    misbehaving(tmp_path, monkeypatch, "import os, subprocess, sys\n"
                "subprocess.Popen(['sleep', '300'], start_new_session=True)\n"
                "os.execv(sys.executable, [sys.executable, '-m', 'autolev', *sys.argv[1:]])\n")
    monkeypatch.setattr(background, "LINGER_SECONDS", 1.0)
    case = background_case("cache", action="remove", moment="early", delay=0.2,
                           repair=False)
    result = background.check_background_case(case, background_shared / "worker-leak")
    assert result["outcome"] == "leaked" and "sleep 300" in result["detail"]
    assert not [pid for pid in background_sleepers() if pid]


def background_sleepers() -> list[int]:
    """`sleep 300` processes still alive (the test's leak, killed by the case)."""
    found = []
    for entry in os.listdir("/proc"):
        try:
            line = open(f"/proc/{entry}/cmdline", "rb").read()
        except OSError:
            continue
        if line == b"sleep\x00300\x00" and background._alive(int(entry)):
            found.append(int(entry))
    return found


def test_a_command_stopped_on_its_terminal_without_a_ctrl_z_is_a_hang(background_shared,
                                                                     tmp_path, monkeypatch):
    # as a background writer on a terminal with tostop was (SIGTTOU): a shell leaves it
    misbehaving(tmp_path, monkeypatch, "import os, signal\n"
                "os.kill(os.getpid(), signal.SIGSTOP)\n")
    monkeypatch.setattr(background, "COMMAND_SECONDS", 3.0)
    case = background_case("terminal", event="tostop", moment="early", delay=0.1)
    result = background.check_background_case(case, background_shared / "worker-stop")
    assert result["outcome"] == "hang" and "with no ^Z typed" in result["detail"]


def test_a_temporary_the_recovery_run_leaves_is_a_leftover(background_shared, tmp_path,
                                                          monkeypatch):
    misbehaving(tmp_path, monkeypatch, "import os, subprocess, sys\n"
                "done = subprocess.call([sys.executable, '-m', 'autolev', *sys.argv[1:]])\n"
                "out = sys.argv[sys.argv.index('--out') + 1]\n"
                "open(os.path.join(out, '.harmonic.1.999.beef.autolev-part'), 'w').close()\n"
                "sys.exit(done)\n")
    case = background_case("signal-child", signal="SIGSTOP", moment="compiling",
                           delay=0.1, pause=0.2)
    result = background.check_background_case(case, background_shared / "worker-left")
    assert result["outcome"] == "leftover", result["detail"]
    assert "out/.harmonic.1.999.beef.autolev-part" in result["detail"]


# -- hostile mode -------------------------------------------------------------------
def test_hostile_cases_are_deterministic_and_draw_every_kind():
    cases = [fuzz.make_case("hostile", 5, i) for i in range(300)]
    assert cases == [fuzz.make_case("hostile", 5, i) for i in range(300)]
    assert {c.generator for c in cases} == set(hostile.WHERES)
    assert {c.change["kind"] for c in cases} == set(hostile.READ_KINDS)
    assert {c.change["kind"] for c in cases if c.generator == "output"} == \
        set(hostile.WRITE_KINDS)
    assert {c.change["command"] for c in cases} == set(hostile.COMMANDS)
    for c in cases:     # each command reads or writes the hostile name
        assert c.change["command"] in (hostile.WRITTEN if c.generator == "output"
                                       else hostile.READERS[c.generator])


def hostile_case(where: str, kind: str, argv: list, overwrite: bool = False) -> "fuzz.Case":
    files = hostile.pendulum(1)
    name = hostile.NAMES.get(where) or f"out/{argv[-1].replace('.al', '.c')}"
    change = {"where": where, "kind": kind, "command": argv[0], "name": name,
              "overwrite": overwrite}
    return fuzz.Case(0, where, "x.al", files.pop("x.al"), mode="hostile", files=files,
                     commands=[argv], change=change)


@pytest.mark.parametrize("where, kind, argv", [
    ("model", "fifo", ["check", "x.al"]),
    ("macro", "fifo-held", ["run", "--out", "{out}", "--tfinal", "0.2", "x.al"]),
    ("in", "devzero", ["linearize", "--in", "vals.in", "x.al"]),
    ("output", "tty", ["code", "--out", "{out}", "x.al"]),
    ("output", "fifo-held", ["code", "--out", "{out}", "x.al"]),
])
def test_hostile_files_are_refused_or_replaced(tmp_path, where, kind, argv):
    result = hostile.check_hostile_case(hostile_case(where, kind, argv), tmp_path / "w")
    assert result["outcome"] == "ok", result["detail"]


def test_a_read_blocked_on_a_fifo_is_a_hang(tmp_path, monkeypatch):
    misbehaving(tmp_path, monkeypatch, "import sys\nopen(sys.argv[-1]).read()\n")
    monkeypatch.setattr(hostile, "COMMAND_SECONDS", 2.0)
    result = hostile.check_hostile_case(hostile_case("model", "fifo", ["check", "x.al"]),
                                        tmp_path / "w")
    assert result["outcome"] == "hang", result["detail"]


def test_a_write_through_a_fifo_is_clobbered(tmp_path, monkeypatch):
    misbehaving(tmp_path, monkeypatch, "import os, sys\n"
                "out = sys.argv[sys.argv.index('--out') + 1]\n"
                "open(os.path.join(out, 'x.c'), 'w').write('int x;\\n')\n")
    result = hostile.check_hostile_case(
        hostile_case("output", "fifo-held", ["code", "--out", "{out}", "x.al"]),
        tmp_path / "w")
    assert result["outcome"] == "clobbered" and "written through out/x.c" in \
        result["detail"]


def test_a_failure_must_name_the_file(tmp_path, monkeypatch):
    misbehaving(tmp_path, monkeypatch, "import sys\n"
                "print('autolev: error: cannot read a file', file=sys.stderr)\n"
                "sys.exit(1)\n")
    result = hostile.check_hostile_case(hostile_case("model", "dir", ["check", "x.al"]),
                                        tmp_path / "w")
    assert result["outcome"] == "wrong" and "without naming x.al" in result["detail"]
    assert hostile._names_it("autolev: error: x.al: cannot read", "x.al")
    assert not hostile._names_it("error (out/.x.1.4752.bcb9.autolev-part)", "out/x.1")


def test_a_process_a_hostile_command_leaves_is_leaked(tmp_path, monkeypatch):
    misbehaving(tmp_path, monkeypatch, "import os, subprocess, sys\n"
                "subprocess.Popen(['sleep', '300'], start_new_session=True)\n"
                "os.execv(sys.executable, [sys.executable, '-m', 'autolev', *sys.argv[1:]])\n")
    monkeypatch.setattr(hostile, "LINGER_SECONDS", 1.0)
    result = hostile.check_hostile_case(hostile_case("model", "socket", ["check", "x.al"]),
                                        tmp_path / "w")
    assert result["outcome"] == "leaked" and "sleep 300" in result["detail"]
    assert not background_sleepers()


def test_fixed_seed_hostile_cases_in_a_worker_never_fail():
    # (the background cases are played in the worker by the same CHECKS)
    assert fuzz.CHECKS["background"] is background.check_background_case
    cases = [fuzz.make_case("hostile", 2024, i) for i in range(4)]
    results = fuzz.run_cases(cases, jobs=1, timeout=120)
    assert not [r for r in results if r.outcome != "ok"], \
        [(r.index, r.outcome, r.detail) for r in results if r.outcome != "ok"]


def test_background_and_hostile_cases_replay_by_hand(tmp_path):
    case = background_case("signal-parent", signal="SIGINT", moment="early", delay=0.4)
    commands = fuzz.write_case(case, tmp_path / "b")
    assert (tmp_path / "b" / "model" / "harmonic.al").read_text() == case.text
    started = next(k for k, c in enumerate(commands) if c.endswith("& pid=$!"))
    assert commands[started + 1:started + 4] == ["sleep 0.4", "kill -INT $pid", "wait $pid"]
    case = hostile_case("model", "fifo", ["check", "x.al"])
    commands = fuzz.write_case(case, tmp_path / "h")
    assert "rm -rf x.al; mkfifo x.al" in commands
    assert commands[-1].endswith("-m autolev check x.al; echo exit $?")


def test_a_file_lands_where_the_cache_was_though_the_command_makes_it_again(tmp_path,
                                                                             monkeypatch):
    # the command running beside the fault makes its cache folder again between the
    # folder's removal and the file's arrival (seed 2 case 728 crashed the fuzzer there)
    cache = tmp_path / "cache"
    cache.mkdir()
    vanish, made_again = background._vanish, []

    def vanish_then_made_again(folder):
        vanish(folder)
        if len(made_again) < 2:
            folder.mkdir()
            made_again.append(folder)
    monkeypatch.setattr(background, "_vanish", vanish_then_made_again)
    background._file_in_place_of(cache, "a file\n")
    assert len(made_again) == 2 and cache.is_file() and cache.read_text() == "a file\n"
    assert [p.name for p in tmp_path.iterdir()] == ["cache"]
