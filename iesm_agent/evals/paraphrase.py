"""Paraphrase consistency (issue 19): suite lines that share a `group` are wordings of one intent.

Per method, over the groups with at least two wordings: the share of groups answered correctly in
every wording ("all-wordings-correct") and the share whose wordings all picked the same instance
("consistent pick"; a wording that picked nothing breaks it), overall and per query type, plus the
worst groups (fewest correct wordings). A group's type is its lines' type, `-` when they differ.
"""

from __future__ import annotations

from collections import defaultdict
from typing import Sequence

from .journal import ResultRecord
from .query_types import UNTYPED, ordered_types

#: worst groups listed per method
WORST = 5


def _group_type(records: Sequence[ResultRecord]) -> str:
    types = {r.type or UNTYPED for r in records}
    return types.pop() if len(types) == 1 else UNTYPED


def _rates(groups: Sequence[Sequence[ResultRecord]]) -> dict:
    """n groups, wordings (lines), all-wordings-correct and consistent-pick shares (0..1)."""
    n = len(groups)
    return {
        "n": n,
        "wordings": sum(len(g) for g in groups),
        "all_correct": sum(all(r.correct for r in g) for g in groups) / n if n else 0.0,
        "consistent_pick": sum(g[0].predicted is not None and len({r.predicted for r in g}) == 1
                               for g in groups) / n if n else 0.0,
    }


def _worst(groups: dict[str, list[ResultRecord]]) -> list[dict]:
    """Up to `WORST` groups with a wrong wording, fewest correct wordings (as a share) first."""
    def right(g: list[ResultRecord]) -> int:
        return sum(r.correct for r in g)

    failing = sorted((name for name, g in groups.items() if right(g) < len(g)),
                     key=lambda name: (right(groups[name]) / len(groups[name]), name))
    return [{"group": name, "type": _group_type(groups[name]), "correct": right(groups[name]),
             "n": len(groups[name]),
             "wordings": [{"id": r.id, "query": r.query, "predicted": r.predicted, "correct": r.correct}
                          for r in groups[name]]}
            for name in failing[:WORST]]


def group_summary(records: Sequence[ResultRecord]) -> dict | None:
    """`{"overall": rates, "by_type": {type: rates}, "worst": [...]}` for one method's records,
    None when no group has two wordings (suites without groups)."""
    grouped: dict[str, list[ResultRecord]] = defaultdict(list)
    for record in records:
        if record.group is not None:
            grouped[record.group].append(record)
    groups = {name: sorted(g, key=lambda r: r.id) for name, g in sorted(grouped.items()) if len(g) >= 2}
    if not groups:
        return None
    by_type: dict[str, list[list[ResultRecord]]] = defaultdict(list)
    for g in groups.values():
        by_type[_group_type(g)].append(g)
    return {"overall": _rates(list(groups.values())),
            "by_type": {t: _rates(by_type[t]) for t in ordered_types(by_type)},
            "worst": _worst(groups)}
