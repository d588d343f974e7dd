"""Results as data (issue 34, item 1): a run's output columns as CSV, a Matlab file and a
pandas DataFrame; a linearization's A, B, C, D as CSV and a Matlab file.  Values are
checked against Autolev's own tables (NAME.1, NAME.2) and the pendulum's closed form."""
import math

import numpy as np
import pytest
import scipy.io

import autolev
from autolev.cli import main
from autolev.engine.results import matlab_names
from helpers import EXAMPLES
from helpers.models import PENDULUM


def autolev_table(path):
    """The labels and rows of one of Autolev's output files."""
    lines = path.read_text().splitlines()
    labels = lines[2].lstrip("%").split()
    return labels, np.loadtxt(path, comments="%", ndmin=2)


@pytest.fixture(scope="module")
def pendulum_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("formats") / "o"
    assert main(["run", str(EXAMPLES / "double_pendulum.al"), "--out", str(out),
                 "--csv", "--mat", "-q"]) == 0
    return out


def test_the_csv_holds_every_output_column_of_autolevs_tables_once(pendulum_run):
    first_labels, first = autolev_table(pendulum_run / "double_pendulum.1")
    second_labels, second = autolev_table(pendulum_run / "double_pendulum.2")
    lines = (pendulum_run / "double_pendulum.csv").read_text().splitlines()
    header = lines[0].split(",")
    # T is in both files, and in the CSV once
    assert "T" in first_labels and "T" in second_labels and header.count("T") == 1
    assert header == list(dict.fromkeys(first_labels + second_labels))
    values = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    assert values.shape == (len(first), len(header))
    for labels, table in ((first_labels, first), (second_labels, second)):
        for j, label in enumerate(labels):
            # Autolev's tables print 7 significant digits; the CSV all 17
            assert np.allclose(values[:, header.index(label)], table[:, j], rtol=1e-6,
                               atol=1e-300), label


def test_the_mat_file_holds_the_same_columns_with_labels_and_units(pendulum_run):
    lines = (pendulum_run / "double_pendulum.csv").read_text().splitlines()
    header = lines[0].split(",")
    values = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    mat = scipy.io.loadmat(pendulum_run / "double_pendulum.mat")
    assert [str(x[0]) for x in mat["labels"].ravel()] == header
    units = [str(x[0]) for x in mat["units"].ravel()]
    assert units[header.index("T")] == "sec" and units[header.index("Q1")] == "deg"
    for j, label in enumerate(header):
        assert mat[label].shape == (len(values), 1)
        assert np.array_equal(mat[label][:, 0], values[:, j]), label


def test_a_result_is_a_data_frame_with_its_units():
    pd = pytest.importorskip("pandas", reason="pandas is an optional extra")
    result = autolev.load(EXAMPLES / "double_pendulum.al").simulate(tfinal=1)
    frame = result.to_frame()
    assert isinstance(frame, pd.DataFrame) and len(frame) == len(result.t)
    assert list(frame.columns) == [label for label, _, _ in result.columns()]
    # the output column, in the OUTPUT's unit (result["Q1"] is the state, in radians)
    assert np.array_equal(frame["Q1"].to_numpy(), result.outputs[0]["Q1"])
    assert np.allclose(np.radians(frame["Q1"].to_numpy()), result["Q1"], rtol=1e-14)
    assert frame.attrs["units"]["Q1"] == "deg"


def test_labels_become_distinct_matlab_names():
    names = matlab_names(["T", "dot(v_bhat_n>,", "2X", "Q1'", "Q1_", "units", "", "t"])
    assert names == ["T", "dot_v_bhat_n", "x2X", "Q1", "Q1_2", "units_2", "column", "t_2"]
    assert all(n[0].isalpha() and n.replace("_", "").isalnum() for n in names)
    long = matlab_names(["A" * 80, "A" * 70])
    assert all(len(n) <= 63 for n in long) and len(set(long)) == 2


def test_linearize_out_writes_a_b_c_d(tmp_path, capsys):
    model_file = tmp_path / "pendulum.al"
    model_file.write_text(PENDULUM)
    out = tmp_path / "out"
    assert main(["linearize", str(model_file), "--at", "Q=0.3", "--out", str(out)]) == 0
    # m L^2 u' = -m g L sin(q) + TQ, outputs Q, X = L cos q, U': by hand at q = 0.3
    g, L, m, q = 9.81, 2.0, 3.0, 0.3
    expected = {"A": [[0, 1], [-g / L * math.cos(q), 0]], "B": [[0], [1 / (m * L * L)]],
                "C": [[1, 0], [-L * math.sin(q), 0], [-g / L * math.cos(q), 0]],
                "D": [[0], [0], [1 / (m * L * L)]]}
    heads = {"A": "A,Q,U", "B": "B,TQ", "C": "C,Q,U", "D": "D,TQ"}
    for which, matrix in expected.items():
        lines = (out / f"pendulum-{which}.csv").read_text().splitlines()
        assert lines[0] == heads[which]
        numbers = [[float(x) for x in line.split(",")[1:]] for line in lines[1:]]
        assert np.allclose(numbers, matrix, rtol=1e-14, atol=1e-14), which
    mat = scipy.io.loadmat(out / "pendulum-linear.mat")
    for which, matrix in expected.items():
        assert np.allclose(mat[which], matrix, rtol=1e-14, atol=1e-14), which
    assert [str(x[0]) for x in mat["states"].ravel()] == ["Q", "U"]
    assert [str(x[0]) for x in mat["inputs"].ravel()] == ["TQ"]


def test_plot_draws_the_chosen_columns_against_the_runs_time(tmp_path, capsys,
                                                              monkeypatch):
    pytest.importorskip("matplotlib", reason="--plot needs the optional matplotlib")
    from autolev import plots
    drawn = []
    real = plots.figure
    monkeypatch.setattr(plots, "figure", lambda table, times=None:
                        drawn.append((table, times)) or real(table, times))
    out = tmp_path / "o"
    assert main(["run", str(EXAMPLES / "double_pendulum.al"), "--out", str(out),
                 "--tfinal", "0.5", "--plot", "q2,Q1", "-q"]) == 0
    assert sorted(p.name for p in out.glob("*.png")) == ["double_pendulum.plot.png"]
    (table, times), = drawn
    assert table.labels == ["Q2", "Q1"]             # as asked, from the first table
    labels, rows = autolev_table(out / "double_pendulum.1")
    # the file prints 7 significant digits
    assert np.allclose(times, rows[:, labels.index("T")], rtol=1e-6, atol=1e-12)
    assert np.allclose(table.data[:, 1], rows[:, labels.index("Q1")], rtol=1e-6)


def test_plot_of_a_column_no_run_writes_is_refused_before_the_run(tmp_path, capsys):
    pytest.importorskip("matplotlib", reason="without matplotlib --plot is refused first")
    out = tmp_path / "o"
    assert main(["run", str(EXAMPLES / "double_pendulum.al"), "--out", str(out),
                 "--plot", "Q1,Q9", "-q"]) == 2
    err = capsys.readouterr().err
    assert "--plot: no output column Q9; the runs write T, Q1, Q2" in err
    assert not out.exists()                         # nothing ran


def test_pictures_and_tables_of_an_earlier_run_do_not_linger(tmp_path, capsys):
    pytest.importorskip("matplotlib", reason="--plot needs the optional matplotlib")
    out = tmp_path / "o"
    model = str(EXAMPLES / "double_pendulum.al")
    assert main(["run", model, "--out", str(out), "--tfinal", "0.2", "--plot", "--csv",
                 "-q"]) == 0
    assert {p.name for p in out.glob("*.png")} == {"double_pendulum.1.png",
                                                   "double_pendulum.2.png"}
    (out / "notes.png").write_bytes(b"mine")        # not the run's: kept
    (out / "double_pendulum.mat").write_bytes(b"not written by autolev")
    assert main(["run", model, "--out", str(out), "--tfinal", "0.3", "-q"]) == 0
    left = {p.name for p in out.iterdir()}
    assert not {"double_pendulum.1.png", "double_pendulum.2.png",
                "double_pendulum.csv"} & left
    assert {"notes.png", "double_pendulum.mat", "double_pendulum.1"} <= left


def test_a_linearizations_csv_quotes_names_with_commas():
    import csv
    import io

    from autolev.engine.linear import Linearization
    lin = Linearization(A=np.array([[0.0, 1.0], [-2.0, -0.5]]), B=np.zeros((2, 0)),
                        C=np.array([[1.0, 0.0]]), D=np.zeros((1, 0)), states=["Q", "U"],
                        inputs=[], outputs=["X[1,2]"], point={}, rates=np.zeros(2),
                        accelerations=np.zeros(1))
    rows = list(csv.reader(io.StringIO(lin.matrix_csv("C"))))
    assert rows == [["C", "Q", "U"], ["X[1,2]", "1", "0"]]
    a = list(csv.reader(io.StringIO(lin.matrix_csv("A"))))
    assert [float(v) for v in a[2][1:]] == [-2.0, -0.5]
