"""`summary.json`'s content from a run's records: metrics per variant and the paired tests. Read
by the runner, the Markdown report and the HTML report alike (it sits below all three, so none
imports another to get it)."""

from __future__ import annotations

from typing import Sequence

from .journal import ResultRecord
from .metrics import summarize
from .query_types import UNTYPED, ordered_types
from .significance import compare_to_first


def build_summary(records: Sequence[ResultRecord], variants: Sequence[str], extra: dict | None = None) -> dict:
    """Metrics per variant plus paired McNemar tests of the first variant against the others."""
    summary = summarize(records, variants)
    types = {r.id: r.type or UNTYPED for r in records}
    correct: dict[str, dict[str, bool]] = {v: {} for v in summary["methods"]}
    for r in records:
        correct[r.variant][r.id] = r.correct
    summary["types"] = ordered_types(set(types.values()) - {UNTYPED})
    summary["significance"] = compare_to_first(correct, types, list(summary["methods"]))
    summary.update(extra or {})
    return summary
