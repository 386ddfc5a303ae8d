"""`Retriever`: one query in, one `RetrievalResult` out, whatever the model does.

The method is looked up by name in `methods` (mtefr, mtefr-uniform, experts:<a>,<b>, spr,
keyword, or one added with `register_method`).
"""

from __future__ import annotations

import asyncio
import math
import time
from collections.abc import Iterable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

from ..config import RetrievalConfig
from ..errors import IesmError
from ..embeddings import load_seconds
from ..prompting import Fenced, PromptLibrary
from ..providers import Model, get_model
from ..understanding import QueryInfo, analyse_query
from .calls import Outcome, Session
from .candidates import Candidates, CandidateViews, select_candidates
from .experts import load_experts
from .fusion import fuse
from .methods import QueryContext, resolve_method
from .result import RetrievalResult

#: ids whose display names a result carries besides the experts' picks
_NAMED_TOP = 5
#: the longest query accepted, in characters
MAX_QUERY_CHARS = 2000


def check_query(query: str) -> str:
    """`query` when it is a usable request; an empty, wordless or over-long one is an `IesmError` naming
    the argument (the CLI and the server refuse it before any model call)."""
    if not query.strip():
        raise IesmError("the query is empty", None, "query")
    if not any(c.isalnum() for c in query):  # "@@@", an emoji: nothing to read
        raise IesmError("the query has no word (no letter or digit)", None, "query")
    if len(query) > MAX_QUERY_CHARS:
        raise IesmError(f"the query has {len(query)} characters; at most {MAX_QUERY_CHARS} are accepted",
                        None, "query")
    try:
        query.encode("utf-8")
    except UnicodeEncodeError as exc:  # bytes that are not UTF-8 (from argv) or lone surrogates
        raise IesmError(f"the query is not valid text (character {exc.start + 1} cannot be encoded)",
                        None, "query") from None
    return query


class Retriever:
    """Answers queries over `store` (a MapStore) with `provider` (a spec such as "offline" or a
    `Model`). `cache` as in `providers.get_model`. Never raises on model misbehaviour: failures
    are recorded in the result."""

    def __init__(self, store: Any, provider: str | Model = "offline", method: str = "mtefr",
                 config: RetrievalConfig | None = None, prompts_dir: str | Path | None = None,
                 experts_dirs: Iterable[str | Path] = (), cache: bool | str | Path | None = None):
        self.store = store
        self.config = config or RetrievalConfig()
        self.prompts = PromptLibrary([prompts_dir] if prompts_dir else [])
        self.registry = load_experts(experts_dirs)
        self.runner = resolve_method(method, self.registry)
        self.method = self.runner.name
        self.model = get_model(provider, cache=cache)
        if self.config.max_candidates is None:  # the model's own budget
            self.config = self.config.model_copy(update={"max_candidates": self.model.candidate_budget})
        self._views: dict[tuple[str, ...], dict[int, Fenced]] = {}
        self._template_hashes: dict[str, str] = {}

    async def aask(self, query: str, *, target: int | None = None) -> RetrievalResult:
        """Retrieve the instance `query` refers to; `target` (ground truth) records candidate recall.
        When the model's context window is known (or learnt from a refusal, then the query runs
        once more) the candidate set is cut, best candidates kept, until every prompt fits."""
        started, loaded_before = time.perf_counter(), load_seconds()
        deadline = time.monotonic() + self.config.deadline_s
        info = analyse_query(query)
        selected = select_candidates(self.store, query, info, self.config.max_candidates, target)
        candidates = await self._fit(query, info, selected, target)
        outcome, session = await self._run(query, info, candidates, selected.ids, deadline=deadline)
        if session.overflowed and len(candidates.ids) > 1:
            refit = await self._fit(query, info, candidates, target, selected.ids)
            if refit.ids != candidates.ids:
                candidates = refit
                outcome, session = await self._run(query, info, candidates, selected.ids, deadline=deadline)
        before = len(selected.ids) if candidates.ids != selected.ids else None
        result = self._result(query, outcome, session, candidates, target, started, before)
        result.load_ms = (load_seconds() - loaded_before) * 1000.0  # the encoder loaded for this query
        result.latency_ms -= result.load_ms
        return result

    async def _run(self, query: str, info: QueryInfo, candidates: Candidates, selected: tuple[int, ...],
                   dry_run: bool = False, deadline: float = math.inf) -> tuple[Outcome, Session]:
        """Run the method over `candidates` (`dry_run`: render its prompts, send nothing; every
        call ends by `deadline`, monotonic s); the instances `selected` before a cut to the
        context window are never shown as references, so cutting the candidates always shrinks
        the prompts."""
        session = Session(self.model, self.prompts, self._template_hashes, dry_run=dry_run, deadline=deadline)
        views = CandidateViews(self.store, info, candidates.ids, self._views, not_references=selected)
        outcome = await self.runner.run(QueryContext(query, info, self.store, candidates, views, session, self.config))
        return outcome, session

    async def _fit(self, query: str, info: QueryInfo, candidates: Candidates, target: int | None,
                   selected: tuple[int, ...] | None = None) -> Candidates:
        """The longest prefix of `candidates` whose prompts all fit the model's prompt limit
        (estimated tokens); unchanged when the limit is unknown or it already fits. At least
        one candidate is kept: a prompt that cannot fit even then is refused by the model."""
        limit = await self.model.aprompt_limit()
        ids = candidates.ids
        if limit is None or self.method == "keyword":
            return candidates
        while len(ids) > 1:
            _, dry = await self._run(query, info, Candidates(ids, candidates.considered),
                                     selected or candidates.ids, dry_run=True)
            need = max(dry.estimates, default=0)
            if need <= limit:
                break
            ids = ids[:max(1, min(len(ids) - 1, len(ids) * limit // need))]
        if ids == candidates.ids:
            return candidates
        return Candidates(ids=ids, considered=candidates.considered,
                          recall=None if target is None else target in ids)

    def ask(self, query: str, *, target: int | None = None) -> RetrievalResult:
        """Synchronous `aask`; from inside a running event loop it runs on a worker thread."""
        try:
            asyncio.get_running_loop()
        except RuntimeError:
            return asyncio.run(self.aask(query, target=target))
        with ThreadPoolExecutor(1) as pool:
            return pool.submit(asyncio.run, self.aask(query, target=target)).result()

    async def aclose(self) -> None:
        """Release the model's connections (also when the model was passed in)."""
        await self.model.aclose()

    def _name(self, instance_id: int) -> str:
        view = self.store.candidate_view(instance_id, ["label", "room"])
        return f"{view['label']} ({view['room']})" if view["room"] else view["label"]

    def _result(self, query: str, outcome: Outcome, session: Session, candidates: Candidates,
                target: int | None, started: float, before_fit: int | None) -> RetrievalResult:
        cfg = self.config
        fusion = outcome.fusion or fuse({}, {}, kappa=cfg.kappa, gamma=cfg.gamma, mu=cfg.mu)
        seen = set(fusion.ranking)
        ranking = list(fusion.ranking) + [i for i in candidates.ids if i not in seen]
        chosen = self.store.candidate_view(fusion.best, ["label", "room", "caption"]) if fusion.best is not None else {}
        mentioned = {i for ids in outcome.experts.values() for i in ids} | set(ranking[:_NAMED_TOP])
        calls = session.calls
        return RetrievalResult(
            query=query, method=self.method, instance_id=fusion.best,
            label=chosen.get("label"), room=chosen.get("room"), caption=chosen.get("caption"), ranking=ranking, scores=fusion.scores,
            sum_scores=fusion.sum_scores, peak_scores=fusion.peak_scores, lam=fusion.lam, kappa=cfg.kappa,
            deciding_expert=fusion.deciding_expert() if outcome.gate else None, gate=outcome.gate, hints=outcome.hints,
            experts=outcome.experts, names={i: self._name(i) for i in sorted(mentioned)},
            calls=calls, failures=session.failures, notes=session.notes,
            abstained=dict(fusion.abstained) if outcome.gate else {}, candidate_ids=list(candidates.ids),
            instances_considered=candidates.considered, target=target, candidate_recall=candidates.recall,
            candidates_before_fit=before_fit,
            latency_ms=(time.perf_counter() - started) * 1000.0,
            tokens=sum(c.prompt_tokens + c.completion_tokens for c in calls),
            prompt_tokens=sum(c.prompt_tokens for c in calls), cached_tokens=sum(c.cached_tokens for c in calls),
            completion_tokens=sum(c.completion_tokens for c in calls),
            cache_hits=sum(c.cached for c in calls))
