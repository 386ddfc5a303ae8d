"""`iesm serve` under concurrent calls: local model calls run on the server's loop, and on the
bounded worker pool when they need a new sentence embedding; concurrent answers are the serial
ones (lexicons alone and with the encoder);
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


def test_calls_needing_no_new_embedding_run_on_the_loop(apartment_store, monkeypatch):
    """Without an encoder no call needs one: every model call runs on the server's loop."""
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
            return await _serial_then_concurrent(service, queries), threading.current_thread().name
        finally:
            await service.aclose()

    (serial, concurrent), loop_thread = asyncio.run(run())
    assert isinstance(service.retriever(None, "mtefr", None).model, OffLoopModel)
    assert threads and set(threads) == {loop_thread}
    assert [_without_timing(r) for r in concurrent] == [_without_timing(r) for r in serial]
    assert len({r["instance_id"] for r in serial}) >= 6


def test_new_embeddings_are_computed_on_the_pool_one_job_per_query(apartment_store, monkeypatch):
    """A query whose text the encoder has not embedded sends the calls that need it to a worker
    as one job (never another query's calls with them), and the encoder's backend runs there,
    never on the loop; asked again, the query is answered on the loop, the same answer."""
    from test_encoder_held_only import HashBackend

    from iesm_agent.embeddings import Encoder
    from iesm_agent.providers.offline import model as offline_model

    backend = HashBackend()
    encoder = Encoder(backend)
    monkeypatch.delenv("IESM_EMBEDDINGS", raising=False)
    monkeypatch.setattr(offline_model, "get_encoder", lambda: encoder)
    service = MapService({"apartment": apartment_store}, workers=2)
    jobs: list[tuple[str, int]] = []  # (thread, calls in the job) of every job run on a worker
    complete_all = OffLoopModel._complete_all

    async def recording(self, requests):
        if threading.current_thread().name.startswith("iesm-worker"):
            jobs.append((threading.current_thread().name, len(requests)))
        return await complete_all(self, requests)

    monkeypatch.setattr(OffLoopModel, "_complete_all", recording)
    queries = suite_queries(8)

    async def run():
        try:
            concurrent = await asyncio.gather(*(service.find_goal(q) for q in queries))  # every text new
            n_jobs = len(jobs)
            for retriever in service._retrievers.values():
                retriever._views.clear()
            serial = [await service.find_goal(q) for q in queries]  # every text held now
            return concurrent, n_jobs, serial
        finally:
            await service.aclose()

    concurrent, n_jobs, serial = asyncio.run(run())
    assert n_jobs == len(queries) and len(jobs) == n_jobs  # one job per new query, none for held ones
    assert all(1 < size < 6 for _, size in jobs)  # the experts weighing embeddings, never two queries' calls
    assert backend.batches and all(thread.startswith("iesm-worker") for thread, _ in backend.batches)
    assert [_without_timing(r) for r in concurrent] == [_without_timing(r) for r in serial]


def test_a_failing_call_fails_alone_within_its_job():
    """Each caller of a job gets its own completion, exception or timeout, on the loop and on
    the pool; a failed job fails every call."""
    from test_encoder_held_only import HashBackend

    from iesm_agent.embeddings import Encoder
    from iesm_agent.providers.base import Completion, Message, Model
    from iesm_agent.server.workers import WorkerPool

    encoder = Encoder(HashBackend())

    class Picky(Model):
        async def acomplete(self, messages, options=None):
            text = messages[0].text()
            if "new" in text:
                encoder.encode([text])  # refused on the loop: computed on the pool
            if "bad" in text:
                raise ValueError("refused")
            if "slow" in text:
                await asyncio.sleep(0.3)
            return Completion(text=f"{text.upper()} {threading.current_thread().name}", model="picky")

    pool = WorkerPool(2)
    model = OffLoopModel(Picky(), pool)

    def ask(text: str, timeout: float = 10.0):
        return asyncio.wait_for(model.acomplete([Message(role="user", content=text)]), timeout)

    async def run():
        return await asyncio.gather(ask("good one"), ask("bad one"), ask("slow one", timeout=0.05), ask("good new"),
                                    ask("bad new"), return_exceptions=True)

    good, bad, late, good_new, bad_new = asyncio.run(run())
    assert good.text == "GOOD ONE MainThread" and good_new.text.startswith("GOOD NEW iesm-worker")
    assert isinstance(bad, ValueError) and str(bad) == "refused"
    assert isinstance(bad_new, ValueError) and str(bad_new) == "refused"
    assert isinstance(late, TimeoutError)  # its deadline passed; the job's later answer is dropped
    pool.shutdown()

    async def after_shutdown():
        return await asyncio.gather(model.acomplete([Message(role="user", content="x")]),
                                    model.acomplete([Message(role="user", content="another new")]),
                                    return_exceptions=True)

    on_loop, closed = asyncio.run(after_shutdown())
    assert on_loop.text == "X MainThread"
    assert isinstance(closed, RuntimeError)  # the pool refuses new work: the call fails, it does not hang


@pytest.mark.slow
def test_concurrent_calls_with_the_encoder_match_serial_ones(apartment_store, monkeypatch):
    """(o,d) and unknown-word queries embed text on several worker threads at once."""
    from iesm_agent.embeddings import get_encoder

    monkeypatch.delenv("IESM_EMBEDDINGS", raising=False)
    if get_encoder() is None:
        pytest.skip("sentence encoder not installed")
    queries = ["that yellow photo book", "a cosy thing to read on", "the thingamajig by the sink",
               "something shiny in the bathroom", "a red leather chair in the office",
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
