"""Notebooks (issue 34, item 3): a Model, a Result and a Linearization show themselves
in Jupyter; a notebook using them runs under nbclient and renders with nbconvert."""
import importlib.util
import math

import pytest

import autolev
from helpers import EXAMPLES

PENDULUM = EXAMPLES / "double_pendulum.al"


def test_a_model_shows_what_it_declares_with_its_values():
    page = autolev.load(PENDULUM)._repr_html_()
    assert "<b>autolev model double_pendulum</b>" in page
    assert "G = 9.81 m/sec^2" in page and "Q1 = 30 deg, Q2 = 60 deg, U1 = 0 rad/sec" in page
    assert "P1 (mass M1), P2 (mass M2)" in page
    assert "DYNAMICS double_pendulum.c" in page


def test_text_from_the_model_reaches_the_page_escaped(tmp_path):
    path = tmp_path / "a<script>x.al"
    path.write_text("CONSTANTS K\nINPUT K = 2\n")
    page = autolev.load(path)._repr_html_()
    assert "<script>" not in page and "a&lt;script&gt;x" in page
    assert "K = 2" in page


def test_a_result_shows_its_rows_and_columns_and_a_linearization_its_eigenvalues():
    model = autolev.load(PENDULUM)
    page = model.simulate(TFINAL=0.5)._repr_html_()
    assert "CODE DYNAMICS double_pendulum" in page and "<td style='text-align:left'>51<" in page
    assert "Q1, Q2, U1, U2" in page
    if importlib.util.find_spec("matplotlib") is not None:
        assert "data:image/png;base64," in page
    else:
        assert "<th>Q1</th>" in page
    lin = model.linearize({"Q1": 0, "Q2": 0})
    page = lin._repr_html_()
    # at rest the hanging pendulum's modes are undamped: imaginary pairs, real part 0
    imaginary = sorted(abs(ev.imag) for ev in lin.eigenvalues())
    assert f"<td>{imaginary[-1]:.15g}</td>" in page.replace("<td>-", "<td>")
    assert "<th>damping ratio</th>" in page and math.isfinite(lin.zero_tolerance())


def test_a_models_motion_shows_inline_in_its_own_frame_and_saves(tmp_path):
    import html
    view = autolev.load(PENDULUM).animate(TFINAL=0.5)
    shown = view._repr_html_()
    assert shown.startswith('<iframe srcdoc="') and "<script" not in shown  # quoted whole
    assert html.unescape(shown.split('srcdoc="')[1].split('" width')[0]) == view.page
    assert "double_pendulum (double_pendulum)" in view.page and '"times":[0.0,' in view.page
    saved = view.save(tmp_path / "motion.html")
    assert saved.read_text() == view.page


@pytest.mark.skipif(importlib.util.find_spec("nbclient") is None or
                    importlib.util.find_spec("nbconvert") is None or
                    importlib.util.find_spec("ipykernel") is None,
                    reason="needs nbclient, nbconvert and ipykernel (pip install nbconvert "
                    "ipykernel), which autolev does not require")
def test_a_notebook_runs_and_renders_the_views(tmp_path):
    import nbformat
    from nbclient import NotebookClient
    from nbconvert import HTMLExporter
    cells = [f"import autolev\nmodel = autolev.load({str(PENDULUM)!r})\nmodel",
             "model.simulate(TFINAL=0.2)",
             "model.linearize({'Q1': 0, 'Q2': 0})",
             "model.animate(TFINAL=0.2)"]
    book = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    NotebookClient(book, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(tmp_path)}}).execute()
    shown = [output["data"]["text/html"] for cell in book.cells for output in cell.outputs
             if output.get("output_type") == "execute_result"]
    assert len(shown) == 4 and shown[3].startswith("<iframe srcdoc=")
    assert "autolev model double_pendulum" in shown[0]
    assert "autolev result" in shown[1] and "autolev linearization" in shown[2]
    page, _ = HTMLExporter().from_notebook_node(book)
    assert page.count("autolev model double_pendulum") == 1
    (tmp_path / "notebook.html").write_text(page)
