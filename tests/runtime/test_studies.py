"""Model.sweep: parameter studies of linearizations and simulations, on one core, on
forked workers, and on executors (a process pool; a Dask LocalCluster where Dask is
installed).  Values are checked against the pendulum's closed forms."""
import math
import warnings
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
import multiprocessing

import numpy as np
import pytest

import autolev
from autolev.runtime import studies
from autolev.engine.errors import AutolevModelError
from helpers.models import PENDULUM


@pytest.fixture(scope="module")
def pendulum(tmp_path_factory):
    path = tmp_path_factory.mktemp("sweep") / "pendulum.al"
    path.write_text(PENDULUM)
    return autolev.load(path)


def swing_rates(lengths) -> np.ndarray:
    return np.sqrt(9.81 / np.asarray(lengths, dtype=float))     # hanging: +-i sqrt(g/L)


def test_grid_is_every_combination():
    points = autolev.grid(A=[1, 2, 3], B=[10, 20])
    assert len(points) == 6
    assert points[0] == {"A": 1.0, "B": 10.0} and points[-1] == {"A": 3.0, "B": 20.0}
    assert {(p["A"], p["B"]) for p in points} == {(a, b) for a in (1, 2, 3) for b in (10, 20)}


def test_a_linearization_sweep_gives_the_closed_form(pendulum):
    lengths = [0.5, 1.0, 2.0, 4.0]
    table = pendulum.sweep({"L": lengths, "Q": [0.0] * 4}, as_frame=False, workers=1)
    assert table.names == ["L", "Q", "re1", "im1", "re2", "im2", "steady"]
    assert np.array_equal(table["L"], lengths)
    assert np.allclose(table["im1"], -swing_rates(lengths), rtol=1e-14)
    assert np.allclose(table["im2"], swing_rates(lengths), rtol=1e-14)
    assert np.all(table["re1"] == 0) and table["steady"].dtype == bool
    assert table["steady"].all()


def test_forked_workers_give_the_same_numbers(pendulum, monkeypatch):
    if "fork" not in multiprocessing.get_all_start_methods():
        pytest.skip("no fork on this platform: local sweeps run in one process")
    points = autolev.grid(L=np.linspace(0.5, 3, 25), Q=[0.0, 0.2])
    here = pendulum.sweep(points, as_frame=False, workers=1)
    monkeypatch.setattr(studies, "LOCAL_SECONDS", 0.0)      # fork whatever the cost
    forked = pendulum.sweep(points, as_frame=False, workers=2, chunk_size=4)
    assert forked.names == here.names
    for name in here.names:
        assert np.array_equal(forked[name], here[name]), name
    # tilted, the pendulum is not at rest: the column says so
    assert not forked["steady"][1] and forked["steady"][0]


def test_a_refused_point_gets_its_message_and_the_rest_go_on(pendulum):
    table = pendulum.sweep([{"L": 2.0, "M": 3.0, "Q": 0}, {"L": 2.0, "M": 0.0, "Q": 0}],
                           as_frame=False, workers=1)
    assert table["failure"][0] == "" and "singular" in table["failure"][1]
    assert np.isnan(table["im2"][1]) and table["im2"][0] == pytest.approx(
        math.sqrt(9.81 / 2), rel=1e-14)


def test_points_that_give_different_names_keep_each_its_own():
    points = studies.Points.of([{"L": 2.0}, {"M": 3.0, "L": 1.0}, {"Q": 0.5}])
    assert points.names == ["L", "M", "Q"] and len(points) == 3
    # a name a point does not give is not invented for it (NaN in the table, absent here)
    assert points.point(0) == {"L": 2.0}
    assert points.point(1) == {"L": 1.0, "M": 3.0}
    assert points.point(2) == {"Q": 0.5}
    assert np.isnan(points.values[0, 1]) and points.values[1, 1] == 3.0
    whole = studies.Points.of({"L": [1, 2], "Q": [0, 0.1]})
    assert whole.given is None and whole.point(1) == {"L": 2.0, "Q": 0.1}


def test_a_point_without_a_name_gives_nan_in_its_column(pendulum):
    table = pendulum.sweep([{"L": 2.0, "Q": 0.0}, {"Q": 0.0}], as_frame=False, workers=1)
    assert table["L"][0] == 2.0 and np.isnan(table["L"][1])
    # the second point runs with the model's own L (INPUT L = 2)
    assert table["im2"][1] == pytest.approx(math.sqrt(9.81 / 2.0), rel=1e-12)


def test_bad_studies_are_refused(pendulum):
    with pytest.raises(AutolevModelError, match="no quantity named NOPE"):
        pendulum.sweep([{"NOPE": 1.0}])
    with pytest.raises(ValueError, match="what: one of linearize, simulate"):
        pendulum.sweep([{"L": 1.0}], what="optimize")
    with pytest.raises(TypeError, match="no option method"):
        pendulum.sweep([{"L": 1.0}], method="rk45")
    with pytest.raises(ValueError, match="as many values"):
        pendulum.sweep({"L": [1, 2], "M": [1]})


def test_a_simulation_sweep_keeps_the_last_row(pendulum):
    # without gravity the pendulum turns at its initial rate: Q(T) = Q0 + U0 T
    table = pendulum.sweep({"U": [0.5, 1.5], "G": [0, 0], "TFINAL": [2, 3]},
                           what="simulate", as_frame=False, workers=1)
    q0 = math.radians(10)
    assert np.allclose(table["Q"], [q0 + 0.5 * 2, q0 + 1.5 * 3], rtol=1e-12)
    assert np.allclose(table["U"], [0.5, 1.5], rtol=1e-14)

    def final_time(result):
        return {"t_end": result.t[-1], "rows": len(result.t)}
    table = pendulum.sweep({"TFINAL": [1, 2]}, what="simulate", collect=final_time,
                           as_frame=False, workers=1)
    assert table["t_end"] == pytest.approx([1.0, 2.0], abs=1e-12)
    assert table["rows"][1] > table["rows"][0]


def test_an_executor_rebuilds_the_model_from_its_translation(pendulum):
    points = {"L": [0.5, 1.0, 2.0], "Q": [0.0, 0.0, 0.0]}
    here = pendulum.sweep(points, as_frame=False, workers=1)
    context = multiprocessing.get_context("spawn")       # shares nothing with this one
    with ProcessPoolExecutor(2, mp_context=context) as pool:
        there = pendulum.sweep(points, executor=pool, as_frame=False, chunk_size=1)
    with ThreadPoolExecutor(2) as pool:
        threads = pendulum.sweep(points, executor=pool, as_frame=False, chunk_size=1)
    for name in here.names:
        assert np.array_equal(there[name], here[name]), name
        assert np.array_equal(threads[name], here[name]), name


def test_an_executor_refuses_a_model_changed_after_loading(tmp_path):
    path = tmp_path / "pendulum.al"
    path.write_text(PENDULUM)
    model = autolev.load(path)
    model.input(model.quantity("L"), 3)
    with ThreadPoolExecutor(1) as pool, pytest.raises(AutolevModelError,
                                                      match="changed after it was loaded"):
        model.sweep([{"Q": 0.0}], executor=pool)


def test_a_dask_cluster_gives_the_same_numbers(pendulum):
    distributed = pytest.importorskip(
        "distributed", reason="Dask is an optional extra (pip install 'autolev[cluster]')")
    points = autolev.grid(L=[0.5, 1.0, 2.0, 4.0], Q=[0.0, 0.1])
    here = pendulum.sweep(points, as_frame=False, workers=1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                      dashboard_address=None) as cluster, \
                distributed.Client(cluster) as client:
            there = pendulum.sweep(points, executor=client, as_frame=False, chunk_size=2)
    for name in here.names:
        assert np.array_equal(there[name], here[name]), name


def test_a_data_frame_when_pandas_is_installed(pendulum):
    pandas = pytest.importorskip("pandas", reason="pandas is optional")
    frame = pendulum.sweep({"L": [1.0, 2.0], "Q": [0, 0]}, workers=1)
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame["L"]) == [1.0, 2.0]
    assert frame["im2"].iloc[1] == pytest.approx(math.sqrt(9.81 / 2), rel=1e-14)


def test_progress_lines_for_a_long_study(pendulum, monkeypatch):
    import io
    from autolev.engine import progress
    clock = iter(range(0, 1000, 2))
    monkeypatch.setattr(progress.time, "monotonic", lambda: float(next(clock)))
    stream = io.StringIO()
    pendulum.sweep({"L": np.linspace(1, 2, 10)}, workers=1, as_frame=False, progress=stream)
    lines = stream.getvalue().splitlines()
    assert lines[0].startswith("  sweep: ") and lines[-1].startswith("  sweep: 10/10 points")
    assert "s left" in lines[0]


def test_sweeps_in_two_threads_each_get_their_own_model(tmp_path, monkeypatch):
    # earth and moon pendulums swept at once: each table from its own model, though
    # with other threads running the workers are started afresh, not forked
    monkeypatch.setattr(studies, "LOCAL_SECONDS", 0.0)
    import threading
    models = {}
    for name, g in (("earth", 9.81), ("moon", 1.62)):
        path = tmp_path / f"{name}.al"
        path.write_text(PENDULUM.replace("G = 9.81", f"G = {g}"))
        models[name] = (autolev.load(path), g)
    assert "G = 9.81" in PENDULUM
    lengths = np.linspace(0.5, 3, 24)
    tables = {}

    def sweep(name):
        model, _ = models[name]
        tables[name] = model.sweep({"L": lengths, "Q": [0.0] * len(lengths)},
                                   as_frame=False, workers=2, chunk_size=3, progress=False)
    threads = [threading.Thread(target=sweep, args=(n,)) for n in models]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for name, (_, g) in models.items():
        assert np.allclose(tables[name]["im2"], np.sqrt(g / lengths), rtol=1e-12), name
