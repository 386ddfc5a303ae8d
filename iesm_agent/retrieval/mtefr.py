"""MTEFR: a gate LLM weights the experts, each expert ranks the candidates, fusion decides.

By default the gate and every expert run concurrently (one model round trip per query). With
`skip_below` set (cost-saving mode) the gate runs first; only experts whose weight reaches the
threshold are called, and they get the gate's hints. With a model that serves one call at a time
(the calls queue anyway) the gate also runs first and experts it gives weight 0 are not called.
An expert that reads geometry (the spatial one) is called only when the reading of the query finds
a spatial relation. A single expert needs no gate (weight 1); with `gate=False` (method
`mtefr-uniform`) no gate is asked and every expert weighs the same.
"""

from __future__ import annotations

import asyncio
from collections.abc import Sequence

from .. import contract
from ..config import RetrievalConfig
from ..prompting import FencedList
from ..store.mapstore import GEOMETRY_FIELDS, VIEW_FIELDS
from ..understanding.spatial import parse_query
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


def asked_experts(specs: Sequence[ExpertSpec], query: str) -> tuple[list[ExpertSpec], list[ExpertSpec]]:
    """(asked, not asked): an expert that reads geometry (a spatial-relation expert) is asked only
    when the reading of `query` finds a spatial relation, comparison, order or viewpoint - its
    prompt tells it to abstain otherwise - so a query without one sends no geometry at all."""
    if not any(set(s.fields) & set(GEOMETRY_FIELDS) for s in specs) or parse_query(query).relations:
        return list(specs), []
    asked = [s for s in specs if not set(s.fields) & set(GEOMETRY_FIELDS)]
    return asked, _others(specs, asked)


def _others(specs: Sequence[ExpertSpec], chosen: Sequence[ExpertSpec]) -> list[ExpertSpec]:
    """The specs not in `chosen` (a selection from `specs`), found by identity: `not in` compared
    the pydantic models field by field, about 4 us a pair (40 us a query)."""
    taken = {id(s) for s in chosen}
    return [s for s in specs if id(s) not in taken]


def _weighted(session: Session, specs: Sequence[ExpertSpec], weights: dict[str, float],
              skip_below: float | None) -> list[ExpertSpec]:
    """The experts to ask after the gate: weight >= `skip_below` (or the top weight when lower),
    or with `skip_below` None any weight above 0; the others are noted as not asked."""
    floor = min(skip_below, max(weights.values())) if skip_below is not None else None
    active = [s for s in specs if (weights[s.name] > 0 if floor is None else weights[s.name] >= floor)]
    if len(active) < len(specs):
        session.notes.append(f"not asked, gate weight {'0' if floor is None else f'under {floor:.2f}'}: "
                             + ", ".join(s.name for s in _others(specs, active)))
    return active


async def run_mtefr(session: Session, query: str, specs: Sequence[ExpertSpec], candidate_ids: Sequence[int],
                    views: CandidateViews, config: RetrievalConfig, gate: bool = True) -> Outcome:
    """Gate + experts + fusion over `candidate_ids` (uniform weights without the gate when
    `gate` is False); model misbehaviour is recorded, never raised.

    The gate goes first when the cost-saving mode is on (`skip_below`) or the model serves one
    call at a time (the calls queue anyway): experts under the threshold, or with weight 0, are
    not asked (no weight, no say in the fusion); if none of the asked experts with weight returns
    a ranking, the others are asked after all, so the fusion is the one of every expert asked."""
    specs, unasked = asked_experts(specs, query)
    for spec in unasked:
        session.notes.append(f"{spec.name}: not asked (the query states no spatial relation, comparison, "
                             "order or viewpoint)")
    if not specs:
        return Outcome()
    kappa, names = config.kappa, [s.name for s in specs]
    block = views.fields(shared_fields(specs))

    def ask(chosen: Sequence[ExpertSpec], hints: dict[str, str]) -> list:
        return [_expert_call(session, s, query, views, block, kappa, hints.get(s.name, "")) for s in chosen]

    hints: dict[str, str] = {}
    if len(specs) < 2 or not gate:
        weights, active = {name: 1.0 / len(names) for name in names}, list(specs)
        replies = await asyncio.gather(*ask(active, {}))
    else:
        experts = [{"name": s.name, "gate_description": s.gate_description} for s in specs]
        hinted = config.skip_below is not None  # hints are asked for only when the experts get them
        gate_call = session.call("gate", "gate.j2", session.render("gate.j2", query=query, experts=experts,
                                                                   candidates=block, hints=hinted),
                                 contract.gate_schema(tuple(names), hints=hinted))
        if config.skip_below is None and await session.model.aparallel_calls() != 1:
            active = list(specs)
            gate_reply, *replies = await asyncio.gather(gate_call, *ask(active, {}))
            weights, hints = _gate_weights(session, gate_reply, names)
        else:
            weights, hints = _gate_weights(session, await gate_call, names)
            active = _weighted(session, specs, weights, config.skip_below)
            replies = await asyncio.gather(*ask(active, hints if hinted else {}))

    candidates = frozenset(candidate_ids)
    rankings, abstentions = {}, {}

    def read(chosen: Sequence[ExpertSpec], answers: Sequence[Reply]) -> None:
        for spec, reply in zip(chosen, answers):
            ids = session.ranking(reply, candidates, kappa)
            if ids:
                rankings[spec.name] = ids
            elif ids is not None:
                abstentions[spec.name] = abstain_reason(reply.text or "") or "no ranking"

    read(active, replies)
    rest = _others(specs, active)
    if rest and not any(weights[name] > 0 for name in rankings):
        session.notes.append("no expert with gate weight returned a ranking: " + ", ".join(s.name for s in rest)
                             + " asked after all")
        read(rest, await asyncio.gather(*ask(rest, hints if hinted else {})))
        active += rest
    # an expert not asked for its weight 0 did not abstain: it is left out of the fusion's weights
    asked = {s.name for s in active}
    fusion = fuse({n: w for n, w in weights.items() if w > 0 or n in asked}, rankings, kappa=kappa,
                  gamma=config.gamma, mu=config.mu)
    answered = ", ".join(fusion.weights) or "none"
    for name, reason in abstentions.items():
        session.notes.append(f"{name} abstained ({reason}): its weight {fusion.abstained.get(name, 0.0):.2f} "
                             f"redistributed over {answered}")
    if fusion.uniform_fallback:
        session.failures.append("fusion: no expert with a positive gate weight returned a ranking; "
                                "uniform weights over the others used")
    return Outcome(fusion=fusion, gate=weights, hints=hints, experts=rankings)
