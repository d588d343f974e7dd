"""What a run that fails tells the user of its model: masses and inertias no body
has, constants that are 0 (integration_notes.py says why the integrator struggled).
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sm

from .. import symbols as S
from ..calculus import NumericPoint, is_real_number
from ...engine.errors import AutolevModelError
from .inputs import display_name
from ...engine.integrate import Integration, IntegrationFailure, failure_basis
from ...engine.integration_notes import halving_verdict


def inertia_problems(snapshot, system, inputs, zero: bool = True) -> list[str]:
    """Bodies and particles whose mass (or a principal inertia) is negative or not a
    number (and, with `zero`, zero) as the run uses them: a constant its equations do
    not contain (a planar model's I11 or I12) counts as 0 and never had a value chosen
    for it: a mass or inertia holding one is not called zero or singular, and an axis
    whose moment holds one is left out of the principal inertias judged."""
    values = {p: inputs.internal(p) for p in system.params}
    # a sweep asks at every point: what depends only on the model is found once, and
    # the answer kept for the last values of the constants the masses and inertias hold
    kept = snapshot.derived.table("inertia check")
    plan = kept.get(tuple(system.params))
    if plan is None:
        plan = kept[tuple(system.params)] = _inertia_plan(snapshot, values)
    masses, partial, judged_axes, unused, held = plan
    key = (tuple(system.params), zero, tuple(values[p] for p in held))
    if kept.get("last", (None,))[0] == key:
        return kept["last"][1]
    defs = snapshot.definitions
    point = NumericPoint(defs, {**values, **{f: 0.0 for f in unused}})

    def num(e):
        z = defs.numeric(sm.sympify(e), point)
        return z.real if is_real_number(z) else math.nan

    out = []
    for name, mass_expr, inertia in masses:
        mass_partial, inertia_partial = partial[name]
        mass = num(mass_expr)
        axes = judged_axes[name]
        principal = [] if inertia is None or not axes else principal_inertias(
            np.array([[num(inertia[i, j]) for j in axes] for i in axes]))
        zero_mass = zero and not mass_partial
        if math.isinf(mass) or not all(map(math.isfinite, principal)):
            out.append(f"{name} has a {'mass' if math.isinf(mass) else 'central inertia'} "
                       "that is not a finite number (a value beyond double precision?)")
        elif not mass > 0 and (zero_mass or mass != 0):
            what = f"{name} has mass {mass:g}"
            if principal and not any(d > 0 for d in principal):
                what += " and no inertia"
            out.append(what)
        elif principal and any(d < 0 or math.isnan(d) for d in principal):
            out.append(f"{name} has principal inertias "
                       + ", ".join(f"{d:.6g}" for d in principal))
        elif zero and not inertia_partial and len(principal) == 3 and min(principal) == 0:
            out.append(f"{name} has a singular central inertia (principal inertias "
                       + ", ".join(f"{d:.6g}" for d in principal) + ")")
    kept["last"] = (key, out)
    return out


def _inertia_plan(snapshot, values: dict) -> tuple:
    """(masses with their central inertias, which hold constants the run does not use,
    the axes of each inertia whose moment holds none, those constants, the constants of
    the run they hold) of the model as it stands."""
    unused = set()
    defs = snapshot.definitions

    def primitives(e):
        out = set()
        for f in sm.sympify(e).free_symbols:
            out |= defs.primitive_deps(f) if f in defs.rhs else {f}
        return out

    def unused_in(e) -> bool:
        found = {f for f in primitives(e)
                 if f not in values and f not in defs.varying and f != S.TIME}
        unused.update(found)
        return bool(found)

    masses = [(f"particle {p.name}", p.mass, None) for p in snapshot.particles
              if p.mass is not None]
    for b in snapshot.bodies:
        if b.mass is not None:
            try:
                inertia = b.central_inertia.to_matrix(b)
            except AutolevModelError:
                inertia = None
            masses.append((f"body {b.name}", b.mass, inertia))
    # every entry looked at (no short cut): each unused constant must get its 0
    partial = {name: (unused_in(mass), inertia is not None
                      and any([unused_in(e) for e in inertia]))
               for name, mass, inertia in masses}
    # a principal submatrix of a body's inertia is positive semidefinite when the whole
    # is: the axes the run reads are judged whatever the numbers on the others
    judged_axes = {name: [] if inertia is None
                   else [i for i in range(3) if not (primitives(inertia[i, i]) & unused)]
                   for name, _, inertia in masses}
    held = set()
    for _, mass, inertia in masses:
        for e in [mass] + ([] if inertia is None else list(inertia)):
            held |= primitives(e)
    return masses, partial, judged_axes, unused, [p for p in values if p in held]


def principal_inertias(numbers) -> list[float]:
    """The principal inertias of a numeric inertia matrix, those within rounding of
    0 (1e-12 of the largest) shown as 0; [nan] when an entry is not a number."""
    if not np.all(np.isfinite(numbers)):
        return [math.nan]
    principal = np.linalg.eigvalsh((numbers + numbers.T) / 2)
    scale = max(float(np.abs(principal).max()), 0.0)
    return [0.0 if abs(d) <= 1e-12 * scale else float(d) for d in principal]


def zero_hint(zero_params) -> str:
    if not zero_params:
        return ""
    shown = ", ".join(zero_params[:12]) + (", ..." if len(zero_params) > 12 else "")
    return f" (constants that are 0: {shown})"


def failure_message(exc: IntegrationFailure, snapshot, system, inputs, result, zero_params,
                    integration: Integration) -> str:
    """Autolev's message for a failed integration, with what we can tell of its cause."""
    message = failure_basis(exc, result.state_names) + (
        zero_hint(zero_params) if result.stats["rows"] <= 1 else "")
    if "singular" in str(exc) or (result.stats["rows"] <= 1 and "not finite" in str(exc)):
        problems = inertia_problems(snapshot, system, inputs)
        if problems:
            message += "; " + "; ".join(problems)
    huge = [f"{display_name(p)} = {v:g}" for p, v in zip(system.params,
                                                           system.constant_values)
            if abs(v) > 1e100]
    mass = system.last_mass_matrix() if "singular" in str(exc) else None
    if mass is not None and not np.all(np.isfinite(mass)):
        message += ("; its entries are not finite numbers (inf or NaN): a value beyond "
                    "double precision" + (f" (from {', '.join(huge[:4])}?)" if huge else ""))
    elif huge and result.stats["rows"] <= 1:
        # (a tree's recursion has no mass matrix to show: the inputs say it)
        message += (f"; {', '.join(huge[:4])}: a product or power of so large a value is "
                    "beyond double precision (inf or NaN), which this failure may come from")
    if exc.cuts:
        message += "; " + halving_verdict(integration, exc)
    return message
