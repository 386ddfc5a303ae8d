"""`llamacpp:<path.gguf>`: a GGUF model run in this process by llama-cpp-python (`llama_cpp.Llama`),
for robots without a network. Imported lazily: llama-cpp-python is an optional install
(`make test-llm` builds it).

Structured output is `response_format: {"type": "json_object", "schema": ...}` (a grammar);
the window is the context the model was loaded with (`context_window`, default
`DEFAULT_N_CTX` capped by the model's training length) and prompts are counted with the
model's own tokenizer, so a prompt that does not fit is refused before it is evaluated.
"""

from __future__ import annotations

import asyncio
import threading
import time
from pathlib import Path
from typing import Any

from ..errors import IesmError, ProviderError
from .base import (LLM_CANDIDATES, MESSAGE_OVERHEAD_TOKENS, Capabilities, ChatOptions, Completion, Message, Model, Usage,
                   clean_text)
from .endpoint import REPLY_RESERVE_TOKENS, ContextOverflowError, wire_schema

#: tokens of context the model is loaded with unless `context_window` says otherwise
DEFAULT_N_CTX = 8192


class LlamaCppModel(Model):
    """The GGUF file `path` loaded once (on the first call, seconds) with `context_window`
    tokens of context and `threads` CPU threads (default: all). Calls run one at a time on a
    worker thread."""

    candidate_budget = LLM_CANDIDATES

    def __init__(self, path: str | Path, *, context_window: int | None = None, threads: int | None = None,
                 seed: int = 0):
        self.path = Path(path).expanduser()
        self.name = f"llamacpp:{path}"
        if not self.path.is_file():
            raise IesmError("no such GGUF model file", self.name)
        self.capabilities = Capabilities(json_schema=True)
        self.n_ctx = int(context_window or DEFAULT_N_CTX)
        self.threads, self.seed = threads, seed
        self._llama: Any = None
        self._lock = threading.Lock()

    def cache_identity(self) -> dict[str, Any]:
        stat = self.path.stat()
        return {"provider": "llamacpp", "file": self.path.name, "bytes": stat.st_size, "n_ctx": self.n_ctx}

    def _load(self) -> Any:
        if self._llama is None:
            try:
                from llama_cpp import Llama  # deferred: optional, and loading takes seconds
            except ImportError as exc:
                raise IesmError(f"llama-cpp-python is not installed ({exc}); `make test-llm` builds it",
                                self.name) from exc
            try:
                self._llama = Llama(model_path=str(self.path), n_ctx=self.n_ctx, n_threads=self.threads,
                                    seed=self.seed, verbose=False)
            except (ValueError, RuntimeError) as exc:
                raise IesmError(f"cannot load the model: {exc}", self.name) from exc
            self.n_ctx = self._llama.n_ctx()
        return self._llama

    async def aprompt_limit(self, options: ChatOptions | None = None) -> int | None:
        await asyncio.to_thread(self._load)
        reserve = options.max_tokens if options and options.max_tokens else REPLY_RESERVE_TOKENS
        return max(self.n_ctx - reserve, 0)

    async def aparallel_calls(self) -> int | None:
        """One: the model in this process answers one call at a time (its lock)."""
        return 1

    def estimate_tokens(self, messages: list[Message]) -> int:
        """Exact token count of the texts by the model's tokenizer, plus the per-message overhead."""
        llama = self._load()
        return sum(len(llama.tokenize(m.text().encode(), add_bos=False)) + MESSAGE_OVERHEAD_TOKENS
                   for m in messages)

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        options = options or ChatOptions()
        return await asyncio.to_thread(self._complete, messages, options)

    def _complete(self, messages: list[Message], options: ChatOptions) -> Completion:
        started = time.perf_counter()
        with self._lock:
            llama = self._load()
            limit = self.n_ctx - (options.max_tokens or REPLY_RESERVE_TOKENS)
            need = self.estimate_tokens(messages)
            if need > limit:
                raise ContextOverflowError(
                    f"prompt of {need} tokens does not fit the context window of {self.n_ctx} tokens "
                    f"with {self.n_ctx - limit} kept for the reply; not evaluated", self.name,
                    prompt_tokens=need, window=self.n_ctx, estimated=True)
            kwargs: dict[str, Any] = {"temperature": options.temperature, "max_tokens": options.max_tokens}
            if options.seed is not None:
                kwargs["seed"] = options.seed
            if options.json_schema is not None:
                kwargs["response_format"] = {"type": "json_object", "schema": wire_schema(options.json_schema)}
            try:
                reply = llama.create_chat_completion(
                    messages=[{"role": m.role, "content": m.text()} for m in messages], **kwargs)
            except (ValueError, RuntimeError) as exc:
                raise ProviderError(f"llama.cpp failed: {exc}", self.name) from exc
        usage = reply.get("usage") or {}
        choice = reply["choices"][0]
        return Completion(text=clean_text(choice["message"].get("content") or ""), model=self.name,
                          usage=Usage(prompt_tokens=usage.get("prompt_tokens", 0),
                                      completion_tokens=usage.get("completion_tokens", 0)),
                          truncated=choice.get("finish_reason") == "length",
                          latency_ms=(time.perf_counter() - started) * 1000.0)
