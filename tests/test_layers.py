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


def _imports(path: Path):
    """(imported module, line) of every import in `path`, relative imports resolved."""
    module = ".".join(path.relative_to(ROOT.parent).with_suffix("").parts)
    is_package = path.name == "__init__.py"
    if is_package:
        module = module.rsplit(".", 1)[0]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
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


def test_every_package_is_placed_in_the_layer_order():
    packages = {p.stem if p.is_file() else p.name for p in ROOT.iterdir()
                if (p.suffix == ".py" and p.stem != "__init__") or (p / "__init__.py").is_file()}
    assert packages <= set(LAYERS), f"place these in LAYERS: {sorted(packages - set(LAYERS))}"


def test_no_import_runs_back_up_the_pipeline():
    rank = {name: k for k, name in enumerate(LAYERS)}
    upward = []
    for path in ROOT.rglob("*.py"):
        source = _package(".".join(path.relative_to(ROOT.parent).with_suffix("").parts))
        for target, line in _imports(path):
            if not target.startswith("iesm_agent."):
                continue
            dest = _package(target)
            if source in rank and dest in rank and rank[dest] > rank[source]:
                upward.append(f"{path.relative_to(ROOT)}:{line} ({source}) imports {target} ({dest})")
        text = path.read_text(encoding="utf-8")
        if "import_module(" in text or "__import__(" in text:
            upward.append(f"{path.relative_to(ROOT)} imports a module by name")
    assert not upward, "\n".join(upward)


def test_the_layer_check_sees_an_upward_import(tmp_path):
    """The check itself: an import from a stage to evals is reported."""
    bad = ROOT / "mapping" / "_layer_probe.py"
    bad.write_text("from ..evals import metrics\n", encoding="utf-8")
    try:
        found = [t for t, _ in _imports(bad)]
    finally:
        bad.unlink()
    assert found == ["iesm_agent.evals"]
