"""docs/architecture.md names only what is there (issue 52, item 5): every file and
folder it names, of the repository (`tools/regen_parser.py`) or of src/autolev by its
path from the package or from any folder of it (`kane.py`, `numerics/run.py`); every
module its drawings list under a package; every `module.name` it writes of a module of
autolev; every dotted `autolev.` name; and every class it names (`KaneEquations`)."""
import importlib
import re

import pytest

from helpers import ROOT

PAGE = (ROOT / "docs" / "architecture.md").read_text()
PACKAGE = ROOT / "src" / "autolev"
# the package's files and folders by their path in it: runtime/numerics/run.py
IN_PACKAGE = sorted(p.relative_to(PACKAGE).as_posix() for p in PACKAGE.rglob("*")
                    if "__pycache__" not in p.parts)
# a file by its name and extension, or a folder by its trailing slash, with the folders
# before it: `engine/functions.py`, `cli/`, `loop.c`
PATH = re.compile(r"(?<![\w/.<-])((?:[A-Za-z_][\w-]*/)+(?:[\w-]+\.(?:py|c|g4|md|txt))?"
                  r"|[A-Za-z_][\w-]*\.(?:py|c|g4))(?![\w/])")
DRAWINGS = re.findall(r"```mermaid\n(.*?)```", PAGE, re.S)
# a drawing's node: id["label"]
LABEL = re.compile(r'\w+\["([^"]*)"\]')
DOTTED = re.compile(r"\bautolev(?:\.[A-Za-z_]\w*)+")
# `module.name` in code spans, a module of the package and what it holds
ATTRIBUTE = re.compile(r"`([a-z_][a-z0-9_]*)\.([A-Za-z_][\w.]*)[`(]")
# a class by its name in a code span, alone or before one of its own: `Model.loaded`
CLASS = re.compile(r"`([A-Z][a-z]+[A-Z]?\w*)[`.(]")


def is_there(path: str) -> bool:
    path = path.rstrip("/")
    return (ROOT / path).exists() or any(p == path or p.endswith("/" + path)
                                         for p in IN_PACKAGE)


def paths_named() -> list[str]:
    return sorted(set(PATH.findall(PAGE.replace("<br/>", " "))))


def listed_modules() -> list[str]:
    """`package/module` for each module a drawing lists as `a · b + c.c` under the
    package its node names first (`engine/ ...`)."""
    found = set()
    for drawing in DRAWINGS:
        for label in LABEL.findall(drawing):
            first, *lines = label.split("<br/>")
            package = re.match(r"([\w/]+/)", first)
            for line in lines if package else []:
                if "·" not in line:
                    continue
                for item in re.split(r"[·+]", line):
                    item = item.strip()
                    if re.fullmatch(r"[a-z_][a-z0-9_]*", item):
                        found.add(package.group(1) + item + ".py")
    return sorted(found)


def _resolves(dotted: str) -> bool:
    """A module, or what a module holds, by its dotted name."""
    parts = dotted.split(".")
    for k in range(len(parts), 0, -1):
        try:
            thing = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for part in parts[k:]:
            if not hasattr(thing, part):
                return False
            thing = getattr(thing, part)
        return True
    return False


def attributes_named() -> list[tuple[str, str]]:
    """(module, name) for each `module.name` whose module is one of the package's."""
    stems = {p.rsplit("/", 1)[-1][:-3] for p in IN_PACKAGE if p.endswith(".py")}
    return sorted({(m, a) for m, a in ATTRIBUTE.findall(PAGE)
                   if m in stems and a.split(".")[0] not in ("py", "c")})


def classes_named() -> list[str]:
    return sorted(set(CLASS.findall(PAGE)))


def test_the_page_is_read_whole():
    # the patterns find what the page names: a pattern gone blind passes nothing
    assert len(paths_named()) > 60 and len(listed_modules()) > 30
    assert len(attributes_named()) > 15 and DOTTED.search(PAGE)
    assert len(classes_named()) > 30


@pytest.mark.parametrize("path", paths_named())
def test_every_file_and_folder_it_names_is_there(path):
    assert is_there(path)


@pytest.mark.parametrize("path", listed_modules())
def test_every_module_its_drawings_list_is_there(path):
    assert is_there(path)


@pytest.mark.parametrize("dotted", sorted(set(DOTTED.findall(PAGE))))
def test_every_dotted_autolev_name_is_there(dotted):
    assert _resolves(dotted)


@pytest.mark.parametrize("module, name", attributes_named())
def test_every_name_it_gives_a_module_is_in_one_of_that_name(module, name):
    modules = ["autolev." + p[:-3].replace("/", ".").removesuffix(".__init__")
               for p in IN_PACKAGE if p.endswith(".py") and p.rsplit("/", 1)[-1] == module + ".py"]
    assert any(_resolves(m + "." + name) for m in modules), modules


@pytest.mark.parametrize("name", classes_named())
def test_every_class_it_names_is_defined(name):
    defined = re.compile(rf"^\s*(class|def) {name}\b|^{name} = ", re.M)
    assert any(defined.search(p.read_text()) for p in PACKAGE.rglob("*.py"))
