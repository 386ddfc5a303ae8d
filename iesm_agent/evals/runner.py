"""The eval runner: suites x variants (method [+ prompt dir]) with bounded concurrency.

Each finished (query, variant) is appended to `RUN_DIR/results.jsonl` at once, so a killed run
loses at most the queries in flight; `resume=True` skips the pairs already journaled
whose model calls all got a reply (a pair with failed calls is asked again). The run's
configuration is kept in `RUN_DIR/run.json` and a resume under another configuration is refused.
"""

from __future__ import annotations

import asyncio
import hashlib
import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Optional

from pydantic import BaseModel, ConfigDict, ValidationError

from ..errors import IesmError
from ..fileio import MAX_TEXT_BYTES, load_json, read_bytes, recordable_path, validation_message
from ..providers.base import Model
from ..retrieval.methods import is_method_name
from .journal import RESULTS, RUN_CONFIG, ResultRecord, append_record, read_journal, repair_journal
from .prompt_log import PromptRecorder, journaled_calls, template_hashes
from .report import write_outputs
from .summary import build_summary
from .suite import MapRegistry, Suite, SuiteEntry, load_suites



class Variant(BaseModel):
    """A retrieval method, optionally with a prompt directory overriding the shipped templates."""

    name: str
    method: str
    prompts_dir: Optional[str] = None


class RunConfig(BaseModel):
    """What determines a run's results; a resume must match it exactly."""

    model_config = ConfigDict(extra="forbid")

    suites: list[str]
    suites_sha256: str
    variants: list[Variant]
    provider: str
    base_url: Optional[str] = None
    cache: bool = False
    skip_invalid: bool = False
    experts_dirs: list[str] = []
    #: ground truth for N-SR: "DIR" (the suite's one map with starts) or "MAP=DIR"
    gt: list[str] = []
    #: variant -> template name -> sha256 (12 hex) of its source: the prompts by content, not path
    prompt_hashes: dict[str, dict[str, str]] = {}
    #: candidates sent to the model at most (None: the default of `RetrievalConfig`)
    max_candidates: Optional[int] = None
    #: seconds within which every model call of one query ends (None: the default)
    deadline_s: Optional[float] = None
    #: model requests in flight at once (None: the provider's default)
    max_concurrency: Optional[int] = None
    #: structured-output dialect instead of a negotiated one (None: negotiated)
    dialect: Optional[str] = None

    def retrieval_config(self):
        """The `RetrievalConfig` of this run."""
        from ..config import RetrievalConfig

        values = {"max_candidates": self.max_candidates, "deadline_s": self.deadline_s}
        try:
            return RetrievalConfig(**{k: v for k, v in values.items() if v is not None})
        except ValidationError as exc:
            raise IesmError(validation_message(exc), "eval") from None


def split_methods(specs: list[str]) -> list[str]:
    """Comma lists of methods; a bare expert name continues the `experts:` list before it,
    so `mtefr,experts:obj,desc,spr` -> [mtefr, experts:obj,desc, spr]."""
    methods: list[str] = []
    for token in (t.strip() for spec in specs for t in spec.split(",")):
        if not token:
            continue
        if is_method_name(token) or not methods or not methods[-1].startswith("experts:"):
            methods.append(token)
        else:
            methods[-1] += f",{token}"
    return methods


#: the name `--prompts` takes for the shipped templates
SHIPPED_PROMPTS = "default"


def make_variants(methods: list[str], prompt_dirs: list[str | Path]) -> list[Variant]:
    """One variant per method, or per (method, prompt dir) named `method@dirname`; the prompt dir
    `default` names the shipped templates (`method@default`), to compare against them."""
    if not methods:
        raise IesmError("no retrieval method given", "--method")
    if not prompt_dirs:
        return [Variant(name=m, method=m) for m in dict.fromkeys(methods)]
    labels: dict[str, Path | None] = {}
    for d in map(Path, prompt_dirs):
        if str(d) == SHIPPED_PROMPTS and not d.is_dir():
            labels[SHIPPED_PROMPTS] = None  # `--prompts default`: the shipped templates, as a variant
            continue
        if not d.is_dir():
            raise IesmError("prompt directory does not exist (use 'default' for the shipped prompts)", d)
        label = d.resolve().name or "prompts"
        labels[label if label not in labels else f"{label}{len(labels)}"] = d.resolve()
    return [Variant(name=f"{m}@{label}", method=m, prompts_dir=str(d) if d else None)
            for m in dict.fromkeys(methods) for label, d in labels.items()]


def make_config(suite_paths: list[str | Path], variants: list[Variant], provider: str, *,
                base_url: str | None = None, cache: bool = False, skip_invalid: bool = False,
                experts_dirs: list[str | Path] = (), gt: list[str] = (), max_candidates: int | None = None,
                deadline_s: float | None = None, max_concurrency: int | None = None,
                dialect: str | None = None) -> RunConfig:
    paths = [Path(p).resolve() for p in suite_paths]
    digest = hashlib.sha256()
    for path in paths:
        recordable_path(path)
        try:  # a regular file of bounded size (a FIFO or /dev/zero is refused, not read)
            digest.update(read_bytes(path, MAX_TEXT_BYTES))
        except IesmError as exc:
            raise IesmError(f"cannot read suite: {exc.message}", path) from None
    for variant in variants:
        if variant.prompts_dir is not None:
            recordable_path(variant.prompts_dir, "--prompts")
    return RunConfig(suites=[str(p) for p in paths], suites_sha256=digest.hexdigest(), variants=variants,
                     provider=provider, base_url=base_url, cache=cache, skip_invalid=skip_invalid,
                     experts_dirs=[recordable_path(Path(d).resolve(), "--experts-dir") for d in experts_dirs],
                     gt=[recordable_path(_resolve_gt(g), "--gt") for g in gt],
                     prompt_hashes={v.name: template_hashes(v.prompts_dir) for v in variants},
                     max_candidates=max_candidates, deadline_s=deadline_s, max_concurrency=max_concurrency,
                     dialect=dialect)


def _resolve_gt(spec: str) -> str:
    """`--gt` as given, with its frame directory (and map file) made absolute."""
    ref, sep, directory = spec.rpartition("=")
    path = Path(directory)
    if not (path / "gt").is_dir():
        raise IesmError("not a frame directory with ground truth (no gt/)", path, "--gt")
    if sep and Path(ref).exists():
        ref = str(Path(ref).resolve())
    return f"{ref}={path.resolve()}" if sep else str(path.resolve())


def nav_ground_truth(specs: list[str], map_paths: set[Path]) -> dict[Path, Path]:
    """Built map path -> frame directory whose ground truth judges N-SR there. A bare DIR belongs
    to the suites' one map with robot starts (`map_paths`); MAP=DIR names the map."""
    from ..store.refs import resolve_map_path

    out: dict[Path, Path] = {}
    for spec in specs:
        ref, sep, directory = spec.rpartition("=")
        if sep:
            out[resolve_map_path(ref, Path.cwd())] = Path(directory)
        elif len(map_paths) == 1:
            out[next(iter(map_paths))] = Path(directory)
        else:
            raise IesmError(f"the suites have {len(map_paths)} maps with robot starts: say which one this "
                            "ground truth belongs to with MAP=DIR", None, "--gt")
    return out


def prepare_run_dir(run_dir: Path, config: RunConfig, resume: bool) -> None:
    """Refuse a non-empty run dir without `resume`, or a resume under another configuration;
    then record the configuration."""
    stored = run_dir / RUN_CONFIG
    if resume and stored.exists():
        try:
            previous = RunConfig.model_validate(load_json(stored))
        except IesmError as exc:
            raise IesmError(f"cannot read the stored run configuration: {exc.message}", stored, exc.where) from None
        except ValidationError as exc:
            message, field = validation_message(exc)
            raise IesmError(f"cannot read the stored run configuration: {message}", stored, field) from None
        old, new = previous.model_dump(), config.model_dump()
        changed = [k for k in new if old.get(k) != new[k]]
        if changed:
            raise IesmError(f"refusing to resume: this run was made with a different {', '.join(changed)} "
                            "(start a new run directory instead)", stored)
    elif run_dir.exists() and any(run_dir.iterdir()):
        if not resume:
            raise IesmError("run directory is not empty: pass --resume to continue that run, "
                            "or choose another -o", run_dir)
        raise IesmError(f"cannot resume: no {RUN_CONFIG} in a non-empty run directory", run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    tmp = stored.with_suffix(".tmp")
    tmp.write_text(config.model_dump_json(indent=2) + "\n", encoding="utf-8")
    tmp.replace(stored)


def check_variants(config: RunConfig) -> None:
    """Every variant's method and prompt directory, and the expert directories, are usable
    (an `IesmError` naming the first that is not)."""
    from ..retrieval.experts import load_experts
    from ..retrieval.methods import resolve_method

    registry = load_experts(config.experts_dirs)
    for variant in config.variants:
        resolve_method(variant.method, registry)
        if variant.prompts_dir is not None and not Path(variant.prompts_dir).is_dir():
            raise IesmError("prompt directory does not exist", variant.prompts_dir)


def _rank(ranking: list[int], scored: set[int], accept: list[int]) -> Optional[int]:
    """Rank of the first accepted id within the full candidate `ranking`, the same depth for
    every method: the ids the method `scored` first in its order, then the rest tied, each
    counted at its expected position under a random order, rounded up (k accepted among n
    unscored: len(scored) + ceil((n + 1) / (k + 1))). A method that scores 2 ids and one that
    scores 10 are judged on the same full ranking; the candidates' padding order plays no part.
    None when no candidate is accepted."""
    import math

    accepted = set(accept)
    head = [i for i in ranking if i in scored]
    rank = next((k for k, iid in enumerate(head, start=1) if iid in accepted), None)
    if rank is not None:
        return rank
    tail = [i for i in ranking if i not in scored]
    hits = sum(i in accepted for i in tail)
    return len(head) + math.ceil((len(tail) + 1) / (hits + 1)) if hits else None


@dataclass
class RunOutcome:
    records: list[ResultRecord]
    suite: Suite
    done_before: int
    new: int
    wall_s: float


def _build_model(config: RunConfig) -> Model:
    from ..providers import get_model

    opts = {"concurrency": config.max_concurrency} if config.max_concurrency else {}
    if config.dialect:
        opts["dialect"] = config.dialect
    if config.deadline_s:  # a deadline also lets one request wait that long
        opts["deadline"] = opts["timeout"] = config.deadline_s
    return get_model(config.provider, base_url=config.base_url, cache=config.cache, **opts)


async def run_eval(config: RunConfig, run_dir: str | Path, *, resume: bool = False, concurrency: int = 4,
                   model: Model | None = None, keep_prompts: bool = False,
                   on_start: Callable[[int], None] | None = None,
                   on_result: Callable[[ResultRecord], None] | None = None) -> RunOutcome:
    """Run (or resume) the evaluation described by `config` into `run_dir`. `model` overrides
    the provider named in the config (tests); `on_start(n_pending)` and `on_result` drive a
    progress display. The response cache (if on) lives in `$IESM_CACHE_DIR` or the user cache.
    `keep_prompts` journals every call's rendered prompt and raw reply (for the HTML report)."""
    from ..retrieval import Retriever
    from ..store.mapstore import MapStore

    if concurrency < 1:
        raise IesmError("concurrency must be at least 1", "--concurrency")
    run_dir = Path(run_dir)
    registry = MapRegistry()
    suite = load_suites(config.suites, skip_invalid=config.skip_invalid, registry=registry)
    check_variants(config)  # before the run directory is made: a typo leaves nothing behind
    retrieval = config.retrieval_config()
    model = model or _build_model(config)
    recorder = PromptRecorder(model) if keep_prompts else None
    model = recorder or model
    try:
        prepare_run_dir(run_dir, config, resume)
    except BaseException:
        await model.aclose()
        raise
    journal = run_dir / RESULTS
    repair_journal(journal)
    # the last record of a key wins (a resumed query replaces its failed record); queries whose
    # model calls failed are asked again
    latest = {r.key: r for r in read_journal(journal)}
    previous = [r for r in latest.values() if r.failed_calls == 0]
    done = {r.key for r in previous}
    jobs = [(e, v) for e in suite.entries for v in config.variants if (e.query.id, v.name) not in done]
    if on_start:
        on_start(len(jobs))

    stores = {path: MapStore(registry.get(path)) for path in {e.map_path for e, _ in jobs}}
    with_starts = {e.map_path for e in suite.entries if e.query.start is not None}
    navs = {}
    if config.gt:  # the simulator's ground truth is read only when N-SR is asked for
        from ..sim.ground_truth import GroundTruth
        from .navigation import NavTrials

        navs = {path: NavTrials.for_map(registry.get(path), GroundTruth.load(directory), directory)
                for path, directory in nav_ground_truth(config.gt, with_starts).items() if path in stores}
    retrievers = {(path, v.name): Retriever(store, provider=model, method=v.method, config=retrieval,
                                            prompts_dir=v.prompts_dir, experts_dirs=config.experts_dirs, cache=False)
                  for path, store in stores.items() for v in config.variants}
    new: list[ResultRecord] = []
    started = time.perf_counter()

    with journal.open("a", encoding="utf-8") as handle:
        pending = iter(jobs)

        async def worker() -> None:
            for entry, variant in pending:
                record = await _ask(retrievers[entry.map_path, variant.name], entry, variant, navs.get(entry.map_path),
                                    recorder)
                append_record(handle, record)
                new.append(record)
                if on_result:
                    on_result(record)

        tasks = [asyncio.create_task(worker()) for _ in range(min(concurrency, max(len(jobs), 1)))]
        try:
            await asyncio.gather(*tasks)
        finally:
            for task in tasks:
                task.cancel()
            await asyncio.gather(*tasks, return_exceptions=True)
            await model.aclose()
    return RunOutcome(records=previous + new, suite=suite, done_before=len(previous), new=len(new),
                      wall_s=time.perf_counter() - started)


async def _ask(retriever, entry: SuiteEntry, variant: Variant, nav=None,
               recorder: PromptRecorder | None = None) -> ResultRecord:
    """One retrieval as a record; `ranking` lists the ids the method scored, `rank` is the target's
    rank within the full candidate ranking (`_rank`: unscored candidates tied). With `nav`
    (NavTrials) and a start, the simulated robot then goes to the retrieved instance (N-SR).
    The record keeps the evidence the HTML report shows (gate, experts, U/S/P, calls)."""
    from .navigation import record_fields

    q = entry.query
    res = await retriever.aask(q.query, target=q.target)
    scored = [i for i in res.ranking if i in res.scores]
    return ResultRecord(
        id=q.id, variant=variant.name, method=variant.method, type=q.type, group=q.group, map=q.map, query=q.query,
        target=q.target, predicted=res.instance_id, correct=res.instance_id in q.accept,
        rank=_rank(res.ranking, set(res.scores), q.accept), ranking=scored[:10], latency_ms=res.latency_ms,
        tokens=res.tokens, prompt_tokens=res.prompt_tokens, cached_tokens=res.cached_tokens,
        completion_tokens=res.completion_tokens, candidates_cut=res.candidates_cut,
        cache_hits=res.cache_hits, failures=res.failures, failed_calls=res.failed_calls,
        candidate_recall=res.candidate_recall, **record_fields(nav, q.start, res.instance_id),
        accept=q.accept, start=q.start, nav_path=_planned_path(nav, q.start, res.instance_id),
        gate=res.gate, hints=res.hints, experts=res.experts, abstained=res.abstained,
        scores={i: res.scores[i] for i in scored[:10]}, sum_scores={i: res.sum_scores.get(i, 0.0) for i in scored[:10]},
        peak_scores={i: res.peak_scores.get(i, 0.0) for i in scored[:10]}, lam=res.lam, kappa=res.kappa,
        deciding_expert=res.deciding_expert, notes=res.notes, names=res.names,
        calls=journaled_calls(res.calls, recorder))


def _planned_path(nav, start, predicted) -> list[tuple[float, float]]:
    """The path planned from `start` to the prediction (m, at most 200 points) when N-SR is measured."""
    if nav is None or start is None or predicted is None:
        return []
    waypoints = nav.planner.plan(predicted, start).waypoints
    if len(waypoints) > 200:
        waypoints = waypoints[:: len(waypoints) // 200 + 1] + waypoints[-1:]
    return [(round(x, 3), round(y, 3)) for x, y in waypoints]


def _shown(path: str) -> str:
    """`path` relative to the working directory when it lies below it."""
    rel = os.path.relpath(path)
    return path if rel.startswith("..") else Path(rel).as_posix()


def write_run_outputs(run_dir: str | Path, config: RunConfig, outcome: RunOutcome) -> dict:
    """Summary (with run facts and skipped suite lines), report and plot of a finished run."""
    summary = build_summary(outcome.records, [v.name for v in config.variants], {
        "run": {"provider": config.provider, "suites": [_shown(s) for s in config.suites], "queries": len(outcome.suite.entries),
                "variants": [v.model_dump() for v in config.variants], "results": len(outcome.records),
                "resumed_with": outcome.done_before, "new_results": outcome.new,
                "failed_calls": sum(r.failed_calls for r in outcome.records),
                "queries_with_failed_calls": sum(r.failed_calls > 0 for r in outcome.records),
                "wall_s": round(outcome.wall_s, 3),
                "results_per_s": round(outcome.new / outcome.wall_s, 2) if outcome.wall_s > 0 else None},
        "invalid_lines": [str(e) for e in outcome.suite.errors],
    })
    write_outputs(Path(run_dir), summary)
    return summary
