"""How a CODE command is run: the options of Model.simulate, Model.run and autolev run,
declared once."""
from __future__ import annotations

from dataclasses import dataclass, fields, replace


@dataclass(frozen=True)
class RunOptions:
    """`method`: the integrator's name (integrators.METHODS; None: that of Autolev's
    program for the CODE file, ode45 ("rk45") for a .m file, else its Kutta-Merson);
    `backend`: "auto" (C when a compiler is found), "c" or "python"; `infile`: an
    Autolev .in file read over the INPUT values; `specified`: {name: a function f(t) or
    f(t, x), a number, or a sympy expression} for specified quantities the model leaves
    undefined; `progress`: a stream for progress lines (None: none); `overrides`: {name:
    value} in the quantities' own units, read last; `compiled`: the integration loop in
    C where the right-hand side is; `constraints`: configuration constraints g(q) kept
    at their initial values by projection at every print time; `quirks`: compute what
    Autolev's programs computed where they were wrong (docs/language.md); `keep_rows`:
    the Result holds every row (False: only the last; the files hold them all);
    `missing_values`: "refuse" (constants without a value stop the run before anything
    is compiled) or "zero"; `overwrite`: replace files in the output folder that autolev
    did not write; `recursion`: a model whose bodies form a tree of joints has its
    accelerations from the articulated-body recursion (runtime/articulated.py; False:
    Kane's mass matrix solved at each evaluation, as Autolev's programs did)."""

    method: str | None = None
    backend: str = "auto"
    infile: object = None
    specified: dict | None = None
    progress: object = None
    overrides: dict | None = None
    compiled: bool = True
    constraints: object = None
    quirks: bool = True
    keep_rows: bool = True
    missing_values: str = "refuse"
    overwrite: bool = False
    recursion: bool = True

    @classmethod
    def split(cls, given: dict) -> "RunOptions":
        """The options among keyword arguments (`simulate(method="rk45", L=2)`); any
        other name is an input's value, in its unit (an override)."""
        names = {f.name for f in fields(cls)}
        options = {k: v for k, v in given.items() if k in names}
        values = {k: v for k, v in given.items() if k not in names}
        if values:
            options["overrides"] = {**(options.get("overrides") or {}), **values}
        return cls(**options)

    def but(self, **changes) -> "RunOptions":
        """These options with some changed."""
        return replace(self, **changes)

    def __post_init__(self) -> None:
        if self.missing_values not in ("refuse", "zero"):
            raise ValueError(f"missing_values: 'refuse' or 'zero', not "
                             f"{self.missing_values!r}")
