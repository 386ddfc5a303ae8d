"""Queries waiting together are parsed together.

The English parser costs about a third of the CPU per sentence when it parses a batch
(`understanding.parse_queries`, one `nlp.pipe` call) than when it parses one sentence at a time,
and the parse is the same. `find_goal` registers its query when it arrives (`ParseBatcher.arrived`)
and, once admitted to run, asks for it parsed (`ParseBatcher.parse`): the first of the waiting
queries to need its parse parses every waiting query at once, and `analyse_query` then finds each
parse memoised. Before it parses, it lets the event loop turn a few times while queries keep
arriving (`ParseBatcher.settle`): the requests of a burst reach `find_goal` one by one, and
without that the first ones were parsed alone or in small batches (docs/performance.md, "Seventh
round"). Nothing waits for a batch to fill: a query alone is parsed after `SETTLE_TURNS` turns.
"""

from __future__ import annotations

import asyncio

from ..understanding import parse_queries

#: queries remembered as parsed (`analyse_query` memoises as many)
SEEN_MAX = 4096
#: event-loop turns in a row without a new query before the waiting queries are parsed, and the
#: most turns a query waits however many keep arriving (a burst of 40 over HTTP settled in 4-11)
SETTLE_TURNS, SETTLE_MAX_TURNS = 4, 64


class ParseBatcher:
    """The queries that arrived and are not parsed yet; used from the event loop only."""

    def __init__(self) -> None:
        self._waiting: dict[str, None] = {}  # (dicts keep arrival order and drop repeats)
        self._seen: dict[str, None] = {}  # the oldest is forgotten first
        self._arrivals = 0

    def arrived(self, query: str) -> None:
        """Register `query` to be parsed with the others waiting (nothing when parsed before)."""
        if query not in self._seen:
            self._waiting[query] = None
            self._arrivals += 1

    async def settle(self, query: str) -> None:
        """While `query` waits for its parse, yield to the event loop until `SETTLE_TURNS` turns in a
        row bring no new query (at most `SETTLE_MAX_TURNS` turns), so that the requests already
        received join its batch."""
        quiet = 0
        for _ in range(SETTLE_MAX_TURNS):
            if quiet >= SETTLE_TURNS or query not in self._waiting:
                return
            arrivals = self._arrivals
            await asyncio.sleep(0)
            quiet = quiet + 1 if self._arrivals == arrivals else 0

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
