"""Queries waiting together are parsed together.

The English parser costs about a third of the CPU per sentence when it parses a batch
(`understanding.parse_queries`, one `nlp.pipe` call) than when it parses one sentence at a time,
and the parse is the same. `find_goal` registers its query when it arrives (`ParseBatcher.arrived`)
and, once admitted to run, asks for it parsed (`ParseBatcher.parse`): the first of the waiting
queries to need its parse parses every waiting query at once, and `analyse_query` then finds each
parse memoised. Nothing waits for a batch to fill: a query alone is parsed alone.
"""

from __future__ import annotations

from ..understanding import parse_queries

#: queries remembered as parsed (`analyse_query` memoises as many)
SEEN_MAX = 4096


class ParseBatcher:
    """The queries that arrived and are not parsed yet; used from the event loop only."""

    def __init__(self) -> None:
        self._waiting: dict[str, None] = {}  # (dicts keep arrival order and drop repeats)
        self._seen: dict[str, None] = {}  # the oldest is forgotten first

    def arrived(self, query: str) -> None:
        """Register `query` to be parsed with the others waiting (nothing when parsed before)."""
        if query not in self._seen:
            self._waiting[query] = None

    def parse(self, query: str) -> None:
        """Parse `query` now, with every query waiting, unless it is parsed already. A parser
        error leaves the queries to be parsed one by one, where each reports it."""
        if query not in self._waiting:
            return
        texts = list(self._waiting)
        self._waiting.clear()
        try:
            parse_queries(texts)
        except Exception:  # noqa: BLE001 - see the docstring: analyse_query raises it per query
            return
        self._seen.update(dict.fromkeys(texts))
        while len(self._seen) > SEEN_MAX:
            del self._seen[next(iter(self._seen))]
