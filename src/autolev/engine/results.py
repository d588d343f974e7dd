"""Results of a run: the tables of its output files and the Result it returns.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np

from .code_kinds import CodeKind


@dataclass
class Column:
    """One output column: the expression, its label and unit."""

    expr: object
    label: str
    unit: str | None


@dataclass
class OutputTable:
    """The rows of one output file (values in the file's units)."""

    filename: str
    labels: list
    units: list
    data: np.ndarray

    def __getitem__(self, label: str) -> np.ndarray:
        for j, name in enumerate(self.labels):
            if name.upper() == label.upper():
                return self.data[:, j]
        raise KeyError(label)

    def __contains__(self, label) -> bool:
        return isinstance(label, str) and any(n.upper() == label.upper()
                                              for n in self.labels)


@dataclass
class Result:
    """What a run produced.

    t: the print times (DYNAMICS, ODE), or the swept input's values (ALGEBRAIC with a
    sweep, in its unit); states: one row per print time, internal units (radians);
    outputs: one OutputTable per OUTPUT statement, in the units the OUTPUT asked for;
    encoded: the ENCODE quantities at the last row; failure: Autolev's message when
    the run stopped early (the rows before it are kept)."""

    kind: CodeKind
    name: str
    t: np.ndarray
    states: np.ndarray
    state_names: list
    outputs: list
    encoded: dict
    inputs: dict
    solution: dict = field(default_factory=dict)
    files: list = field(default_factory=list)
    failure: str | None = None
    failure_time: float | None = None
    stats: dict = field(default_factory=dict)
    system: object = field(default=None, repr=False)   # the NumericSystem (rhs, outputs)
    # what computed it (execute.Execution): a run plan keeps it
    execution: object = field(default=None, repr=False)

    @property
    def ok(self) -> bool:
        return self.failure is None

    def __getitem__(self, name: str) -> np.ndarray:
        """A state's column (by name, any case), else the first output column so
        labelled, else an ALGEBRAIC/NONLINEAR unknown."""
        for j, s in enumerate(self.state_names):
            if s.upper() == name.upper():
                return self.states[:, j]
        for table in self.outputs:
            try:
                return table[name]
            except KeyError:
                pass
        for k, v in self.solution.items():
            if k.upper() == name.upper():
                return v
        raise KeyError(name)

    def _repr_html_(self) -> str:
        """Jupyter's view: the run, and its output columns drawn against time."""
        from .notebook import result_html
        return result_html(self)

    def columns(self) -> list[tuple[str, str, np.ndarray]]:
        """Every output column once, in file order: (label, unit, values); a label that
        several files hold (T) is kept from the first."""
        seen, out = set(), []
        for table in self.outputs:
            for j, (label, unit) in enumerate(zip(table.labels, table.units)):
                if label.upper() not in seen:
                    seen.add(label.upper())
                    out.append((label, unit or "", table.data[:, j]))
        return out

    def to_frame(self):
        """The output columns as a pandas DataFrame (pandas is an optional extra), their
        units in `frame.attrs["units"]`."""
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("Result.to_frame needs pandas (pip install pandas)") from None
        columns = self.columns()
        frame = pd.DataFrame({label: values for label, _, values in columns})
        frame.attrs["units"] = {label: unit for label, unit, _ in columns}
        return frame

    def csv_text(self) -> str:
        """The output columns as CSV: a header of labels, a row per printed row."""
        columns = self.columns()
        header = ",".join(_csv_field(label) for label, _, _ in columns)
        if not columns:
            return header + "\n"
        data = np.column_stack([values for _, _, values in columns])
        return "\n".join([header] + [",".join(f"{x:.17g}" for x in row) for row in data]) + "\n"

    def mat_bytes(self) -> bytes:
        """The output columns as a Matlab .mat file (scipy.io): a column vector per
        label (made a Matlab name), and `labels` and `units` as cell arrays."""
        columns = self.columns()
        names = matlab_names([label for label, _, _ in columns])
        contents = {name: values.reshape(-1, 1) for name, (_, _, values) in zip(names, columns)}
        contents["labels"] = np.array([label for label, _, _ in columns], dtype=object)
        contents["units"] = np.array([unit for _, unit, _ in columns], dtype=object)
        return mat_file(contents)

    def __repr__(self) -> str:
        status = "ok" if self.ok else f"failed: {self.failure}"
        return (f"<autolev Result {self.kind} {self.name}: {len(self.t)} rows, "
                f"{len(self.outputs)} output files, {status}>")


def mat_file(contents: dict) -> bytes:
    """A Matlab .mat file (scipy.io, compressed) of {Matlab name: array}."""
    import io
    import scipy.io
    buffer = io.BytesIO()
    scipy.io.savemat(buffer, contents, do_compression=True)
    return buffer.getvalue()


# Matlab's namelengthmax
MATLAB_NAME_LENGTH = 63


def matlab_names(labels: list[str]) -> list[str]:
    """A Matlab variable name for each label (letters, digits and _, a letter first),
    distinct from each other and from `labels` and `units`."""
    taken = {"labels", "units"}
    out = []
    for label in labels:
        name = re.sub(r"\W", "_", label.strip(), flags=re.ASCII).strip("_") or "column"
        if not name[0].isalpha():
            name = "x" + name
        name = base = name[:MATLAB_NAME_LENGTH]
        k = 1
        while name.lower() in taken:
            k += 1
            name = f"{base[:MATLAB_NAME_LENGTH - len(str(k)) - 1]}_{k}"
        taken.add(name.lower())
        out.append(name)
    return out


def _csv_field(text: str) -> str:
    """A CSV field: quoted (quotes doubled) when it holds a comma, a quote or a line end."""
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def split_outputs(system, values, result_rows, writer, encoded_out: dict) -> None:
    pos = 0
    for k, cols in enumerate(system.files):
        vals = values[pos:pos + len(cols)].tolist()
        # units.to_output, with the unit test made once per column
        row = [v * 180 / math.pi if deg else v
               for v, deg in zip(vals, system.degree_columns[k])]
        pos += len(cols)
        result_rows[k].append(row)
        if writer is not None:
            writer.write(k, row)
    read_encoded(system, values, pos, encoded_out)


def read_encoded(system, values, pos: int, encoded_out: dict) -> None:
    """The ENCODE quantities from one row of outputs, from position `pos` on (after the
    files' columns)."""
    for name, shape in system.encode_shapes:
        size = int(np.prod(shape)) if shape else 1
        chunk = values[pos:pos + size]
        pos += size
        encoded_out[name] = chunk.reshape(shape) if shape else float(chunk[0])


def split_output_rows(system, values: np.ndarray, result_rows, writer, encoded_out: dict,
                      keep_rows: bool) -> None:
    """split_outputs of many print times at once (`values`: a row each): the files'
    rows written together; `result_rows` keeps them all, or with `keep_rows` False only
    the last; ENCODE's values are the last row's."""
    pos = 0
    for k, cols in enumerate(system.files):
        block = values[:, pos:pos + len(cols)]
        degrees = [i for i, deg in enumerate(system.degree_columns[k]) if deg]
        if degrees:
            block = block.copy()
            # the same operations, in the same order, as split_outputs's
            block[:, degrees] = block[:, degrees] * 180 / math.pi
        pos += len(cols)
        if keep_rows:
            result_rows[k].extend(block.tolist())
        else:
            result_rows[k][:] = block[-1:].tolist()
        if writer is not None:
            writer.write_rows(k, block)
    read_encoded(system, values[-1], pos, encoded_out)


def tables_of(system, rows, stem: str) -> list[OutputTable]:
    out = []
    for k, cols in enumerate(system.files):
        data = np.array(rows[k], dtype=float).reshape(len(rows[k]), len(cols))
        out.append(OutputTable(f"{stem}.{k + 1}", [c.label for c in cols],
                               [c.unit for c in cols], data))
    return out


def run_summary(kind: CodeKind, filename: str, result: Result, seconds: float) -> str:
    """`CODE DYNAMICS bike.c: 101 rows in 1.30 s (building 1.02 s; integrating 0.21 s:
    kutta-merson, 412 steps)`: the whole command, then what took the time (building:
    forming and compiling its numeric system, reading it back, or its run plan; a cold
    run's Kutta-Merson steps in Python while its C compiles, and says so)."""
    stats = result.stats
    what = (f"{stats.get('rows', 0)} rows" if kind.integrates
            else "solved" if kind is not CodeKind.ALGEBRAIC or result.solution
            else "evaluated")
    parts = [f"building {stats.get('build_seconds', 0.0):.2f} s"]
    if "seconds" in stats:
        parts.append(f"integrating {stats['seconds']:.2f} s" + (
            f": {stats['method']}, {stats.get('steps')} steps" if stats.get("method")
            else "") + _tiers(stats))
    return f"CODE {kind.upper()} {filename}: {what} in {seconds:.2f} s ({'; '.join(parts)})"


def _tiers(stats: dict) -> str:
    """What computed the steps of a run that began before its C was compiled."""
    if stats.get("python_only"):
        return ", in Python (its C was compiling)"
    if "python_until" in stats:
        return f", in Python until T = {stats['python_until']:.6g} (C compiling), then C"
    return ""


def command_error(kind: CodeKind, exc: Exception) -> str:
    """Why a CODE command could not run, as its message begins: `CODE DYNAMICS: ...`."""
    text = str(exc)
    return text if text.startswith("CODE") else f"CODE {kind.upper()}: {text}"
