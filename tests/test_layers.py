"""The import graph follows the pipeline: a package imports only packages below it.

The order is stated once, here. `cli` and `demo` sit on top; `evals` and `sim` read every
stage's output; no stage imports them, and nothing uses importlib to get round the graph."""

from __future__ import annotations

import ast
from pathlib import Path

import iesm_agent

ROOT = Path(iesm_agent.__file__).parent

#: bottom to top; a module may import its own package and any package listed before it
LAYERS = ["errors", "resources", "fileio", "cachedir", "contract", "config", "lexicon", "colours", "encoding", "embeddings", "store", "frames", "segment",
          "understanding", "providers", "prompting", "mapping", "rooms", "captioning", "retrieval", "nav",
          "server", "sim", "evals", "cli", "demo"]


def _package(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _module_of(path: Path) -> tuple[str, bool]:
    """(dotted module name, is a package's __init__) of a file under the package root."""
    module = ".".join(path.relative_to(ROOT.parent).with_suffix("").parts)
    if path.name == "__init__.py":
        return module.rsplit(".", 1)[0], True
    return module, False


def _imports(source: str, module: str, is_package: bool):
    """(imported module, line) of every import in `source` (the text of `module`), relative
    imports resolved."""
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = module.split(".")
                if not is_package:
                    base = base[:-1]
                base = base[:len(base) - (node.level - 1)]
                yield ".".join(base + ([node.module] if node.module else [])), node.lineno
            else:
                yield node.module or "", node.lineno
        elif isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, node.lineno


def _violations(source: str, module: str, is_package: bool = False) -> list[str]:
    """The imports in `source` (module `module`) that run back up LAYERS, and imports by name."""
    rank = {name: k for k, name in enumerate(LAYERS)}
    origin = _package(module)
    found = []
    for target, line in _imports(source, module, is_package):
        if not target.startswith("iesm_agent."):
            continue
        dest = _package(target)
        if origin in rank and dest in rank and rank[dest] > rank[origin]:
            found.append(f"{module}:{line} ({origin}) imports {target} ({dest})")
    if "import_module(" in source or "__import__(" in source:
        found.append(f"{module} imports a module by name")
    return found


def test_every_package_is_placed_in_the_layer_order():
    packages = {p.stem if p.is_file() else p.name for p in ROOT.iterdir()
                if (p.suffix == ".py" and p.stem != "__init__") or (p / "__init__.py").is_file()}
    assert packages <= set(LAYERS), f"place these in LAYERS: {sorted(packages - set(LAYERS))}"


def test_no_import_runs_back_up_the_pipeline():
    upward = [v for path in ROOT.rglob("*.py")
              for v in _violations(path.read_text(encoding="utf-8"), *_module_of(path))]
    assert not upward, "\n".join(upward)


def test_the_layer_check_reports_an_upward_import_and_an_import_by_name():
    """The check itself, on source text placed in the mapping stage."""
    assert _violations("from ..evals import metrics\n", "iesm_agent.mapping.probe") == [
        "iesm_agent.mapping.probe:1 (mapping) imports iesm_agent.evals (evals)"]
    assert _violations("from ..store import model\n", "iesm_agent.mapping.probe") == []
    assert _violations("import importlib\nimportlib.import_module('iesm_agent.evals')\n",
                       "iesm_agent.mapping.probe") == ["iesm_agent.mapping.probe imports a module by name"]


def _module_graph(package: str) -> dict[str, set[str]]:
    """Module -> the modules of `package` it imports (any import, at top level or inside a
    function: both make a loop a reader must untangle)."""
    graph: dict[str, set[str]] = {}
    modules = {_module_of(p)[0]: p for p in (ROOT / package).rglob("*.py")}
    for module, path in modules.items():
        targets = set()
        for target, _line in _imports(path.read_text(encoding="utf-8"), *_module_of(path)):
            while target and target not in modules:  # `from .html import X` names a package's module
                target = target.rpartition(".")[0]
            if target and target != module:
                targets.add(target)
        graph[module] = targets
    return graph


def _reaches(graph: dict[str, set[str]], start: str, goal: str) -> bool:
    seen, todo = set(), [start]
    while todo:
        here = todo.pop()
        if here == goal:
            return True
        if here not in seen:
            seen.add(here)
            todo += graph.get(here, ())
    return False


def test_the_report_is_not_in_an_import_loop():
    """Issue 30: evals/report.py -> html/ -> html/run_data.py -> runner.py -> report.py was a loop;
    the shared pieces (build_summary, the run's file names) now sit below all of them."""
    graph = _module_graph("evals")
    report = "iesm_agent.evals.report"
    assert _reaches(graph, report, "iesm_agent.evals.html.run_data")  # the page is still written
    looped = [m for m in graph[report] if _reaches(graph, m, report)]
    assert not looped, f"report.py is in a loop through {looped}"
    assert not _reaches(graph, "iesm_agent.evals.html.run_data", "iesm_agent.evals.runner")
