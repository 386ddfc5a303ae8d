"""MTEFR: a gate LLM weights the experts, each expert ranks the candidates, fusion decides.

By default the gate and every expert run concurrently (one model round trip per query). With
`skip_below` set (cost-saving mode) the gate runs first; only experts whose weight reaches the
threshold are called, and they get the gate's hints. A single expert needs no gate (weight 1);
with `gate=False` (method `mtefr-uniform`) no gate is asked and every expert weighs the same.
"""

from __future__ import annotations

import asyncio
from collections.abc import Sequence

from .. import contract
from ..config import RetrievalConfig
from ..prompting import FencedList
from ..store.mapstore import VIEW_FIELDS
from .calls import Outcome, Reply, Session
from .candidates import CandidateViews
from .experts import ExpertSpec
from .fusion import fuse
from .replies import abstain_reason, parse_gate


def shared_fields(specs: Sequence[ExpertSpec]) -> tuple[str, ...]:
    """The candidate fields every prompt of one query shows: those any of `specs` asks for, in
    `VIEW_FIELDS` order. One block for all, so the prompts share a byte-identical prefix."""
    wanted = {f for spec in specs for f in spec.fields}
    return tuple(f for f in VIEW_FIELDS if f in wanted)


def _expert_call(session: Session, spec: ExpertSpec, query: str, views: CandidateViews,
                 candidates: FencedList, kappa: int, hint: str = ""):
    template = session.prompts.template_for(spec.name, spec.template)
    messages = session.render(template, query=query, focus=spec.focus, hint=hint, expert=spec.name,
                              expert_title=spec.title, candidates=candidates, kappa=kappa,
                              references=views.references(spec.fields))
    return session.call(spec.name, template, messages, contract.ranking_schema(kappa))


def _gate_weights(session: Session, reply: Reply, names: list[str]) -> tuple[dict[str, float], dict[str, str]]:
    uniform = {name: 1.0 / len(names) for name in names}
    text = session.record(reply)
    if text is None:
        return uniform, {}
    try:
        return parse_gate(text, names)
    except ValueError as exc:
        session.reject(reply, f"unusable reply ({exc}); uniform weights used")
        return uniform, {}


async def run_mtefr(session: Session, query: str, specs: Sequence[ExpertSpec], candidate_ids: Sequence[int],
                    views: CandidateViews, config: RetrievalConfig, gate: bool = True) -> Outcome:
    """Gate + experts + fusion over `candidate_ids` (uniform weights without the gate when
    `gate` is False); model misbehaviour is recorded, never raised."""
    kappa, names = config.kappa, [s.name for s in specs]
    block = views.fields(shared_fields(specs))
    gate_messages = None
    if len(specs) > 1 and gate:
        experts = [{"name": s.name, "gate_description": s.gate_description} for s in specs]
        gate_messages = session.render("gate.j2", query=query, experts=experts, candidates=block)
        gate_schema = contract.gate_schema(tuple(names))

    if gate_messages is None:
        weights, hints, active = {name: 1.0 / len(names) for name in names}, {}, list(specs)
        replies = await asyncio.gather(*(_expert_call(session, s, query, views, block, kappa) for s in active))
    elif config.skip_below is None:
        active = list(specs)
        gate_reply, *replies = await asyncio.gather(
            session.call("gate", "gate.j2", gate_messages, gate_schema),
            *(_expert_call(session, s, query, views, block, kappa) for s in active))
        weights, hints = _gate_weights(session, gate_reply, names)
    else:
        gate_reply = await session.call("gate", "gate.j2", gate_messages, gate_schema)
        weights, hints = _gate_weights(session, gate_reply, names)
        top = max(weights.values())
        active = [s for s in specs if weights[s.name] >= min(config.skip_below, top)]
        replies = await asyncio.gather(*(_expert_call(session, s, query, views, block, kappa, hints.get(s.name, ""))
                                         for s in active))

    candidates = frozenset(candidate_ids)
    rankings, abstentions = {}, {}
    for spec, reply in zip(active, replies):
        ids = session.ranking(reply, candidates, kappa)
        if ids:
            rankings[spec.name] = ids
        elif ids is not None:
            abstentions[spec.name] = abstain_reason(reply.text or "") or "no ranking"
    fusion = fuse(weights, rankings, kappa=kappa, gamma=config.gamma, mu=config.mu)
    answered = ", ".join(fusion.weights) or "none"
    for name, reason in abstentions.items():
        session.notes.append(f"{name} abstained ({reason}): its weight {fusion.abstained.get(name, 0.0):.2f} "
                             f"redistributed over {answered}")
    if fusion.uniform_fallback:
        session.failures.append("fusion: no expert with a positive gate weight returned a ranking; "
                                "uniform weights over the others used")
    return Outcome(fusion=fusion, gate=weights, hints=hints, experts=rankings)
