"""The hostile mode of bench/fuzz.py: hostile file types where autolev reads or writes.

Each case puts one hostile object at a name autolev reads or writes (the generator is
where), and runs one command on a small pendulum `x.al` that calls a macro (link.a),
includes a RUN file (values.al) and calls a user function (damping.r):

  model     the model x.al itself
  in        the --in file vals.in (run, linearize, animate, convert --to sympy)
  run-file  values.al, which the model includes by RUN VALUES.AL
  macro     link.a, the macro the model calls
  function  damping.r, the function the model calls
  session   x.all, the session `autolev verify` replays
  output    a name the command writes in its output folder: x.1, x.dir, x.in (run,
            animate), x.c, x.in (code), x.html (animate), x.all (transcript --out),
            x.py (convert -o); now and then with --overwrite

The object (its kind, the case's stage with the command):

  fifo        a FIFO nobody opens from the other side (reading or writing it blocks)
  fifo-held   a FIFO the case holds open from the other side: a writer that never
              writes (where autolev reads), a reader that takes what comes (where it
              writes: anything read is a write through it)
  dir         a folder by that name (where autolev writes: with a file in it)
  devnull, devzero, urandom
              a link to /dev/null, /dev/zero, /dev/urandom
  tty         a link to a pseudo-terminal whose master the case holds: reading it
              blocks, and what is written through it is read at the master
  socket      a UNIX socket bound at the name
  unreadable  (where autolev reads) a regular file of the right text, mode 000
  eio         (where autolev reads) a link to /proc/self/mem: a regular file whose
              read fails (EIO)
  loop        (where autolev reads) a link to itself

The commands are drawn among check, run, code, convert, linearize, transcript, verify
and animate --format html (those that read or write the name), each run in the case's
folder with its own home, cache and tag, without the capabilities that let root ignore
a file's mode (as the background mode runs them).  Outcomes:

  ok         exit 1 or 2 with a message naming the file; where autolev writes, exit 0
             too, the name then a regular file autolev wrote (a link replaced; a user's
             FIFO, socket or folder only with --overwrite)
  crash      exit status 70 or any other than 0, 1, 2, a traceback, "internal error"
  hang       the command over COMMAND_SECONDS, or its background child holding its lock
             over CHILD_SECONDS
  leaked     a process of the case alive LINGER_SECONDS after that
  clobbered  something written through the hostile object (bytes read at a FIFO's or a
             terminal's other end, a file put into the folder, exit 0 with the output
             still a link to a device), a user's FIFO, socket or folder replaced without
             --overwrite, or anything changed outside the output folder
  wrong      exit 0 having read the hostile object, or a failure that does not name it

    python bench/fuzz.py --mode hostile --cases 1000 --seeds 1,2 --jobs 1
    python bench/fuzz.py --mode hostile --replay SEED:INDEX [--into DIR]
"""
from __future__ import annotations

import os
import random
import re
import resource
import shlex
import shutil
import signal
import socket
import stat
import subprocess
import sys
import time
from pathlib import Path

if str(Path(__file__).resolve().parent) not in sys.path:
    sys.path.append(str(Path(__file__).resolve().parent))
import fuzz_background  # noqa: E402
import fuzz_stale  # noqa: E402

WHERES = ("model", "in", "run-file", "macro", "function", "session", "output")
WHERE_WEIGHTS = (20, 14, 13, 13, 12, 10, 18)
GENERATORS = WHERES
READ_KINDS = ("fifo", "fifo-held", "dir", "devnull", "devzero", "urandom", "tty", "socket",
              "unreadable", "eio", "loop")
WRITE_KINDS = ("fifo", "fifo-held", "dir", "devnull", "devzero", "urandom", "tty",
               "socket")
DEVICES = {"devnull": "/dev/null", "devzero": "/dev/zero", "urandom": "/dev/urandom",
           "eio": "/proc/self/mem"}
# what a user leaves at a name (autolev replaces it only with --overwrite)
USERS_KINDS = ("fifo", "fifo-held", "dir", "socket")
COMMANDS = ("check", "run", "code", "convert", "linearize", "transcript", "verify",
            "animate")
# the commands that read each input, and the names each command writes
READERS = {"model": COMMANDS, "in": ("run", "linearize", "animate", "convert"),
           "run-file": COMMANDS, "macro": COMMANDS, "function": COMMANDS,
           "session": ("verify",)}
WRITTEN = {"run": ("x.1", "x.dir", "x.in"), "animate": ("x.html", "x.1", "x.dir", "x.in"),
           "code": ("x.c", "x.in"), "transcript": ("x.all",), "convert": ("x.py",)}
NAMES = {"model": "x.al", "in": "vals.in", "run-file": "values.al", "macro": "link.a",
         "function": "damping.r", "session": "x.all"}
OUTCOMES = ("ok", "crash", "hang", "leaked", "clobbered", "wrong")
SEVERITY = ("crash", "hang", "leaked", "clobbered", "wrong", "ok")
COMMAND_SECONDS = 30.0
CHILD_SECONDS = 60.0
LINGER_SECONDS = 15.0


# ---------------------------------------------------------------------------------
# A case

def pendulum(n: int) -> dict:
    """A pendulum of n links: its links by the macro link.a, its values by the RUN file
    values.al, a damping torque by the function damping.r; a response comment for
    `autolev verify x.al`."""
    idx = range(1, n + 1)
    lines = ["% a pendulum (bench/fuzz_hostile.py)", "NEWTONIAN N",
             "FRAMES " + ", ".join(f"A{i}" for i in idx),
             "PARTICLES " + ", ".join(f"P{i}" for i in idx),
             "MOTIONVARIABLES' " + ", ".join(f"Q{i}''" for i in idx),
             "CONSTANTS G, " + ", ".join(f"L{i}, M{i}" for i in idx)]
    lines += [f"LINK({i}, {'NO' if i == 1 else f'P{i - 1}'})" for i in idx]
    lines += ["RUN VALUES.AL", "TORQUE(N/A1, -DAMPING(Q1')*N3>)",
              "REACH = L1 + 2*M1", "% -> REACH = L1 + 2*M1",
              "ZERO = FR() + FRSTAR()", "KANE()",
              "INPUT " + ", ".join(f"Q{i} = 0.{i + 1}" for i in idx)
              + ", " + ", ".join(f"Q{i}' = 0" for i in idx),
              "INPUT TFINAL = 1, INTEGSTP = 0.01",
              "OUTPUT T, " + ", ".join(f"Q{i}" for i in idx),
              "CODE DYNAMICS() x.c"]
    values = "INPUT G = 9.81, " + ", ".join(f"L{i} = 0.{5 + i}, M{i} = 1.{i}" for i in idx)
    return {"x.al": "\n".join(lines) + "\n",
            "link.a": ("% one link: #1# its number, #2# the point it hangs from\n"
                       "SIMPROT(N, A#1#, 3, Q#1#)\nP_#2#_P#1#> = L#1#*A#1#1>\n"
                       "V2PTS(N, A#1#, #2#, P#1#)\nMASS P#1# = M#1#\n"),
            "values.al": values + "\nGRAVITY(G*N1>)\n",
            "damping.r": "0.2*#1#\n"}


def _argv(rng: random.Random, command: str, with_in: bool, session: bool) -> list:
    """A command's arguments ({out}: the output folder, relative names in the case's
    folder)."""
    inputs = ["--in", "vals.in"] if with_in else []
    if command == "check":
        return ["check", "x.al"]
    if command == "run":
        return ["run", "--out", "{out}", "--tfinal", "0.2", *inputs, "x.al"]
    if command == "animate":
        return ["animate", "--format", "html", "--frames", "10", "--out", "{out}",
                "--tfinal", "0.2", *inputs, "x.al"]
    if command == "code":
        return ["code", "--out", "{out}", "x.al"]
    if command == "convert":
        return ["convert", "-o", "{out}/x.py",
                *(["--to", "sympy", *inputs] if with_in else []), "x.al"]
    if command == "linearize":
        return ["linearize", *inputs, "x.al"]
    if command == "transcript":
        return ["transcript", *(["--out", "{out}"] if rng.random() < 0.5 else []), "x.al"]
    return ["verify", "x.all" if session else "x.al"]


def hostile_case(seed: int, index: int) -> dict:
    """The fields of case `index` of seed `seed` (a fuzz.Case): the model and its files,
    the command, and what is hostile where (`change`)."""
    rng = random.Random(f"autolev-fuzz:hostile:{seed}:{index}")
    where = rng.choices(WHERES, weights=WHERE_WEIGHTS)[0]
    files = pendulum(rng.randint(1, 3))
    overwrite = False
    if where == "output":
        kind = rng.choice(WRITE_KINDS)
        command = rng.choice(tuple(WRITTEN))
        name = "out/" + rng.choice(WRITTEN[command])
        argv = _argv(rng, command, False, False)
        if command == "transcript" and "--out" not in argv:
            argv[1:1] = ["--out", "{out}"]
        overwrite = rng.random() < 0.3
        if overwrite:
            argv.insert(1, "--overwrite")
    else:
        kind = rng.choice(READ_KINDS)
        command = rng.choice(READERS[where])
        name = NAMES[where]
        argv = _argv(rng, command, where == "in" or rng.random() < 0.1,
                     where == "session")
    model = files.pop("x.al")
    change = {"where": where, "kind": kind, "command": command, "name": name,
              "overwrite": overwrite}
    return {"index": index, "generator": where, "filename": "x.al", "text": model,
            "mode": "hostile", "files": files, "commands": [argv], "change": change}


def described(case) -> list[str]:
    change = case.change
    return [f"hostile: {change['name']} is {change['kind']} ({change['where']}; "
            f"`autolev {change['command']}`"
            + (", --overwrite" if change["overwrite"] else "") + ")"]


# ---------------------------------------------------------------------------------
# Planting the object, and what holds its other end

class Planted:
    """The hostile object at its name, and what the case holds of it: a FIFO's other
    end, a terminal's master, a bound socket."""

    def __init__(self, path: Path, kind: str, text: str | None, writes: bool):
        self.path, self.kind, self.writes = path, kind, writes
        self.fds: list[int] = []
        self.peer: int | None = None        # read after the command: bytes written through
        self.sock: socket.socket | None = None
        path.parent.mkdir(parents=True, exist_ok=True)
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        elif os.path.lexists(path):
            path.unlink()
        if kind in ("fifo", "fifo-held"):
            os.mkfifo(path)
            if kind == "fifo-held":
                # where autolev writes: a reader that takes what comes; where it reads: a
                # writer that never writes (both ends, so opening never blocks)
                flags = (os.O_RDONLY if writes else os.O_RDWR) | os.O_NONBLOCK
                self.peer = os.open(path, flags)
                self.fds.append(self.peer)
        elif kind == "dir":
            path.mkdir()
            (path / "inside.txt").write_text("a file in the folder\n")
        elif kind in DEVICES:
            os.symlink(DEVICES[kind], path)
        elif kind == "tty":
            master, slave = os.openpty()
            os.symlink(os.ttyname(slave), path)
            os.close(slave)
            os.set_blocking(master, False)
            self.peer = master
            self.fds.append(master)
        elif kind == "socket":
            self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            self.sock.bind(str(path))
        elif kind == "unreadable":
            path.write_text(text or "")
            path.chmod(0)
        elif kind == "loop":
            os.symlink(path.name, path)
        else:
            raise ValueError(f"no hostile kind {kind}")

    def written_through(self) -> bytes:
        """What reached the other end (a FIFO's reader, a terminal's master)."""
        if self.peer is None or not self.writes and self.kind != "tty":
            return b""
        got = b""
        while True:
            try:
                chunk = os.read(self.peer, 1 << 16)
            except (BlockingIOError, OSError):
                return got
            if not chunk:
                return got
            got += chunk

    def state(self) -> tuple:
        """What the name holds now: its type, inode and link text."""
        try:
            st = os.lstat(self.path)
        except FileNotFoundError:
            return ("gone",)
        link = os.readlink(self.path) if stat.S_ISLNK(st.st_mode) else None
        return (stat.S_IFMT(st.st_mode), st.st_ino, link)

    def close(self) -> None:
        for fd in self.fds:
            os.close(fd)
        self.fds = []
        if self.sock is not None:
            self.sock.close()
            self.sock = None


# ---------------------------------------------------------------------------------
# A case, checked

def _content(where: str, files: dict, shared: Path, scratch: Path) -> str | None:
    """The text a readable file at the name would hold (for the unreadable kind)."""
    if where == "in":
        return fuzz_stale.in_template(shared, scratch, files, "x.al") or ""
    if where == "session":
        return "   (1) NEWTONIAN N\n   (2) CONSTANTS A\n   (3) X = A + 1\n-> (4) X = 1 + A\n"
    if where == "model":
        return files["x.al"].decode()
    return files[NAMES[where]].decode()


def _tree(folder: Path, skip: set) -> dict:
    """The case's folder outside the output folder, as fuzz.tree_state sees it."""
    state = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        dirnames[:] = [d for d in dirnames if os.path.join(dirpath, d) not in skip]
        for name in dirnames + filenames:
            path = os.path.join(dirpath, name)
            if path in skip:
                continue
            try:
                st = os.lstat(path)
            except FileNotFoundError:
                continue
            value = [stat.S_IFMT(st.st_mode), st.st_ino, st.st_mtime_ns, st.st_size]
            if stat.S_ISLNK(st.st_mode):
                value.append(os.readlink(path))
            state[os.path.relpath(path, folder)] = value
    return state


def _names_it(text: str, name: str) -> bool:
    """Whether a message names the file (by itself: not inside a temporary's name)."""
    base = re.escape(os.path.basename(name))
    return re.search(rf"(?i)(?<![\w.]){base}(?!\w)", text) is not None


def check_hostile_case(case, folder: Path) -> dict:
    """Plant a hostile case's object, run its command, judge it."""
    t0 = time.perf_counter()
    change = case.change
    work = folder / "hostile"
    fuzz_background._make_writable(work)
    shutil.rmtree(work, ignore_errors=True)
    case_dir = work / "case"
    out = case_dir / "out"
    out.mkdir(parents=True)
    (work / "tmp").mkdir()
    files = {case.filename: case.text, **case.files}
    for name, text in files.items():
        fuzz_stale._write(case_dir / name, text)
    raw = {name: text.encode() for name, text in files.items()}
    if "--in" in case.commands[0]:
        fuzz_stale._write(case_dir / "vals.in", _content("in", raw, folder.parent, folder))
    text = _content(change["where"], raw, folder.parent, folder) \
        if change["kind"] == "unreadable" else None
    writes = change["where"] == "output"
    planted = Planted(case_dir / change["name"], change["kind"], text, writes)
    tag = f"{os.getpid()}-{time.time_ns()}"
    found: list[tuple[str, str]] = []
    stage = f"{change['kind']}:{change['command']}"
    try:
        before = _tree(case_dir, {str(out)})
        planted_state = planted.state()
        [argv] = case.commands
        args = [a.replace("{out}", str(out)) for a in argv]
        env = fuzz_background.environment(work, tag, None, 0.0)
        logs = work / "logs"
        logs.mkdir()
        with open(logs / "stdout", "wb") as so, open(logs / "stderr", "wb") as se:
            proc = subprocess.Popen([*fuzz_background.PROGRAM, *args], cwd=case_dir,
                                    env=env, stdin=subprocess.DEVNULL, stdout=so, stderr=se,
                                    start_new_session=True,
                                    preexec_fn=fuzz_background.command_preexec)
        try:
            status = proc.wait(timeout=COMMAND_SECONDS)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            status = None
        printed = "".join((logs / n).read_bytes().decode("utf-8", "replace")
                          for n in ("stdout", "stderr"))
        found += _waited(tag)
        through = planted.written_through()
        after = _tree(case_dir, {str(out)})
        found += judged(change, status, printed, through, planted_state, planted.state(),
                        planted.path)
        changed = _changed(before, after, planted.path.relative_to(case_dir))
        if changed:
            found.append(("clobbered", "changed outside the output folder: "
                          + ", ".join(changed[:5])))
    finally:
        planted.close()
        fuzz_background.kill_tagged(tag)
        fuzz_background._make_writable(work)
    if not found:
        outcome, detail = "ok", None
    else:
        found.sort(key=lambda f: SEVERITY.index(f[0]))
        outcome = found[0][0]
        detail = "\n".join(f"{o}: {d}" for o, d in found) + \
            f"\n$ autolev {' '.join(case.commands[0])}\n{outcome}: " \
            + found[0][1].splitlines()[0]
    return {"outcome": outcome, "stage": stage, "detail": detail,
            "seconds": time.perf_counter() - t0,
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def _changed(before: dict, after: dict, planted: Path) -> list[str]:
    """What changed in the case's folder (the planted object's own name aside: the
    judgement looks at it)."""
    def how(name: str) -> str:
        return "new" if name not in before else "removed" if name not in after else "changed"
    return [f"{name} {how(name)}" for name in sorted(before.keys() | after.keys())
            if before.get(name) != after.get(name) and Path(name) != planted
            and planted not in Path(name).parents]


def _waited(tag: str) -> list[tuple[str, str]]:
    """Wait for the command's background child (its lock) and then for every process
    of the case to end; a hang or the processes leaked (killed)."""
    found = []
    deadline = time.monotonic() + CHILD_SECONDS
    while fuzz_background.lock_holders(tag):
        if time.monotonic() > deadline:
            found.append(("hang", f"a background child held its lock over "
                          f"{CHILD_SECONDS:g} s"))
            break
        time.sleep(0.05)
    deadline = time.monotonic() + LINGER_SECONDS
    while fuzz_stale.tagged(tag) and time.monotonic() < deadline:
        time.sleep(0.05)
    left = fuzz_stale.tagged(tag)
    if left:
        found.append(("leaked", f"processes of the case alive {LINGER_SECONDS:g} s after "
                      "its command: " + ", ".join(
                          f"{pid} ({fuzz_background._command_line(pid)})" for pid in left[:4])))
        fuzz_background.kill_tagged(tag)
    return found


def judged(change: dict, status: int | None, printed: str, through: bytes,
           planted_before: tuple, planted_after: tuple, path: Path) -> list:
    """What is wrong with a command's end, given the hostile object."""
    found = []
    name = change["name"]
    if status is None:
        return [("hang", f"the command was over {COMMAND_SECONDS:g} s:\n{printed[-1500:]}")]
    if status not in (0, 1, 2) or "Traceback (most recent call last)" in printed or \
            "internal error" in printed:
        return [("crash", f"exit status {status}:\n{printed[-3000:]}")]
    if through:
        found.append(("clobbered", f"{len(through)} bytes written through {name} "
                      f"({change['kind']}): {through[:80]!r}"))
    if change["kind"] == "dir" and path.is_dir() and not path.is_symlink() and \
            sorted(p.name for p in path.iterdir()) != ["inside.txt"]:
        found.append(("clobbered", f"written into the folder {name}: "
                      + ", ".join(sorted(p.name for p in path.iterdir()))))
    if change["where"] != "output":
        if status == 0:
            found.append(("wrong", f"exit status 0 with {name} {change['kind']}:\n"
                          f"{printed[-1500:]}"))
        elif not _names_it(printed, name):
            found.append(("wrong", f"exit status {status} without naming {name}:\n"
                          f"{printed[-1500:]}"))
        return found
    replaced = planted_after != planted_before
    users = change["kind"] in USERS_KINDS
    if users and replaced and not change["overwrite"]:
        found.append(("clobbered", f"the user's {change['kind']} {name} replaced without "
                      "--overwrite"))
    if status == 0:
        regular = planted_after[0] == stat.S_IFREG
        if not regular and change["kind"] in DEVICES and not replaced:
            found.append(("clobbered", f"exit status 0, {name} still the link to "
                          f"{DEVICES[change['kind']]}: written through it"))
        elif not regular:
            found.append(("wrong", f"exit status 0, {name} not a file autolev wrote "
                          f"(still {change['kind']}):\n{printed[-1500:]}"))
    elif not _names_it(printed, name):
        found.append(("wrong", f"exit status {status} without naming {name}:\n"
                      f"{printed[-1500:]}"))
    return found


# ---------------------------------------------------------------------------------
# Replay by hand

def write_case(case, into: Path) -> list[str]:
    """The case's files written into `into`/case and the shell commands that plant the
    object and run the command (the terminal kind: a link to a terminal of your own)."""
    change = case.change
    case_dir = into / "case"
    shutil.rmtree(case_dir, ignore_errors=True)
    (case_dir / "out").mkdir(parents=True)
    for name, text in {case.filename: case.text, **case.files}.items():
        fuzz_stale._write(case_dir / name, text)
    path = shlex.quote(change["name"])
    kind = change["kind"]
    plant = {"fifo": f"mkfifo {path}",
             "fifo-held": f"mkfifo {path}; exec 3<>{path}   # held open from here",
             "dir": f"mkdir {path}; echo inside > {path}/inside.txt",
             "tty": f"ln -s $(tty) {path}", "socket": f"python3 -c 'import socket; "
             f"socket.socket(socket.AF_UNIX).bind(\"{change['name']}\")'",
             "unreadable": f"chmod 000 {path}   # (not as root)",
             "loop": f"ln -s {shlex.quote(os.path.basename(change['name']))} {path}"}
    if kind in DEVICES:
        line = f"ln -s {DEVICES[kind]} {path}"
    else:
        line = plant[kind]
    if kind != "unreadable" and change["where"] != "in":
        line = f"rm -rf {path}; {line}"
    args = " ".join(shlex.quote(a.replace("{out}", str(case_dir / "out")))
                    for a in case.commands[0])
    lines = [f"cd {shlex.quote(str(case_dir))}"]
    if "--in" in case.commands[0]:
        lines.append(f"{shlex.quote(sys.executable)} -m autolev code --out . x.al && "
                     "mv x.in vals.in   # the .in file autolev writes")
    lines += [line, f"{shlex.quote(sys.executable)} -m autolev {args}; echo exit $?"]
    return lines
