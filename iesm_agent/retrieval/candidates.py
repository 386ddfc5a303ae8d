"""Candidate set C (paper Sec. 3.4.2): every instance when the map holds at most G of them,
else the top G for the query.

The pick combines the store's own search (lexical + embeddings) with the lexicon's reading of
the query: the categories it names (through synonyms and raw-label head nouns) and the ones its
functional phrases imply ("something I can type on" -> keyboard, laptop). Instances whose label
denotes such a category come first, so a target the query never spells out still reaches the
experts. `CandidateViews` renders the chosen candidates (and the landmarks the query names) for
the methods' prompts.
"""

from __future__ import annotations

import weakref
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np

from ..lexicon import load_lexicon
from ..prompting import Fenced, FencedList
from ..understanding import QueryInfo, label_concepts

#: alternative labels (the mapper's runner-up categories) count this much
_ALT_WEIGHT = 0.5


@dataclass(frozen=True)
class Candidates:
    """`ids` in prompt order; `considered` = instances in the map; `recall` = target in `ids`
    (None without a target)."""

    ids: tuple[int, ...]
    considered: int
    recall: bool | None = None


@lru_cache(maxsize=65536)
def _denoted(label: str, alt_labels: tuple[str, ...]) -> tuple[tuple[str, float], ...]:
    """Categories an instance's label (weight 1) and alternative labels denote."""
    out = list(label_concepts(label))
    out += [(c, _ALT_WEIGHT * w) for alt in alt_labels for c, w in label_concepts(alt)]
    return tuple(out)


def _wanted(info: QueryInfo, landmarks: bool = False) -> dict[str, float]:
    """Categories the query names (weight 1) or implies by function (affordance weight); with
    `landmarks`, also those it names beside the target (their weight, 0.35)."""
    wanted = dict(info.afford)
    for concept, weight in [*info.targets.items(), *(info.landmarks.items() if landmarks else ())]:
        wanted[concept] = max(wanted.get(concept, 0.0), weight)
    return wanted


def _fit(wanted: dict[str, float], denoted: tuple[tuple[str, float], ...]) -> float:
    lex = load_lexicon()
    return max((wq * wl * lex.concept_sim(qc, lc) for qc, wq in wanted.items() for lc, wl in denoted),
               default=0.0)


class _LabelIndex:
    """A store's instances grouped by (label, alternative labels): `ids` (N,), `group` (N,)
    index into `keys`, so a query's concept fit is computed once per distinct label."""

    def __init__(self, instances: Any):
        self.ids = np.array([inst.id for inst in instances], np.int64)
        position: dict[tuple[str, tuple[str, ...]], int] = {}
        self.group = np.array([position.setdefault((inst.label, tuple(inst.alt_labels)), len(position))
                               for inst in instances], np.int64)
        self.keys = list(position)


_INDEXES: "weakref.WeakKeyDictionary[Any, _LabelIndex]" = weakref.WeakKeyDictionary()


def select_candidates(store: Any, query: str, info: QueryInfo, max_candidates: int,
                      target: int | None = None) -> Candidates:
    """Pick at most `max_candidates` instance ids of `store` for `query` (read as `info`): by concept fit first,
    then by the store's search score, then by id."""
    instances = store.scene.instances
    if len(instances) <= max_candidates:
        ids = tuple(inst.id for inst in instances)
    else:
        index = _INDEXES.get(store)
        if index is None:
            index = _INDEXES[store] = _LabelIndex(instances)
        wanted = _wanted(info)
        group_fit = np.array([_fit(wanted, _denoted(*key)) if wanted else 0.0 for key in index.keys])
        order = np.lexsort((index.ids, -store.search_scores(query), -group_fit[index.group]))
        ids = tuple(int(i) for i in index.ids[order[:max_candidates]])
    return Candidates(ids=ids, considered=len(instances),
                      recall=None if target is None else target in ids)


def reference_ids(store: Any, info: QueryInfo, exclude: tuple[int, ...], limit: int = 60) -> tuple[int, ...]:
    """Instances outside `exclude` (the candidates) whose category the query names anywhere,
    landmarks included ("the cup on the table": tables), best fit first, at most `limit`; empty
    when every instance is a candidate. Spatial prompts show them as reference objects."""
    instances = store.scene.instances
    if len(instances) <= len(exclude):
        return ()
    index = _INDEXES.get(store)
    if index is None:
        index = _INDEXES[store] = _LabelIndex(instances)
    wanted = _wanted(info, landmarks=True)
    if not wanted:
        return ()
    fit = np.array([_fit(wanted, _denoted(*key)) for key in index.keys])[index.group]
    keep = (fit >= 0.3) & ~np.isin(index.ids, np.array(exclude, np.int64))
    order = np.lexsort((index.ids, -fit))
    return tuple(int(i) for i in index.ids[order][keep[order]][:limit])


@dataclass
class CandidateViews:
    """The candidates' views for one query, rendered once per field set (experts sharing fields
    share one fenced block). `cache` (id -> view per field set) may outlive the query."""

    store: Any
    info: QueryInfo
    ids: tuple[int, ...]
    cache: dict[tuple[str, ...], dict[int, Fenced]] = field(default_factory=dict)
    #: never shown as references (the candidates before a cut to the context window); default `ids`
    not_references: tuple[int, ...] | None = None
    _built: dict[tuple[str, ...], FencedList] = field(default_factory=dict)
    _landmarks: tuple[int, ...] | None = None

    def fields(self, names: Sequence[str]) -> FencedList:
        """The candidates' views with these fields, in candidate order."""
        key = tuple(names)
        if key not in self._built:
            known = self.cache.setdefault(key, {})
            for i in self.ids:
                if i not in known:
                    known[i] = Fenced(self.store.candidate_view(i, list(key)))
            self._built[key] = FencedList(known[i] for i in self.ids)
        return self._built[key]

    def references(self, names: Sequence[str]) -> FencedList:
        """Views of the instances outside the candidates that the query names (spatial
        landmarks: `candidates.reference_ids`)."""
        if self._landmarks is None:
            self._landmarks = reference_ids(self.store, self.info, tuple(set(self.ids) | set(self.not_references or ())))
        return FencedList(Fenced(self.store.candidate_view(i, list(names))) for i in self._landmarks)
