"""The README speaks of what ships with the project (issue 19, item 7): every file it
names is in the repository, and it points at nothing beside it."""
import re

from helpers import ROOT
from helpers.markdown import run_page

README = (ROOT / "README.md").read_text()


def test_no_path_leaves_the_repository():
    assert "../" not in README


def test_every_file_it_names_ships():
    named = set(re.findall(r"\b((?:docs|bench|tests|tools|autolev_examples|grammar|src)"
                           r"/[\w./-]+\.\w+)", README))
    assert len(named) > 10
    missing = sorted(p for p in named if not (ROOT / p).exists())
    assert missing == []


def test_every_code_block_runs(tmp_path, monkeypatch):
    # in a fresh folder beside the shipped files, in the README's order (later blocks
    # read what earlier ones wrote); a console block's shown output (when it shows one)
    # is what the command prints
    ran = run_page(ROOT / "README.md", tmp_path, monkeypatch)
    assert ran["python"] >= 6 and ran["console"] >= 3 and ran["sh"] >= 5
