"""How a Model shows itself in Jupyter (`_repr_html_`): what it declares with its
values (a Result and a Linearization: engine/notebook.py).  Every text from a model
is escaped: names and expressions reach the page as text, never as markup.
"""
from __future__ import annotations

import html

import sympy as sm

from ..engine.notebook import names, table


def model_html(model) -> str:
    """The model's frames, bodies and particles with their masses, its motion variables
    with their initial values and its constants with their values (INPUT), its
    specified quantities and CODE commands."""
    by_kind: dict[str, list] = {}
    for symbol, info in sorted(model.info.items(), key=lambda item: item[1].index):
        if not str(symbol).endswith("'"):
            by_kind.setdefault(info.kind, []).append(symbol)

    def valued(symbol) -> str:
        if symbol not in model.inputs:
            return f"{symbol} (no value)"
        value, unit = model.inputs[symbol]
        shown = f"{float(value):g}" if isinstance(value, (int, float, sm.Number)) else value
        return f"{symbol} = {shown}" + (f" {unit}" if unit else "")
    rows = [("Newtonian frame", str(model.newtonian_frame or "none")),
            ("frames", names(model.frames_by_name)),
            ("bodies", names(f"{b} (mass {b.mass})" for b in model.bodies_list)),
            ("particles", names(f"{p} (mass {p.mass})" for p in model.particles_list)),
            ("motion variables", names(valued(q) for q in by_kind.get("motionvariable", []))),
            ("variables", names(by_kind.get("variable", []))),
            ("constants", names(valued(c) for c in by_kind.get("constant", []))),
            ("specified", names(by_kind.get("specified", []))),
            ("CODE commands", names(f"{c.kind.upper()} {c.filename}"
                                     for c in model.code_commands))]
    return f"<b>autolev model {html.escape(model.name)}</b>" + table(rows)
