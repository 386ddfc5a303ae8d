"""The server's bounded worker pool: model calls that compute locally run there, off the event
loop, when they would hold it long, so the loop keeps accepting and answering requests meanwhile.

`WorkerPool(size)` holds a `ThreadPoolExecutor` of `size` threads (default: the cores), each
with its own event loop for the coroutines it runs. `OffLoopModel(model, pool)` is a `Model`
for models that answer locally (`cacheable` False, such as the offline model): the calls a
query starts together are first computed on the server's loop with the sentence encoder held to
the rows it has (`embeddings.held_only`: about 1 ms for a query's six calls), and only the calls
that need a new embedding (about 4 ms of CPU a sentence) go to the pool, as one job. Models
that wait on the network stay on the server's loop, where their I/O already overlaps.

What the offloaded calls share is safe to share: the offline model keeps no per-call state,
its memo tables (lexicon, query analyses, grounding) are filled with deterministic values under
the GIL, and the encoder's memo is locked (its onnxruntime session may run in several threads).
"""

from __future__ import annotations

import asyncio
import contextvars
import os
import threading
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from typing import Any, Callable, Coroutine

from ..embeddings import EncodingNeeded, held_only
from ..providers.base import ChatOptions, Completion, Message, Model, WrappedModel


class WorkerPool:
    """`size` worker threads (default `os.cpu_count()`). `await pool.run(fn, *args)` runs a
    blocking function there; `await pool.run_async(make, *args)` runs the coroutine
    `make(*args)` there, on the thread's own event loop."""

    def __init__(self, size: int | None = None):
        self.size = max(1, size or os.cpu_count() or 1)
        self._executor = ThreadPoolExecutor(self.size, thread_name_prefix="iesm-worker")
        self._local = threading.local()
        self._loops: list[asyncio.AbstractEventLoop] = []

    async def run(self, fn: Callable[..., Any], *args: Any) -> Any:
        """`fn(*args)` computed on a worker thread."""
        return await asyncio.get_running_loop().run_in_executor(self._executor, fn, *args)

    async def run_async(self, make: Callable[..., Coroutine], *args: Any) -> Any:
        """The result of the coroutine `make(*args)`, run to completion on a worker thread."""
        return await self.run(self._drive, make, args)

    def _drive(self, make: Callable[..., Coroutine], args: tuple) -> Any:
        loop = getattr(self._local, "loop", None)
        if loop is None:
            loop = self._local.loop = asyncio.new_event_loop()
            self._loops.append(loop)
        return loop.run_until_complete(make(*args))

    def shutdown(self) -> None:
        """Stop the threads (waits for running calls) and close their event loops."""
        self._executor.shutdown(wait=True)
        while self._loops:
            self._loops.pop().close()


#: the query a model call belongs to (`new_query`); calls of different queries never share a job
_query: contextvars.ContextVar[object | None] = contextvars.ContextVar("iesm_query", default=None)


def new_query() -> None:
    """Mark the model calls the current task (and the tasks it starts) makes from now on as one
    query's, so that `OffLoopModel` sends them as one job and no other query's calls join it
    (each query's answer then waits for its own calls only)."""
    _query.set(object())


class OffLoopModel(WrappedModel):
    """`model` with its completions computed on the server's loop while the sentence encoder holds
    every row they need, and on `pool` otherwise; everything else is the model's own.

    The calls of one query (`new_query`) started in one step of an event loop (the gate and the
    experts, started together) are one job: computed on the loop within `held_only()`; those that
    raised `EncodingNeeded` go to the pool together and run there concurrently on the worker's
    loop (a query pays at most one hand-off to a worker thread and back, about 0.3 ms of CPU, and
    only when it needs a new embedding); each caller gets its own completion or exception. What the
    refused calls computed before the refusal stays in the model's memos for their second run."""

    def __init__(self, model: Model, pool: WorkerPool):
        super().__init__(model)
        self.pool = pool
        #: per (event loop, query), the calls waiting for the job the loop's next step sends
        self._pending: dict[tuple[asyncio.AbstractEventLoop, object | None], list[_Call]] = {}

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        loop = asyncio.get_running_loop()
        key = (loop, _query.get())
        call = _Call(messages, options, loop.create_future())
        batch = self._pending.get(key)
        if batch is None:
            batch = self._pending[key] = []
            loop.call_soon(self._send, key)
        batch.append(call)
        return await call.future

    def _send(self, key: tuple[asyncio.AbstractEventLoop, object | None]) -> None:
        batch = self._pending.pop(key)
        job = key[0].create_task(self._run([(c.messages, c.options) for c in batch]))
        job.add_done_callback(lambda done: _settle(batch, done))

    async def _run(self, requests: list[tuple[list[Message], ChatOptions | None]]) -> list[Any]:
        """Each request's completion or exception: on this loop when the encoder holds what it
        needs, else (`EncodingNeeded`) on the pool, the refused requests as one job."""
        with held_only():
            outcomes = await self._complete_all(requests)
        refused = [k for k, outcome in enumerate(outcomes) if isinstance(outcome, EncodingNeeded)]
        if refused:
            try:
                again = await self.pool.run_async(self._complete_all, [requests[k] for k in refused])
            except Exception as exc:  # noqa: BLE001 - the pool took no job (shut down): those calls fail
                again = [exc] * len(refused)
            for k, outcome in zip(refused, again):
                outcomes[k] = outcome
        return outcomes

    async def _complete_all(self, requests: list[tuple[list[Message], ChatOptions | None]]) -> list[Any]:
        return await asyncio.gather(*(self.inner.acomplete(m, o) for m, o in requests), return_exceptions=True)


@dataclass
class _Call:
    """One `acomplete` call waiting for its batch."""

    messages: list[Message]
    options: ChatOptions | None
    future: asyncio.Future


def _settle(batch: list[_Call], job: asyncio.Task) -> None:
    """Give each call of `batch` its completion or exception from the finished `job` (a call
    cancelled meanwhile, e.g. by its deadline, is left alone)."""
    failed = job.cancelled() or job.exception() is not None
    outcomes = [None] * len(batch) if failed else job.result()
    for call, outcome in zip(batch, outcomes):
        if call.future.done():
            continue
        if job.cancelled():
            call.future.cancel()
        elif failed:
            call.future.set_exception(job.exception())
        elif isinstance(outcome, BaseException):
            call.future.set_exception(outcome)
        else:
            call.future.set_result(outcome)
