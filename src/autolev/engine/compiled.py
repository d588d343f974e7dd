"""A compiled numeric function, C or Python, pickled as its source and built again (or
found in the build cache) when read back: a run plan's read back without sympy; and a
C source compiled on a thread of its own while the caller goes on."""
from __future__ import annotations

import marshal
import threading
import warnings
from dataclasses import dataclass

from . import clibrary
from .pyfunction import python_function


@dataclass
class Function:
    """A compiled numeric function with its backend and source; pickled as its source,
    compiled again (or found in the build cache) when it is read back."""

    call: object
    backend: str            # "c" or "python"
    source: str
    recipe: tuple = ()      # the rest of what builds `call` from `source`

    def compiled(self) -> "Function":
        """Itself (WalkedFirst's compiled(): the function as compiled code)."""
        return self

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


class CompilingInBackground:
    """A program's C compiled on a thread of its own while the caller goes on (gcc is a
    subprocess: the interpreter is free meanwhile).  `done()` asks; `function()` waits
    and gives the C Function, or None when the compiler failed (with compile_program's
    warning: the caller stays with Python)."""

    def __init__(self, source: str, recipe: tuple, name: str,
                 after: CompilingInBackground | None = None):
        """`source` and `recipe` as clibrary.c_function takes them; `after`: a compile
        to finish first (the cores go to what is needed first)."""
        self.name = name
        self._after = after
        self._source, self._recipe = source, recipe
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
