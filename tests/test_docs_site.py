"""The documentation site (issue 34, item 7): it builds with Sphinx, warnings as errors,
and its tutorials run as a reader would run them, each command's shown output what it
prints."""
import ctypes
import importlib.util
import shutil
import subprocess
import sys

import numpy as np
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
                 "tutorials/trajectory.html", "tutorials/gait.html", "api.html",
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


# the parameters gait2de_al.c reads (par->NAME), as its own header declared them
GAIT2DE_PARAMETERS = ("TrunkMass", "TrunkInertia", "TrunkCMy", "ThighMass", "ThighInertia",
                      "ThighCMy", "ThighLen", "ShankMass", "ShankInertia", "ShankCMy",
                      "ShankLen", "FootMass", "FootInertia", "FootCMx", "FootCMy", "ContactY",
                      "ContactHeelX", "ContactToeX", "ContactStiff", "ContactDamp",
                      "ContactV0", "ContactFric")


def autolevs_gait2de(source, folder):
    """Autolev's own program of gait2de (gait2de_al.c, gait2d's post-processing of what
    Autolev wrote), compiled: (parameters, q, q', mom) -> q''."""
    header = "".join(["#define NDOF 9\n#define NSTICK 10\ntypedef struct {\n"]
                     + [f"    double {name};\n" for name in GAIT2DE_PARAMETERS]
                     + ["} param_struct;\n"])
    (folder / "gait2de.h").write_text(header)
    library = folder / "gait2de_al.so"
    subprocess.run(["cc", "-O1", "-shared", "-fPIC", "-I", str(folder), "-o", str(library),
                    str(source), "-lm"], check=True, capture_output=True)
    function = ctypes.CDLL(str(library)).gait2d_al

    def accelerations(parameters: dict, q, qd, mom):
        par = (ctypes.c_double * len(GAIT2DE_PARAMETERS))(
            *[parameters[f"par__{name}"] for name in GAIT2DE_PARAMETERS])
        arrays = [np.ascontiguousarray(a, dtype=float) for a in (q, qd, np.zeros(9), mom,
                                                                 np.zeros(6), np.zeros(20))]
        function(ctypes.byref(par), *[a.ctypes.data_as(ctypes.c_void_p) for a in arrays])
        return arrays[2]
    return accelerations


@pytest.mark.corpus
def test_the_gait_tutorial_rises_and_autolevs_own_program_agrees(tmp_path, monkeypatch,
                                                                 corpus):
    pytest.importorskip("casadi", reason="the tutorial hands the model to CasADi (an extra)")
    (tmp_path / "gait2d").symlink_to(corpus / "csu-hmc+gait2d")
    ran = run_page(DOCS / "tutorials" / "gait.md", tmp_path, monkeypatch)
    assert ran["python"] == 5
    if shutil.which("cc") is None:
        pytest.skip("Autolev's C program of the model needs cc")
    motion = np.load(tmp_path / "squat.npz")
    names = list(motion["state_names"])
    q = motion["states"][:, [names.index(f"q{i}") for i in range(1, 10)]]
    qd = motion["states"][:, [names.index(f"q{i}'") for i in range(1, 10)]]
    steps = np.diff(motion["t"])[:, None]
    autolevs = autolevs_gait2de(corpus / "csu-hmc+gait2d/algait2de/gait2de_al.c", tmp_path)
    parameters = dict(zip(motion["parameter_names"], motion["parameter_values"]))
    assert parameters["gravity"] == 9.81       # the value gait2de_al.c has built in
    # backward Euler: the rates over each step are the accelerations at its end
    rates = (qd[1:] - qd[:-1]) / steps
    theirs = np.array([autolevs(parameters, q[k], qd[k],
                                np.concatenate([np.zeros(3), motion["moments"][k - 1]]))
                       for k in range(1, len(q))])
    assert np.abs(theirs - rates).max() < 1e-8 * max(1.0, np.abs(rates).max())
