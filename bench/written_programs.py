"""Running the Matlab programs `autolev code` writes, as their users do: GNU Octave without
a window, and the values of their ReadUserInput table put in.  Shared by the tests
(tests/helpers/programs.py) and bench/journeys.py."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path


def octave() -> str | None:
    return shutil.which("octave")


def run_octave(script: str, folder: Path, timeout: float = 900):
    """Octave, without a window, running `script` (a program's name) in `folder`."""
    return subprocess.run([octave(), "--no-gui", "--quiet", "--no-window-system", "--eval",
                           script], cwd=folder, capture_output=True, text=True,
                          timeout=timeout)


def with_table_values(text: str, value_of) -> str:
    """A Matlab program in Autolev's layout with each row of its ReadUserInput table
    (`NAME   =  value;   % ...`) given the text value_of(NAME) (None: kept)."""
    out, in_table = [], False
    for line in text.splitlines():
        if line.startswith("function") and "ReadUserInput" in line:
            in_table = True
        elif line.startswith("% Unit conversions"):
            in_table = False
        m = re.match(r"^([A-Za-z]\w*)(\s*=\s*)[^;%]*;(.*)$", line) if in_table else None
        value = value_of(m.group(1)) if m else None
        if value is not None:
            line = f"{m.group(1)}{m.group(2)}{value};{m.group(3)}"
        out.append(line)
    return "\n".join(out) + "\n"
