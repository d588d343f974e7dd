"""`autolev run`'s output formats (cli/run.py's OUTPUT_FORMATS, issue 52): each one's
flag is on the command, asking for it writes its files beside Autolev's own, and a
format whose optional package is missing is refused before anything runs."""
import importlib.util

import pytest

from autolev.cli import build_parser, main
from autolev.cli.run import OUTPUT_FORMATS
from helpers import EXAMPLES

MODEL = EXAMPLES / "double_pendulum.al"
# what each format writes of the double pendulum (two OUTPUT files: two PNGs), and
# what it may write besides (the animation's GIF, with matplotlib)
WRITES = {"plot": {"double_pendulum.1.png", "double_pendulum.2.png"},
          "csv": {"double_pendulum.csv"}, "mat": {"double_pendulum.mat"},
          "animate": {"double_pendulum.html"}}
MAY_WRITE = {"animate": {"double_pendulum.gif"}}


def installed(package: str | None) -> bool:
    return package is None or importlib.util.find_spec(package) is not None


def run(out, *flags) -> int:
    return main(["run", str(MODEL), "--out", str(out), "--tfinal", "0.2", "-q", *flags])


def test_every_output_format_is_tested_here():
    assert set(WRITES) == {f.name for f in OUTPUT_FORMATS}


@pytest.fixture(scope="module")
def plain_files(tmp_path_factory):
    """The files of the run without any output format."""
    out = tmp_path_factory.mktemp("plain") / "o"
    assert run(out) == 0
    return {p.name for p in out.iterdir()}


@pytest.mark.parametrize("output_format", OUTPUT_FORMATS, ids=lambda f: f.name)
def test_each_output_formats_flag_writes_its_files(output_format, plain_files, tmp_path):
    ns = build_parser().parse_args(["run", str(MODEL), output_format.flag])
    assert output_format.asked(ns)
    assert not [f.name for f in OUTPUT_FORMATS if f is not output_format and f.asked(ns)]
    if not installed(output_format.needs):
        pytest.skip(f"{output_format.flag} needs the optional {output_format.needs}")
    out = tmp_path / "o"
    assert run(out, output_format.flag) == 0
    added = {p.name for p in out.iterdir()} - plain_files
    assert WRITES[output_format.name] <= added
    assert added - WRITES[output_format.name] <= MAY_WRITE.get(output_format.name, set())


@pytest.mark.parametrize("output_format", [f for f in OUTPUT_FORMATS if f.needs],
                         ids=lambda f: f.name)
def test_a_format_without_its_package_is_refused_before_the_run(output_format, tmp_path,
                                                                capsys):
    if installed(output_format.needs):
        pytest.skip(f"{output_format.needs} is installed: nothing to refuse")
    out = tmp_path / "o"
    assert run(out, output_format.flag) == 2
    assert (f"{output_format.flag} needs {output_format.needs} (pip install "
            f"'autolev[{output_format.extra}]')") in capsys.readouterr().err
    assert not out.exists()
