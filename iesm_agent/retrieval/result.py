"""What one retrieval returns: the chosen instance, the fused ranking and the evidence trail."""

from __future__ import annotations


from pydantic import BaseModel, Field

#: raw replies are kept up to this many characters in the trace
REPLY_CHARS = 2000


class CallTrace(BaseModel):
    """One model call: which prompt (template hash, sha256 of the rendered messages), the raw
    reply (truncated), cost (`latency_ms` = wall time of the call as awaited), and the error if
    the call or its parsing failed."""

    name: str
    template: str
    template_hash: str
    prompt_sha256: str
    reply: str = ""
    latency_ms: float = 0.0
    prompt_tokens: int = 0
    #: prompt tokens the server read from its prompt cache (included in `prompt_tokens`)
    cached_tokens: int = 0
    completion_tokens: int = 0
    #: the reply's bound (`max_tokens`, derived from the reply schema); None: unbounded
    max_tokens: int | None = None
    cached: bool = False
    #: what the client did on the way (e.g. the server refused a structured-output dialect, and why)
    notes: list[str] = Field(default_factory=list)
    error: str | None = None
    #: the call itself failed (no reply: endpoint error, timeout, refused prompt), as opposed to
    #: a reply that could not be used
    failed: bool = False


class RetrievalResult(BaseModel):
    """Outcome of `Retriever.ask`. `ranking` orders the whole candidate set: ids that scored,
    best first by U, then the rest in candidate order. `scores`/`sum_scores`/`peak_scores` are
    U, S_sum and P of the scored ids; `gate` the normalised expert weights; `experts` each
    expert's validated top-kappa; `deciding_expert` the one that most separates the chosen instance
    from the runner-up; `names` a display name ("label (room)") for the ids mentioned."""

    query: str
    method: str
    instance_id: int | None = None
    label: str | None = None
    room: str | None = None
    caption: str | None = None
    ranking: list[int] = Field(default_factory=list)
    scores: dict[int, float] = Field(default_factory=dict)
    sum_scores: dict[int, float] = Field(default_factory=dict)
    peak_scores: dict[int, float] = Field(default_factory=dict)
    lam: float | None = None
    kappa: int | None = None
    deciding_expert: str | None = None
    gate: dict[str, float] = Field(default_factory=dict)
    hints: dict[str, str] = Field(default_factory=dict)
    experts: dict[str, list[int]] = Field(default_factory=dict)
    names: dict[int, str] = Field(default_factory=dict)
    calls: list[CallTrace] = Field(default_factory=list)
    failures: list[str] = Field(default_factory=list)
    #: gate weight of each expert that abstained (returned no ranking); redistributed over the others
    abstained: dict[str, float] = Field(default_factory=dict)
    notes: list[str] = Field(default_factory=list)
    candidate_ids: list[int] = Field(default_factory=list)
    instances_considered: int = 0
    target: int | None = None
    candidate_recall: bool | None = None
    #: candidates selected before the set was cut to fit the model's context window (None: not cut)
    candidates_before_fit: int | None = None
    #: wall time of the query (ms), without `load_ms`
    latency_ms: float = 0.0
    #: time spent loading models during the query (ms; the sentence encoder's first load), not in latency_ms
    load_ms: float = 0.0
    #: prompt + completion tokens of every call
    tokens: int = 0
    #: tokens of the calls' prompts; of those, read from the server's prompt cache; of the replies
    prompt_tokens: int = 0
    cached_tokens: int = 0
    completion_tokens: int = 0
    cache_hits: int = 0

    @property
    def candidates_cut(self) -> int:
        """Instances of the map not sent to the model (the `max_candidates` budget and the
        context window)."""
        return max(self.instances_considered - len(self.candidate_ids), 0)

    def cost_line(self) -> str:
        """Tokens and candidates in one line, for `--explain` and logs."""
        cut = (f", {self.candidates_cut} of {self.instances_considered} instances cut before the model"
               if self.candidates_cut else "")
        return (f"tokens: {self.prompt_tokens} prompt ({self.cached_tokens} from the server's cache), "
                f"{self.completion_tokens} completion over {len(self.calls)} calls; "
                f"{len(self.candidate_ids)} candidates{cut}")

    @property
    def failed_calls(self) -> int:
        """Calls that got no reply at all (see `CallTrace.failed`)."""
        return sum(c.failed for c in self.calls)

    def explain(self, top: int = 3) -> str:
        """Why this instance: gate weights, each expert's top-kappa, U/S/P of the `top` best."""
        name = self.names.get
        lines = [f"query: {self.query!r}  method: {self.method}"]
        if self.instance_id is None:
            lines.append("chosen: nothing (no candidate scored)")
        else:
            lines.append(f"chosen: #{self.instance_id} {name(self.instance_id, '?')}")
        if self.gate:
            weights = ", ".join(f"{e} {w:.2f}" for e, w in sorted(self.gate.items(), key=lambda kv: -kv[1]))
            lines.append(f"gate weights: {weights}")
        for expert, ids in self.experts.items():
            picks = ", ".join(f"#{i} {name(i, '?')}" for i in ids) or "(abstained)"
            lines.append(f"  {expert} expert: {picks}")
        lines.extend(self._agreement())
        scored = [i for i in self.ranking if i in self.scores][:top]
        for i in scored:
            voters = [e for e, ids in self.experts.items() if i in ids]
            lines.append(f"  #{i} {name(i, '?')}: U={self.scores[i]:.3f} "
                         f"S={self.sum_scores.get(i, 0.0):.3f} P={self.peak_scores.get(i, 0.0):.3f}"
                         f" (ranked by {', '.join(voters) or 'none'})")
        if self.deciding_expert:
            lines.append(f"deciding expert: {self.deciding_expert} (most separates #{self.instance_id} "
                         "from the runner-up)")
        lines.append(self.cost_line())
        lines += [f"note: {note}" for note in self.notes]
        for failure in self.failures:
            lines.append(f"failure: {failure}")
        return "\n".join(lines)

    def _agreement(self) -> list[str]:
        """One line: whether the experts' top picks agree, and when they do not, which pick the
        fusion followed and the gate weight behind it."""
        tops: dict[int, list[str]] = {}
        for expert, ids in self.experts.items():
            if ids:
                tops.setdefault(ids[0], []).append(expert)
        if len(tops) < 2:
            return [f"experts agree on the top pick #{next(iter(tops))}"] if tops else []
        picks = "; ".join(f"{', '.join(e)} -> #{i}" for i, e in tops.items())
        line = f"experts disagree on the top pick: {picks}"
        backers = tops.get(self.instance_id) if self.instance_id is not None else None
        if backers and self.gate:
            weight = sum(self.gate.get(e, 0.0) for e in backers)
            others = max(sum(self.gate.get(e, 0.0) for e in es) for i, es in tops.items() if i != self.instance_id)
            line += (f"; fusion followed {', '.join(backers)} (weight {weight:.2f} against "
                     f"{others:.2f})")
        elif self.instance_id is not None:
            line += f"; fusion chose #{self.instance_id}, no expert's top pick (ranked high by several)"
        return [line]
