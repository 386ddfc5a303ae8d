"""`iesm report` (the HTML report of one eval run, or two compared) and `iesm view` (the HTML
map viewer): self-contained pages, see docs/evaluation.md#report."""

from __future__ import annotations

import time
from pathlib import Path
from typing import List

import typer


def report_command(
    run_dirs: List[Path] = typer.Argument(..., help="Eval run directory; a second one compares the two runs."),
    out: Path = typer.Option(None, "--out", "-o", help="HTML file to write (default RUN_DIR/report.html)."),
) -> None:
    """Write the self-contained HTML report of an eval run (two runs: compared side by side)."""
    from ..errors import IesmError
    from ..evals.html import REPORT, write_report

    if len(run_dirs) > 2:
        raise IesmError(f"give one run directory, or two to compare (got {len(run_dirs)})", "RUN_DIR")
    target = out or run_dirs[0] / REPORT
    t0 = time.perf_counter()
    size = write_report(run_dirs, target)
    print(f"wrote {target} ({size / 1e3:.0f} kB) in {time.perf_counter() - t0:.1f} s")


def view_command(
    map_ref: str = typer.Argument(..., metavar="MAP", help="Map file (.iesm or JSON) or shipped map name."),
    out: Path = typer.Option(..., "--out", "-o", help="HTML file to write."),
) -> None:
    """Write a self-contained HTML viewer of a map: instances by category, rooms, stacked cells, search."""
    from ..evals.html import write_map_view

    size = write_map_view(map_ref, out)
    print(f"wrote {out} ({size / 1e3:.0f} kB)")


def register(app: typer.Typer) -> None:
    app.command("report")(report_command)
    app.command("view")(view_command)
