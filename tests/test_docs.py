"""The user guide and the CLI reference match the code: the README starts with the two commands,
and docs/cli.md names every command and option the live `iesm` command tree has."""

import re
from pathlib import Path

from typer.main import get_command

from iesm_agent.cli import app

REPO = Path(__file__).resolve().parents[1]
REGENERATE = "regenerate it: .venv/bin/python docs/gen_cli.py > docs/cli.md"


def test_readme_starts_with_make_demo_then_make_test():
    text = (REPO / "README.md").read_text(encoding="utf-8")
    first_block = re.search(r"```(?:bash)?\n(.*?)```", text, re.S).group(1)
    commands = [line.split("#")[0].strip() for line in first_block.splitlines() if line.strip()]
    assert commands == ["make demo", "make test"]


def test_cli_reference_lists_every_command_and_option():
    doc = (REPO / "docs" / "cli.md").read_text(encoding="utf-8")
    sections = dict(re.findall(r"^## iesm (\S+)\n(.*?)(?=^## iesm |\Z)", doc, re.S | re.M))
    missing = []
    for name, command in get_command(app).commands.items():
        if name not in sections:
            missing.append(f"command {name}")
            continue
        for param in (p for p in command.params if p.param_type_name == "option"):
            for flag in [*getattr(param, "opts", []), *getattr(param, "secondary_opts", [])]:
                if flag != "--help" and not re.search(rf"(?<![\w-]){re.escape(flag)}(?![\w-])", sections[name]):
                    missing.append(f"iesm {name} {flag}")
    assert not missing, f"docs/cli.md lacks {missing}; {REGENERATE}"


def test_relative_links_in_the_guide_and_docs_resolve():
    pages = [REPO / "README.md", REPO / "evals" / "README.md", *sorted((REPO / "docs").rglob("*.md"))]
    broken = []
    for page in pages:
        for target in re.findall(r"\]\(([^)\s]+)\)", page.read_text(encoding="utf-8")):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            path = target.split("#")[0]
            if not (page.parent / path).exists():
                broken.append(f"{page.relative_to(REPO)} -> {target}")
    assert not broken, broken
