"""How a Result and a Linearization show themselves in Jupyter (`_repr_html_`): a
run's columns drawn against time, a linearization's eigenvalues.  Every text from a
model is escaped: names reach the page as text, never as markup.
"""
from __future__ import annotations

import base64
import html
import importlib.util
import io

import numpy as np


def table(rows: list[tuple[str, str]]) -> str:
    cells = "".join(f"<tr><th style='text-align:left'>{html.escape(k)}</th>"
                    f"<td style='text-align:left'>{html.escape(v)}</td></tr>" for k, v in rows)
    return f"<table>{cells}</table>"


def names(items, limit: int = 40) -> str:
    shown = [str(x) for x in items]
    return ", ".join(shown[:limit]) + (f", ... ({len(shown)} in all)"
                                       if len(shown) > limit else "") or "none"


def _figure_png(result) -> str | None:
    """The run's output columns against its time as an embedded PNG (matplotlib, when
    installed; None without it or without rows)."""
    if importlib.util.find_spec("matplotlib") is None or len(result.t) < 2:
        return None
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    columns = [(label, unit, values) for label, unit, values in result.columns()
               if len(values) == len(result.t) and
               not np.allclose(values, result.t, rtol=1e-6, atol=1e-12)]
    if not columns:
        return None
    fig, ax = plt.subplots(figsize=(6, 3))
    for label, unit, values in columns[:12]:
        ax.plot(result.t, values, label=f"{label} ({unit})" if unit else label)
    ax.set_xlabel("time" if result.kind.integrates else "swept input")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="best")
    fig.tight_layout()
    picture = io.BytesIO()
    fig.savefig(picture, format="png", dpi=80)
    plt.close(fig)
    return base64.b64encode(picture.getvalue()).decode("ascii")


def result_html(result) -> str:
    """What was run, how many rows over which span, a failure if any, and a picture of
    the output columns (else the first and last rows)."""
    rows = [("command", f"CODE {result.kind.upper()} {result.name}"),
            ("rows", str(len(result.t)))]
    if len(result.t):
        rows.append(("from, to", f"{result.t[0]:g}, {result.t[-1]:g}"))
    rows.append(("columns", names(label for label, _, _ in result.columns())))
    if result.failure:
        rows.append(("failure", result.failure))
    out = f"<b>autolev result</b>{table(rows)}"
    png = _figure_png(result)
    if png is not None:
        return out + f"<img src='data:image/png;base64,{png}'/>"
    columns = result.columns()
    if columns and len(columns[0][2]):
        head = "".join(f"<th>{html.escape(label)}</th>" for label, _, _ in columns)
        picked = sorted({0, 1, 2, len(columns[0][2]) - 1} & set(range(len(columns[0][2]))))
        body = "".join("<tr>" + "".join(f"<td>{values[k]:.6g}</td>" for _, _, values in columns)
                       + "</tr>" for k in picked)
        out += f"<table><tr>{head}</tr>{body}</table>"
    return out


def linearization_html(lin) -> str:
    """The state, the inputs, and the eigenvalue table (roundoff shown as 0)."""
    lines = lin.eigenvalue_table().splitlines()
    head = "".join(f"<th>{html.escape(h.replace('_', ' '))}</th>"
                   for h in lines[0].split(","))
    body = "".join("<tr>" + "".join(f"<td>{html.escape(cell)}</td>"
                                    for cell in line.split(",", 4)) + "</tr>"
                   for line in lines[1:])
    rows = [("states", names(lin.states)), ("inputs", names(lin.inputs)),
            ("steady", "yes" if lin.steady else "no: the accelerations are not zero here"),
            ("zero tolerance", f"{lin.zero_tolerance():.2g}")]
    return f"<b>autolev linearization</b>{table(rows)}<table><tr>{head}</tr>{body}</table>"
