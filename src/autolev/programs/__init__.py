"""The programs a model's CODE commands name, written in the layout of the programs
Autolev wrote (`autolev code`), so that toolchains built on them rebuild unchanged."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path, PureWindowsPath

from ..engine.errors import AutolevModelError
from ..runtime.io import CodeKind
from ..runtime.numerics.command import hidden_note
from ..engine.outputs import Written as WrittenFiles
from ..engine.outputs import inside, write_output
from .c import write_c
from .c_dynamics import write_c_dynamics
from .f import write_f_dynamics
from .m import write_m, write_m_dynamics
from .plan import plan_algebraic, plan_dynamics

# (kind, extension) -> (plan, writer); anything else is reported as not written
WRITERS = {
    (CodeKind.ALGEBRAIC, ".c"): (plan_algebraic, write_c),
    (CodeKind.ALGEBRAIC, ".m"): (plan_algebraic, write_m),
    (CodeKind.NONLINEAR, ".c"): (plan_algebraic, write_c),
    (CodeKind.NONLINEAR, ".m"): (plan_algebraic, write_m),
    (CodeKind.DYNAMICS, ".c"): (plan_dynamics, write_c_dynamics),
    (CodeKind.DYNAMICS, ".m"): (plan_dynamics, write_m_dynamics),
    (CodeKind.DYNAMICS, ".f"): (plan_dynamics, write_f_dynamics),
    (CodeKind.DYNAMICS, ".for"): (plan_dynamics, write_f_dynamics),
    # CODE ODE(EQ, x'', ...): the DYNAMICS program, its derivatives from the equations
    (CodeKind.ODE, ".c"): (plan_dynamics, write_c_dynamics),
    (CodeKind.ODE, ".m"): (plan_dynamics, write_m_dynamics),
    (CodeKind.ODE, ".f"): (plan_dynamics, write_f_dynamics),
    (CodeKind.ODE, ".for"): (plan_dynamics, write_f_dynamics),
}


@dataclass
class Written:
    """What `write_programs` did for one CODE command: the files, or why none."""

    command: object
    files: list
    refused: str | None = None
    notes: list = field(default_factory=list)   # what the user is told of the program


def relative_path(filename: str) -> tuple[Path, str | None]:
    """The CODE command's file name as a path inside the output folder: its folders
    kept (as Autolev wrote them relative to where it ran) while they stay inside; a
    name whose folders would leave it (`../c/bike.c`, an absolute path) is written by
    its own name in the output folder, as autolev run writes that program's files
    there, and said (the note).  A name that is no file's is refused."""
    path = PureWindowsPath(filename.replace("/", "\\"))
    parts = [p for p in path.parts if p not in (path.anchor, ".")]
    if not parts or any(c in p for p in parts for c in '<>:"|?*\0') or \
            parts[-1].strip() in ("", "..") or not parts[-1].rsplit(".", 1)[0].strip():
        raise AutolevModelError(f"unusable file name in CODE: {filename!r} (it names no "
                                "file; give the program a name such as bike.c)")
    if path.anchor or ".." in parts or any(not p.strip() for p in parts):
        return Path(parts[-1]), (f"CODE {filename}: its folders lead outside the output "
                                 f"folder; the program is written there as {parts[-1]}, "
                                 "beside the files autolev run writes for it")
    return Path(*parts), None


def program_texts(model, command, sources=None, quirks: bool = True) -> dict:
    """{relative path: text} of one CODE command's program and its .in file;
    `sources`: {NAME: "file:line: statement"} (the translation's `defined_at`), for
    comments that say which statement defines each named quantity; `quirks`: its
    outputs as Autolev's program computed them (as `autolev run` does)."""
    return _program(model, command, sources, quirks)[0]


def _program(model, command, sources, quirks: bool) -> tuple[dict, list[str]]:
    """(program_texts, the notes the user is told of the program)."""
    _, leaving = relative_path(command.filename)  # refused before the work, if it must be
    extension = os.path.splitext(command.filename)[1].lower()
    found = WRITERS.get((command.kind, extension))
    if found is None:
        raise AutolevModelError(
            f"CODE {command.kind.upper()} {command.filename}: programs of this kind in "
            f"{extension or 'a file without extension'} are not written yet (autolev "
            "code writes CODE ALGEBRAIC and NONLINEAR programs in .c and .m, CODE DYNAMICS "
            "and ODE in .c, .m and Fortran .f/.for)")
    plan_of, write = found
    plan = plan_of(model, command, quirks)
    plan.sources = dict(sources or {})
    notes = [hidden_note(command.filename, plan.hidden)] if plan.hidden else []
    notes += [leaving] if leaving else []
    texts = {relative_path(name)[0]: text for name, text in write(plan).items()}
    return texts, notes + plan.notes


def write_programs(model, out_dir, commands=None, overwrite: bool = False,
                   quirks: bool = True) -> list[Written]:
    """Write each CODE command's program (default: all of the model's) and the .in
    file it reads into `out_dir`, naming in comments the statements of the model's .al
    file that define its quantities (a model loaded from its translation).  Every text
    is made before any file is written, and each file appears whole (written aside,
    then renamed).  A file in the way that autolev did not write stops it before
    anything is written, unless `overwrite`.  `quirks`: as program_texts'."""
    sources = model.loaded.defined_at if model.loaded is not None else {}
    out = Path(out_dir)
    done = []
    texts = {}
    for command in (model.code_commands if commands is None else commands):
        try:
            made, notes = _program(model, command, sources, quirks)
        except AutolevModelError as exc:
            done.append(Written(command, [], str(exc)))
            continue
        texts.update(made)
        done.append(Written(command, [out / p for p in made], notes=notes))
    if texts:
        out.mkdir(parents=True, exist_ok=True)
    # every name checked first: one that leads outside, or a file of someone else's in
    # the way, means none is written
    paths = {rel: inside(out, rel) for rel in texts}
    for path in paths.values():
        WrittenFiles(path.parent).check([path.name], overwrite)
    for rel, text in texts.items():
        write_output(out, rel, text, overwrite=True)
    return done


__all__ = ["write_programs", "program_texts", "Written", "relative_path"]
