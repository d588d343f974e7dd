"""The package's shape: its import graph (tools/import_graph.py) and its layers."""
import ast
import importlib.util
import re
import sys

import pytest

from helpers import ROOT

_spec = importlib.util.spec_from_file_location("import_graph", ROOT / "tools" / "import_graph.py")
import_graph = importlib.util.module_from_spec(_spec)
sys.modules["import_graph"] = import_graph
_spec.loader.exec_module(import_graph)

GRAPH = import_graph.import_graph()
SYMBOLIC_ENGINE_TOP = {"autolev.runtime.model", "autolev.runtime.simulation",
                       "autolev.runtime.studies", "autolev.runtime.algebra",
                       "autolev.runtime.equations", "autolev.runtime.mass_properties"}


def _under(package: str) -> list[str]:
    return [m for m in GRAPH if m == package or m.startswith(package + ".")]


def test_the_graph_tool_sees_a_cycle_and_layers_a_chain():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert import_graph.cycles(graph) == [["a", "b", "c"]]
    chain = {"top": {"mid"}, "mid": {"low"}, "low": set()}
    assert import_graph.layers(chain) == {"low": 0, "mid": 1, "top": 2}


def test_the_graph_holds_function_level_imports_but_not_type_checking_ones():
    # vectors.py imports Frame (frame.py) for type checking only; numerics/run.py is
    # imported by simulation.py in the methods that run a command
    assert "autolev.runtime.frame" not in GRAPH["autolev.runtime.vectors"]
    assert "autolev.runtime.vectors" in GRAPH["autolev.runtime.frame"]
    assert "autolev.runtime.numerics.run" in GRAPH["autolev.runtime.simulation"]


def test_no_import_cycle_in_the_package():
    # function-level imports count: the package's lazily resolved verbs included
    assert import_graph.cycles(GRAPH) == []


@pytest.mark.parametrize("module", _under("autolev.runtime"))
def test_runtime_never_imports_the_translator_or_the_parser(module):
    outside = {m for m in GRAPH[module] if not m.startswith(("autolev.runtime",
                                                               "autolev.engine"))}
    assert outside <= {"autolev.errors"}, f"{module} imports {sorted(outside)}"


@pytest.mark.parametrize("module", _under("autolev.runtime.numerics"))
def test_numerics_sit_on_the_symbolic_engine_not_on_the_model(module):
    above = GRAPH[module] & SYMBOLIC_ENGINE_TOP
    assert not above, f"{module} imports {sorted(above)}"


def test_kanes_method_is_apart_from_the_model():
    assert "autolev.runtime.model" not in GRAPH["autolev.runtime.kane"]
    assert "autolev.runtime.kane" in GRAPH["autolev.runtime.model"]


def test_the_stages_import_each_other_directly_not_through_the_package():
    for stage in ("autolev.loader", "autolev.verification", "autolev.transcript"):
        assert "autolev" not in GRAPH[stage], stage


def test_no_runtime_module_but_the_models_own_imports_it_even_for_types():
    # frames and points hold their Scene (definitions, symbols, what is derived, the
    # change notice), not the Model; the package's __init__ only re-exports it
    runtime = ROOT / "src" / "autolev" / "runtime"
    found = []
    for path in runtime.rglob("*.py"):
        if path.name in ("model.py", "__init__.py") and path.parent == runtime:
            continue
        text = path.read_text()
        if re.search(r"from \.+model import|runtime\.model|import model\b", text):
            found.append(str(path.relative_to(runtime)))
    assert found == []


def model_reads(text: str) -> list[tuple[int, str]]:
    """(line, expression) of every attribute read on a Model in a module's text: on a
    parameter named `model` or `m` or annotated `Model`, on a name bound to one
    (`m = system.model`), and of any `.model` held by another object."""
    found = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Attribute) and node.attr == "model":
            found.add((node.lineno, ast.unparse(node)))
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            continue
        args = node.args.posonlyargs + node.args.args + node.args.kwonlyargs
        bound = {a.arg for a in args if a.arg in ("model", "m") or (
            a.annotation is not None and re.search(r"\bModel\b", ast.unparse(a.annotation)))}
        inner = list(ast.walk(node))
        for sub in inner:
            if isinstance(sub, ast.Assign) and (
                    isinstance(sub.value, ast.Attribute) and sub.value.attr == "model"
                    or isinstance(sub.value, ast.Name) and sub.value.id in bound):
                bound |= {t.id for t in sub.targets if isinstance(t, ast.Name)}
        for sub in inner:
            if isinstance(sub, ast.Attribute) and isinstance(sub.value, ast.Name) \
                    and sub.value.id in bound:
                found.add((sub.lineno, ast.unparse(sub)))
    return sorted(found)


def test_the_model_read_scanner_sees_each_way_of_holding_a_model():
    text = ("def f(model):\n    return model.defs\n"
            "def g(system):\n    m = system.model\n    return lambda: m.info\n"
            "def h(x: 'Model', y: ModelSnapshot):\n    return x.outputs, y.outputs\n")
    assert model_reads(text) == [(2, "model.defs"), (4, "system.model"), (5, "m.info"),
                                 (7, "x.outputs")]


def test_the_numerics_never_read_a_model_only_its_snapshot():
    # the numerics take what they need as one ModelSnapshot (Model.snapshot_for): a
    # change to the Model's attributes cannot reach them unseen
    numerics = ROOT / "src" / "autolev" / "runtime" / "numerics"
    found = [f"{path.relative_to(ROOT)}:{line}: {expr}"
             for path in sorted(numerics.glob("*.py"))
             for line, expr in model_reads(path.read_text())]
    assert found == [], "the numerics read the Model:\n" + "\n".join(found)


def test_no_field_of_a_model_is_read_with_a_default():
    # a Model declares what it holds (Model.loaded for what loading attached)
    found = [str(p) for p in (ROOT / "src" / "autolev").rglob("*.py")
             if re.search(r"getattr\((model|self\.model|m), ", p.read_text())]
    assert found == []


@pytest.mark.parametrize("module", _under("autolev.engine"))
def test_the_engine_imports_nothing_outside_itself(module):
    # what a run plan executes (issue 52): its imports, function-level ones too, stay in
    # the package, so a warm run needs no model, translator or sympy
    outside = {m for m in GRAPH[module] if not m.startswith("autolev.engine")}
    assert outside == set(), f"{module} imports {sorted(outside)}"


def test_the_engine_needs_no_sympy_nor_scipy_to_import():
    import subprocess
    engine = ROOT / "src" / "autolev" / "engine"
    modules = sorted(p.stem for p in engine.glob("*.py") if p.stem != "__init__")
    code = ("import sys\n" + "".join(f"import autolev.engine.{m}\n" for m in modules)
            + "print(sorted(m for m in ('sympy', 'scipy') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=ROOT, env={"PYTHONPATH": str(ROOT / "src"), "PATH": ""})
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"
