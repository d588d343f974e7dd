"""The import graph of src/autolev: its cycles, its layers, and a Mermaid drawing.

    python tools/import_graph.py              # layers and cycles, as text
    python tools/import_graph.py --mermaid    # the drawing docs/architecture.md shows

Every import counts, also one inside a function; imports under `if TYPE_CHECKING:`
do not (they never run).  The generated parser (_antlr) is one node.
"""
from __future__ import annotations

import argparse
import ast
import sys
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "autolev"


def module_files(root: Path = PACKAGE) -> dict[str, Path]:
    """Dotted module name -> file, the generated parser's files left out."""
    found = {}
    for path in sorted(root.rglob("*.py")):
        parts = path.relative_to(root.parent).with_suffix("").parts
        if "_antlr" in parts:
            continue
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found[".".join(parts)] = path
    found["autolev._antlr"] = root / "_antlr" / "__init__.py"
    return found


def _type_checking_nodes(tree: ast.AST) -> set[int]:
    skipped: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            skipped.update(id(n) for n in ast.walk(node))
    return skipped


def _imported(name: str, path: Path, node: ast.AST, modules: dict) -> list[str]:
    """The package modules one import statement loads."""
    if isinstance(node, ast.Import):
        targets = [a.name for a in node.names]
    else:
        if node.level:
            package = name if path.name == "__init__.py" else name.rpartition(".")[0]
            base = package.split(".")[:len(package.split(".")) - node.level + 1]
            target = ".".join(base + ([node.module] if node.module else []))
        else:
            target = node.module or ""
        subs = [f"{target}.{a.name}" for a in node.names if f"{target}.{a.name}" in modules]
        # `from . import x` of submodules loads them; anything else loads `target`
        targets = subs if len(subs) == len(node.names) else [target] + subs
    found = []
    for t in targets:
        if t.startswith("autolev._antlr"):
            t = "autolev._antlr"
        if t in modules and t != name:
            found.append(t)
    return found


def import_graph(root: Path = PACKAGE) -> dict[str, set[str]]:
    """Module -> the package modules it imports."""
    modules = module_files(root)
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        graph[name] = set()
        if name == "autolev._antlr":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        skipped = _type_checking_nodes(tree)
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)) and id(node) not in skipped:
                graph[name].update(_imported(name, path, node, modules))
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def layers(graph: dict[str, set[str]]) -> dict[str, int]:
    """Each module's layer: 0 imports nothing of the package, else one above the
    highest layer it imports (the graph must be acyclic)."""
    level: dict[str, int] = {}

    def depth(v: str) -> int:
        if v not in level:
            level[v] = 1 + max((depth(w) for w in graph[v]), default=-1)
        return level[v]
    for v in graph:
        depth(v)
    return level


def mermaid(graph: dict[str, set[str]], under: str = "autolev") -> str:
    """A Mermaid flowchart of the modules under `under`, edges pointing down."""
    names = {v for v in graph if v == under or v.startswith(under + ".")}
    short = {v: v.removeprefix("autolev.") or "autolev" for v in names}
    lines = ["flowchart TD"]
    for v in sorted(names):
        for w in sorted(graph[v] & names):
            lines.append(f"    {short[v].replace('.', '_')}[{short[v]}] --> "
                         f"{short[w].replace('.', '_')}[{short[w]}]")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mermaid", metavar="PACKAGE", nargs="?", const="autolev",
                    help="print a Mermaid drawing of PACKAGE's modules (default autolev)")
    ns = ap.parse_args(argv)
    graph = import_graph()
    found = cycles(graph)
    if ns.mermaid:
        print(mermaid(graph, ns.mermaid))
        return 0
    for component in found:
        print("cycle: " + " <-> ".join(component))
    if found:
        return 1
    for name, level in sorted(layers(graph).items(), key=lambda kv: (kv[1], kv[0])):
        print(f"{level:2d}  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
