"""Regenerate docs/cli.md from the live command tree (what `iesm <command> --help` prints):

    .venv/bin/python docs/gen_cli.py > docs/cli.md
"""

import re

from typer.main import get_command

from iesm_agent.cli import app

HEADER = """# Command line reference

Generated from the commands themselves (`iesm <command> --help`); regenerate with
`.venv/bin/python docs/gen_cli.py > docs/cli.md`.

Common behaviour:

* `MAP` is a `.iesm` file, a JSON map the importers read (an object list or the paper's
  `scene_*_caption.json`, imported in memory) or the name of a shipped map (`apartment`).
* Bad input (a malformed map, a missing field, an unknown id or method, a dead endpoint) prints one
  line `iesm: error: <file>:<field>: <problem>` and exits 2: no traceback, and never a half-written
  output file (every file is written to a temporary name and renamed). A command whose optional
  extra is missing names the extra to install, also with exit 2.
* Methods (`-m`): `mtefr` (default), `mtefr-uniform` (gate off: uniform expert weights), `spr`
  (the paper's single-pass Full+SPR baseline), `keyword` (HOV-SG style) and `experts:<a>,<b>`
  (MTEFR restricted to those experts). `iesm eval -m` takes comma lists and repeats.
* Providers (`-p`): `offline`, `openai:<model>`, `ollama:<model>`, `openai-compat:<model>` with
  `--base-url`, or a plug-in prefix; see [providers.md](providers.md).
* `--help` on any command prints the same text as below.

Commands: {index}
"""


def _type(text: str) -> str:
    return re.sub(r"<list\[(\w+)\]>", lambda m: f"<{m.group(1).lower()}>", text)


def main() -> None:
    root = get_command(app)
    names = list(root.commands)
    out = [HEADER.format(index=", ".join(f"[`{n}`](#iesm-{n})" for n in names))]
    for name, cmd in root.commands.items():
        ctx = cmd.context_class(cmd, info_name=name, parent=root.context_class(root, info_name="iesm"))
        out.append(f"## iesm {name}\n")
        out.append((cmd.help or "").strip() + "\n")
        usage = " ".join(cmd.collect_usage_pieces(ctx))
        usage = re.sub(r"\{(\w+)\}", lambda m: m.group(1).upper(), usage)
        out.append(f"```\niesm {name} {usage}\n```\n")
        rows = []
        for p in cmd.params:
            if p.name == "help":
                continue
            if p.param_type_name == "argument":
                label = f"`{(p.metavar or p.name).upper()}`" + (" ..." if p.nargs == -1 else "")
                rows.append((label, (p.help or "").strip()))
                continue
            record = p.get_help_record(ctx)
            if record is not None:
                opts, text = record
                rows.append((f"`{_type(opts)}`", text.strip()))
        if rows:
            out.append("| argument / option | meaning |\n|---|---|")
            for a, b in rows:
                out.append(f"| {a.replace('|', chr(92) + '|')} | {' '.join(b.split()).replace('|', chr(92) + '|')} |")
            out.append("")
    print("\n".join(out).rstrip() + "\n", end="")


if __name__ == "__main__":
    main()
