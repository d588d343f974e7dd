"""What the numerics read of a model for one CODE command, as one frozen value the
Model builds (`Model.snapshot_for`): no numeric module reads the Model itself
(tests/test_architecture.py), as sympy's KanesMethod is built from explicit inputs.
"""
from __future__ import annotations

from collections.abc import Callable, Hashable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import sympy as sm

    from ..articulated import Tree
    from ..calculus import Definitions
    from ..derived import DerivedCache
    from ..io import CodeCommand
    from ..kane import KaneEquations, SymbolInfo, System


@dataclass(frozen=True)
class FormedDynamics:
    """Kane's equations of a model with a Newtonian frame, formed when a numeric system
    first asks, in the view of the definitions then in effect (its command's)."""

    independent_speeds: Callable[[], list]
    equations: Callable[[], KaneEquations]     # KANE()'s, else formed as it stands
    mass_matrix: Callable[[], sm.Matrix]
    forcing: Callable[[], sm.Matrix]
    mechanics: Callable[[], System]            # what Kane's method reads of it
    # its bodies as a tree of joints over the speeds given (articulated.tree), built once
    # for the model's revision: a run's recursion and the Newton-Euler rows share it
    joints: Callable[[list], Tree]


@dataclass(frozen=True)
class ModelSnapshot:
    """The model as the numerics see it for `command` (and the commands made from it: a
    linearization's, one with specified quantities given)."""

    command: CodeCommand
    place: Hashable                 # the command's among the model's: its system's key
    definitions: Definitions        # the model's; a command reads them as_of its own
    symbols: Mapping[sm.Symbol, SymbolInfo]     # declared: kind, order, index
    outputs: tuple                  # OUTPUT before the command: [(value, label, unit)]
    encoded: tuple                  # ENCODE before it: (name, value)
    units: Mapping                  # UNITS x = unit, as the model stands
    solved_rates: tuple             # SOLVEs that defined speeds' derivatives
    solved_speeds: frozenset        # the speeds whose derivatives SOLVE defined
    bodies: tuple
    particles: tuple
    dynamics: FormedDynamics | None     # None: no Newtonian frame
    derived: DerivedCache           # what is kept for the model's revision
    names_a_quantity: Callable[[str], bool]
    # a numeric system built or extended: the cache of built models writes it again
    systems_changed: Callable[[], None]

    def kind_of(self, sym) -> str | None:
        info = self.symbols.get(sym)
        return info.kind if info else None
