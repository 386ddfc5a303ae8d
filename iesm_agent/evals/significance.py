"""Paired significance between two variants: exact McNemar test on per-query correctness."""

from __future__ import annotations

from math import comb
from typing import Iterable


def mcnemar_exact(b: int, c: int) -> float:
    """Two-sided exact McNemar p-value for `b` pairs where only A is correct and `c` where only B is.

    Under H0 the discordant pairs split Binomial(b + c, 1/2); the p-value doubles the smaller tail
    (capped at 1). No discordant pairs -> 1.0.
    """
    if b < 0 or c < 0:
        raise ValueError("discordant counts must be non-negative")
    n = b + c
    if n == 0:
        return 1.0
    tail = sum(comb(n, k) for k in range(min(b, c) + 1)) / 2 ** n
    return min(1.0, 2 * tail)


def paired_test(a: dict[str, bool], b: dict[str, bool]) -> dict:
    """McNemar on the queries both variants answered: `a` and `b` map query id -> correct.

    Returns {"n": shared queries, "a_only": b, "b_only": c, "p": p-value}.
    """
    shared = a.keys() & b.keys()
    a_only = sum(1 for q in shared if a[q] and not b[q])
    b_only = sum(1 for q in shared if b[q] and not a[q])
    return {"n": len(shared), "a_only": a_only, "b_only": b_only, "p": mcnemar_exact(a_only, b_only)}


def compare_to_first(correct: dict[str, dict[str, bool]], types: dict[str, str],
                     order: Iterable[str]) -> list[dict]:
    """Paired tests of the first variant in `order` against each other one, per type and overall.

    `correct` maps variant -> {query id -> correct}; `types` maps query id -> type.
    """
    variants = list(order)
    if len(variants) < 2:
        return []
    groups: dict[str, set[str]] = {"overall": set(types)}
    for qid, qtype in types.items():
        groups.setdefault(qtype, set()).add(qid)
    base, out = variants[0], []
    for other in variants[1:]:
        for group, ids in groups.items():
            test = paired_test({q: v for q, v in correct[base].items() if q in ids},
                               {q: v for q, v in correct[other].items() if q in ids})
            out.append({"a": base, "b": other, "type": group, **test})
    return out
