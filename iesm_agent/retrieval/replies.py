"""Validate model replies (untrusted text) against what was asked: expert names, candidate ids.

Every parser raises `ValueError` (with a short reason) when a reply is unusable; JSON is pulled
out of the text by `providers.jsonreply`, never evaluated.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence
from typing import Any

from .. import contract
from ..providers.jsonreply import parse_json_reply

#: the gate scores each expert on this scale
GATE_MAX = float(contract.GATE_MAX)


def _number(value: Any) -> float | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, str):
        try:
            value = float(value.strip())
        except ValueError:
            return None
    if isinstance(value, (int, float)) and math.isfinite(value):
        return float(value)
    return None


def parse_gate(text: str, experts: Sequence[str]) -> tuple[dict[str, float], dict[str, str]]:
    """Gate reply {"scores": {name: 0-4}, "hints": {name: str}} -> (weights summing to 1, hints).

    Scores are clipped to [0, 4]; non-numeric scores and unknown names are ignored, missing names
    score 0. A gate that finds no expert useful (all scores 0) gets uniform weights: a valid
    answer, not a failure. Raises ValueError when the reply has no usable score at all."""
    data = parse_json_reply(text)
    scores = data.get("scores")
    if not isinstance(scores, dict):
        scores = data  # tolerate {"obj": 4, ...} without the wrapper
    numbers = {name: _number(scores.get(name)) for name in experts}
    if all(n is None for n in numbers.values()):
        raise ValueError("gate reply scores none of the experts")
    raw = {name: min(max(n or 0.0, 0.0), GATE_MAX) for name, n in numbers.items()}
    total = sum(raw.values())
    if total <= 0:
        raw, total = dict.fromkeys(experts, 1.0), float(len(experts))
    hints = data.get("hints")
    hints = hints if isinstance(hints, dict) else {}
    return ({name: s / total for name, s in raw.items()},
            {name: str(hints[name])[:200] for name in experts if isinstance(hints.get(name), str) and hints[name]})


def _instance_id(item: Any) -> int | None:
    if isinstance(item, dict):
        item = item.get("id", item.get("instance_id"))
    value = _number(item)
    if value is None or not value.is_integer():
        return None
    return int(value)


def parse_ranking(text: str, candidates: Collection[int], kappa: int,
                  key: str = contract.RANKING_KEY) -> tuple[list[int], list[Any]]:
    """Expert reply {key: [id, ...]} -> (valid ids best first, deduplicated, at most `kappa`;
    the entries dropped because they are not ids of `candidates`). Numeric strings are accepted."""
    data = parse_json_reply(text)
    items = data.get(key)
    if not isinstance(items, list):
        raise ValueError(f"reply has no list {key!r}")
    ids: list[int] = []
    dropped: list[Any] = []
    for item in items:
        d = _instance_id(item)
        if d is None or d not in candidates:
            dropped.append(item)
        elif d not in ids and len(ids) < kappa:
            ids.append(d)
    return ids, dropped


def parse_keywords(text: str) -> tuple[str | None, str | None]:
    """Keyword reply {"object": str|null, "room": str|null} -> (object, room), blanks as None."""
    data = parse_json_reply(text)
    if "object" not in data and "room" not in data:
        raise ValueError("reply has neither 'object' nor 'room'")

    def clean(value: Any) -> str | None:
        return value.strip()[:100] or None if isinstance(value, str) else None

    return clean(data.get("object")), clean(data.get("room"))


#: JSON schemas of the replies, passed to models that support structured output (see `contract`)
GATE_SCHEMA: dict[str, Any] = contract.gate_schema()
KEYWORD_SCHEMA: dict[str, Any] = contract.keyword_schema()
ranking_schema = contract.ranking_schema


def abstain_reason(text: str) -> str:
    """The reason an expert reply gives for abstaining ("" when it gives none)."""
    try:
        reason = parse_json_reply(text).get(contract.ABSTAIN_KEY)
    except ValueError:
        return ""
    return reason.strip()[:200] if isinstance(reason, str) else ""

