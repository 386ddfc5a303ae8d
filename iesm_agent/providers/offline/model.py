"""`OfflineModel`: a deterministic stand-in for a chat LLM on the retrieval prompts.

It sees only the rendered messages (no side channel), works out the task from the reply
format the prompt asks for, reads the fenced data and answers in that format. Unknown or
unreadable prompts get a valid empty answer, never an exception.
"""

from __future__ import annotations

import json
import time
from typing import Any

from ... import contract
from ...embeddings import encoder_name, get_encoder
from ..base import Capabilities, ChatOptions, Completion, Message, Model, Usage
from . import spatial, tasks
from .prompt import read_prompt


class OfflineModel(Model):
    """Rule-based model over the shipped lexicon, plus sentence embeddings when
    `use_embeddings` (default: when installed and not disabled by IESM_EMBEDDINGS=0)."""

    name = "offline"
    capabilities = Capabilities(json_schema=True)
    cacheable = False

    def __init__(self, use_embeddings: bool | None = None):
        self._use_embeddings = use_embeddings

    def encoder(self):
        """The sentence encoder, loaded on first need (seconds), or None when not used."""
        return None if self._use_embeddings is False else get_encoder()

    def answer(self, messages: list[Message]) -> dict[str, Any]:
        """The reply object for `messages`."""
        prompt = read_prompt(messages)
        if prompt.task == contract.GATE:
            return spatial.weigh(prompt, tasks.gate(prompt))
        if prompt.task == contract.RANK_GEOMETRY:
            return spatial.rank(prompt, self.encoder)
        if prompt.task == contract.RANK:
            return tasks.rank(prompt, self.encoder)
        if prompt.task == contract.KEYWORD:
            return tasks.keyword(prompt)
        return {}

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        start = time.perf_counter()
        text = json.dumps(self.answer(messages), ensure_ascii=False)
        prompt_chars = sum(len(m.text()) for m in messages)
        return Completion(
            text=text, model=self.name,
            usage=Usage(prompt_tokens=max(1, prompt_chars // 4), completion_tokens=max(1, len(text) // 4)),
            latency_ms=(time.perf_counter() - start) * 1000.0,
        )

    def cache_identity(self) -> dict[str, Any]:
        return {"model": self.name,
                "embeddings": None if self._use_embeddings is False else encoder_name()}
