"""A compiled numeric function: C when a compiler is there (or asked for), else Python;
pickled as its source and built again (or found in the build cache) when read back.
A C function reads back without sympy (a run plan's); generating code needs it."""
from __future__ import annotations

import marshal
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..errors import AutolevModelError
from . import clibrary

if TYPE_CHECKING:
    from .codegen import Program


@dataclass
class Function:
    """A compiled numeric function with its backend and source; pickled as its source,
    compiled again (or found in the build cache) when it is read back."""

    call: object
    backend: str            # "c" or "python"
    source: str
    recipe: tuple = ()      # the rest of what builds `call` from `source`

    def __getstate__(self) -> dict:
        state = {"backend": self.backend, "source": self.source, "recipe": self.recipe}
        if self.backend == "python":       # Python's compiled code: faster to read back
            state["code"] = marshal.dumps(self.call.code)
        return state

    def __setstate__(self, state: dict) -> None:
        code = state.pop("code", None)
        self.__dict__.update(state)
        if self.backend == "c":
            self.call = clibrary.c_function(self.source, *self.recipe)
        else:
            from . import codegen      # (sympy): Python code is read back with the model
            self.call = codegen.python_function(
                self.source, *self.recipe, code=marshal.loads(code) if code else None)


def compile_program(prog: Program, backend: str, name: str,
                    extra_source: str = "", extra_flags: tuple = ()) -> Function:
    from . import codegen              # (sympy): generating code is the model's work
    if backend in ("auto", "c") and clibrary.compiler() is not None:
        try:
            call, source, recipe = codegen.compile_c(prog, name, extra_source, extra_flags)
            return Function(call, "c", source, recipe)
        except clibrary.CompileError as exc:
            if backend == "c":
                raise AutolevModelError(f"the C compiler failed: {exc}") from None
            warnings.warn(f"compiling {name} failed; using Python ({exc})")
    elif backend == "c":
        raise AutolevModelError("no C compiler found (set CC, or use backend='python')")
    call, source, recipe = codegen.compile_python(prog, name)
    return Function(call, "python", source, recipe)
