"""`iesm eval-check`: every suite against its committed reference verdicts (`make eval-suites`)."""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import List

import typer

from .progress import progress_bar


def eval_check_command(
    evals: Path = typer.Option(Path("evals"), "--evals", help="The suites' folder (its *.jsonl and blind/round*.jsonl)."),
    referring: Path = typer.Option(Path("../shared/data/referring_dev"), "--referring",
                                   help="The referring development corpus (scanrefer_dev, nr3d_dev); skipped when absent."),
    references: Path = typer.Option(Path("evals/reference_verdicts"), "--references",
                                    help="Reference verdicts, one JSONL per suite."),
    out: Path = typer.Option(Path("runs/eval-suites"), "--out", "-o",
                             help="Where verdicts.jsonl and regression.json are written."),
    method: List[str] = typer.Option(["mtefr,spr"], "--method", "-m", help="Methods, comma separated."),
    suite: List[str] = typer.Option([], "--suite", help="Only this suite (repeatable; names as in the table)."),
    update: bool = typer.Option(False, "--update", help="Rewrite the references of the suites that ran."),
    concurrency: int = typer.Option(4, "--concurrency", "-j", help="Queries in flight at once."),
) -> None:
    """Score every shipped suite, blind round and the referring corpus on the offline model against
    the reference verdicts; exit 1 when a suite drops by more than one query per hundred."""
    from ..evals.regression import run_check
    from ..evals.runner import split_methods

    started = time.perf_counter()
    with progress_bar("eval-check") as progress:
        task = progress.add_task("eval-check", total=None)
        report, specs = run_check(evals, referring, references, out,
                                  methods=split_methods(method), only=suite, update=update,
                                  concurrency=concurrency, on_start=lambda n: progress.update(task, total=n),
                                  on_result=lambda _record: progress.advance(task))
    for name, reason in report.skipped.items():
        print(f"skipped: {name} ({reason})")
    _print_report(report)
    wall = time.perf_counter() - started
    if update:
        print(f"references rewritten for {len(report.updated)} suite(s) in {references}")
    for name in report.unreferenced:
        print(f"iesm: eval-check: no reference verdicts for {name}: run `iesm eval-check --update` "
              "and commit them", file=sys.stderr)
    for d in report.failed:
        print(f"iesm: eval-check: {d.suite} {d.method} dropped {-d.delta} of {d.n} queries "
              f"(allowed {d.allowed_drop:.2f})", file=sys.stderr)
    print(f"{len(report.deltas)} suite x method comparisons, {len(report.failed)} failing, "
          f"{len(specs) - len(report.skipped)} suite(s) run in {wall:.0f} s; {out / 'regression.json'}")
    if not update and not report.passed:
        raise typer.Exit(1)


def _print_report(report) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console(width=None if sys.stdout.isatty() else 160)
    table = Table(title="Correct queries: reference -> now (offline model)")
    for column in ("suite", "method", "n", "before", "after", "delta", "changed (+/-)", ""):
        table.add_column(column, justify="left" if column in ("suite", "method", "") else "right", no_wrap=True)
    for d in report.deltas:
        gained = sum(c.after_correct for c in d.changes)
        table.add_row(d.suite, d.method, str(d.n), _count(d.before, d.n), _count(d.after, d.n), f"{d.delta:+d}",
                      f"+{gained} / -{len(d.changes) - gained}", "FAIL" if d.failed else "ok")
    if table.row_count:
        console.print(table)
    for d in report.deltas:
        for c in d.changes:
            console.print(f"  {'gained' if c.after_correct else 'LOST  '} {d.suite} {d.method} {c.id} "
                          f"{c.query!r}: predicted {c.before_predicted} -> {c.after_predicted}",
                          markup=False, highlight=False, soft_wrap=True)  # one line per query, for grep
        if d.new_ids or d.gone_ids:
            console.print(f"  {d.suite} {d.method}: {len(d.new_ids)} query(ies) without a reference, "
                          f"{len(d.gone_ids)} reference(s) without a query (run --update after editing a suite)",
                          markup=False, highlight=False)
    _print_disagreement(console, report.disagreements)


def _print_disagreement(console, disagreements: dict) -> None:
    from rich.table import Table

    table = Table(title="MTEFR vs SPR: queries where exactly one is right, and which (MTEFR / SPR); "
                        "per query set: non-spatial types, no relation read, all")
    for column in ("suite", "n", "differ", "wins", "n no rel.", "differ no rel.", "wins no rel.", "n all",
                   "differ all", "wins all"):
        table.add_column(column, justify="left" if column == "suite" else "right", no_wrap=True)
    for name, counts in disagreements.items():
        if counts["all"] is None:
            continue
        cells = []
        for part in (counts["non_spatial"], counts.get("no_relation"), counts["all"]):
            cells += ([str(part["n"]), _count(part["verdicts_differ"], part["n"]),
                       f"{part['mtefr_wins']} / {part['spr_wins']}"] if part and part["n"] else ["0", "-", "-"])
        table.add_row(name, *cells)
    if table.row_count:
        console.print(table)


def _count(k: int, n: int) -> str:
    return f"{k} ({100 * k / n:.1f}%)" if n else str(k)


def register(app: typer.Typer) -> None:
    app.command("eval-check")(eval_check_command)
