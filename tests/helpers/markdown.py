"""Running the code blocks of a Markdown page (the README, the tutorials) as a reader
would, in order, in a fresh folder beside the shipped files."""
import importlib.util
import re
import shlex
import subprocess
import sys
from collections import Counter
from pathlib import Path

from helpers import ROOT


def code_blocks(text: str) -> list[tuple[int, str, str]]:
    """(line, language, text) of every fenced code block."""
    blocks, lines = [], text.splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("```"):
            end = next(j for j in range(k + 1, len(lines)) if lines[j].startswith("```"))
            blocks.append((k + 1, lines[k][3:].strip(), "\n".join(lines[k + 1:end])))
            k = end
        k += 1
    return blocks


def shell_command(line: str) -> str | None:
    """A page's command as this interpreter runs it; None for set-up the CI does itself
    (installing, running the tests)."""
    if "pip install" in line or "pytest" in line:
        return None
    python = shlex.quote(sys.executable)
    for prefix in (".venv/bin/autolev ", "autolev "):
        if line.startswith(prefix):
            return f"{python} -m autolev " + line[len(prefix):]
    for prefix in (".venv/bin/python ", "python "):
        if line.startswith(prefix):
            return python + " " + line[len(prefix):]
    return line


def untimed(text: str) -> str:
    """The text with its durations ("0.2 s") masked and without what computed a cold
    run's steps (", in Python (its C was compiling)"): they differ from run to run."""
    text = re.sub(r", in Python( until T = \S+ \(C compiling\), then C| \(its C was "
                  r"compiling\))", "", text)
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


def run_page(page: Path, folder: Path, monkeypatch) -> Counter:
    """Run every block of `page` in `folder` (the shipped examples and docs linked
    beside it): Python in one namespace, shell and console lines with bash; a console
    block's shown output must be what the command prints, and a command whose shown
    output has "error:" must fail.  The count of blocks run, by language."""
    for shipped in ("autolev_examples", "docs"):
        if not (folder / shipped).exists():      # a page read after another
            (folder / shipped).symlink_to(ROOT / shipped)
    monkeypatch.chdir(folder)
    namespace: dict = {}
    ran = Counter()
    name = page.name
    for line, language, text in code_blocks(page.read_text()):
        if language == "python":
            exec(compile(text, f"{name}:{line}", "exec"), namespace)
        elif language in ("sh", "console"):
            for command, shown in commands_of(text, language):
                runnable = shell_command(command)
                if runnable is None:
                    continue
                done = subprocess.run(["bash", "-c", runnable], capture_output=True,
                                      text=True, timeout=600)
                expected_status = 1 if "error:" in shown else 0
                if "--plot" in command and importlib.util.find_spec("matplotlib") is None:
                    # the page says it needs matplotlib (an optional extra): it says so
                    assert done.returncode == 2 and "needs matplotlib" in done.stderr
                    continue
                assert done.returncode == expected_status, \
                    f"{name}:{line}: {command}\n{done.stdout}{done.stderr}"
                if shown:
                    assert untimed(shown) in untimed(done.stdout + done.stderr), \
                        f"{name}:{line}: {command}\n{done.stdout}{done.stderr}"
        elif language.startswith("{"):
            continue                     # a MyST directive (toctree, eval-rst): no code
        else:
            raise AssertionError(f"{name}:{line}: a code block in {language!r}")
        ran[language] += 1
    return ran
