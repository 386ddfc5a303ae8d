"""`iesm ask MAP QUERY`: retrieve the instance a sentence refers to, with the evidence."""

from __future__ import annotations

import asyncio
import sys
from pathlib import Path

import typer


def open_store(map_ref: str):
    """A MapStore from a `.iesm` file, an importable JSON file or a shipped map name."""
    from ..store import MapStore, open_map

    return MapStore(open_map(map_ref))


def ask_command(
    map_ref: str = typer.Argument(..., metavar="MAP", help="A .iesm file, an importable JSON map, or a shipped map name (e.g. apartment)."),
    query: str = typer.Argument(..., help="The sentence naming the goal object."),
    provider: str = typer.Option("offline", "--provider", "-p", help="Model spec, e.g. offline, openai:gpt-4o-mini."),
    method: str = typer.Option("mtefr", "--method", "-m", help="mtefr, spr, keyword or experts:obj,desc,..."),
    as_json: bool = typer.Option(False, "--json", help="Print the full result as JSON."),
    explain: bool = typer.Option(False, "--explain", help="Explain the decision (weights, rankings, scores)."),
    base_url: str | None = typer.Option(None, "--base-url", help="Endpoint for openai-compat providers."),
    no_cache: bool = typer.Option(False, "--no-cache", help="Do not use the response cache (on by default except offline)."),
    kappa: int | None = typer.Option(None, "--kappa", help="Top-k per expert (paper: 2)."),
    experts_dir: list[Path] = typer.Option([], "--experts-dir", help="Extra expert spec directory (repeatable)."),
    prompts: Path | None = typer.Option(None, "--prompts", help="Prompt directory overriding shipped templates."),
    max_candidates: int | None = typer.Option(None, "--max-candidates", help="Candidates sent to the model at most "
                                              "(the best by a cheap pre-ranking; default 20 for LLM endpoints, 100 offline)."),
    max_concurrency: int = typer.Option(8, "--max-concurrency", help="Model requests in flight at once (fewer when "
                                        "the server reports fewer slots)."),
    dialect: str | None = typer.Option(None, "--dialect", help="Structured output as json_schema, json_object or "
                                       "prompt (no grammar) instead of negotiating it (HTTP providers)."),
    deadline: float | None = typer.Option(None, "--deadline", help="Seconds within which every model call of the "
                                          "query ends, and one request may wait (default 60)."),
) -> None:
    """Retrieve the map instance QUERY refers to (MTEFR by default)."""
    from ..config import load_settings
    from ..providers import get_model
    from ..retrieval import Retriever
    from ..retrieval.retriever import check_query

    check_query(query)
    if max_concurrency < 1:
        from ..errors import IesmError

        raise IesmError(f"must be >= 1, got {max_concurrency}", None, "--max-concurrency")
    store = open_store(map_ref)
    overrides = {"retrieval.kappa": kappa, "retrieval.max_candidates": max_candidates, "retrieval.deadline_s": deadline}
    config = load_settings(None, {k: v for k, v in overrides.items() if v is not None}).retrieval
    # a deadline also lets one request wait that long (a local server reading a long prompt)
    opts = {"deadline": deadline, "timeout": deadline} if deadline is not None else {}
    model = get_model(provider, base_url=base_url, cache=not no_cache, concurrency=max_concurrency,
                      **opts, **({"dialect": dialect} if dialect else {}))
    retriever = Retriever(store, provider=model, method=method, config=config, prompts_dir=prompts,
                          experts_dirs=experts_dir)

    async def run():
        try:
            return await retriever.aask(query)
        finally:
            await retriever.aclose()

    result = asyncio.run(run())
    if result.calls and result.failed_calls == len(result.calls):  # e.g. nothing listens there
        from ..errors import IesmError

        raise IesmError(f"all {len(result.calls)} model calls failed; the first: {result.calls[0].error}",
                        provider)
    if as_json:
        print(result.model_dump_json(indent=2))
    else:
        _print_human(result, explain)
    if as_json and explain:
        print(result.explain())
    if result.instance_id is None:
        raise typer.Exit(1)  # nothing retrieved (the output says why)


def _print_human(result, explain: bool) -> None:
    """The chosen instance, then either the short evidence (gate, experts' picks) or, with
    `explain`, the full explanation (scores and the deciding expert too). Plain text: no
    terminal library to import at start-up, and clean in pipes and logs."""
    lines = []
    if result.instance_id is None:
        lines.append("no instance found")
    else:
        lines.append(f"#{result.instance_id} {result.label or ''} in {result.room or 'no room'}")
        if result.caption:
            lines.append(f"  {result.caption}")
    if explain:
        lines.append(result.explain())
    else:
        if result.gate:
            lines.append("gate: " + "  ".join(f"{e} {w:.2f}" for e, w in
                                             sorted(result.gate.items(), key=lambda kv: -kv[1])))
        for expert, ids in result.experts.items():
            picks = ", ".join(f"#{i} {result.names.get(i, '?')}" for i in ids) or "(nothing)"
            lines.append(f"  {expert}: {picks}")
    loading = f" (+ {result.load_ms:.0f} ms loading the sentence encoder)" if result.load_ms >= 1 else ""
    lines.append(f"{result.latency_ms:.0f} ms{loading}, {len(result.calls)} calls, {result.cache_hits} cached")
    if not explain and (result.prompt_tokens or result.candidates_cut):
        lines.append(result.cost_line())
    print("\n".join(lines))
    if result.calls and all(c.error for c in result.calls):
        print(f"error: all {len(result.calls)} model calls failed; the first: {result.calls[0].error}",
              file=sys.stderr)
    elif not explain:  # the explanation lists the failures
        for failure in result.failures:
            print(f"warning: {failure}", file=sys.stderr)


def register(app: typer.Typer) -> None:
    app.command("ask")(ask_command)
