"""Validate model replies (untrusted text) against what was asked: expert names, candidate ids.

Every parser raises `ValueError` (with a short reason) when a reply is unusable. JSON is pulled
out of the text by `providers.jsonreply`, never evaluated; its shape is the reply kind's pydantic
model in `contract` (the same model gives the schema sent to the model).
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from .. import contract
from ..providers.jsonreply import parse_json_reply

#: the gate scores each expert on this scale
GATE_MAX = float(contract.GATE_MAX)

_Reply = TypeVar("_Reply", bound=BaseModel)


def read_reply(text: str, kind: type[_Reply]) -> _Reply:
    """The reply `text` read as `kind`; `ValueError` with the first problem in one line."""
    data = parse_json_reply(text)
    try:
        return kind.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(p) for p in first["loc"])
        message = first["msg"].removeprefix("Value error, ")
        raise ValueError(f"{message}{f' at {where!r}' if where else ''}") from None


def parse_gate(text: str, experts: Sequence[str]) -> tuple[dict[str, float], dict[str, str]]:
    """Gate reply {"scores": {name: 0-4}, "hints": {name: str}} -> (weights summing to 1, hints).

    Scores are clipped to [0, 4]; non-numeric scores and unknown names are ignored, missing names
    score 0. A gate that finds no expert useful (all scores 0) gets uniform weights: a valid
    answer, not a failure. Raises ValueError when the reply has no usable score at all."""
    reply = read_reply(text, contract.GateReply)
    numbers = {name: reply.scores.get(name) for name in experts}
    if all(n is None for n in numbers.values()):
        raise ValueError("gate reply scores none of the experts")
    raw = {name: min(max(n or 0.0, 0.0), GATE_MAX) for name, n in numbers.items()}
    total = sum(raw.values())
    if total <= 0:
        raw, total = dict.fromkeys(experts, 1.0), float(len(experts))
    return ({name: s / total for name, s in raw.items()},
            {name: reply.hints[name] for name in experts if name in reply.hints})


def _instance_id(item: Any) -> int | None:
    if isinstance(item, dict):
        item = item.get("id", item.get("instance_id"))
    value = contract.number(item)
    if value is None or not value.is_integer():
        return None
    return int(value)


def parse_ranking(text: str, candidates: Collection[int], kappa: int) -> tuple[list[int], list[Any]]:
    """Expert reply {"ranked_instance_ids": [id, ...]} -> (valid ids best first, deduplicated,
    at most `kappa`; the entries dropped because they are not ids of `candidates`). Numeric
    strings and {"id": ...} objects are accepted."""
    data = parse_json_reply(text)
    try:
        reply = contract.RankingReply.model_validate(data)
    except ValidationError:
        raise ValueError(f"reply has no list {contract.RANKING_KEY!r}") from None
    ids: list[int] = []
    dropped: list[Any] = []
    for item in reply.ranked_instance_ids:
        d = _instance_id(item)
        if d is None or d not in candidates:
            dropped.append(item)
        elif d not in ids and len(ids) < kappa:
            ids.append(d)
    return ids, dropped


def parse_keywords(text: str) -> tuple[str | None, str | None]:
    """Keyword reply {"object": str|null, "room": str|null} -> (object, room), blanks as None."""
    reply = read_reply(text, contract.KeywordReply)
    return reply.object, reply.room


def abstain_reason(text: str) -> str:
    """The reason an expert reply gives for abstaining ("" when it gives none)."""
    try:
        return read_reply(text, contract.RankingReply).abstain
    except ValueError:
        return ""
