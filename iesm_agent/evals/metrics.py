"""Retrieval metrics (paper Sec. 4.3): O-SR per query type and overall, MRR and top-k from the
rank of the first accepted id. That rank is taken within the full candidate ranking for every
method (runner._rank): the ids a method scored in its order, then the candidates it did not score
tied at their expected position under a random order (rounded up). So SPR (2 scored ids), MTEFR
(2-5) and keyword (0-10) are compared at the same depth, and no method gains from the order the
unscored candidates happen to be listed in."""

from __future__ import annotations

import statistics
from collections import defaultdict
from typing import Iterable, Optional, Sequence

from .journal import ResultRecord
from .paraphrase import group_summary
from .query_types import UNTYPED, ordered_types


def osr(records: Sequence[ResultRecord]) -> float:
    """Object retrieval success rate: fraction of records whose prediction is accepted."""
    return sum(r.correct for r in records) / len(records) if records else 0.0


def nsr(records: Sequence[ResultRecord]) -> Optional[float]:
    """Navigation success rate (paper Sec. 4.3) over the records whose retrieval was correct and
    whose trial could be judged; None when there are none."""
    judged = [r.nav_success for r in records if r.correct and r.nav_success is not None]
    return sum(judged) / len(judged) if judged else None


def mrr(ranks: Iterable[Optional[int]]) -> float:
    """Mean reciprocal rank; a missing rank (no accepted id ranked) counts 0."""
    ranks = list(ranks)
    return sum(1.0 / r for r in ranks if r) / len(ranks) if ranks else 0.0


def top_k(ranks: Iterable[Optional[int]], k: int) -> float:
    """Fraction of queries with an accepted id within the first `k` of the ranking."""
    ranks = list(ranks)
    return sum(1 for r in ranks if r is not None and r <= k) / len(ranks) if ranks else 0.0


def _overall(records: Sequence[ResultRecord]) -> dict:
    ranks = [r.rank for r in records]
    latencies = [r.latency_ms for r in records]
    recalls = [r.candidate_recall for r in records if r.candidate_recall is not None]
    return {
        "n": len(records),
        "osr": osr(records),
        "mrr": mrr(ranks),
        "top3": top_k(ranks, 3),
        "latency_ms_p50": statistics.median(latencies) if latencies else 0.0,
        "latency_ms_mean": statistics.fmean(latencies) if latencies else 0.0,
        "tokens": sum(r.tokens for r in records),
        "prompt_tokens": sum(r.prompt_tokens for r in records),
        "cached_tokens": sum(r.cached_tokens for r in records),
        "completion_tokens": sum(r.completion_tokens for r in records),
        "candidates_cut": sum(r.candidates_cut for r in records),
        "cache_hits": sum(r.cache_hits for r in records),
        "queries_with_failures": sum(1 for r in records if r.failures),
        "candidate_recall": statistics.fmean(map(float, recalls)) if recalls else None,
        "nsr": nsr(records),
    }


def _type_row(records: Sequence[ResultRecord]) -> dict:
    """n, O-SR and MRR of one query type, and N-SR when its trials could be judged."""
    row = {"n": len(records), "osr": osr(records), "mrr": mrr(r.rank for r in records)}
    rate = nsr(records)
    if rate is not None:
        row["nsr"] = rate
    return row


def summarize(records: Iterable[ResultRecord], variants: Sequence[str] = ()) -> dict:
    """`{"methods": {variant: {"overall": {...}, "by_type": {type: {"n", "osr"}}}}}`, variants
    in the order given (then any others in order of appearance). A variant whose records carry
    paraphrase groups also gets `"groups"` (`paraphrase.group_summary`)."""
    grouped: dict[str, list[ResultRecord]] = {v: [] for v in variants}
    for record in records:
        grouped.setdefault(record.variant, []).append(record)
    methods = {}
    for variant, group in grouped.items():
        by_type: dict[str, list[ResultRecord]] = defaultdict(list)
        for record in group:
            by_type[record.type or UNTYPED].append(record)
        order = ordered_types(by_type)
        overall = _overall(group)
        typed = [osr(by_type[t]) for t in order if t != UNTYPED]
        overall["osr_type_mean"] = statistics.fmean(typed) if typed else None
        methods[variant] = {
            "overall": overall,
            "by_type": {t: _type_row(by_type[t]) for t in order},
        }
        groups = group_summary(group)
        if groups is not None:
            methods[variant]["groups"] = groups
    return {"methods": methods}


THRESHOLD_METRICS = ("osr", "osr_type_mean", "mrr", "top3")


def parse_thresholds(specs: Iterable[str]) -> dict[str, float]:
    """`["osr=0.6", "mrr=0.5,top3=0.8"]` -> {"osr": 0.6, "mrr": 0.5, "top3": 0.8}."""
    from ..errors import IesmError

    out = {}
    for spec in (s.strip() for item in specs for s in item.split(",")):
        if not spec:
            continue
        name, sep, value = spec.partition("=")
        try:
            if not sep or name.strip() not in THRESHOLD_METRICS:
                raise ValueError
            number = float(value)
            if not 0.0 <= number <= 1.0:  # also refuses nan, which no value would ever fall below
                raise ValueError
            out[name.strip()] = number
        except ValueError:
            raise IesmError(f"expected METRIC=VALUE with METRIC one of {', '.join(THRESHOLD_METRICS)} and VALUE "
                            f"a number from 0 to 1, got {spec!r}", "--fail-under") from None
    return out


def threshold_failures(summary: dict, thresholds: dict[str, float]) -> list[str]:
    """One message per (variant, metric) whose overall value is below its threshold."""
    failures = []
    for variant, m in summary["methods"].items():
        for metric, minimum in thresholds.items():
            value = m["overall"].get(metric)
            if value is None or value < minimum:
                shown = "n/a" if value is None else f"{value:.3f}"
                failures.append(f"{variant}: {metric} {shown} < {minimum:g}")
    return failures
