"""Parameter studies: one model linearized or simulated at many points, translated and
compiled once, as one table.

Where the points are evaluated:
- on this machine's cores (the default): the first point is evaluated here, which
  builds and compiles everything, then worker processes forked from this one (they
  inherit the model and its compiled code) take the rest in chunks -- or, when this
  process runs other threads, workers started afresh that get the model pickled;
- on any executor passed as `executor=` (a `concurrent.futures.Executor`, or a Dask
  `distributed.Client`, whose `submit` is the same): each task carries the model's
  translation, and each worker process rebuilds the model once and keeps it for the
  tasks that follow (a cluster's workers share no memory with this process).
"""
from __future__ import annotations

import collections
import hashlib
import itertools
import multiprocessing
import os
import pickle
import sys
import threading
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass

import numpy as np

from ..engine.errors import AutolevModelError
from .io import INTEGRATION_PARAMETERS
from ..engine.options import RunOptions
from ..engine.progress import Progress
from .numerics.run import run_command

STUDIES = ("linearize", "simulate")
# options a study passes on: Model.linearize's and Model.simulate's keywords
_OPTIONS = {
    "linearize": {"inputs", "code", "backend", "infile", "missing_values", "overrides",
                  "constraints", "dependent", "locked", "specified"},
    "simulate": {"method", "backend", "infile", "specified", "compiled", "constraints",
                 "quirks", "missing_values", "code"},
}
# in an executor's worker: {digest of a model's source: model}, per thread (a model's
# numeric state is not shared between threads)
_WORKER_MODELS = threading.local()
# what forked workers inherit: {a sweep's token: its model}, one entry per sweep under
# way (sweeps in several threads each find their own)
_FORKED: dict = {}
# evaluated here, without workers, when the points left would take less than this
LOCAL_SECONDS = 2.0
# a progress line's words
SWEEP = "{what}: {position}/{end} points"


def grid(**axes) -> list[dict]:
    """Every combination of the values given for each name (a full factorial), as the
    list of points `sweep` takes: grid(V=[3, 4, 5], M_B=[80, 85]) has 6 points."""
    names = list(axes)
    values = [list(np.atleast_1d(np.asarray(v, dtype=float))) for v in axes.values()]
    return [dict(zip(names, (float(x) for x in combo)))
            for combo in itertools.product(*values)]


@dataclass
class SweepTable:
    """A study's results: one row per point, columns by name (NumPy arrays)."""

    columns: dict

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]

    def __len__(self) -> int:
        return len(next(iter(self.columns.values()))) if self.columns else 0

    @property
    def names(self) -> list:
        return list(self.columns)

    def to_pandas(self):
        import pandas
        return pandas.DataFrame(self.columns)

    def to_csv(self) -> str:
        """The table as CSV text (numbers to full precision)."""
        lines = [",".join(self.columns)]
        for k in range(len(self)):
            lines.append(",".join(_cell(col[k]) for col in self.columns.values()))
        return "\n".join(lines) + "\n"


def sweep(model, points, what: str = "linearize", *, executor=None,
          workers: int | None = None, collect=None, progress=None, as_frame=None,
          chunk_size: int | None = None, **options):
    """Evaluate `model` at every point of `points` and return one table.

    `points`: a list of {name: value}, or {name: sequence} (the k-th point takes the
    k-th value of each; `grid` makes a full factorial).  `what="linearize"`: each point
    is an operating point (SI units and radians, as `Model.linearize` takes it); the
    columns are the point's values, then re_k and im_k for each eigenvalue (in
    `eigenvalues()` order) and `steady`.  `what="simulate"`: each point gives input
    values in the quantities' own units (TFINAL too, as `Model.simulate` takes them);
    the columns are the point's values, then the last row's states and OUTPUT columns.
    `collect(linearization or result) -> {column: number}` chooses other columns (with
    an executor it must be a function pickle can send, defined at a module's top level).
    A point the model refuses (AutolevModelError) gets NaN and its message in the
    `failure` column.  `options`: passed on to linearize or simulate.

    `executor`: None runs on the local cores (`workers` processes, default all; 1:
    here, in order); else any object with `submit(fn, *args)` (a concurrent.futures
    Executor, a Dask Client).  The local workers are forked from this process when it
    runs no other thread; beside other threads (a sweep from a thread, Jupyter's, a
    GUI's) they start afresh and import the script that started the sweep, which then
    needs Python's `if __name__ == "__main__":` guard around what it runs, as every
    program of separate processes does.  `progress`: a stream for progress lines (default: stderr
    when the study takes more than a few seconds; False: none).  `as_frame`: a pandas
    DataFrame (default when pandas is installed) or a SweepTable (False)."""
    if what not in STUDIES:
        raise ValueError(f"what: one of {', '.join(STUDIES)}, not {what!r}")
    unknown = set(options) - _OPTIONS[what]
    if unknown:
        raise TypeError(f"sweep(what={what!r}) takes no option {', '.join(sorted(unknown))}")
    rows = Points.of(points)
    _check_names(model, rows.names, what)
    if what == "linearize":         # every point's Jacobians of one tier, chosen by the size
        options = dict(options, sweep_size=len(rows))
    stream = None if progress is False else (
        sys.stderr if progress is None or progress is True else progress)
    # a line per 5 % or 10 s, timed from the first point (which builds and compiles)
    report = Progress(stream, "sweep", 0, len(rows), says=SWEEP, wait=3.0, every=10.0,
                      in_place=False, steps=20, from_first=True)
    results = Results(len(rows))
    if len(rows) and executor is not None:
        _on_executor(model, executor, what, rows, options, collect, chunk_size, report,
                     results)
    elif len(rows):
        _on_local_cores(model, workers, what, rows, options, collect, chunk_size, report,
                        results)
    report.done()
    return _table(rows, results, as_frame)


# -- evaluating one point ------------------------------------------------------------------
def _evaluate(model, what: str, point: dict, options: dict, collect) -> dict:
    try:
        if what == "linearize":
            found = model.linearize(point, **options)
        else:
            opts = dict(options)
            command = model.command_to_run(opts.pop("code", None))
            # the rows only when `collect` may want them: memory stays flat otherwise
            found = run_command(model.snapshot_for(command), None, RunOptions(
                overrides=point, keep_rows=collect is not None, **opts))
            if found.failure:
                return {"failure": found.failure, **(collect or _last_row)(found)}
    except AutolevModelError as exc:
        return {"failure": str(exc)}
    return dict((collect or _default_columns[what])(found))


def _eigenvalue_columns(lin) -> dict:
    columns = {}
    for k, ev in enumerate(lin.eigenvalues(), 1):
        columns[f"re{k}"] = float(ev.real)
        columns[f"im{k}"] = float(ev.imag)
    columns["steady"] = bool(lin.steady)
    return columns


def eigenvalues_and_modes(lin) -> dict:
    """A `collect` for what="linearize" that keeps the modes for `follow_modes`: the
    eigenvalue columns (re_k, im_k, steady) and each eigenvector's components
    (vre_k_j, vim_k_j)."""
    columns = _eigenvalue_columns(lin)
    _, vectors = lin.modes()
    for k in range(vectors.shape[1]):
        for j in range(vectors.shape[0]):
            columns[f"vre{k + 1}_{j + 1}"] = float(vectors[j, k].real)
            columns[f"vim{k + 1}_{j + 1}"] = float(vectors[j, k].imag)
    return columns


def follow_modes(eigenvalues: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """Each row of `eigenvalues` (points x n) reordered so that a column follows one
    mode along the points: row k's modes are matched to row k-1's by the overlap of
    their eigenvectors (`vectors`: points x n x n, one mode per column), the distance
    of the eigenvalues breaking ties (a conjugate pair's vectors overlap).  Returns the
    permutation of each row (points x n)."""
    from scipy.optimize import linear_sum_assignment
    count, n = eigenvalues.shape
    order = np.tile(np.arange(n), (count, 1))
    for k in range(1, count):
        before = vectors[k - 1][:, order[k - 1]]
        values_before = eigenvalues[k - 1, order[k - 1]]
        now, values_now = vectors[k], eigenvalues[k]
        if not (np.all(np.isfinite(before)) and np.all(np.isfinite(now))):
            continue                     # a failed point: keep the sorted order
        norms = np.linalg.norm(before, axis=0)[:, None] * np.linalg.norm(now, axis=0)[None]
        overlap = np.abs(before.conj().T @ now) / np.where(norms > 0, norms, 1.0)
        distance = np.abs(values_before[:, None] - values_now[None]) / (
            np.abs(values_before[:, None]) + np.abs(values_now[None]) + 1.0)
        _, matched = linear_sum_assignment(1.0 - overlap + distance)
        order[k] = matched
    return order


def _last_row(result) -> dict:
    columns = {}
    if len(result.states):
        columns.update(zip(result.state_names, (float(v) for v in result.states[-1])))
    for table in result.outputs:
        if len(table.data):
            for label, value in zip(table.labels, table.data[-1]):
                columns.setdefault(label, float(value))
    return columns


_default_columns = {"linearize": _eigenvalue_columns, "simulate": _last_row}


def _evaluate_chunk(model, what, chunk, options, collect) -> list:
    return [_evaluate(model, what, point, options, collect) for point in chunk]


# -- where the points are evaluated --------------------------------------------------------
def _on_local_cores(model, workers, what, rows, options, collect, chunk_size, report,
                    results):
    """Here until the first point (which builds and compiles) and some more have shown
    what a point costs; the rest in forked workers when they would take more than a
    couple of seconds here."""
    results.put(0, _evaluate(model, what, rows.point(0), options, collect))
    report.advance(1)
    done = 1
    count = _worker_count(workers, len(rows) - 1)
    start = time.perf_counter()
    while done < len(rows):
        per_point = (time.perf_counter() - start) / max(done - 1, 1)
        if count > 1 and done > 1 and per_point * (len(rows) - done) > LOCAL_SECONDS:
            break
        results.put(done, _evaluate(model, what, rows.point(done), options, collect))
        report.advance(1)
        done += 1
    if done == len(rows):
        return
    size = chunk_size or max(1, min(64, (len(rows) - done) // (4 * count)))
    spans = _spans(done, len(rows), size)
    chunks = (rows.points(lo, hi) for lo, hi in spans)
    for (lo, hi), chunk_results in zip(spans, _in_workers(model, count, what, chunks,
                                                          options, collect)):
        results.put_all(lo, chunk_results)
        report.advance(hi - lo)


def _in_workers(model, count: int, what, chunks, options, collect):
    """The chunks' results, in order, from `count` worker processes: forked from this
    one (inheriting the model and its compiled code) when it runs no other thread;
    else started afresh, the model sent pickled (a fork beside other threads -- Jupyter's,
    a GUI's, a Dask client's, another sweep's -- can deadlock in their locks)."""
    if threading.active_count() == 1 and "fork" in multiprocessing.get_all_start_methods():
        token = f"{os.getpid()}-{next(_SWEEPS)}"
        _FORKED[token] = model
        try:
            with ProcessPoolExecutor(count, mp_context=multiprocessing.get_context("fork")) \
                    as pool:
                yield from _in_order(pool, 4 * count, (
                    (_forked_chunk, token, what, chunk, options, collect) for chunk in chunks))
        finally:
            _FORKED.pop(token, None)
        return
    payload = _pickled(model)
    digest = hashlib.sha256(payload).hexdigest()
    method = "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() \
        else "spawn"
    with ProcessPoolExecutor(count, mp_context=multiprocessing.get_context(method)) as pool:
        yield from _in_order(pool, 4 * count, (
            (_pickled_chunk, payload, digest, what, chunk, options, collect)
            for chunk in chunks))


def _in_order(pool, window: int, tasks):
    """The results of `tasks` ((function, *arguments) each) in order, at most `window`
    submitted and not yet taken: the points and results of a long study are never all
    in memory at once."""
    pending = collections.deque()
    for task in tasks:
        pending.append(pool.submit(*task))
        if len(pending) >= window:
            yield pending.popleft().result()
    while pending:
        yield pending.popleft().result()


_SWEEPS = itertools.count()
# sympy expressions nest deeply: pickling walks them recursively
_RECURSION = 20000


def _pickled(model) -> bytes:
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, _RECURSION))
    try:
        return pickle.dumps(model, protocol=pickle.HIGHEST_PROTOCOL)
    finally:
        sys.setrecursionlimit(limit)


def _forked_chunk(token: str, what, chunk, options, collect) -> list:
    return _evaluate_chunk(_FORKED[token], what, chunk, options, collect)


def _pickled_chunk(payload: bytes, digest: str, what, chunk, options, collect) -> list:
    """A chunk in a worker started afresh: the model unpickled once per worker."""
    kept = getattr(_WORKER_MODELS, "pickled", None)
    if kept is None or kept[0] != digest:
        limit = sys.getrecursionlimit()
        sys.setrecursionlimit(max(limit, _RECURSION))
        try:
            kept = _WORKER_MODELS.pickled = (digest, pickle.loads(payload))
        finally:
            sys.setrecursionlimit(limit)
    return _evaluate_chunk(kept[1], what, chunk, options, collect)


def _on_executor(model, executor, what, rows, options, collect, chunk_size, report,
                 results):
    source = model.loaded.source if model.loaded is not None else None
    if source is None:
        raise AutolevModelError("this model was not loaded from a file (autolev.load): "
                                "an executor's workers have nothing to rebuild it from")
    if model.revision() != source.state:
        raise AutolevModelError(
            "the model was changed after it was loaded; an executor's workers rebuild it "
            "from its file's translation and would not see the change (give the values "
            "as the study's points or options instead)")
    payload = pickle.dumps(source)
    digest = hashlib.sha256(payload).hexdigest()
    spans = _spans(0, len(rows), chunk_size or max(1, min(64, len(rows) // 16 or 1)))
    tasks = ((_remote_chunk, payload, digest, what, rows.points(lo, hi), options, collect)
             for lo, hi in spans)
    # a cluster's workers are many: keep a good number of tasks queued for them
    for (lo, hi), chunk_results in zip(spans, _in_order(executor, 256, tasks)):
        results.put_all(lo, chunk_results)
        report.advance(hi - lo)


def _remote_chunk(payload: bytes, digest: str, what, chunk, options, collect) -> list:
    """A task on an executor's worker: the model from its source, rebuilt once per
    worker process (the digest is checked: the payload is what was sent)."""
    kept = getattr(_WORKER_MODELS, "kept", None)
    if kept is not None and kept[0] == digest:
        model = kept[1]
    else:
        if hashlib.sha256(payload).hexdigest() != digest:
            raise RuntimeError("a sweep task's model does not match its digest")
        model = pickle.loads(payload).load()
        _WORKER_MODELS.kept = (digest, model)       # one model per worker thread
    return _evaluate_chunk(model, what, chunk, options, collect)


def _worker_count(workers, n_points: int) -> int:
    if workers is None:
        try:
            workers = len(os.sched_getaffinity(0))
        except AttributeError:          # not on Linux
            workers = os.cpu_count() or 1
    if workers < 1:
        raise ValueError(f"workers: at least 1, not {workers}")
    return min(workers, n_points)


def _spans(lo: int, hi: int, size: int) -> list:
    return [(k, min(k + size, hi)) for k in range(lo, hi, size)]


# -- the points and the table --------------------------------------------------------------
@dataclass
class Points:
    """A study's points as one array (a row per point, a column per name) and which
    names each point gives: 8 bytes a value, where a dict per point took some 200."""

    names: list
    values: np.ndarray
    given: np.ndarray | None = None      # None: every point gives every name

    @classmethod
    def of(cls, points) -> "Points":
        if isinstance(points, dict):
            lengths = {len(np.atleast_1d(v)) for v in points.values()}
            if len(lengths) > 1:
                raise ValueError("points: every name needs as many values (or use grid() "
                                 "for every combination)")
            count = lengths.pop() if lengths else 0
            values = np.empty((count, len(points)))
            for k, v in enumerate(points.values()):
                values[:, k] = np.atleast_1d(np.asarray(v, dtype=float))
            return cls([str(n) for n in points], values)
        rows = []
        for point in points:
            if not isinstance(point, dict):
                raise TypeError(f"points: each point is a {{name: value}} dict, not "
                                f"{point!r}")
            rows.append({str(k): float(v) for k, v in point.items()})
        names = list(dict.fromkeys(n for row in rows for n in row))
        values = np.full((len(rows), len(names)), np.nan)
        given = np.zeros((len(rows), len(names)), dtype=bool)
        where = {n: k for k, n in enumerate(names)}
        for j, row in enumerate(rows):
            for n, v in row.items():
                values[j, where[n]] = v
                given[j, where[n]] = True
        return cls(names, values, None if given.all() else given)

    def __len__(self) -> int:
        return len(self.values)

    def point(self, j: int) -> dict:
        row = self.values[j]
        return {n: float(row[k]) for k, n in enumerate(self.names)
                if self.given is None or self.given[j, k]}

    def points(self, lo: int, hi: int) -> list:
        return [self.point(j) for j in range(lo, hi)]


class Results:
    """Each point's columns, put into one array per column as they come."""

    def __init__(self, count: int):
        self.count = count
        self.columns: dict = {}
        self.booleans: dict = {}         # name -> how many of its values were booleans
        self.failures: dict = {}         # point -> why the model refused it

    def put(self, j: int, row: dict) -> None:
        for name, value in row.items():
            if name == "failure":
                self.failures[j] = value
                continue
            column = self.columns.get(name)
            if column is None:
                column = self.columns[name] = np.full(self.count, np.nan)
                self.booleans[name] = 0
            column[j] = value
            self.booleans[name] += isinstance(value, (bool, np.bool_))

    def put_all(self, lo: int, rows: list) -> None:
        for j, row in enumerate(rows, lo):
            self.put(j, row)

    def column(self, name: str) -> np.ndarray:
        """A column; of booleans when every point gave a boolean."""
        column = self.columns[name]
        return column.astype(bool) if self.booleans[name] == self.count else column


def _check_names(model, names: list, what: str) -> None:
    unknown = sorted(n for n in names if not model.names_a_quantity(n)
                     and not (what == "simulate" and n.upper() in INTEGRATION_PARAMETERS))
    if unknown:
        raise AutolevModelError("points: the model has no quantity named "
                                + ", ".join(unknown))


def _table(rows: Points, results: Results, as_frame):
    columns = {}
    for k, name in enumerate(rows.names):
        column = rows.values[:, k].copy()
        if rows.given is not None:
            column[~rows.given[:, k]] = np.nan
        if name in results.columns:     # where a collect gives a point's own name, it wins
            found = results.columns[name]
            column = np.where(np.isnan(found), column, found)
        columns[name] = column
    for name in results.columns:
        if name not in columns:
            columns[name] = results.column(name)
    if results.failures:
        failure = np.full(len(rows), "", dtype=object)
        for j, why in results.failures.items():
            failure[j] = why
        columns["failure"] = failure
    table = SweepTable(columns)
    if as_frame is False:
        return table
    try:
        import pandas  # noqa: F401
    except ImportError:
        if as_frame:
            raise ImportError("as_frame=True needs pandas (pip install pandas)") from None
        return table
    return table.to_pandas()


def _cell(value) -> str:
    if isinstance(value, (float, np.floating)):
        return f"{value:.17g}"
    text = str(value)
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n') else text
