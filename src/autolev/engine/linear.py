"""A linearization's answer (A, B, C, D at a point, with names): what
`autolev linearize` reports and keeps, without sympy or scipy (a kept linearization
is read back with this alone)."""
from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

import numpy as np

from .results import mat_file


@dataclass
class Linearization:
    """A, B, C, D at one operating point, with the names of their rows and columns;
    values in SI units and radians."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    states: list
    inputs: list
    outputs: list
    point: dict             # every constant, state and input value used
    rates: np.ndarray       # x' at the point
    accelerations: np.ndarray   # the rates of the speeds there (Kane's or SOLVE's)
    dependent: list = field(default_factory=list)   # coordinates the constraints fixed
    locked: list = field(default_factory=list)      # coordinates held (with their speeds)

    def eigenvalues(self) -> np.ndarray:
        """The eigenvalues of A, by real part, then imaginary part."""
        return self.modes()[0]

    def matrix_csv(self, which: str) -> str:
        """A, B, C or D as CSV: a header naming the columns, each row led by its name."""
        matrix = getattr(self, which)
        rows = self.outputs if which in "CD" else self.states
        columns = self.inputs if which in "BD" else self.states
        text = io.StringIO()
        writer = csv.writer(text, lineterminator="\n")    # quotes an output named X[1,2]
        writer.writerow([which] + list(columns))
        writer.writerows([name] + [f"{x:.17g}" for x in row] for name, row in zip(rows, matrix))
        return text.getvalue()

    def mat_bytes(self) -> bytes:
        """A, B, C, D with the names of states, inputs and outputs and the operating
        point, as a Matlab .mat file (scipy.io)."""
        contents = {"A": self.A, "B": self.B, "C": self.C, "D": self.D}
        for key in ("states", "inputs", "outputs"):
            contents[key] = np.array(list(getattr(self, key)), dtype=object)
        contents["point_names"] = np.array([str(n) for n in self.point], dtype=object)
        contents["point_values"] = np.array([float(v) for v in self.point.values()])
        return mat_file(contents)

    def _repr_html_(self) -> str:
        """Jupyter's view: the state, the inputs and the eigenvalue table."""
        from .notebook import linearization_html
        return linearization_html(self)

    def zero_tolerance(self) -> float:
        """Parts of eigenvalues smaller than this are shown as 0: roundoff, not motion (a
        double zero, an ignorable coordinate and its speed, splits into about plus and
        minus the square root of eps times the norm of A); sqrt(eps) times A's 1-norm,
        at least sqrt(eps)."""
        return float(np.sqrt(np.finfo(float).eps) * max(1.0, np.linalg.norm(self.A, 1)))

    def eigenvalue_table(self) -> str:
        """The eigenvalues as CSV: real part, imaginary part, and for a complex pair the
        frequency (Hz) and damping ratio; parts within `zero_tolerance()` of 0 shown as 0,
        and the zero eigenvalues' notes (`zero_notes()`)."""
        tol = self.zero_tolerance()
        lines = ["real,imaginary,frequency_hz,damping_ratio,note"]
        notes = iter(self.zero_notes())
        for ev in self.eigenvalues():
            ev = complex(ev.real if abs(ev.real) >= tol else 0.0,
                         ev.imag if abs(ev.imag) >= tol else 0.0)
            mag = abs(ev)
            freq = f"{abs(ev.imag) / (2 * np.pi):.12g}" if ev.imag != 0 else ""
            zeta = f"{0.0 - ev.real / mag:.12g}" if ev.imag != 0 and mag > 0 else ""
            note = next(notes, "zero") if ev == 0 else ""
            lines.append(f"{ev.real:.15g},{ev.imag:.15g},{freq},{zeta},{note}")
        return "\n".join(lines) + "\n"

    def zero_notes(self) -> list:
        """What the zero eigenvalues are, one note each as far as A shows it: a state
        nothing depends on (its column of A is zero: an ignorable coordinate) and a state
        whose rate depends on nothing (its row is zero: constant), each named once, in the
        states' order.  A zero eigenvalue is repeated (an ignorable coordinate and its
        speed make a double zero), so which note goes with which copy is a convention."""
        tol = self.zero_tolerance()
        ignorable = [j for j in range(len(self.states)) if np.all(np.abs(self.A[:, j]) <= tol)]
        constant = [j for j in range(len(self.states)) if j not in ignorable
                    and np.all(np.abs(self.A[j, :]) <= tol)]
        count = int(np.sum(np.abs(self.eigenvalues()) < tol))
        notes = [f"{self.states[j]} is ignorable (nothing depends on it)" for j in ignorable]
        notes += [f"{self.states[j]} is constant (its rate depends on nothing)"
                  for j in constant]
        return notes[:count]

    def modes(self) -> tuple[np.ndarray, np.ndarray]:
        """(eigenvalues, eigenvectors as columns, each of unit norm), in the order of
        `eigenvalues`."""
        values, vectors = np.linalg.eig(self.A)
        order = np.lexsort((values.imag, values.real))
        return values[order], vectors[:, order]

    @property
    def steady(self) -> bool:
        """Whether the point is an equilibrium or a steady motion: the accelerations
        vanish (coordinates may move at constant rates, a bicycle's wheels turning)."""
        scale = max(1.0, float(np.max(np.abs(self.rates), initial=0.0)))
        return bool(np.all(np.abs(self.accelerations) <= 1e-9 * scale))
