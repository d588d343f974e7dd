"""The top-level modules import one another without a cycle: each stage (source,
irbuild, translate, loader, verification, transcript) imports what it uses directly,
and the package imports the stages only when they are first used."""
import ast
from pathlib import Path

from helpers import ROOT


def _imports(module: Path, package: Path) -> set[str]:
    """The modules of the package `module` imports (anywhere in it), as paths relative
    to the package without the suffix ('loader', 'runtime/vector', '__init__')."""
    here = module.parent.relative_to(package).parts
    found = set()
    for node in ast.walk(ast.parse(module.read_text())):
        if isinstance(node, ast.ImportFrom):
            module_parts = node.module.split(".") if node.module else []
            if node.level:
                base = list(here[:len(here) - node.level + 1]) + module_parts
            elif module_parts[0] == "autolev":
                base = module_parts[1:]
            else:
                continue
            names = [base + [a.name] for a in node.names]
        elif isinstance(node, ast.Import):
            names = [a.name.split(".")[1:] for a in node.names
                     if a.name.split(".")[0] == "autolev"]
        else:
            continue
        for parts in names:
            while parts and not (package.joinpath(*parts).with_suffix(".py").exists()
                                 or package.joinpath(*parts).is_dir()):
                parts = parts[:-1]
            found.add("/".join(parts + (["__init__"] if package.joinpath(*parts).is_dir()
                                        else [])))
    return found


def test_the_top_level_modules_import_no_cycle():
    package = ROOT / "src" / "autolev"
    top = {p.stem: p for p in package.glob("*.py")}
    graph = {name: {m for m in _imports(path, package) if m in top and m != name}
             for name, path in top.items()}

    def on_a_cycle(name: str) -> bool:
        stack, seen = list(graph[name]), set()
        while stack:
            m = stack.pop()
            if m == name:
                return True
            if m not in seen:
                seen.add(m)
                stack.extend(graph[m])
        return False
    assert [name for name in graph if on_a_cycle(name)] == []
