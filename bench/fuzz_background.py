"""The background mode of bench/fuzz.py: the background machinery under faults.

A cold `autolev run --out DIR` forks at its start; the child does the work, tells the
parent its exit status once the files are written, and goes on compiling the model's C
in the background (its own process group, holding a lock file in the cache) to write a
run plan.  Each case runs one such command on a small model and injects ONE fault at a
random moment (its delay drawn from the case's random stream); the generator is its
family:

  signal-parent  SIGINT, SIGTERM, SIGHUP, SIGKILL, SIGSTOP then SIGCONT, or SIGTSTP then
                 SIGCONT to the command, while it works (the delay from its start)
  signal-child   the same to the background child (found by the case's tag in its
                 environment): while the outputs are written ("early"), or after the
                 command returned, while the child compiles ("compiling": the compiler is
                 a wrapper that sleeps before it links the loop's shared.o)
  terminal       the command is the foreground job of a pseudo-terminal with `stty
                 tostop` (a small job-control shell leads the session): left alone
                 (tostop), or ^C, ^Z (then `fg` after a pause) or a hang-up (the
                 terminal's master closed) at a random moment
  cache          the cache folder removed, made read-only (chmod 0o500) or replaced by a
                 file: before the command, while it works, or while the child compiles
  config         the config folder of the cache key made read-only, or the key cut
                 short, at the same moments

Every command runs without CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH and CAP_FOWNER (as
root it would write into a read-only folder all the same).  After the fault the case
waits for the command (over COMMAND_SECONDS: a hang), for every background child to
release its lock (over CHILD_SECONDS: a hang) and then to end (LINGER_SECONDS more: a
process still carrying the tag is leaked, and killed), and runs the same command once
more (a recovery run, now and then after the fault is repaired: the cache's mode given
back, the file in its place removed), which must exit 0 and write the files a fresh run
of the model writes in an empty cache in the foreground (kept per model for the fuzz
run, as the stale mode keeps its fresh answers).

Outcomes: ok; crash (exit status 70, a traceback, "internal error", or death by a signal
the case did not send); hang; leaked; leftover (a temporary or a lock in the output
folder, the cache or the record of written files that the recovery run and its child did
not clear; an output folder with a .dir and not every file of the run); wrong (the
faulted command's exit status not one the fault explains -- a signal it sent: 0, its
conventional 128+N, death by it, or exit 1 with a message; SIGKILL to the child: 0 or 1
with a message; anything else: 0 --, a command that exited 0 with files other than the
fresh run's, or a recovery run that did not exit 0 with them).

    python bench/fuzz.py --mode background --cases 1000 --seeds 1,2 --jobs 1
    python bench/fuzz.py --mode background --replay SEED:INDEX [--into DIR]
"""
from __future__ import annotations

import ctypes
import errno
import os
import random
import re
import resource
import select
import shlex
import shutil
import signal
import subprocess
import sys
import termios
import threading
import time
from dataclasses import dataclass
from pathlib import Path

if str(Path(__file__).resolve().parent) not in sys.path:
    sys.path.append(str(Path(__file__).resolve().parent))
import fuzz_stale  # noqa: E402

GENERATORS = ("signal-parent", "signal-child", "terminal", "cache", "config")
WEIGHTS = (24, 26, 16, 20, 14)
SIGNALS = ("SIGINT", "SIGTERM", "SIGHUP", "SIGKILL", "SIGSTOP", "SIGTSTP")
# what ends a process (the rest stop it, and the case continues it)
ENDING = ("SIGINT", "SIGTERM", "SIGHUP", "SIGKILL")
TERMINAL_EVENTS = ("tostop", "ctrl-c", "ctrl-z", "hangup")
CACHE_FAULTS = ("remove", "read-only", "file")
CONFIG_FAULTS = ("read-only", "truncated")
MOMENTS = ("before", "early", "compiling")
OUTCOMES = ("ok", "crash", "hang", "leaked", "leftover", "wrong")
SEVERITY = ("crash", "hang", "leaked", "leftover", "wrong", "ok")

TAG_VARIABLE = fuzz_stale.TAG_VARIABLE
SLEEP_VARIABLE = fuzz_stale.SLEEP_VARIABLE
COMMAND_SECONDS = 60.0          # a command over this is a hang
CHILD_SECONDS = 60.0            # so is a background child holding its lock longer
LINGER_SECONDS = 15.0           # a process of the case alive this long after: leaked
EARLY_SECONDS = 1.2             # "early" faults land within this of the command's start
TEMPORARY_SUFFIX = ".autolev-part"
# the command the cases run (the tests put a program that misbehaves in its place)
PROGRAM = [sys.executable, "-m", "autolev"]


# ---------------------------------------------------------------------------------
# A case

def _source(rng: random.Random) -> fuzz_stale.Source:
    """A small model: a shipped example, the harmonic oscillator of the tests, or a
    generated pendulum or spring chain (with macros, RUN files, a SPECIFIED)."""
    if rng.random() < 0.45:
        return rng.choice(fuzz_stale.example_sources())
    return fuzz_stale.chain_source(rng, None, code=True)


def background_case(seed: int, index: int) -> dict:
    """The fields of case `index` of seed `seed` (a fuzz.Case): the model, the command
    and the fault (`change`)."""
    rng = random.Random(f"autolev-fuzz:background:{seed}:{index}")
    family = rng.choices(GENERATORS, weights=WEIGHTS)[0]
    source = _source(rng)
    argv = ["run", "--out", "{out}"]
    if source.tfinal or rng.random() < 0.25:
        argv += ["--tfinal", source.tfinal or rng.choice(("0.5", "1", "2"))]
    if rng.random() < 0.15:
        argv.append("-q")
    argv += source.arguments
    argv += [a for name in source.specified
             for a in ("--specified", f"{name}={rng.choice(fuzz_stale.EXPRESSIONS)}")]
    argv.append(source.model)
    fault: dict = {"family": family, "source": source.label,
                   "link_sleep": round(rng.uniform(0.3, 2.0), 1)}
    if family == "signal-parent":
        fault.update(signal=rng.choice(SIGNALS), moment="early")
    elif family == "signal-child":
        fault.update(signal=rng.choice(SIGNALS), moment=rng.choice(("early", "compiling")))
    elif family == "terminal":
        fault.update(event=rng.choice(TERMINAL_EVENTS), moment="early")
    elif family == "cache":
        action = rng.choice(CACHE_FAULTS)
        moments = MOMENTS[1:] if action == "remove" else MOMENTS
        fault.update(action=action, moment=rng.choice(moments),
                     repair=action != "remove" and rng.random() < 0.5)
    else:
        action = rng.choice(CONFIG_FAULTS)
        fault.update(action=action, moment=rng.choice(MOMENTS),
                     repair=action == "read-only" and rng.random() < 0.5,
                     key_length=rng.choice((0, 1, 16, 31)))
    if fault["moment"] == "early":
        fault["delay"] = round(rng.uniform(0.0, EARLY_SECONDS), 2)
    elif fault["moment"] == "compiling":
        fault["delay"] = round(rng.uniform(0.0, fault["link_sleep"] + 0.6), 2)
    else:
        fault["delay"] = 0.0
    if fault.get("signal") in ("SIGSTOP", "SIGTSTP") or fault.get("event") == "ctrl-z":
        fault["pause"] = round(rng.uniform(0.1, 2.0), 2)
    others = {name: text for name, text in source.files.items() if name != source.model}
    return {"index": index, "generator": family, "filename": source.model,
            "text": source.files[source.model], "mode": "background", "files": others,
            "commands": [argv], "change": fault}


def fault_words(fault: dict) -> str:
    """The fault in a few words: what, to whom, when."""
    family = fault["family"]
    if family.startswith("signal"):
        what = f"{fault['signal']} to the {family.split('-')[1]}"
        if "pause" in fault:
            what += f", SIGCONT {fault['pause']} s later"
    elif family == "terminal":
        what = f"a terminal with tostop: {fault['event']}"
        if "pause" in fault:
            what += f", fg {fault['pause']} s later"
    elif family == "cache":
        what = f"the cache {fault['action']}"
    else:
        what = ("the config folder read-only" if fault["action"] == "read-only" else
                f"the cache key cut to {fault['key_length']} bytes")
    when = {"before": "before the command",
            "early": f"{fault['delay']} s into the command",
            "compiling": f"{fault['delay']} s after the command returned, the child "
                         "compiling"}[fault["moment"]]
    repaired = "; repaired before the recovery run" if fault.get("repair") else ""
    return f"{what}, {when} (link sleep {fault['link_sleep']} s){repaired}"


def described(case) -> list[str]:
    return [f"fault: {fault_words(case.change)}", f"model: {case.change['source']}"]


# ---------------------------------------------------------------------------------
# The commands of a case

_PR_CAPBSET_DROP = 24
# CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH, CAP_FOWNER: what lets root ignore a file's mode
_DROPPED_CAPABILITIES = (1, 2, 3)
_prctl = ctypes.CDLL(None, use_errno=True).prctl if sys.platform.startswith("linux") else None


def command_preexec() -> None:
    """In a command's process before it runs autolev: the worker's memory limit lifted
    (it is on the soft limit) and the capabilities that ignore a file's mode dropped
    (for it and what it starts), so that a mode 0o500 folder is read-only to it."""
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]
    resource.setrlimit(resource.RLIMIT_AS, (hard, hard))
    if _prctl is not None:
        for capability in _DROPPED_CAPABILITIES:
            _prctl(_PR_CAPBSET_DROP, capability, 0, 0, 0)    # without CAP_SETPCAP: kept


def environment(work: Path, tag: str, compiler: str | None, link_sleep: float) -> dict:
    """A case's commands' environment: its own home, config, cache and state; the tag."""
    env = {k: v for k, v in os.environ.items() if k not in fuzz_stale.CLEARED}
    home = work / "home"
    env.update(HOME=str(home), XDG_CACHE_HOME=str(home / "cache"),
               XDG_CONFIG_HOME=str(home / "config"), XDG_STATE_HOME=str(home / "state"),
               AUTOLEV_CACHE=str(work / "cache"), AUTOLEV_TRACEBACK="1",
               TMPDIR=str(work / "tmp"),
               **{TAG_VARIABLE: tag, SLEEP_VARIABLE: f"{link_sleep:g}"})
    if compiler:
        env["CC"] = compiler
    return env


# The session leader of a terminal case: a job-control shell in a few lines.  It makes
# the terminal (its stdin) its controlling terminal, starts the command as a job of its
# own process group in the foreground, continues it (`fg`) `pause` seconds after a stop
# (a negative pause: never, as a shell leaves a job stopped), passes a hang-up on to
# it, and reports to a file: "job PID", "stopped N", "hangup", "status N".
_SHELL = r"""
import fcntl, os, signal, sys, termios, time
report, pause, argv = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
def say(text):
    with open(report, "a") as f:
        f.write(text + "\n")
fcntl.ioctl(0, termios.TIOCSCTTY, 0)
shell_ignores = (signal.SIGTTOU, signal.SIGTTIN, signal.SIGTSTP, signal.SIGINT,
                 signal.SIGQUIT)
for s in shell_ignores:
    signal.signal(s, signal.SIG_IGN)
job = os.fork()
if job == 0:
    os.setpgid(0, 0)
    os.tcsetpgrp(0, os.getpid())
    for s in shell_ignores:
        signal.signal(s, signal.SIG_DFL)
    os.execv(argv[0], argv)
try:
    os.setpgid(job, job)
except OSError:
    pass
try:
    os.tcsetpgrp(0, job)
except OSError:
    pass
say(f"job {job}")
def hang_up(signum, frame):
    say("hangup")
    for s in (signal.SIGHUP, signal.SIGCONT):
        try:
            os.killpg(job, s)
        except OSError:
            pass
signal.signal(signal.SIGHUP, hang_up)
while True:
    _, how = os.waitpid(job, os.WUNTRACED)
    if os.WIFSTOPPED(how):
        say(f"stopped {os.WSTOPSIG(how)}")
        if pause < 0:
            continue
        time.sleep(pause)
        try:
            os.tcsetpgrp(0, job)
        except OSError:
            pass
        os.killpg(job, signal.SIGCONT)
        say("continued")
        continue
    say(f"status {os.waitstatus_to_exitcode(how)}")
    break
"""


class Terminal:
    """A pseudo-terminal with `stty tostop`; what is written to it is read (drained)
    by a thread, which also hangs it up (closes the master) when asked."""

    def __init__(self):
        self.master, self.slave = os.openpty()
        attributes = termios.tcgetattr(self.slave)
        attributes[3] |= termios.TOSTOP
        termios.tcsetattr(self.slave, termios.TCSANOW, attributes)
        self.said: list[bytes] = []
        self.hangup_asked = threading.Event()
        self.closed = threading.Event()
        self.thread = threading.Thread(target=self._drain, daemon=True)

    def start(self) -> None:
        os.close(self.slave)            # the command's copies stay open in it
        self.slave = -1
        self.thread.start()

    def _drain(self) -> None:
        try:
            while not self.hangup_asked.is_set():
                if not select.select([self.master], [], [], 0.05)[0]:
                    continue
                try:
                    chunk = os.read(self.master, 1 << 16)
                except OSError:         # EIO: every slave descriptor closed
                    chunk = b""
                if not chunk:
                    while not self.hangup_asked.wait(0.05):
                        pass            # kept open (not hung up) until asked
                    break
                self.said.append(chunk)
        finally:
            os.close(self.master)
            self.closed.set()

    def type(self, data: bytes) -> None:
        if not self.closed.is_set():
            os.write(self.master, data)

    def hang_up(self) -> None:
        self.hangup_asked.set()
        self.closed.wait(5)

    def close(self) -> None:
        if self.slave >= 0:
            os.close(self.slave)
            self.slave = -1
        if self.thread.is_alive():
            self.hang_up()
        elif not self.closed.is_set():
            os.close(self.master)
            self.closed.set()

    def text(self) -> str:
        return b"".join(self.said).decode("utf-8", "replace")


@dataclass
class Ended:
    """A command's end: exit status (None: over its time limit, killed), what it
    printed (stdout and stderr, or the terminal's text as stderr), when."""

    label: str
    status: int | None
    stdout: str
    stderr: str
    began: float
    ended: float

    def printed(self) -> str:
        return self.stdout + self.stderr


class Command:
    """A case's command started: plainly (its output to files, a session of its own) or
    as the foreground job of a terminal under the little shell."""

    def __init__(self, case: "Play", label: str, argv: list, link_sleep: float,
                 terminal: Terminal | None = None, pause: float = 0.0):
        self.case, self.label, self.terminal = case, label, terminal
        self.out = case.work / "out"
        args = [str(self.out) if a == "{out}" else a for a in argv]
        self.args = [*PROGRAM, *args]
        env = environment(case.work, case.tag, case.compiler, link_sleep)
        logs = case.work / "logs"
        logs.mkdir(parents=True, exist_ok=True)
        self.streams = (logs / f"{label}.stdout", logs / f"{label}.stderr")
        self.report = logs / f"{label}.shell"
        self.began = case.now()
        if terminal is None:
            with open(self.streams[0], "wb") as out, open(self.streams[1], "wb") as err:
                self.proc = subprocess.Popen(
                    self.args, cwd=case.model_dir, env=env, stdin=subprocess.DEVNULL,
                    stdout=out, stderr=err, start_new_session=True,
                    preexec_fn=command_preexec)
        else:
            self.proc = subprocess.Popen(
                [sys.executable, "-c", _SHELL, str(self.report), f"{pause:g}", *self.args],
                cwd=case.model_dir, env=env, stdin=terminal.slave, stdout=terminal.slave,
                stderr=terminal.slave, start_new_session=True, preexec_fn=command_preexec)
            terminal.start()

    def shell_said(self) -> list[str]:
        try:
            return self.report.read_text().splitlines()
        except OSError:
            return []

    def parent(self) -> int | None:
        """The autolev command's process id (under a terminal: the shell's job)."""
        if self.terminal is None:
            return self.proc.pid
        for line in self.shell_said():
            if line.startswith("job "):
                return int(line.split()[1])
        return None

    def children(self) -> list[int]:
        """The command's forked children alive now (the same command line)."""
        parent = self.parent()
        wanted = ("\0".join(self.args) + "\0").encode()
        found = []
        for pid in fuzz_stale.tagged(self.case.tag):
            if pid == parent:
                continue
            try:
                if Path(f"/proc/{pid}/cmdline").read_bytes() == wanted and _alive(pid):
                    found.append(pid)
            except OSError:
                continue
        return found

    def running(self) -> bool:
        return self.proc.poll() is None

    def wait(self, seconds: float) -> bool:
        try:
            self.proc.wait(timeout=max(seconds, 0.0))
        except subprocess.TimeoutExpired:
            return False
        return True

    def finish(self) -> Ended:
        limit = COMMAND_SECONDS - (self.case.now() - self.began)
        if not self.wait(limit):
            for pid in [self.proc.pid, self.parent()]:
                with _gone():
                    os.killpg(pid, signal.SIGKILL)
            self.proc.wait()
            status = None
        else:
            status = self.proc.returncode
        if self.terminal is None:
            texts = [p.read_bytes().decode("utf-8", "replace") for p in self.streams]
        else:
            self.terminal.thread.join(0.3)      # what is still in the terminal's buffer
            texts = ["", self.terminal.text()]
            if status is not None:
                ends = [line for line in self.shell_said() if line.startswith("status ")]
                # the shell's own end, when it said none (it died: told in the timeline)
                status = int(ends[-1].split()[1]) if ends else status
        return Ended(self.label, status, texts[0], texts[1], self.began, self.case.now())


class _gone:
    """Ignore a process (or file) already gone."""

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        return kind is not None and issubclass(kind, (ProcessLookupError, TypeError,
                                                      FileNotFoundError))


def _alive(pid: int) -> bool:
    """Not a zombie (nor gone)."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(") ", 1)[1][0] not in "ZX"
    except (OSError, IndexError):
        return False


def lock_holders(tag: str) -> list[int]:
    """The processes of the case holding a finishing lock open (a background child),
    the lock's file removed meanwhile or not."""
    found = []
    for pid in fuzz_stale.tagged(tag):
        try:
            fds = os.listdir(f"/proc/{pid}/fd")
        except OSError:
            continue
        for fd in fds:
            try:
                target = os.readlink(f"/proc/{pid}/fd/{fd}")
            except OSError:
                continue
            if "/finishing_" in target and ".lock" in target:
                found.append(pid)
                break
    return found


# ---------------------------------------------------------------------------------
# A case played

class Play:
    """One case: its folder, cache and home, its tag; the command, the fault, the
    recovery run; what was found."""

    def __init__(self, case, folder: Path):
        self.case, self.fault = case, case.change
        self.shared = folder.parent
        self.scratch = folder
        self.work = folder / "background"
        _make_writable(self.work)
        shutil.rmtree(self.work, ignore_errors=True)
        self.model_dir = self.work / "model"
        self.model_dir.mkdir(parents=True)
        (self.work / "tmp").mkdir()
        for name, text in {case.filename: case.text, **case.files}.items():
            fuzz_stale._write(self.model_dir / name, text)
        self.cache = self.work / "cache"
        self.config = self.work / "home" / "config" / "autolev"
        self.state = self.work / "home" / "state"
        self.compiler = fuzz_stale.slow_compiler(self.shared)
        self.tag = f"{os.getpid()}-{time.time_ns()}"
        self.start = time.monotonic()
        self.notes: list[tuple[float, str]] = []
        self.found: list[tuple[str, str, str]] = []
        self.sent: list[dict] = []

    def now(self) -> float:
        return time.monotonic() - self.start

    def note(self, text: str) -> None:
        self.notes.append((self.now(), text))

    def problem(self, outcome: str, stage: str, detail: str) -> None:
        self.found.append((outcome, stage, detail))

    # -- the fault ---------------------------------------------------------------
    def send(self, pid: int | None, name: str, to: str) -> bool:
        if pid is None:
            self.note(f"{name} not sent: no {to}")
            return False
        try:
            os.kill(pid, getattr(signal, name))
        except ProcessLookupError:
            self.note(f"{name} not sent: the {to} ({pid}) had ended")
            return False
        self.note(f"{name} sent to the {to} ({pid})")
        self.sent.append({"signal": name, "to": to})
        return True

    def signal_fault(self, command: Command) -> None:
        fault = self.fault
        name, to = fault["signal"], fault["family"].split("-")[1]
        if to == "parent":
            pid = command.parent() if command.running() else None
        else:
            pid = self.find_child(command)
        if self.send(pid, name, to) and "pause" in fault:
            time.sleep(fault["pause"])
            self.send(pid, "SIGCONT", to)

    def find_child(self, command: Command) -> int | None:
        """The background child: now, or as soon as it is forked while the command runs
        (the command may end first: then the child that compiles, if any)."""
        while True:
            children = command.children()
            if children:
                return children[0]
            if not command.running():
                children = command.children()
                return children[0] if children else None
            time.sleep(0.01)

    def terminal_fault(self, command: Command, terminal: Terminal) -> None:
        event = self.fault["event"]
        if event == "tostop" or not command.running():
            if event != "tostop":
                self.note(f"{event} not typed: the command had ended")
            return
        if event == "hangup":
            terminal.hang_up()
            self.note("the terminal hung up (its master closed)")
            self.sent.append({"signal": "SIGHUP", "to": "terminal"})
            return
        terminal.type(b"\x03" if event == "ctrl-c" else b"\x1a")
        self.note(f"{event} typed")
        if event == "ctrl-c":
            self.sent.append({"signal": "SIGINT", "to": "terminal"})

    def cache_fault(self) -> None:
        action = self.fault["action"]
        if action == "remove":
            _vanish(self.cache)
        elif action == "read-only":
            self.cache.mkdir(parents=True, exist_ok=True, mode=0o700)
            self.cache.chmod(0o500)
        else:
            _file_in_place_of(self.cache, "a file where the cache folder was\n")
        self.note(f"the cache {action}")

    def config_fault(self) -> None:
        if self.fault["action"] == "read-only":
            self.config.mkdir(parents=True, exist_ok=True, mode=0o700)
            self.config.chmod(0o500)
            self.note("the config folder read-only")
            return
        key = self.config / "cache.key"
        n = self.fault["key_length"]
        if key.exists():
            with open(key, "r+b") as f:
                f.truncate(n)
        else:
            self.config.mkdir(parents=True, exist_ok=True, mode=0o700)
            fd = os.open(key, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
            os.write(fd, ("5a" * 32)[:n].encode())
            os.close(fd)
        self.note(f"the cache key cut to {n} bytes")

    def apply(self, command: Command | None, terminal: Terminal | None) -> None:
        family = self.fault["family"]
        if family.startswith("signal"):
            self.signal_fault(command)
        elif family == "terminal":
            self.terminal_fault(command, terminal)
        elif family == "cache":
            self.cache_fault()
        else:
            self.config_fault()

    def repair(self) -> None:
        if not self.fault.get("repair"):
            return
        if self.fault["family"] == "cache" and self.fault["action"] == "read-only":
            self.cache.chmod(0o700)
        elif self.fault["family"] == "cache":
            if self.cache.is_file():
                self.cache.unlink()
        else:
            self.config.chmod(0o700)
        self.note("the fault repaired")

    # -- the commands ------------------------------------------------------------
    def faulted(self, argv: list) -> Ended:
        """The command with its fault, waited for."""
        fault = self.fault
        moment = fault["moment"]
        if moment == "before":
            self.apply(None, None)
        terminal = Terminal() if fault["family"] == "terminal" else None
        try:
            command = Command(self, "faulted", argv, fault["link_sleep"], terminal,
                              fault.get("pause", -1.0))
            self.note("the command started")
            if moment == "early":
                if command.wait(fault["delay"]):
                    self.note("the command had ended within the delay")
                self.apply(command, terminal)
            ended = command.finish()
            self.note(f"the command ended, exit status {ended.status}")
            stops = [line for line in command.shell_said() if line.startswith("stopped")]
            if terminal is not None and stops and fault["event"] != "ctrl-z":
                self.problem("hang", "faulted", f"the command stopped ({stops[0]}) with no "
                             "^Z typed: a shell leaves it stopped")
            if moment == "compiling":
                holders = lock_holders(self.tag)
                time.sleep(fault["delay"])
                self.note("a background child holds its lock" if holders else
                          "no background child held a lock at the command's end")
                self.apply(command, terminal)
        finally:
            if terminal is not None:
                terminal.close()
        return ended

    def wait_for_children(self, after: str) -> None:
        """Until no process of the case holds a lock (hang), then until none is left
        (leaked, and killed)."""
        deadline = time.monotonic() + CHILD_SECONDS
        while lock_holders(self.tag):
            if time.monotonic() > deadline:
                self.problem("hang", after, f"a background child still held its lock "
                             f"{CHILD_SECONDS:g} s after {after}")
                break
            time.sleep(0.05)
        deadline = time.monotonic() + LINGER_SECONDS
        while fuzz_stale.tagged(self.tag) and time.monotonic() < deadline:
            time.sleep(0.05)
        left = fuzz_stale.tagged(self.tag)
        if left:
            shown = ", ".join(f"{pid} ({_command_line(pid)})" for pid in left[:4])
            self.problem("leaked", after, f"processes of the case alive "
                         f"{LINGER_SECONDS:g} s after {after} released its locks: {shown}")
            kill_tagged(self.tag)

    def recovery(self, argv: list) -> Ended:
        command = Command(self, "recovery", argv, 0.0)
        ended = command.finish()
        self.note(f"the recovery run ended, exit status {ended.status}")
        return ended

    def end(self) -> None:
        kill_tagged(self.tag)
        _make_writable(self.work)

    def timeline(self) -> str:
        return "timeline:\n" + "\n".join(f"  {at:6.2f} s  {text}" for at, text in self.notes)


def _command_line(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ") \
            .decode("utf-8", "replace").strip()[:120]
    except OSError:
        return "?"


def kill_tagged(tag: str) -> None:
    """Kill the case's processes and wait until they are gone: on a loaded machine a
    killed process lingers a while, and a later case or test would count it.  Gone means
    two scans a moment apart find none: a process in the middle of an exec shows no
    environment to one scan (CI, loaded: a `sleep` being exec'd outlived the kill)."""
    deadline = time.monotonic() + 10
    quiet_scans = 0
    while quiet_scans < 2:
        left = fuzz_stale.tagged(tag)
        quiet_scans = 0 if left else quiet_scans + 1
        if left and time.monotonic() > deadline:
            raise RuntimeError(f"processes of case {tag} outlived SIGKILL: {left}")
        for pid in left:
            with _gone():
                os.kill(pid, signal.SIGKILL)
        time.sleep(0.05 if left else 0.2)


def _file_in_place_of(folder: Path, text: str) -> None:
    """A file where `folder` was.  The command running meanwhile may make the folder
    again between its removal and the file's arrival (a fuzzer's own IsADirectoryError,
    seed 2 case 728): the file is renamed into place, the folder removed again until it
    lands."""
    made = folder.with_name(folder.name + f".file-{time.time_ns()}")
    made.write_text(text)
    for _ in range(100):
        _vanish(folder)
        try:
            os.rename(made, folder)
            return
        except OSError as exc:
            if exc.errno not in (errno.EISDIR, errno.EEXIST, errno.ENOTEMPTY):
                raise
    raise RuntimeError(f"{folder} was made again a hundred times: no file in its place")


def _vanish(folder: Path) -> None:
    """The folder gone at once (renamed aside, then removed)."""
    aside = folder.with_name(folder.name + f".gone-{time.time_ns()}")
    try:
        os.rename(folder, aside)
    except FileNotFoundError:
        return
    except OSError as exc:
        if exc.errno != errno.ENOTDIR:
            raise
        os.unlink(folder)
        return
    _make_writable(aside)
    shutil.rmtree(aside, ignore_errors=True)


def _make_writable(folder: Path) -> None:
    """Folders the case made read-only given back their mode (to be removed)."""
    if not folder.is_dir() or folder.is_symlink():
        return
    for path in [folder, *folder.rglob("*")]:
        try:
            if path.is_dir() and not path.is_symlink():
                path.chmod(0o700)
        except OSError:
            pass


# ---------------------------------------------------------------------------------
# The judgement

def crash_of(ended: Ended, sent: list = ()) -> str | None:
    """How a command crashed: exit status 70, a traceback, an internal error.  A
    KeyboardInterrupt in Python's own start (importing runpy, finding the module: no
    frame of autolev's), when the case sent SIGINT, is the interrupt's end: no program
    can take it there."""
    text = ended.printed()
    if ended.status == 70 or "internal error" in text or (
            "Traceback (most recent call last)" in text and not (
                any(s["signal"] == "SIGINT" for s in sent) and python_start_interrupted(text))):
        return f"exit status {ended.status}:\n{text[-3000:]}"
    return None


_FRAME = re.compile(r'File "([^"]*)", line \d+')


def python_start_interrupted(text: str) -> bool:
    """A KeyboardInterrupt traceback none of whose frames is autolev's."""
    lines = text.rstrip().splitlines()
    frames = _FRAME.findall(text)
    return bool(lines) and lines[-1].strip() == "KeyboardInterrupt" and bool(frames) and \
        text.count("Traceback (most recent call last)") == 1 and \
        not any(f"{os.sep}autolev{os.sep}" in frame for frame in frames)


def expected_statuses(sent: list) -> dict:
    """The exit statuses the signals sent explain: status -> whether it needs a message
    (exit 1 must say why)."""
    allowed = {0: False}
    for s in sent:
        number = getattr(signal, s["signal"]).value
        if s["signal"] == "SIGKILL":
            if s["to"] == "child":
                allowed[1] = True
            else:
                allowed[-number] = False
        elif s["signal"] in ENDING:
            allowed.update({1: True, 128 + number: False, -number: False})
    return allowed


def judge_faulted(play: Play, ended: Ended) -> None:
    crashed = crash_of(ended, play.sent)
    if crashed:
        play.problem("crash", "faulted", crashed)
        return
    if ended.status is None:
        play.problem("hang", "faulted", f"the command was over {COMMAND_SECONDS:g} s:\n"
                     + ended.printed()[-1500:])
        return
    allowed = expected_statuses(play.sent)
    sent = ", ".join(f"{s['signal']} to the {s['to']}" for s in play.sent) or "no signal"
    if ended.status < 0 and ended.status not in allowed:
        name = signal.Signals(-ended.status).name
        play.problem("crash", "faulted", f"the command died of {name}, which the case "
                     f"did not send ({sent}):\n{ended.printed()[-1500:]}")
    elif ended.status not in allowed:
        play.problem("wrong", "faulted", f"exit status {ended.status} after {sent}:\n"
                     + ended.printed()[-1500:])
    elif allowed[ended.status] and not ended.stderr.strip():
        play.problem("wrong", "faulted", f"exit status {ended.status} after {sent}, "
                     "without a message")


def output_files(out: Path) -> dict:
    """The output folder's files but temporaries: name -> text."""
    if not out.is_dir():
        return {}
    return {f"file {p.relative_to(out)}": p.read_bytes().decode("latin-1")
            for p in sorted(out.rglob("*")) if p.is_file() and not p.name.startswith(".")}


def judge_files(play: Play, stage: str, ended: Ended, fresh: dict, complete: bool) -> None:
    """An output folder a run left: a .dir without every file is a mix; `complete` (the
    run said it succeeded): exactly the fresh run's files."""
    files = output_files(play.work / "out")
    wanted = {name for name in fresh["parts"] if name.startswith("file ")}
    dirs = [name for name in files if name.endswith(".dir")]
    missing = sorted(wanted - files.keys())
    if dirs and missing:
        play.problem("leftover", stage, f"{', '.join(dirs)} written, not "
                     f"{', '.join(missing)}: an output folder of two runs, or of none")
    if complete:
        got = {"status": ended.status, "parts": files}
        wanted_parts = {"status": 0, "parts": {k: v for k, v in fresh["parts"].items()
                                               if k.startswith("file ")}}
        if got != wanted_parts:
            play.problem("wrong", stage, "exit status 0 with files other than the fresh "
                         f"run's: {fuzz_stale.difference(got, wanted_parts)}")


def leftovers(play: Play) -> list[str]:
    """Temporaries and locks where the runs wrote (the cache only when it is a folder
    autolev may write: a read-only one keeps what was in it)."""
    found = []
    out = play.work / "out"
    if out.is_dir():
        found += [f"out/{p.relative_to(out)}" for p in out.rglob(".*")]
    cache_writable = play.cache.is_dir() and not play.cache.is_symlink() and \
        play.cache.stat().st_mode & 0o200
    if cache_writable:
        found += [f"cache/{name}" for name in os.listdir(play.cache)
                  if name.endswith(TEMPORARY_SUFFIX) or name.startswith("finishing_")
                  or name.endswith(".tmp")]
    records = play.state / "autolev" / "written"
    if records.is_dir():
        found += [f"state/{name}" for name in os.listdir(records) if name.startswith(".")]
    return found


def check_background_case(case, folder: Path) -> dict:
    """Run a background case in `folder` (the fresh answers kept in the folder above,
    which the run's workers share) and judge it."""
    t0 = time.perf_counter()
    play = Play(case, folder)
    [argv] = case.commands
    stage = case.change["moment"]
    try:
        files = fuzz_stale.snapshot(play.model_dir)
        fresh = fuzz_stale.fresh_answer(play.shared, folder, files, "run", argv, {})
        if fresh["crash"] or fresh["hang"] or fresh["status"] != 0:
            play.problem("wrong", "fresh", "the fresh run failed: "
                         f"{fresh['crash'] or fresh['hang'] or fresh['parts']}")
        ended = play.faulted(argv)
        stage += f", exit {ended.status}"
        judge_faulted(play, ended)
        play.wait_for_children("the faulted command")
        judge_files(play, "faulted", ended, fresh,
                    complete=ended.status == 0 and not play.found)
        play.repair()
        again = play.recovery(argv)
        play.wait_for_children("the recovery run")
        crashed = crash_of(again)
        if crashed:
            play.problem("crash", "recovery", crashed)
        elif again.status is None:
            play.problem("hang", "recovery", f"the recovery run was over "
                         f"{COMMAND_SECONDS:g} s")
        elif again.status != 0:
            play.problem("wrong", "recovery", f"the recovery run: exit status "
                         f"{again.status}:\n{again.printed()[-1500:]}")
        else:
            judge_files(play, "recovery", again, fresh, complete=True)
        left = leftovers(play)
        if left:
            play.problem("leftover", "recovery", "left after the recovery run and its "
                         "child: " + ", ".join(left[:6]))
    finally:
        play.end()
    if not play.found:
        outcome, where, detail = "ok", stage, None
    else:
        play.found.sort(key=lambda f: SEVERITY.index(f[0]))
        outcome, where, detail = play.found[0]
        detail = "\n".join(f"{o}: {d}" for o, _, d in play.found) + "\n" + \
            play.timeline() + f"\n{outcome}: {detail.splitlines()[0]}"
    return {"outcome": outcome, "stage": where, "detail": detail,
            "seconds": time.perf_counter() - t0,
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


# ---------------------------------------------------------------------------------
# Replay by hand

def write_case(case, into: Path) -> list[str]:
    """The case's files written into `into` (model/, the slow compiler) and the shell
    commands that play it as near as a shell gets (the terminal cases: by hand)."""
    fault = case.change
    model_dir = into / "model"
    shutil.rmtree(model_dir, ignore_errors=True)
    model_dir.mkdir(parents=True)
    for name, text in {case.filename: case.text, **case.files}.items():
        fuzz_stale._write(model_dir / name, text)
    cc = fuzz_stale.slow_compiler(into)
    home = into / "home"
    [argv] = case.commands
    autolev = f"{shlex.quote(sys.executable)} -m autolev " + " ".join(
        shlex.quote(str(into / "out")) if a == "{out}" else shlex.quote(a) for a in argv)
    cache, config = into / "cache", home / "config" / "autolev"
    lines = [f"cd {shlex.quote(str(model_dir))}",
             f"export HOME={home} AUTOLEV_CACHE={cache} XDG_CACHE_HOME={home / 'cache'} "
             f"XDG_CONFIG_HOME={home / 'config'} XDG_STATE_HOME={home / 'state'} "
             + (f"CC={cc} " if cc else "") + f"{SLEEP_VARIABLE}={fault['link_sleep']:g}",
             f"# fault: {fault_words(fault)}"]
    family, moment = fault["family"], fault["moment"]
    if family == "cache":
        action = {"remove": f"rm -rf {cache}", "read-only": f"mkdir -p {cache}; "
                  f"chmod 500 {cache}", "file": f"rm -rf {cache}; echo x > {cache}"}
        act = action[fault["action"]]
    elif family == "config":
        act = (f"mkdir -p {config}; chmod 500 {config}" if fault["action"] == "read-only"
               else f"truncate -s {fault['key_length']} {config / 'cache.key'}")
    elif family == "signal-parent":
        act = f"kill -{fault['signal'][3:]} $pid"
    elif family == "signal-child":
        act = f"kill -{fault['signal'][3:]} $(pgrep -P $pid -f autolev || " \
            f"pgrep -f 'autolev run' | grep -v $pid)"
    else:
        act = "# type " + fault["event"] + " in the terminal (stty tostop first)"
    if "pause" in fault and family.startswith("signal"):
        act += f"; sleep {fault['pause']}; " + act.replace(f"-{fault['signal'][3:]}", "-CONT")
    if moment == "before":
        lines += [act, autolev]
    elif moment == "early":
        lines += [f"{autolev} & pid=$!", f"sleep {fault['delay']}", act, "wait $pid"]
    else:
        lines += [f"{autolev}; pid=$!", f"sleep {fault['delay']}", act]
    lines += [f"for lock in {cache}/finishing_*.lock; do [ -e \"$lock\" ] && "
              "flock -s \"$lock\" true; done   # the background child finished",
              f"{autolev}   # the recovery run",
              f"AUTOLEV_CACHE={into / 'fresh-cache'} AUTOLEV_FOREGROUND=1 "
              f"{SLEEP_VARIABLE}=0 " + autolev.replace(str(into / "out"),
                                                      str(into / "fresh")),
              f"diff -r {into / 'out'} {into / 'fresh'}"]
    return lines
