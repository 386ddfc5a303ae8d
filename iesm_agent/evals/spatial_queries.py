"""Spatial referring expressions (query type `s`) with accept sets computed from the map's geometry.

For a target with look-alikes (another instance of its spoken category), relations are tried in a
seeded order: on / under / above a landmark (box geometry and shared grid cells), next to,
closest to, farthest from a landmark category, and the largest / smallest / tallest of its
category. A landmark is named only when a single instance answers to its name (kinship as in
`kinship.covers`: two lamps, or a lamp and a floor lamp, make "the lamp" ambiguous). A relation is
kept only when exactly one instance of the category satisfies it (for superlatives: the best beats
the runner-up by a clear margin); otherwise it is rejected and the next one is tried, so every
accept set is the target alone.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from ..store import geometry as geo
from ..store.mapstore import MapStore
from .kinship import covers

#: a superlative needs the runner-up this much worse (metres for distances, ratio for sizes)
DISTANCE_MARGIN = 0.3
SIZE_RATIO = 1.25
_PHRASES = {
    "on": ("on", "on top of", "sitting on"), "under": ("under", "beneath"), "above": ("above", "over"),
    "near": ("next to", "beside", "near"), "closest": ("closest to", "nearest to"),
    "farthest": ("farthest from", "furthest from"),
    "large": ("largest", "biggest"), "small": ("smallest",), "tall": ("tallest",),
}
_STARTS = ("Find the {np}", "Go to the {np}", "Take me to the {np}", "The {np}", "Navigate to the {np}",
           "Where is the {np}?", "Show me the {np}", "I need the {np}")
#: draws of wordings per wanted paraphrase before a relation is given up
_DRAWS = 8
_NOT_LANDMARKS = {"wall", "floor", "ceiling", "doorway", "door frame", "rug", "carpet", "mat"}


@dataclass(frozen=True)
class GeneratedSpatialQuery:
    """A generated query (one or more distinct wordings of it), the relation it states and the ids
    its geometry accepts (the target)."""

    texts: tuple[str, ...]
    relation: str
    accept: tuple[int, ...]

    @property
    def text(self) -> str:
        return self.texts[0]


class _Geometry:
    """Boxes, spoken categories and stacking of one map (ground truth for the accept sets)."""

    def __init__(self, store: MapStore, categories: Sequence[str]):
        self.store = store
        self.boxes = store.boxes
        self.cats = np.array(categories, dtype=object)
        self.row = {int(i): r for r, i in enumerate(self.boxes.ids)}

    def of(self, category: str) -> np.ndarray:
        """Rows a person naming `category` could mean (`kinship.covers`: "chair" also covers an
        "armchair")."""
        return np.flatnonzero([covers(category, c) for c in self.cats])

    def stacked(self, rows: np.ndarray, field: str) -> np.ndarray:
        """(len(rows), N) bool: row's `on` / `under` geometry field lists instance j."""
        out = np.zeros((len(rows), len(self.boxes)), bool)
        for k, r in enumerate(rows):
            ids = self.store.candidate_view(int(self.boxes.ids[r]), [field])[field]
            out[k, [self.row[i] for i in ids]] = True
        return out


def _unique(rows: np.ndarray, ok: np.ndarray, target: int) -> bool:
    return bool(ok.sum() == 1 and rows[ok][0] == target)


def _best_by_margin(rows: np.ndarray, value: np.ndarray, target: int, margin: float) -> bool:
    """`target` has the lowest value among `rows`, ahead of the runner-up by `margin`."""
    if len(rows) < 2:
        return False
    order = np.argsort(value, kind="stable")
    return bool(rows[order[0]] == target and value[order[1]] - value[order[0]] >= margin)


def _try(g: _Geometry, target: int, relation: str, rng: random.Random) -> Optional[str]:
    """The landmark category ("" for a superlative) by which `relation` singles `target` out among
    its category, else None."""
    cat = g.cats[target]
    rows = g.of(cat)
    tb = g.boxes.take(rows)
    if relation in ("large", "small", "tall"):
        magnitude = tb.size[:, 2] if relation == "tall" else tb.size.prod(axis=1)
        order = np.argsort(magnitude if relation == "small" else -magnitude, kind="stable")
        low, high = sorted((magnitude[order[0]], magnitude[order[1]]))
        if rows[order[0]] != target or high < SIZE_RATIO * low:
            return None
        return ""
    # "the lamp" names one landmark only when one instance answers to it (two lamps: ambiguous)
    marks = [c for c in dict.fromkeys(g.cats.tolist()) if c != cat and c not in _NOT_LANDMARKS
             and len(g.of(c)) == 1 and not covers(c, cat) and not covers(cat, c)]
    rng.shuffle(marks)
    for mark in marks:
        lrows = g.of(mark)
        lb = g.boxes.take(lrows)
        if relation in ("on", "under"):
            ok = (geo.rests_on(tb, lb) if relation == "on" else geo.is_under(tb, lb)).any(axis=1)
            ok |= g.stacked(rows, relation)[:, lrows].any(axis=1)
            good = _unique(rows, ok, target)
        elif relation == "above":
            good = _unique(rows, geo.is_above(tb, lb).any(axis=1), target)
        elif relation == "near":
            good = _unique(rows, (geo.xy_gap(tb, lb) <= geo.NEAR_GAP / 2).any(axis=1), target) and \
                _best_by_margin(rows, geo.xy_gap(tb, lb).min(axis=1), target, DISTANCE_MARGIN)
        else:
            dist = (geo.xy_gap(tb, lb) + 0.25 * geo.center_distance(tb, lb)).min(axis=1)
            good = _best_by_margin(rows, dist if relation == "closest" else -dist, target, DISTANCE_MARGIN)
        if good:
            return mark
    return None


def _say(category: str, relation: str, mark: str, rng: random.Random) -> str:
    """One wording: "Find the lamp closest to the sofa", "Where is the biggest plant?"."""
    phrase = rng.choice(_PHRASES[relation])
    np = f"{category} {phrase} the {mark}" if mark else f"{phrase} {category}"
    return rng.choice(_STARTS).format(np=np)


def _wordings(category: str, relation: str, mark: str, rng: random.Random, k: int) -> tuple[str, ...]:
    """`k` distinct wordings of one relation, () when `_DRAWS * k` draws give fewer."""
    out: dict[str, None] = {}
    for _ in range(_DRAWS * k):
        out[_say(category, relation, mark, rng)] = None
        if len(out) == k:
            return tuple(out)
    return ()


def spatial_queries(store: MapStore, categories: Sequence[str], pool: Sequence[int], per_map: int,
                    rng: random.Random, wordings: int = 1) -> list[tuple[int, GeneratedSpatialQuery]]:
    """Up to `per_map` (instance id, query) pairs for the instances `pool` (ids, tried in the
    given order), each query with `wordings` distinct wordings; `categories` is the spoken category
    of every instance in scene order."""
    g = _Geometry(store, categories)
    out: list[tuple[int, GeneratedSpatialQuery]] = []
    relations = ["on", "under", "above", "near", "closest", "farthest", "large", "small", "tall"]
    for ident in pool:
        if len(out) == per_map:
            break
        target = g.row[int(ident)]
        if len(g.of(g.cats[target])) < 2:
            continue  # nothing to tell apart
        order = relations[:]
        rng.shuffle(order)
        for relation in order:
            mark = _try(g, target, relation, rng)
            texts = () if mark is None else _wordings(g.cats[target], relation, mark, rng, wordings)
            if texts:
                out.append((int(ident), GeneratedSpatialQuery(texts=texts, relation=relation, accept=(int(ident),))))
                break
    return out
