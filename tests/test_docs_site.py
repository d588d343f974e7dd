"""The documentation site (issue 34, item 7): it builds with Sphinx, warnings as errors,
and its tutorials run as a reader would run them, each command's shown output what it
prints."""
import importlib.util
import shutil
import subprocess
import sys

import pytest

from helpers import ROOT
from helpers.markdown import run_page

DOCS = ROOT / "docs"


@pytest.mark.skipif(importlib.util.find_spec("sphinx") is None or
                    importlib.util.find_spec("myst_parser") is None,
                    reason="needs sphinx and myst-parser (pip install -e '.[test]' has them)")
def test_the_site_builds_without_a_warning(tmp_path):
    done = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q",
                           "-b", "html", str(DOCS), str(tmp_path / "html")],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    front = (tmp_path / "html" / "index.html").read_text()
    for page in ("tutorials/migrating.html", "tutorials/toolchain.html",
                 "tutorials/trajectory.html", "api.html",
                 "language.html", "architecture.html"):
        assert page in front, page
    api = (tmp_path / "html" / "api.html").read_text()
    assert "autolev.runtime.model.Model.simulate" in api       # read from the docstrings


def test_the_tutorials_run_in_order(tmp_path, monkeypatch):
    ran = run_page(DOCS / "tutorials" / "migrating.md", tmp_path, monkeypatch)
    assert ran["console"] >= 4 and ran["python"] >= 3 and ran["sh"] >= 2
    if shutil.which("cc") is None:
        pytest.skip("the toolchain tutorial compiles a C program: no cc here")
    ran = run_page(DOCS / "tutorials" / "toolchain.md", tmp_path, monkeypatch)
    assert ran["console"] == 1 and ran["python"] == 1 and ran["sh"] == 1


def test_the_trajectory_tutorial_solves_the_swing_up(tmp_path, monkeypatch):
    pytest.importorskip("casadi", reason="the tutorial hands the model to CasADi (an extra)")
    ran = run_page(DOCS / "tutorials" / "trajectory.md", tmp_path, monkeypatch)
    assert ran["python"] == 4
