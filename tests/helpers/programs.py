"""Compile and run a C program in Autolev's layout, ours or Autolev's own, and read the
values it leaves in its ENCODE arrays (its main() renamed, called by a small driver
that prints every element with %.17g)."""
import hashlib
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from autolev.engine import clibrary

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
# how Octave runs a written .m program: shared with bench/journeys.py
from written_programs import octave, run_octave, with_table_values  # noqa: E402, F401


def compiler():
    return clibrary.compiler()


def value_for(name: str, draw: int) -> float:
    """A value in [-1, 1) (away from 0) fixed by the quantity's name and the draw."""
    digest = hashlib.sha256(f"{draw}:{name.lower()}".encode()).digest()
    x = int.from_bytes(digest[:6], "big") / 2.0 ** 48
    return (0.2 + 0.8 * x) * (1 if digest[6] & 1 else -1)


def filled_in(template: str, draw: int) -> str:
    """An Autolev .in text with each row's value (from column 60) drawn by name."""
    out = []
    for line in template.splitlines():
        if len(line) >= 60 and line[58] == "|" and not set(line[:58]) <= {"-", " "}:
            name = line[21:42].strip()
            if name and name.lower() != "quantity":
                line = line[:59] + f"{value_for(name, draw):.17g}"
        out.append(line)
    return "\n".join(out) + "\n"


def driver(arrays: list[tuple[str, tuple]]) -> str:
    """C that runs the program's main() and prints its ENCODE arrays."""
    lines = ["#include <stdio.h>", "int autolev_main(void);"]
    for name, shape in arrays:
        lines.append(f"extern double {name}" + "".join(f"[{d}]" for d in shape) + ";")
    lines += ["int main(void)", "{", "    autolev_main();"]
    for name, shape in arrays:
        if not shape:
            lines.append(f'    printf("{name} %.17g\\n", {name});')
        elif len(shape) == 1:
            lines.append(f"    for (int i = 0; i < {shape[0]}; i++) "
                         f'printf("{name}[%d] %.17g\\n", i, {name}[i]);')
        else:
            lines.append(f"    for (int i = 0; i < {shape[0]}; i++) "
                         f"for (int j = 0; j < {shape[1]}; j++) "
                         f'printf("{name}[%d][%d] %.17g\\n", i, j, {name}[i][j]);')
    return "\n".join(lines + ["    return 0;", "}"]) + "\n"


def encoded_values(program: Path, in_text: str, in_name: str, arrays, work: Path,
                   flags=("-O0",)) -> dict:
    """{element: value} the program computes from `in_text` (placed where it opens
    its .in file, `in_name`, relative to the folder it runs in).  The program is
    compiled once per folder `work` and run in a folder of its own per input."""
    run = built(program, arrays, work, flags)
    return run_for(run, in_text, in_name, work / f"run{len(list(work.glob('run*')))}")


def built(program: Path, arrays, work: Path, flags=("-O0",)) -> Path:
    """The program compiled with a driver printing its ENCODE arrays (once)."""
    exe = work / "program"
    if exe.exists():
        return exe
    work.mkdir(parents=True, exist_ok=True)
    shutil.copy(program, work / "program.c")
    (work / "driver.c").write_text(driver(arrays))
    cc = compiler()
    subprocess.run([cc, *flags, "-w", "-Dmain=autolev_main", "-c", "program.c"], cwd=work,
                   check=True, capture_output=True)
    subprocess.run([cc, *flags, "-o", "program", "driver.c", "program.o", "-lm"],
                   cwd=work, check=True, capture_output=True)
    return exe


def run_for(exe: Path, in_text: str, in_name: str, folder: Path) -> dict:
    """{element: value} printed by the compiled program run in `folder` with its .in."""
    target = folder / in_name
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(in_text)
    out = subprocess.run([str(exe)], cwd=folder, capture_output=True, text=True,
                         check=True).stdout
    values = {}
    for line in out.splitlines():
        m = re.match(r"^(\w+(?:\[\d+\])*) (\S+)$", line)
        if m:
            values[m.group(1)] = float(m.group(2))
    if not values:
        raise AssertionError(f"{exe} printed no values:\n{out[-500:]}")
    return values


def input_name(program_text: str) -> str:
    """The .in file a program in Autolev's C layout opens."""
    m = re.search(r'strcpy\(fileName, "([^"]+)"\)', program_text)
    if m is None:
        raise AssertionError("no input file name in the program")
    return m.group(1)


def largest_difference(ours: dict, theirs: dict) -> tuple[float, str]:
    """The largest difference of two programs' values relative to the array it is in
    (its largest magnitude), and which array: element by element, a value that
    cancels to almost nothing (1e-19 among values of 1e-3, or Autolev's 4/3 printed
    with 16 digits under a sqrt) differs by rounding alone.  A NaN on one side only
    is an infinite difference."""
    arrays: dict = {}
    for key, b in theirs.items():
        a = ours[key]
        if math.isnan(a) != math.isnan(b):
            return math.inf, key
        if math.isnan(a):
            continue
        big, diff = arrays.get(key.split("[")[0], (0.0, 0.0))
        arrays[key.split("[")[0]] = (max(big, abs(a), abs(b)), max(diff, abs(a - b)))
    worst, where = 0.0, ""
    for name, (big, diff) in arrays.items():
        if diff and diff / big > worst:
            worst, where = diff / big, name
    return worst, where


needs_cc = pytest.mark.skipif(compiler() is None, reason="no C compiler on this machine")
needs_octave = pytest.mark.skipif(
    octave() is None, reason="GNU Octave runs the Matlab programs; it is not installed "
    "(Debian: apt install octave)")
GFORTRAN = shutil.which("gfortran")
needs_gfortran = pytest.mark.skipif(
    GFORTRAN is None, reason="gfortran compiles the Fortran programs; it is not installed "
    "(Debian: apt install gfortran)")


def run_program(program: Path, flags=("-O2",)):
    """A written program run in its folder: a .c one compiled with `flags` (and no
    warning allowed), a .m one under Octave."""
    folder = program.parent
    if program.suffix == ".m":
        return run_octave(program.stem, folder)
    built = subprocess.run([compiler(), *flags, "-o", "prog", program.name, "-lm"],
                           cwd=folder, capture_output=True, text=True)
    assert built.returncode == 0 and built.stderr == "", built.stderr
    return subprocess.run(["./prog"], cwd=folder, capture_output=True, text=True)


def table_rows(path: Path) -> list:
    """The rows of an output file in the C and Matlab programs' layout."""
    return [[float(v) for v in line.split()] for line in path.read_text().splitlines()
            if line.strip() and not line.startswith("%")]


def matlab_with_values(text: str, draw: int) -> str:
    """The program with every table row given a value drawn by name."""
    return with_table_values(text, lambda name: repr(value_for(name, draw)))


def octave_encoded(program: Path, text: str, arrays: list[str], work: Path) -> dict:
    """{element: value} of the ENCODE arrays after Octave ran the program `text`
    (saved under the program's own file name in `work`)."""
    work.mkdir(parents=True, exist_ok=True)
    (work / program.name).write_text(text)
    show = "".join(f"x = {a}; for k = 1:numel(x) printf('{a}[%d] %.17g\\n', k, x(k)); end; "
                   for a in arrays)
    script = f"global {' '.join(arrays)}; {program.stem}; {show}"
    out = run_octave(script, work, timeout=600)
    values = {}
    for line in out.stdout.splitlines():
        m = re.match(r"^(\w+\[\d+\]) (\S+)$", line)
        if m:
            values[m.group(1)] = float(m.group(2))
    if not values:
        raise AssertionError(f"Octave printed no values for {program.name}:\n"
                             f"{out.stdout[-500:]}{out.stderr[-800:]}")
    return values
