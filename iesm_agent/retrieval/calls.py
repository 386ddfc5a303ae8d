"""Model calls of one query, traced: prompt hashes, raw reply, latency, tokens, cache, errors.

A call never raises on model misbehaviour: an exception from the provider becomes the trace's
`error` and a line in `failures`, and the caller carries on without that reply.
"""

from __future__ import annotations

import asyncio
import hashlib
import math
import time
from dataclasses import dataclass, field
from typing import Any

from .. import contract
from ..prompting import PromptLibrary
from ..providers.base import ChatOptions, Message, Model, clean_text
from ..providers.endpoint import ContextOverflowError
from .fusion import FusionResult
from .replies import parse_ranking
from .result import REPLY_CHARS, CallTrace


def prompt_sha256(messages: list[Message]) -> str:
    """sha256 (hex) of the rendered messages, roles included."""
    h = hashlib.sha256()
    for m in messages:
        h.update(m.role.encode())
        h.update(b"\x00")
        h.update(m.text().encode())
        h.update(b"\x01")
    return h.hexdigest()


#: where the part of a user message that the prompts of one query share ends (the fenced query)
SHARED_END = "</query>"


class PromptHasher:
    """`prompt_sha256` for the prompts of one query, which share their system message and the
    start of their user message (the candidates and the query, up to `SHARED_END`): that part is
    hashed once and each prompt hashes its own tail from a copy of the hash state. A text's sha256
    is the same whatever pieces it is fed in, so the hashes are `prompt_sha256`'s; messages of
    another shape are hashed whole. Hashing six 15 kB prompts whole took about 60 us per query."""

    def __init__(self) -> None:
        #: (system text, shared start of the user text, hash state after both)
        self._shared: tuple[str, str, Any] | None = None

    def __call__(self, messages: list[Message]) -> str:
        if len(messages) != 2 or (messages[0].role, messages[1].role) != ("system", "user"):
            return prompt_sha256(messages)
        system, user = messages[0].text(), messages[1].text()
        cut = user.rfind(SHARED_END)
        if cut < 0:
            return prompt_sha256(messages)
        cut += len(SHARED_END)
        shared = self._shared
        if shared is None or shared[0] != system or shared[1] != user[:cut]:
            h = hashlib.sha256()
            h.update(b"system\x00" + system.encode() + b"\x01user\x00")
            h.update(user[:cut].encode())
            self._shared = shared = (system, user[:cut], h)
        h = shared[2].copy()
        h.update(user[cut:].encode())
        h.update(b"\x01")
        return h.hexdigest()


#: `contract.max_reply_tokens` per reply schema, by identity: the schemas are contract's memoised
#: objects, the same for every call (walking one took about 4 us); each entry keeps its schema
_REPLY_BOUNDS: dict[int, tuple[dict[str, Any], int]] = {}


def reply_bound(schema: dict[str, Any]) -> int:
    """`contract.max_reply_tokens(schema)`, memoised by the schema object (do not mutate a schema
    after a call has used it)."""
    hit = _REPLY_BOUNDS.get(id(schema))
    if hit is None or hit[0] is not schema:
        if len(_REPLY_BOUNDS) >= 256:
            _REPLY_BOUNDS.clear()
        hit = _REPLY_BOUNDS[id(schema)] = (schema, contract.max_reply_tokens(schema))
    return hit[1]


@dataclass
class Reply:
    """A finished call: its trace and the reply text (None when the call raised)."""

    trace: CallTrace
    text: str | None


@dataclass
class Session:
    """Renders prompts and runs calls for one query; `record`/`reject` keep traces and failures
    in a deterministic order (the caller's, not completion order). A `dry_run` session sends
    nothing: each call only adds the prompt's estimated tokens to `estimates` and fails (so a
    method's every prompt is rendered without a reply). `overflowed`: a call was refused for
    the model's context window."""

    model: Model
    prompts: PromptLibrary
    template_hashes: dict[str, str]
    dry_run: bool = False
    calls: list[CallTrace] = field(default_factory=list)
    failures: list[str] = field(default_factory=list)
    #: what the method did that is not a failure (an expert abstained, its weight went elsewhere)
    notes: list[str] = field(default_factory=list)
    estimates: list[int] = field(default_factory=list)
    overflowed: bool = False
    #: monotonic time (s) by which every call of this session ends (the query's deadline)
    deadline: float = math.inf
    prompt_hash: PromptHasher = field(default_factory=PromptHasher)

    def render(self, template: str, **variables: Any) -> list[Message]:
        return self.prompts.render(template, **variables)

    def _template_hash(self, template: str) -> str:
        if template not in self.template_hashes:
            self.template_hashes[template] = self.prompts.source_hash(template)
        return self.template_hashes[template]

    async def call(self, name: str, template: str, messages: list[Message],
                   schema: dict[str, Any] | None = None) -> Reply:
        trace = CallTrace(name=name, template=template, template_hash=self._template_hash(template),
                          prompt_sha256=self.prompt_hash(messages),
                          max_tokens=reply_bound(schema) if schema is not None else None)
        options = ChatOptions(temperature=0.0, max_tokens=trace.max_tokens,
                              json_schema=schema if self.model.capabilities.json_schema else None)
        if self.dry_run:
            self.estimates.append(self.model.estimate_tokens(messages))
            trace.error = "dry run"
            return Reply(trace, None)
        started = time.perf_counter()
        try:
            left = self.deadline - time.monotonic()
            if left <= 0:
                raise TimeoutError("the query's deadline has passed; not sent")
            async with asyncio.timeout(None if math.isinf(left) else left):  # (no task of its own, as wait_for's)
                completion = await self.model.acomplete(messages, options)
        except Exception as exc:  # provider errors, timeouts, bugs in plugins: recorded, not raised
            if isinstance(exc, TimeoutError) and not str(exc):
                exc = TimeoutError("no reply before the query's deadline")
            trace.error = clean_text(f"{type(exc).__name__}: {exc}")[:500]
            trace.failed = True
            self.overflowed |= isinstance(exc, ContextOverflowError)
            return Reply(trace, None)
        finally:
            trace.latency_ms = (time.perf_counter() - started) * 1000.0
        trace.reply = completion.text[:REPLY_CHARS]
        trace.prompt_tokens = completion.usage.prompt_tokens
        trace.cached_tokens = completion.usage.cached_tokens
        trace.completion_tokens = completion.usage.completion_tokens
        trace.cached = completion.cached
        trace.notes = completion.notes
        self.notes += [f"{name}: {note}" for note in completion.notes]
        if completion.truncated:
            trace.error = (f"reply cut at its bound of {trace.max_tokens} tokens "
                           f"({completion.usage.completion_tokens} generated): incomplete, not used")
        return Reply(trace, completion.text)

    def record(self, reply: Reply) -> str | None:
        """Keep the trace; a failed call becomes a failure, a reply cut at its bound a bad
        reply. Returns the usable reply text or None."""
        self.calls.append(reply.trace)
        if reply.text is None:
            self.failures.append(f"{reply.trace.name}: call failed: {reply.trace.error}")
        elif reply.trace.error:
            self.failures.append(f"{reply.trace.name}: {reply.trace.error}")
            return None
        return reply.text

    def reject(self, reply: Reply, reason: str) -> None:
        """Mark a recorded reply as unusable (parse or validation failure)."""
        reply.trace.error = reason[:500]
        self.failures.append(f"{reply.trace.name}: {reason}"[:500])

    def ranking(self, reply: Reply, candidates: frozenset[int], kappa: int) -> list[int] | None:
        """Record a ranking reply and validate it against `candidates`: None (recorded as a
        failure) when the call failed or the reply is unusable; dropped entries are recorded."""
        text = self.record(reply)
        if text is None:
            return None
        try:
            ids, dropped = parse_ranking(text, candidates, kappa)
        except ValueError as exc:
            self.reject(reply, f"unusable reply, left out of the fusion ({exc})")
            return None
        if dropped:
            self.failures.append(f"{reply.trace.name}: dropped entries that are not candidate ids: "
                                 f"{[str(d)[:20] for d in dropped[:5]]}")
        return ids


@dataclass
class Outcome:
    """What a retrieval method decided, before it becomes a `RetrievalResult`."""

    fusion: FusionResult | None = None
    gate: dict[str, float] = field(default_factory=dict)
    hints: dict[str, str] = field(default_factory=dict)
    experts: dict[str, list[int]] = field(default_factory=dict)
