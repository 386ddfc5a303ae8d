"""The server's bounded worker pool: model calls that compute locally run there, off the event
loop, so the loop keeps accepting and answering requests while they run.

`WorkerPool(size)` holds a `ThreadPoolExecutor` of `size` threads (default: the cores), each
with its own event loop for the coroutines it runs. `OffLoopModel(model, pool)` is a `Model`
whose `acomplete` runs `model.acomplete` on the pool: used for models that answer locally
(`cacheable` False, such as the offline model); models that wait on the network stay on the
server's loop, where their I/O already overlaps.

What the offloaded calls share is safe to share: the offline model keeps no per-call state,
its memo tables (lexicon, query analyses, grounding) are filled with deterministic values under
the GIL, and the encoder's memo is locked (its onnxruntime session may run in several threads).
"""

from __future__ import annotations

import asyncio
import os
import threading
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable, Coroutine

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


class OffLoopModel(WrappedModel):
    """`model` with its completions computed on `pool`; everything else is the model's own."""

    def __init__(self, model: Model, pool: WorkerPool):
        super().__init__(model)
        self.pool = pool

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        return await self.pool.run_async(self.inner.acomplete, messages, options)

