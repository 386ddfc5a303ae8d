"""Query types (paper Sec. 4.3): their order in tables and their column titles."""

from __future__ import annotations

from typing import Iterable

QUERY_TYPES = ("o", "or", "od", "ord", "ard")
TYPE_TITLES = {"o": "(o)", "or": "(o,r)", "od": "(o,d)", "ord": "(o,r,d)", "ard": "(a,r,d)", "s": "(s)"}
UNTYPED = "-"


def ordered_types(types: Iterable[str]) -> list[str]:
    """The paper's five types in their order, then any other label alphabetically."""
    types = set(types)
    return [t for t in QUERY_TYPES if t in types] + sorted(types - set(QUERY_TYPES))


def type_title(t: str) -> str:
    """Column title of a query type: "(o,r)" for the paper's types, the label itself otherwise."""
    return TYPE_TITLES.get(t, t)
