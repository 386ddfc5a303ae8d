"""`iesm eval` (run query suites against retrieval variants) and `iesm gen-queries`."""

from __future__ import annotations

import asyncio
import sys
from pathlib import Path
from typing import List, Optional

import typer

from .progress import progress_bar


def eval_command(
    suites: List[Path] = typer.Argument(..., help="Query suite(s), JSONL."),
    method: List[str] = typer.Option(["mtefr"], "--method", "-m",
                                     help="Methods, comma separated: mtefr, spr, keyword, experts:obj,desc, ..."),
    provider: str = typer.Option("offline", "--provider", "-p", help="Model spec, e.g. offline, openai:gpt-4o-mini."),
    prompts: List[Path] = typer.Option([], "--prompts", help="Prompt directory, or default for the shipped prompts; each one is a variant of every method."),
    experts_dir: List[Path] = typer.Option([], "--experts-dir",
                                           help="Extra expert spec directory (repeatable), for every variant."),
    out: Path = typer.Option(..., "--out", "-o", help="Run directory (results.jsonl, summary.json, report.md)."),
    concurrency: int = typer.Option(4, "--concurrency", "-j", help="Queries in flight at once."),
    resume: bool = typer.Option(False, "--resume", help="Continue the run in OUT, skipping finished queries "
                                                        "(queries whose model calls failed are asked again)."),
    max_failed_calls: int = typer.Option(0, "--max-failed-calls",
                                         help="Model calls allowed to fail (no reply) before the exit status is 1."),
    fail_under: List[str] = typer.Option([], "--fail-under",
                                         help="METRIC=VALUE (osr, osr_type_mean, mrr, top3); exit 1 if any variant is below."),
    skip_invalid: bool = typer.Option(False, "--skip-invalid", help="Report and skip bad suite lines instead of stopping."),
    no_cache: bool = typer.Option(False, "--no-cache", help="Do not use the response cache (on by default for models worth caching)."),
    base_url: Optional[str] = typer.Option(None, "--base-url", help="Endpoint for openai-compat providers."),
    gt: List[str] = typer.Option([], "--gt", help="Frame directory with gt/ (simulator ground truth): N-SR on the "
                                                  "map built from it; MAP=DIR when the suites have several maps."),
    keep_prompts: bool = typer.Option(False, "--keep-prompts", help="Keep every rendered prompt and raw reply in "
                                                                    "results.jsonl (shown in report.html)."),
    max_candidates: Optional[int] = typer.Option(None, "--max-candidates", help="Candidates sent to the model at "
                                                 "most (the best by a cheap pre-ranking; default 20 for LLM "
                                                 "endpoints, 100 offline)."),
    max_concurrency: Optional[int] = typer.Option(None, "--max-concurrency", help="Model requests in flight at "
                                                  "once (default 8; fewer when the server reports fewer slots)."),
    dialect: Optional[str] = typer.Option(None, "--dialect", help="Structured output as json_schema, json_object "
                                          "or prompt (no grammar) instead of negotiating it (HTTP providers)."),
    deadline: Optional[float] = typer.Option(None, "--deadline", help="Seconds within which every model call of "
                                             "one query ends, and one request may wait (default 60)."),
) -> None:
    """Evaluate retrieval methods on query suites: O-SR per query type, MRR, top-3, significance."""
    from ..evals.metrics import parse_thresholds, threshold_failures
    from ..evals.runner import make_config, make_variants, run_eval, split_methods, write_run_outputs

    thresholds = parse_thresholds(fail_under)
    variants = make_variants(split_methods(method), prompts)
    cache = not no_cache
    config = make_config(suites, variants, provider, base_url=base_url, cache=cache, skip_invalid=skip_invalid,
                         experts_dirs=experts_dir, gt=gt, max_candidates=max_candidates, deadline_s=deadline,
                         max_concurrency=max_concurrency, dialect=dialect)
    config.retrieval_config()  # bad values refused before anything runs
    if max_concurrency is not None and max_concurrency < 1:
        from ..errors import IesmError

        raise IesmError(f"must be >= 1, got {max_concurrency}", None, "--max-concurrency")

    with progress_bar("eval") as progress:
        task = progress.add_task("eval", total=None)
        outcome = asyncio.run(run_eval(
            config, out, resume=resume, concurrency=concurrency, keep_prompts=keep_prompts,
            on_start=lambda n: progress.update(task, total=n),
            on_result=lambda _record: progress.advance(task)))
    for error in outcome.suite.errors:
        print(f"iesm: skipped: {error}", file=sys.stderr)
    summary = write_run_outputs(out, config, outcome)
    _print_table(summary)
    print(f"{outcome.new} new results ({outcome.done_before} resumed) in {outcome.wall_s:.1f} s; "
          f"report: {out / 'report.md'}, {out / 'report.html'}")
    failures = threshold_failures(summary, thresholds)
    for failure in failures:
        print(f"iesm: fail-under: {failure}", file=sys.stderr)
    failed_calls = summary["run"]["failed_calls"]
    if failed_calls:
        print(f"iesm: {failed_calls} model call(s) failed in {summary['run']['queries_with_failed_calls']} "
              f"result(s) (allowed: {max_failed_calls}); see `failures` in {out / 'results.jsonl'}, "
              "--resume asks those queries again", file=sys.stderr)
    if failures or failed_calls > max_failed_calls:
        raise typer.Exit(1)


def _print_table(summary: dict) -> None:
    from rich.console import Console
    from rich.table import Table

    from ..evals.query_types import type_title

    table = Table(title="O-SR (%) by query type")
    table.add_column("variant", no_wrap=True)
    for t in summary["types"]:
        table.add_column(type_title(t), justify="right")
    for column in ("overall", "MRR", "top-3"):
        table.add_column(column, justify="right")
    for name, m in summary["methods"].items():
        o = m["overall"]
        table.add_row(name, *[f"{100 * m['by_type'][t]['osr']:.1f}" if t in m["by_type"] else "-"
                              for t in summary["types"]],
                      f"{100 * o['osr']:.1f}", f"{o['mrr']:.3f}", f"{100 * o['top3']:.1f}")
    console = Console(width=None if sys.stdout.isatty() else 160)  # no truncated columns in logs
    console.print(table)
    _print_groups(console, summary)


def _print_groups(console, summary: dict) -> None:
    """Paraphrase consistency per variant (suites with groups) and each variant's worst groups."""
    from rich.table import Table

    from ..evals.query_types import ordered_types, type_title

    grouped = {name: m["groups"] for name, m in summary["methods"].items() if "groups" in m}
    if not grouped:
        return
    types = ordered_types({t for g in grouped.values() for t in g["by_type"]})
    table = Table(title="Paraphrase groups (%): all wordings correct / same pick")
    for column in ("variant", "groups", "O-SR", "all correct", "same pick", *map(type_title, types)):
        table.add_column(column, justify="left" if column == "variant" else "right", no_wrap=column == "variant")
    for name, g in grouped.items():
        o = g["overall"]
        cells = [f"{100 * g['by_type'][t]['all_correct']:.0f} / {100 * g['by_type'][t]['consistent_pick']:.0f}"
                 if t in g["by_type"] else "-" for t in types]
        table.add_row(name, str(o["n"]), f"{100 * summary['methods'][name]['overall']['osr']:.1f}",
                      f"{100 * o['all_correct']:.1f}", f"{100 * o['consistent_pick']:.1f}", *cells)
    console.print(table)
    for name, g in grouped.items():
        for w in g["worst"][:3]:
            picks = ", ".join(f"{r['query']!r} -> {r['predicted']}{'' if r['correct'] else ' (wrong)'}"
                              for r in w["wordings"])
            console.print(f"worst {name} {w['group']} {w['correct']}/{w['n']}: {picks}", markup=False,
                          highlight=False)


def gen_queries_command(
    maps: List[str] = typer.Argument(..., help="Map files (.iesm) or shipped map names (apartment)."),
    types: str = typer.Option("o,or,od,ord,ard", "--types", help="Query types, comma separated."),
    per_type: int = typer.Option(10, "--per-type", "-n", help="Queries per type and map."),
    seed: int = typer.Option(0, "--seed", help="Random seed (same seed, same suite)."),
    paraphrases: int = typer.Option(1, "--paraphrases", "-k",
                                    help="Wordings per intent; K > 1 writes paraphrase groups (`group`)."),
    id_prefix: str = typer.Option("", "--id-prefix",
                                  help="Prefix for every query id and group (suites from two seeds evaluated together)."),
    out: Path = typer.Option(..., "--out", "-o", help="Suite file to write (JSONL)."),
    provider: Optional[str] = typer.Option(None, "--provider", "-p",
                                           help="Let this model write the queries (prompts/gen_queries.j2); "
                                                "templates otherwise."),
    base_url: Optional[str] = typer.Option(None, "--base-url", help="Endpoint for openai-compat providers."),
    gt: Optional[Path] = typer.Option(None, "--gt", help="Frame directory with gt/: write the queries from its "
                                                         "ground truth, translated to the ids of MAP (a built map)."),
) -> None:
    """Generate a query suite of the paper's five types from map instances."""
    from ..evals.generate import check_options, generate_suite, parse_types

    check_options(per_type, paraphrases, id_prefix)

    model = None
    if provider is not None:
        from ..errors import IesmError
        from ..providers import get_model

        if provider == "offline":
            raise IesmError("the offline model does not write queries; leave out --provider to use templates",
                            "--provider")
        model = get_model(provider, base_url=base_url, cache=True)
    if gt is not None:
        from ..errors import IesmError
        from ..evals.gt_queries import generate_gt_suite

        if len(maps) != 1:
            raise IesmError("--gt takes exactly one MAP (the map built from that frame directory)", "--gt")
        result, counts = asyncio.run(generate_gt_suite(maps[0], gt, out, parse_types(types), per_type=per_type,
                                                       seed=seed, model=model, paraphrases=paraphrases,
                                                       id_prefix=id_prefix))
        print(f"{len(result.queries)} queries from the ground truth in {gt} ({counts.matched} targets paired by "
              f"footprint IoU, {counts.own} by their own instances); {counts.dropped} dropped (target not "
              f"held in {maps[0]})")
        return
    result = asyncio.run(generate_suite(maps, out, parse_types(types), per_type=per_type, seed=seed, model=model,
                                        paraphrases=paraphrases, id_prefix=id_prefix))
    for line in result.report_lines():
        print(line)


def register(app: typer.Typer) -> None:
    app.command("eval")(eval_command)
    app.command("gen-queries")(gen_queries_command)
