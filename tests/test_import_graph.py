"""The import contracts (`[tool.importlinter]` in pyproject.toml, checked by `make lint`) see the
import statements only: nothing in the package may import a module by name."""

from __future__ import annotations

import ast
from pathlib import Path

import iesm_agent

ROOT = Path(iesm_agent.__file__).parent


def imports_by_name(source: str) -> list[int]:
    """Lines of `source` that call importlib.import_module or __import__."""
    lines = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call):
            func = node.func
            name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            if name in ("import_module", "__import__"):
                lines.append(node.lineno)
    return lines


def test_nothing_in_the_package_imports_a_module_by_name():
    found = [f"{path.relative_to(ROOT.parent)}:{line}" for path in sorted(ROOT.rglob("*.py"))
             for line in imports_by_name(path.read_text(encoding="utf-8"))]
    assert not found, found


def test_the_check_finds_both_forms():
    source = "import importlib\nimportlib.import_module('iesm_agent.evals')\nx = __import__('os')\nimport os\n"
    assert imports_by_name(source) == [2, 3]
