"""The README speaks of what ships with the project (issue 19, item 7): every file it
names is in the repository, and it points at nothing beside it."""
import importlib.util
import re
import shlex
import subprocess
import sys
from collections import Counter

from helpers import ROOT

README = (ROOT / "README.md").read_text()


def test_no_path_leaves_the_repository():
    assert "../" not in README


def test_every_file_it_names_ships():
    named = set(re.findall(r"\b((?:docs|bench|tests|tools|autolev_examples|grammar|src)"
                           r"/[\w./-]+\.\w+)", README))
    assert len(named) > 10
    missing = sorted(p for p in named if not (ROOT / p).exists())
    assert missing == []


def code_blocks() -> list[tuple[int, str, str]]:
    """(line, language, text) of every fenced code block."""
    blocks, lines = [], README.splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("```"):
            end = next(j for j in range(k + 1, len(lines)) if lines[j].startswith("```"))
            blocks.append((k + 1, lines[k][3:].strip(), "\n".join(lines[k + 1:end])))
            k = end
        k += 1
    return blocks


def shell_command(line: str) -> str | None:
    """A README command as this interpreter runs it; None for set-up the CI does itself
    (installing, running the tests)."""
    if "pip install" in line or "pytest" in line:
        return None
    python = shlex.quote(sys.executable)
    for prefix in (".venv/bin/autolev ", "autolev "):
        if line.startswith(prefix):
            return f"{python} -m autolev " + line[len(prefix):]
    if line.startswith(".venv/bin/python "):
        return python + " " + line[len(".venv/bin/python "):]
    return line


def test_every_code_block_runs(tmp_path, monkeypatch):
    # in a fresh folder beside the shipped files, in the README's order (later blocks
    # read what earlier ones wrote); a console block's shown output (when it shows one)
    # is what the command prints
    for shipped in ("autolev_examples", "docs"):
        (tmp_path / shipped).symlink_to(ROOT / shipped)
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    ran = Counter()
    for line, language, text in code_blocks():
        if language == "python":
            exec(compile(text, f"README.md:{line}", "exec"), namespace)
        elif language in ("sh", "console"):
            for command, shown in commands_of(text, language):
                runnable = shell_command(command)
                if runnable is None:
                    continue
                done = subprocess.run(["bash", "-c", runnable], capture_output=True,
                                      text=True, timeout=600)
                expected_status = 1 if "error:" in shown else 0
                if "--plot" in command and importlib.util.find_spec("matplotlib") is None:
                    # the README says it needs matplotlib (an optional extra): it says so
                    assert done.returncode == 2 and "needs matplotlib" in done.stderr
                    continue
                assert done.returncode == expected_status, \
                    f"README.md:{line}: {command}\n{done.stdout}{done.stderr}"
                if shown:
                    assert untimed(shown) in untimed(done.stdout + done.stderr), \
                        f"README.md:{line}: {command}\n{done.stdout}{done.stderr}"
        else:
            raise AssertionError(f"README.md:{line}: a code block in {language!r}")
        ran[language] += 1
    assert ran["python"] >= 6 and ran["console"] >= 3 and ran["sh"] >= 5


def untimed(text: str) -> str:
    """The text with its durations ("0.2 s") masked: they differ from run to run."""
    return re.sub(r"\b\d+(\.\d+)? s\b", "# s", text)


def commands_of(text: str, language: str) -> list[tuple[str, str]]:
    """(command, the output the block shows for it) of a shell or console block."""
    if language == "sh":
        return [(line.split("  #")[0].strip(), "") for line in text.splitlines()
                if line.strip() and not line.lstrip().startswith("#")]
    out: list[tuple[str, list[str]]] = []
    for line in text.splitlines():
        if line.startswith("$ "):
            out.append((line[2:].split("  #")[0].strip(), []))
        elif line.strip() and not line.lstrip().startswith("#"):
            out[-1][1].append(line)
    return [(command, "\n".join(shown)) for command, shown in out]
