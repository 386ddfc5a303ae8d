"""Baselines in the MTEFR interface: single-pass retrieval (the paper's Full+SPR) and keyword
matching (HOV-SG style: object and room keywords matched against labels, descriptions ignored).

Both are expressed as a one-expert fusion, so their U scores are the rank scores nu.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .. import contract
from ..config import RetrievalConfig
from ..store.mapstore import CANDIDATE_FIELDS
from .calls import Outcome, Session
from .candidates import CandidateViews
from .fusion import fuse
from .replies import parse_keywords


async def run_spr(session: Session, query: str, candidate_ids: Sequence[int], views: CandidateViews,
                  config: RetrievalConfig) -> Outcome:
    """One call with every candidate field (`spr.j2`); its top-1 is the answer."""
    messages = session.render("spr.j2", query=query, candidates=views.fields(CANDIDATE_FIELDS), kappa=config.kappa)
    reply = await session.call("spr", "spr.j2", messages, contract.ranking_schema(config.kappa))
    ids = session.ranking(reply, frozenset(candidate_ids), config.kappa)
    rankings = {"spr": ids} if ids is not None else {}
    return Outcome(fusion=fuse({"spr": 1.0}, rankings, kappa=config.kappa, gamma=config.gamma, mu=config.mu),
                   experts=rankings)


async def run_keyword(session: Session, store: Any, query: str, config: RetrievalConfig) -> Outcome:
    """`keyword.j2` extracts an object and a room keyword; the store's lexical search matches them
    against labels over the whole map (object in that room first, else the object anywhere)."""
    reply = await session.call("keyword", "keyword.j2", session.render("keyword.j2", query=query), contract.keyword_schema())
    text = session.record(reply)
    if text is None:
        return Outcome()
    try:
        obj, room = parse_keywords(text)
    except ValueError as exc:
        session.reject(reply, f"unusable reply ({exc})")
        return Outcome()
    matches: list[dict] = []
    if obj:
        limit = config.max_candidates
        matches = store.find_instances(category=obj, room=room, limit=limit) if room else []
        matches = matches or store.find_instances(category=obj, limit=limit)
    ids = list(dict.fromkeys(int(m["id"]) for m in matches))
    rankings = {"keyword": ids}
    fusion = fuse({"keyword": 1.0}, rankings, kappa=max(len(ids), 1), gamma=config.gamma, mu=config.mu)
    return Outcome(fusion=fusion, experts=rankings)
