"""Requests parsed together (`parse_many`, one `nlp.pipe` call) read as when parsed one at a time,
and the server parses the queries waiting for the worker pool in one batch."""

from __future__ import annotations

import asyncio
import json
from pathlib import Path

from iesm_agent.server import MapService
from iesm_agent.server import batching
from iesm_agent.server.batching import ParseBatcher
from iesm_agent.understanding import analyse_query, parse

REPO = Path(__file__).resolve().parents[1]


def _suite_texts(name: str, n: int) -> list[str]:
    lines = (REPO / "evals" / name).read_text().splitlines()
    return list(dict.fromkeys(json.loads(line)["query"] for line in lines if line.strip()))[:n]


class _CountingPipeline:
    """The loaded pipeline, counting sentences parsed alone and batches parsed with `pipe`."""

    def __init__(self, nlp):
        self.nlp, self.alone, self.batches = nlp, [], []

    def __call__(self, text):
        self.alone.append(text)
        return self.nlp(text)

    def pipe(self, texts):
        texts = list(texts)
        self.batches.append(texts)
        return self.nlp.pipe(texts)


def test_a_batch_parses_as_one_sentence_at_a_time(monkeypatch):
    texts = [parse.normalise(t) for t in _suite_texts("spatial_suite.jsonl", 12) + _suite_texts(
        "conflict_suite.jsonl", 12)]
    texts += ["Not the red one: the blue mug on the shelf", "I burnt the toast. Take me to it.", "the lamp"]
    parse.parse_request.cache_clear()
    alone = [parse.parse_request(t) for t in texts]
    parse.parse_request.cache_clear()
    counting = _CountingPipeline(parse._pipeline())
    monkeypatch.setattr(parse, "_pipeline", lambda: counting)

    parse.parse_many(texts + texts[:3])  # a repeat is parsed once
    assert len(counting.batches) == 1 and len(counting.batches[0]) == len(texts) - 1
    assert counting.alone == ["the blue mug on the shelf"]  # the fronted exclusion is cut, then parsed
    assert [parse.parse_request(t) for t in texts] == alone  # memoised, and the same structures
    assert len(counting.alone) == 1 and not parse._batch


def test_the_batcher_parses_every_waiting_query_once(monkeypatch):
    batches: list[list[str]] = []
    monkeypatch.setattr(batching, "parse_queries", batches.append)
    batcher = ParseBatcher()
    for q in ("the sofa", "a lamp", "the sofa", "the sink"):
        batcher.arrived(q)
    batcher.parse("a lamp")
    batcher.parse("the sink")  # parsed with the first
    batcher.arrived("the sofa")  # parsed before: not waiting again
    batcher.parse("the sofa")
    assert batches == [["the sofa", "a lamp", "the sink"]]

    def failing(texts):
        raise RuntimeError("parser broke")

    monkeypatch.setattr(batching, "parse_queries", failing)
    batcher.arrived("the bed")
    batcher.parse("the bed")  # no error here: the query is analysed alone, where it is reported
    monkeypatch.setattr(batching, "parse_queries", batches.append)
    batcher.arrived("the bed")
    batcher.parse("the bed")
    assert batches[-1] == ["the bed"]


async def _settling_turns(batcher: ParseBatcher, query: str, arriving: bool) -> int:
    """Turns of the event loop another task saw while `query` settled; with `arriving`, that task
    registers a new query at every turn."""
    turns = 0

    async def tick() -> None:
        nonlocal turns
        while True:
            await asyncio.sleep(0)
            turns += 1
            if arriving:
                batcher.arrived(f"query {turns}")

    ticking = asyncio.ensure_future(tick())
    batcher.arrived(query)
    await batcher.settle(query)
    ticking.cancel()
    return turns


def test_settling_lets_arriving_queries_join_and_a_lone_query_waits_only_a_few_turns(monkeypatch):
    batches: list[list[str]] = []
    monkeypatch.setattr(batching, "parse_queries", batches.append)
    batcher = ParseBatcher()

    async def arrive_later(queries: list[str]) -> None:
        for q in queries:  # one arrival per turn of the loop, as requests reaching find_goal
            await asyncio.sleep(0)
            batcher.arrived(q)

    async def burst() -> list[str]:
        batcher.arrived("the sofa")
        later = asyncio.ensure_future(arrive_later(["a lamp", "the sink", "the bed"]))
        await batcher.settle("the sofa")
        waiting = list(batcher._waiting)
        await later
        return waiting

    assert asyncio.run(burst()) == ["the sofa", "a lamp", "the sink", "the bed"]

    assert asyncio.run(_settling_turns(batcher, "the desk", arriving=False)) <= batching.SETTLE_TURNS + 1
    batcher.parse("the sofa")
    assert batches == [["the sofa", "a lamp", "the sink", "the bed", "the desk"]]
    asyncio.run(batcher.settle("the sofa"))  # parsed: settling returns at once

    # a query arriving at every turn: the settling query still goes on
    assert asyncio.run(_settling_turns(batcher, "the chair", arriving=True)) <= batching.SETTLE_MAX_TURNS + 1


def test_concurrent_first_time_queries_are_parsed_together_and_answered_as_alone(apartment_store, monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    queries = _suite_texts("apartment_human_suite.jsonl", 10)
    batches: list[list[str]] = []
    parse_queries = batching.parse_queries

    def recording(texts):
        batches.append(list(texts))
        parse_queries(texts)

    monkeypatch.setattr(batching, "parse_queries", recording)

    def fresh() -> MapService:
        analyse_query.cache_clear()
        parse.parse_request.cache_clear()
        return MapService({"apartment": apartment_store}, workers=2)

    async def run(service: MapService, together: bool):
        try:
            if together:
                return await asyncio.gather(*(service.find_goal(q) for q in queries))
            return [await service.find_goal(q) for q in queries]
        finally:
            await service.aclose()

    concurrent = asyncio.run(run(fresh(), True))
    assert sorted(q for b in batches for q in b) == sorted(queries)
    assert max(len(b) for b in batches) >= len(queries) - 2  # all but the first admitted ones at once
    batches.clear()
    serial = asyncio.run(run(fresh(), False))
    assert all(len(b) == 1 for b in batches)
    assert [{k: v for k, v in r.items() if k != "latency_ms"} for r in concurrent] == \
        [{k: v for k, v in r.items() if k != "latency_ms"} for r in serial]
