"""`iesm serve` under concurrent calls: local model calls run on the bounded worker pool, off the
event loop, and concurrent answers are the serial ones (lexicons alone and with the encoder);
`find_goal` carries the goal's box and a ranking without zero-score padding."""

from __future__ import annotations

import asyncio
import json
import threading
from pathlib import Path

import numpy as np
import pytest

from iesm_agent.providers.offline import OfflineModel
from iesm_agent.server import MapService
from iesm_agent.server.workers import OffLoopModel

REPO = Path(__file__).resolve().parents[1]


def suite_queries(n: int) -> list[str]:
    lines = (REPO / "evals" / "apartment_suite.jsonl").read_text().splitlines()
    return list(dict.fromkeys(json.loads(line)["query"] for line in lines if line.strip()))[:n]


def _without_timing(result: dict) -> dict:
    return {k: v for k, v in result.items() if k != "latency_ms"}


async def _serial_then_concurrent(service: MapService, queries: list[str]) -> tuple[list, list]:
    serial = [await service.find_goal(q) for q in queries]
    for retriever in service._retrievers.values():  # nothing memoised by the serial pass is reused
        retriever._views.clear()
    concurrent = await asyncio.gather(*(service.find_goal(q) for q in queries))
    return serial, concurrent


def test_local_model_calls_run_on_the_bounded_pool(apartment_store, monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    threads: list[str] = []
    answer = OfflineModel.answer

    def recording(self, messages):
        threads.append(threading.current_thread().name)
        return answer(self, messages)

    monkeypatch.setattr(OfflineModel, "answer", recording)
    service = MapService({"apartment": apartment_store}, workers=2)
    queries = suite_queries(12)

    async def run():
        try:
            return await _serial_then_concurrent(service, queries)
        finally:
            await service.aclose()

    serial, concurrent = asyncio.run(run())
    assert isinstance(service.retriever(None, "mtefr", None).model, OffLoopModel)
    assert threads and all(name.startswith("iesm-worker") for name in threads)  # never the loop's thread
    assert len(set(threads)) <= 2
    assert [_without_timing(r) for r in concurrent] == [_without_timing(r) for r in serial]
    assert len({r["instance_id"] for r in serial}) >= 6


def test_a_query_reaches_the_pool_as_one_job_and_queries_never_share_one(apartment_store, monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    service = MapService({"apartment": apartment_store}, workers=2)
    jobs: list[tuple[str, int]] = []  # (worker thread, calls in the job)
    complete_all = OffLoopModel._complete_all

    async def recording(self, requests):
        jobs.append((threading.current_thread().name, len(requests)))
        return await complete_all(self, requests)

    monkeypatch.setattr(OffLoopModel, "_complete_all", recording)
    queries = suite_queries(8)

    async def run():
        try:
            serial = [await service.find_goal(q) for q in queries]
            n_serial = len(jobs)
            concurrent = await asyncio.gather(*(service.find_goal(q) for q in queries))
            return serial, n_serial, concurrent
        finally:
            await service.aclose()

    serial, n_serial, concurrent = asyncio.run(run())
    assert n_serial == len(queries) and len(jobs) == 2 * len(queries)  # one job per query, serial or not
    sizes = {size for _, size in jobs}
    assert len(sizes) == 1 and sizes.pop() > 1  # the gate and the experts of one query, never two queries'
    assert all(name.startswith("iesm-worker") for name, _ in jobs)
    assert [_without_timing(r) for r in concurrent] == [_without_timing(r) for r in serial]


def test_a_failing_call_fails_alone_within_its_job():
    """Each caller of a job gets its own completion, exception or timeout; a failed job fails every call."""
    from iesm_agent.providers.base import Completion, Message, Model
    from iesm_agent.server.workers import WorkerPool

    class Picky(Model):
        async def acomplete(self, messages, options=None):
            if "bad" in messages[0].text():
                raise ValueError("refused")
            if "slow" in messages[0].text():
                await asyncio.sleep(0.3)
            return Completion(text=messages[0].text().upper(), model="picky")

    pool = WorkerPool(2)
    model = OffLoopModel(Picky(), pool)

    def ask(text: str, timeout: float = 10.0):
        return asyncio.wait_for(model.acomplete([Message(role="user", content=text)]), timeout)

    async def run():
        return await asyncio.gather(ask("good one"), ask("bad one"), ask("slow one", timeout=0.05), ask("good two"),
                                    return_exceptions=True)

    good, bad, late, good_two = asyncio.run(run())
    assert good.text == "GOOD ONE" and good_two.text == "GOOD TWO"
    assert isinstance(bad, ValueError) and str(bad) == "refused"
    assert isinstance(late, TimeoutError)  # its deadline passed; the job's later answer is dropped
    pool.shutdown()

    async def after_shutdown():
        return await asyncio.gather(model.acomplete([Message(role="user", content="x")]), return_exceptions=True)

    (closed,) = asyncio.run(after_shutdown())
    assert isinstance(closed, RuntimeError)  # the pool refuses new work: the call fails, it does not hang


@pytest.mark.slow
def test_concurrent_calls_with_the_encoder_match_serial_ones(apartment_store, monkeypatch):
    """(o,d) and unknown-word queries embed text on several worker threads at once."""
    from iesm_agent.embeddings import get_encoder

    monkeypatch.delenv("IESM_EMBEDDINGS", raising=False)
    if get_encoder() is None:
        pytest.skip("sentence encoder not installed")
    queries = ["the yellow photo book", "a cosy thing to read on", "the thingamajig by the sink",
               "something shiny in the bathroom", "the red leather chair in the office",
               "a soft blue seat near the window"] + suite_queries(18)
    service = MapService({"apartment": apartment_store})

    async def run():
        try:
            return await _serial_then_concurrent(service, queries)
        finally:
            await service.aclose()

    serial, concurrent = asyncio.run(run())
    assert [_without_timing(r) for r in concurrent] == [_without_timing(r) for r in serial]


def test_find_goal_reports_where_the_goal_and_alternatives_are(apartment_store, monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    service = MapService({"apartment": apartment_store})
    out = asyncio.run(service.find_goal("the red chair in the office"))
    boxes = apartment_store.boxes
    row = {int(i): r for r, i in enumerate(boxes.ids)}
    goal = row[out["instance_id"]]
    assert np.allclose(out["position"], boxes.center[goal], atol=0.0051)  # views are rounded to cm
    assert np.allclose(out["box"]["size"], boxes.size[goal], atol=0.0051)  # views are rounded to cm
    assert out["ranking"][0]["id"] == out["instance_id"]
    assert all(entry["score"] > 0 for entry in out["ranking"])
    for entry in out["ranking"]:
        assert np.allclose(entry["box"]["center"], boxes.center[row[entry["id"]]], atol=0.0051)  # views are rounded to cm
    scores = [entry["score"] for entry in out["ranking"]]
    assert scores == sorted(scores, reverse=True)
    # a query that few instances fit: the ranking stops where the scores do, no id-order padding
    narrow = asyncio.run(service.find_goal("the fridge"))
    asyncio.run(service.aclose())
    assert 1 <= len(narrow["ranking"]) and all(entry["score"] > 0 for entry in narrow["ranking"])
