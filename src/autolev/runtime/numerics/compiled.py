"""A compiled numeric function: C when a compiler is there (or asked for), else Python;
pickled as its source and built again (or found in the build cache) when read back.
A C function reads back without sympy (a run plan's); generating code needs it."""
from __future__ import annotations

import marshal
import threading
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..errors import AutolevModelError
from . import clibrary
from .pyfunction import python_function

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
            self.call = python_function(self.source, *self.recipe,
                                        code=marshal.loads(code) if code else None)


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


class WalkedFirst:
    """A program evaluated once per parameter set (the constants'): its first call walks
    it (interpret.py: nothing printed or compiled, the compiled Python's numbers), later
    calls compile it to Python (and a first call whose walk raises: the compiled
    code's numpy fallback gives C's inf and nan).  `compiled()` is that Function."""

    backend = "python"

    def __init__(self, prog: Program, name: str):
        self._prog, self.name = prog, name
        self._function: Function | None = None
        self._walked = False

    def call(self, *arrays) -> None:
        if self._function is None and not self._walked:
            from .interpret import ProgramWalk
            from .pyfunction import MATH_ERRORS
            self._walked = True
            try:
                ProgramWalk(self._prog).evaluate(*arrays)
                return
            except MATH_ERRORS:
                pass
        self.compiled().call(*arrays)

    def compiled(self) -> Function:
        if self._function is None:
            self._function = compile_program(self._prog, "python", self.name)
        return self._function


class CompilingInBackground:
    """A program's C compiled on a thread of its own while the caller goes on (gcc is a
    subprocess: the interpreter is free meanwhile).  `done()` asks; `function()` waits
    and gives the C Function, or None when the compiler failed (with compile_program's
    warning: the caller stays with Python)."""

    def __init__(self, prog: Program, name: str, extra_source: str = "",
                 extra_flags: tuple = (), after: CompilingInBackground | None = None):
        """`after`: a compile to finish first (the cores go to what is needed first)."""
        from . import codegen          # (sympy) the source is printed here, the rest there
        self.name = name
        self._after = after
        self._source, self._recipe = codegen.c_program(prog, name, extra_source, extra_flags)
        self._call = None
        self._refused: clibrary.CompileError | None = None
        self._error: BaseException | None = None
        self._thread = threading.Thread(target=self._build, name=f"compiling {name}",
                                        daemon=True)
        self._thread.start()

    def _build(self) -> None:
        if self._after is not None:
            self._after._thread.join()
        try:
            self._call = clibrary.c_function(self._source, *self._recipe)
        except clibrary.CompileError as exc:
            self._refused = exc
        except BaseException as exc:   # raised again on the caller's thread by function()
            self._error = exc

    def done(self) -> bool:
        return not self._thread.is_alive()

    def function(self) -> Function | None:
        self._thread.join()
        if self._call is None and self._refused is None and self._error is None:
            self._build()              # the thread did not survive a fork: here, then
        if self._error is not None:
            raise self._error
        if self._refused is not None:
            warnings.warn(f"compiling {self.name} failed; using Python ({self._refused})")
            return None
        return Function(self._call, "c", self._source, self._recipe)
