"""Compiling a program the model generated (codegen.Program): C when a compiler is
there (or asked for), else Python, as an engine.compiled.Function; a constants'
program walked first; a C program compiled in the background."""
from __future__ import annotations

import warnings
from typing import TYPE_CHECKING

from ...engine.errors import AutolevModelError
from ...engine import clibrary
from ...engine.compiled import CompilingInBackground, Function

if TYPE_CHECKING:
    from .codegen import Program


def compile_program(prog: Program, backend: str, name: str,
                    extra_source: str = "", extra_flags: tuple = (),
                    lanes: bool = False) -> Function:
    """`lanes`: in C, several nodes at once (a program called over many rows)."""
    from . import codegen  # (sympy): generating code is the model's work
    if backend in ("auto", "c") and clibrary.compiler() is not None:
        try:
            call, source, recipe = codegen.compile_c(prog, name, extra_source, extra_flags,
                                                     lanes)
            return Function(call, "c", source, recipe)
        except clibrary.CompileError as exc:
            if backend == "c":
                raise AutolevModelError(f"the C compiler failed: {exc}") from None
            warnings.warn(f"compiling {name} failed; using Python ({exc})")
    elif backend == "c":
        raise AutolevModelError("no C compiler found (set CC, or use backend='python')")
    call, source, recipe = codegen.compile_python(prog, name)
    return Function(call, "python", source, recipe)


class WalkedFirst:
    """A program evaluated once per parameter set or solution (the constants', an
    algebraic program's outputs): its first call walks its definitions in order
    (interpret.py: nothing built, printed or compiled, the compiled Python's numbers),
    later calls compile it to Python (and a first call whose walk raises: the compiled
    code's numpy fallback gives C's inf and nan).  `compiled()` is that Function.
    `prog` is named here, with the definitions as they stand (a value given to a
    specified quantity defines it only meanwhile), and built when it compiles."""

    backend = "python"

    def __init__(self, prog: Program, name: str):
        self._prog, self.name = prog.name_all(), name
        self._function: Function | None = None
        self._walked = False

    def call(self, *arrays) -> None:
        if self._function is None and not self._walked:
            from .interpret import ProgramWalk
            from ...engine.pyfunction import MATH_ERRORS
            self._walked = True
            try:
                ProgramWalk(self._prog).evaluate(*arrays)
                return
            except MATH_ERRORS:
                pass
        self.compiled().call(*arrays)

    def compiled(self) -> Function:
        if self._function is None:
            self._function = compile_program(self._prog.build(False), "python", self.name)
        return self._function


def compiling_in_background(prog: Program, name: str, extra_source: str = "",
                            extra_flags: tuple = (),
                            after: CompilingInBackground | None = None
                            ) -> CompilingInBackground:
    """The program printed as C here, compiled on a thread of its own (`after`: a
    compile to finish first)."""
    from . import codegen              # (sympy) the source is printed here, the rest there
    source, recipe = codegen.c_program(prog, name, extra_source, extra_flags)
    return CompilingInBackground(source, recipe, name, after)
