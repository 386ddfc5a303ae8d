"""What an eval run records about its prompts: the content hash of every template a variant
sees (`run.json`), and, with `iesm eval --keep-prompts`, the rendered prompt and the raw reply
of every model call (`results.jsonl`, shown by the HTML report).

`PromptRecorder` wraps the run's model and remembers each prompt by the sha256 the retrieval
trace names it by (`retrieval.calls.prompt_sha256`), so the retrieval code is unchanged: the
runner joins each `CallTrace` of a result with what the recorder saw.
"""

from __future__ import annotations

from pathlib import Path

from ..prompting import PromptLibrary
from ..providers.base import ChatOptions, Completion, Message, Model, WrappedModel
from ..retrieval.calls import prompt_sha256
from ..retrieval.result import CallTrace
from .journal import KeptCall

#: a kept message or reply is cut to this many characters (bounds the journal and the report)
KEPT_CHARS = 20_000


def template_hashes(prompts_dir: str | Path | None) -> dict[str, str]:
    """Template name -> sha256 (12 hex) of the source it resolves to, for every template in
    `prompts_dir` and the shipped prompts (`prompts_dir` first, as the retriever searches)."""
    library = PromptLibrary([prompts_dir] if prompts_dir else [])
    names = sorted({p.name for d in library.dirs if d.is_dir() for p in d.glob("*.j2")})
    return {name: library.source_hash(name) for name in names}


class PromptRecorder(WrappedModel):
    """`model` unchanged, remembering the rendered messages and the full reply of each call by
    prompt sha256 (the same prompt asked twice keeps its latest reply)."""

    def __init__(self, model: Model):
        super().__init__(model)
        self.messages: dict[str, list[dict[str, str]]] = {}
        self.replies: dict[str, str] = {}

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        key = prompt_sha256(messages)
        self.messages[key] = [{"role": m.role, "content": m.text()[:KEPT_CHARS]} for m in messages]
        completion = await self.inner.acomplete(messages, options)
        self.replies[key] = completion.text[:KEPT_CHARS]
        return completion

    def kept(self, trace: CallTrace) -> KeptCall:
        """`trace` with the prompt and full reply this recorder saw for it."""
        return KeptCall(**trace.model_dump(exclude={"reply"}), reply=self.replies.get(trace.prompt_sha256, trace.reply),
                        messages=self.messages.get(trace.prompt_sha256))


def journaled_calls(calls: list[CallTrace], recorder: PromptRecorder | None) -> list[KeptCall]:
    """The calls of one result as journaled: with prompts and replies when `recorder` kept
    them, else without the reply text."""
    if recorder is not None:
        return [recorder.kept(c) for c in calls]
    return [KeptCall(**c.model_dump(exclude={"reply"})) for c in calls]
