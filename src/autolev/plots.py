"""Pictures of a run's output tables (matplotlib, an optional dependency: each
function imports it where it draws, so this module loads without it).

One figure per output file: its columns against the integration's time (a dynamics
run's; else the T column, else the first column, which the figure says), one panel per unit so that
degrees do not squash radians per second, the panels sharing the time axis, each
labelled with its unit, numbers written out (no offset notation).
"""
from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from .engine.results import OutputTable
from .engine.outputs import write_output


def _unit_key(unit: str | None) -> str:
    return (unit or "").strip().upper()


def abscissa(table, times=None) -> tuple[int | None, str | None]:
    """(column index of the x axis, a note when it is not time).  With the run's
    `times` (one per row) the x axis is those times, and the index is that of the
    column holding them, None when none does: a column labelled T may be a quantity the
    model declared, drawn then as any other."""
    if times is not None:
        for j in range(table.data.shape[1]):
            if np.allclose(table.data[:, j], times, rtol=1e-6, atol=1e-12):
                return j, None
        return None, None
    for j, label in enumerate(table.labels):
        if label.strip().upper() in ("T", "TIME"):
            return j, None
    return 0, (f"no T column: plotted against its first column, {table.labels[0]}"
               if table.labels else None)


def figure(table, times=None):
    """The figure of one OutputTable, or None when there is nothing to draw (fewer than
    two rows or no column beside the x axis); `times`: the run's time at each row,
    the x axis when given."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = table.data
    if times is not None and len(times) != data.shape[0]:
        times = None
    xj, note = abscissa(table, times)
    if data.shape[0] < 2 or data.shape[1] < 1 + (xj is not None):
        return None
    x = times if times is not None else data[:, xj]
    groups: dict[str, list[int]] = {}
    for j in range(data.shape[1]):
        if j != xj:
            groups.setdefault(_unit_key(table.units[j]), []).append(j)
    fig, axes = plt.subplots(len(groups), 1, sharex=True, squeeze=False,
                             figsize=(8, 1.2 + 2.3 * len(groups)))
    for ax, (unit, columns) in zip(axes[:, 0], groups.items()):
        for j in columns:
            ax.plot(x, data[:, j], label=table.labels[j])
        ax.set_ylabel(table.units[columns[0]] or "no unit")
        ax.ticklabel_format(axis="y", useOffset=False)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="best")
    bottom = axes[-1, 0]
    x_unit = table.units[xj] if xj is not None else None
    x_label = "time" if xj is None else table.labels[xj]
    bottom.set_xlabel(x_label + (f" ({x_unit})" if x_unit else ""))
    bottom.ticklabel_format(axis="x", useOffset=False)
    fig.suptitle(table.filename + (f"\n{note}" if note else ""), fontsize="medium")
    fig.tight_layout()
    return fig


def write_pngs(result, out_dir: Path, overwrite: bool = False) -> list[Path]:
    """A PNG per output table of the run (NAME.k.png); returns the files written.
    `overwrite`: replace such files autolev did not write."""
    import matplotlib.pyplot as plt

    written = []
    times = result.t if result.kind.integrates else None
    for table in result.outputs:
        fig = figure(table, times)
        if fig is None:
            continue
        written.append(_save(fig, Path(out_dir) / f"{table.filename}.png", overwrite))
        plt.close(fig)
    return written


def write_chosen_png(result, out_dir: Path, labels: list[str],
                     overwrite: bool = False) -> list[Path]:
    """NAME.plot.png: the output columns named `labels` (any case; those this run
    wrote) against the integration's time (else the T column, else the swept input);
    returns the file written, none when the run wrote none of them."""
    import matplotlib.pyplot as plt

    columns = {label.upper(): (label, unit, values) for label, unit, values in result.columns()}
    chosen = [columns[name.upper()] for name in labels if name.upper() in columns]
    if not chosen:
        return []
    times = result.t if result.kind.integrates else None
    rows = len(chosen[0][2])
    if times is None or len(times) != rows:
        times = None
        time_column = columns.get("T") or columns.get("TIME")
        if time_column is None and len(result.t) == rows:
            time_column = ("the swept input", "", result.t)
        chosen = ([time_column] if time_column is not None else []) + \
            [c for c in chosen if c is not time_column]
    table = OutputTable(f"{result.name}.plot", [c[0] for c in chosen],
                        [c[1] or None for c in chosen], np.column_stack([c[2] for c in chosen]))
    fig = figure(table, times)
    if fig is None:
        return []
    try:
        return [_save(fig, Path(out_dir) / f"{result.name}.plot.png", overwrite)]
    finally:
        plt.close(fig)


def _save(fig, path: Path, overwrite: bool = False) -> Path:
    """The figure as a PNG, written whole (never through a link at its name, nor over a
    file autolev did not write unless `overwrite`)."""
    picture = io.BytesIO()
    fig.savefig(picture, dpi=100, format="png")
    return write_output(path.parent, path.name, picture.getvalue(), overwrite)


def eigenvalue_figure(name: str, values, eigenvalues, title: str = ""):
    """The eigenvalues against a swept quantity: real parts above, imaginary parts
    below, as points (the branches cross, so no line joins them); `eigenvalues`: one
    array per value."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6.5))
    numbers = np.asarray(eigenvalues, dtype=complex).reshape(len(values), -1)
    along = np.repeat(np.asarray(values, dtype=float), numbers.shape[1])
    top.plot(along, numbers.real.ravel(), "k.", markersize=3)
    bottom.plot(along, np.abs(numbers.imag).ravel(), "b.", markersize=3)
    top.axhline(0.0, color="r", linewidth=0.8)
    top.set_ylabel("real part (1/s)")
    bottom.set_ylabel("|imaginary part| (rad/s)")
    bottom.set_xlabel(name)
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
        ax.ticklabel_format(useOffset=False)
    fig.suptitle(title or f"eigenvalues against {name}", fontsize="medium")
    fig.tight_layout()
    return fig


def write_eigenvalue_png(path: Path, name: str, values, eigenvalues, title: str = "",
                         overwrite: bool = False) -> Path:
    import matplotlib.pyplot as plt

    fig = eigenvalue_figure(name, values, eigenvalues, title)
    written = _save(fig, Path(path), overwrite)
    plt.close(fig)
    return written
