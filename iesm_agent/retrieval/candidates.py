"""Candidate set C (paper Sec. 3.4.2): every instance when the map holds at most G of them,
else the top G of the store's own search (lexical + embeddings) for the query."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Candidates:
    """`ids` in prompt order; `considered` = instances in the map; `recall` = target in `ids`
    (None without a target)."""

    ids: tuple[int, ...]
    considered: int
    recall: bool | None = None


def select_candidates(store: Any, query: str, max_candidates: int, target: int | None = None) -> Candidates:
    """Pick at most `max_candidates` instance ids of `store` for `query`."""
    instances = store.scene.instances
    if len(instances) <= max_candidates:
        ids = tuple(inst.id for inst in instances)
    else:
        ids = tuple(dict.fromkeys(int(i) for i, _ in store.search(query, max_candidates)))[:max_candidates]
    return Candidates(ids=ids, considered=len(instances),
                      recall=None if target is None else target in ids)
