"""How near one colour looks to another, beyond its name: the offline model's sense of colour.

A real scan's colours are means over lit and shaded faces, so a surface people call white may be
recorded as a warm grey and a darker one beside it as a charcoal; no name matches "white", but one
looks nearer to it. Nearness is read from the shipped colour table (CIELAB of each named colour)."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ...colours import ciede2000, colour_table
from ...understanding import QueryInfo, Slot
from ...understanding.spatial import parse_query

#: CIEDE2000 difference at which nearness falls to 1/e (neighbouring colour families differ by 20-40)
_SPREAD = 30.0


def own_colours(q: QueryInfo) -> frozenset[str]:
    """The colours the request says of its target: those the spatial reading gives the target, and every
    other it reads but those it gives a landmark or a part ("the kettle with the black lid": not black)."""
    sq = parse_query(q.text)
    elsewhere = {v for r in sq.relations for attrs in r.landmark_attrs for k, v in attrs if k == "color"}
    return frozenset(v for k, v in q.attrs if k == "color" and v not in elsewhere) | \
        {v for k, v in sq.attrs if k == "color"}


def colour_nearness(asked: Slot, seen: Slot) -> float:
    """In [0, 1]: exp(-(d / 30)^2) for the CIEDE2000 difference d between the nearest table colours the
    two colour slots name; 0 when either names none."""
    return _nearness(_labs(asked.surface, asked.base, asked.values), _labs(seen.surface, seen.base, seen.values))


@lru_cache(maxsize=4096)
def _nearness(asked: tuple[int, ...], seen: tuple[int, ...]) -> float:
    """`colour_nearness` of two sets of table rows."""
    if not asked or not seen:
        return 0.0
    difference = float(_differences()[np.ix_(asked, seen)].min())
    return float(np.exp(-(difference / _SPREAD) ** 2))


@lru_cache(maxsize=1)
def _differences() -> np.ndarray:
    """(N, N) CIEDE2000 difference between every two entries of the colour table, computed once (one
    call for all 26,569 pairs costs less than a few calls for a handful: scikit-image's per-call work)."""
    lab = colour_table().lab
    return ciede2000(lab[:, None, :], lab[None, :, :])


@lru_cache(maxsize=1024)
def _labs(surface: str, base: str, families: frozenset[str]) -> tuple[int, ...]:
    """Rows of the colour table a colour slot names: the entry called as written (`surface`, else
    `base`), else every entry of its families; () when none."""
    table = colour_table()
    return tuple(i for i, name in enumerate(table.names) if name == surface) or \
        tuple(i for i, name in enumerate(table.names) if name == base) or \
        tuple(i for i, family in enumerate(table.families) if family in families)
