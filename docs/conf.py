"""Sphinx configuration of autolev's documentation site.

    python -m sphinx -W -b html docs build/docs

builds it (tests/test_docs_site.py does, warnings as errors).  Pages are Markdown (MyST);
the API reference is read from the docstrings."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

project = "autolev"
author = "the autolev authors"
copyright = "2026, the autolev authors"
extensions = ["myst_parser", "sphinx.ext.autodoc"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["examples", "img/README*"]
myst_heading_anchors = 4
autodoc_member_order = "bysource"
autodoc_typehints = "none"
html_theme = "alabaster"
html_static_path: list = []


def setup(app):
    # the architecture's diagrams are Mermaid source: shown as text
    from pygments.lexers.special import TextLexer
    app.add_lexer("mermaid", TextLexer)
