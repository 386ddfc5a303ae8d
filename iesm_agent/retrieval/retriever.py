"""`Retriever`: one query in, one `RetrievalResult` out, whatever the model does.

Methods: `mtefr` (gate + all experts + fusion), `mtefr-uniform` (the same experts fused with
uniform weights: the gate switched off, to measure what it adds), `experts:<a>,<b>` (MTEFR
restricted to those experts, the paper's ablations), `spr` (single pass over all fields) and
`keyword` (HOV-SG style).
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Iterable, Sequence
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

from ..config import RetrievalConfig
from ..errors import IesmError
from ..prompting import Fenced, FencedList, PromptLibrary
from ..providers import Model, get_model
from .baselines import run_keyword, run_spr
from .calls import Outcome, Session
from .candidates import Candidates, reference_ids, select_candidates
from .experts import ExpertSpec, load_experts
from .fusion import fuse
from .mtefr import run_mtefr
from .result import RetrievalResult

METHODS = ("mtefr", "mtefr-uniform", "spr", "keyword", "experts:<name>,<name>")
#: ids whose display names a result carries besides the experts' picks
_NAMED_TOP = 5


def resolve_method(method: str, registry: dict[str, ExpertSpec]) -> tuple[str, list[ExpertSpec]]:
    """(normalised method, experts it uses); unknown methods or experts raise IesmError."""
    method = method.strip()
    if method in ("spr", "keyword"):
        return method, []
    if method in ("mtefr", "mtefr-uniform"):
        if not registry:
            raise IesmError("no expert specs found", "experts")
        return method, list(registry.values())
    if method.startswith("experts:"):
        names = list(dict.fromkeys(n.strip() for n in method[len("experts:"):].split(",") if n.strip()))
        unknown = [n for n in names if n not in registry]
        if not names or unknown:
            raise IesmError(f"unknown expert(s) {unknown or names}; known: {', '.join(registry)}", "method", method)
        return f"experts:{','.join(names)}", [registry[n] for n in names]
    raise IesmError(f"unknown retrieval method {method!r}; known: {', '.join(METHODS)}", "method")


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
        self.method, self.experts = resolve_method(method, self.registry)
        self.model = get_model(provider, cache=cache)
        self._views: dict[tuple[str, ...], dict[int, dict]] = {}
        self._template_hashes: dict[str, str] = {}

    def _candidate_views(self, ids: Sequence[int], query: str = ""):
        """views(fields) -> the candidates' views with those fields, built once per field set
        for this query (experts sharing fields share one rendered candidate block);
        views.references(fields) -> the same for `candidates.reference_ids` (spatial landmarks)."""
        built: dict[tuple[str, ...], FencedList] = {}
        landmarks: list[tuple[int, ...]] = []

        def references(fields: Sequence[str]) -> FencedList:
            if not landmarks:
                landmarks.append(reference_ids(self.store, query, tuple(ids)))
            return FencedList(Fenced(self.store.candidate_view(i, list(fields))) for i in landmarks[0])

        def views(fields: Sequence[str]) -> FencedList:
            key = tuple(fields)
            if key not in built:
                cache = self._views.setdefault(key, {})
                for i in ids:
                    if i not in cache:
                        cache[i] = Fenced(self.store.candidate_view(i, list(fields)))
                built[key] = FencedList(cache[i] for i in ids)
            return built[key]
        views.references = references
        return views

    async def aask(self, query: str, *, target: int | None = None) -> RetrievalResult:
        """Retrieve the instance `query` refers to; `target` (ground truth) records candidate recall.
        When the model's context window is known (or learnt from a refusal, then the query runs
        once more) the candidate set is cut, best candidates kept, until every prompt fits."""
        started = time.perf_counter()
        selected = select_candidates(self.store, query, self.config.max_candidates, target)
        candidates = await self._fit(query, selected, target)
        outcome, session = await self._run(query, candidates)
        if session.overflowed and len(candidates.ids) > 1:
            refit = await self._fit(query, candidates, target)
            if refit.ids != candidates.ids:
                candidates = refit
                outcome, session = await self._run(query, candidates)
        before = len(selected.ids) if candidates.ids != selected.ids else None
        return self._result(query, outcome, session, candidates, target, started, before)

    async def _run(self, query: str, candidates: Candidates, dry_run: bool = False) -> tuple[Outcome, Session]:
        """Run the method over `candidates` (`dry_run`: render its prompts, send nothing)."""
        session = Session(self.model, self.prompts, self._template_hashes, dry_run=dry_run)
        views = self._candidate_views(candidates.ids, query)
        if self.method == "keyword":
            outcome = await run_keyword(session, self.store, query, self.config)
        elif not candidates.ids:
            outcome = Outcome()
        elif self.method == "spr":
            outcome = await run_spr(session, query, candidates.ids, views, self.config)
        else:
            outcome = await run_mtefr(session, query, self.experts, candidates.ids, views, self.config,
                                      gate=self.method != "mtefr-uniform")
        return outcome, session

    async def _fit(self, query: str, candidates: Candidates, target: int | None) -> Candidates:
        """The longest prefix of `candidates` whose prompts all fit the model's prompt limit
        (estimated tokens); unchanged when the limit is unknown or it already fits. At least
        one candidate is kept: a prompt that cannot fit even then is refused by the model."""
        limit = await self.model.aprompt_limit()
        ids = candidates.ids
        if limit is None or self.method == "keyword":
            return candidates
        while len(ids) > 1:
            _, dry = await self._run(query, Candidates(ids, candidates.considered), dry_run=True)
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
            calls=calls, failures=session.failures, candidate_ids=list(candidates.ids),
            instances_considered=candidates.considered, target=target, candidate_recall=candidates.recall,
            candidates_before_fit=before_fit,
            latency_ms=(time.perf_counter() - started) * 1000.0,
            tokens=sum(c.prompt_tokens + c.completion_tokens for c in calls),
            cache_hits=sum(c.cached for c in calls))
