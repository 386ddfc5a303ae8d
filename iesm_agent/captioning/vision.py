"""The vision captioner (paper Sec. 3.3, Appendix A): one vision prompt per keyframe crop, then
one aggregation prompt that turns the frame descriptions, category and room into a compact
caption and structured tags.

Model replies are untrusted: a frame reply that is not JSON is used as plain description text;
an aggregation reply that does not validate against `CaptionReply` is sent back once with the
validation error (repair); if it still fails, or the model fails, the offline captioner's
result is used and the reason is kept in `CaptionResult.failure` (never raised).
"""

from __future__ import annotations

import asyncio
from typing import Optional

from pydantic import ValidationError

from ..errors import IesmError, ProviderError
from ..prompting import PromptLibrary
from ..providers.base import ChatOptions, ImagePart, Message, Model, TextPart
from ..providers.jsonreply import JsonReplyError, parse_json_reply
from .keyframes import outlined_png
from .offline import OfflineCaptioner, measured_colour, size_words
from .schema import CaptionReply, CaptionResult, FrameDescription
from .views import InstanceView

FRAME_TEMPLATE, AGGREGATE_TEMPLATE = "caption_frame.j2", "caption_aggregate.j2"


class VisionCaptioner:
    """Captions with a vision-capable `model` (sent images as base64 PNG image parts).

    `concurrency` bounds the instances captioned at once (the model's own limit bounds calls).
    Counters: `calls`, `repairs`, `fallbacks`."""

    def __init__(self, model: Model, prompts: PromptLibrary | None = None, concurrency: int = 4):
        if not model.capabilities.vision:
            raise IesmError(f"model {model.name!r} cannot read images; use a vision model or the "
                            "offline captioner", "caption")
        self.model = model
        self.name = model.name
        self.prompts = prompts or PromptLibrary()
        self.fallback = OfflineCaptioner()
        self.concurrency = concurrency
        self.calls = self.repairs = self.fallbacks = 0
        self._semaphore: Optional[asyncio.Semaphore] = None

    async def acaption(self, view: InstanceView) -> CaptionResult:
        if self._semaphore is None:
            self._semaphore = asyncio.Semaphore(self.concurrency)
        async with self._semaphore:
            return await self._caption(view)

    async def _caption(self, view: InstanceView) -> CaptionResult:
        geometry_tags = size_words(view)
        try:
            descriptions = await asyncio.gather(*(self._describe(view, crop) for crop in view.crops))
            descriptions = [d for d in descriptions if d is not None]
            if not descriptions:
                return self._fall_back(view, "no keyframe description")
            reply = await self._aggregate(view, descriptions, geometry_tags)
        except ProviderError as exc:
            return self._fall_back(view, f"model failed: {exc}")
        except _Unrepairable as exc:
            return self._fall_back(view, str(exc))
        return CaptionResult.from_reply(reply, geometry_tags)

    def _fall_back(self, view: InstanceView, reason: str) -> CaptionResult:
        self.fallbacks += 1
        return self.fallback.caption(view).model_copy(update={"failure": reason})

    async def _describe(self, view: InstanceView, crop) -> Optional[dict]:
        """One keyframe -> its description dict (None for an empty reply)."""
        system, user = self.prompts.render(FRAME_TEMPLATE, category=view.instance.label, room=view.room)
        image = ImagePart(data=outlined_png(crop.rgb, crop.mask), mime_type="image/png")
        messages = [system, Message(role="user", content=[TextPart(text=user.text()), image])]
        self.calls += 1
        text = (await self.model.acomplete(messages, ChatOptions(max_tokens=300))).text
        try:
            parsed = FrameDescription.model_validate(parse_json_reply(text))
        except (JsonReplyError, ValidationError):
            plain = " ".join(text.split())[:600]
            return {"description": plain} if plain else None
        described = parsed.model_dump(exclude_defaults=True)
        return described or None

    async def _aggregate(self, view: InstanceView, descriptions: list[dict],
                         geometry_tags: dict[str, str]) -> CaptionReply:
        measured = {"pixel_colour": measured_colour(view), **geometry_tags}
        messages = self.prompts.render(AGGREGATE_TEMPLATE, category=view.instance.label, room=view.room,
                                       descriptions=descriptions, measured=measured)
        options = ChatOptions(max_tokens=300, json_schema=CaptionReply.model_json_schema())
        self.calls += 1
        text = (await self.model.acomplete(messages, options)).text
        try:
            return _validate(text)
        except _Unrepairable as first:
            self.repairs += 1
            repair = messages + [Message(role="assistant", content=text or "(empty)"),
                                 Message(role="user", content=f"That reply is not valid: {first}. Reply "
                                         "again with only the JSON object in the format given.")]
            self.calls += 1
            return _validate((await self.model.acomplete(repair, options)).text)


class _Unrepairable(ValueError):
    """An aggregation reply that does not give a valid `CaptionReply`."""


def _validate(text: str) -> CaptionReply:
    try:
        return CaptionReply.model_validate(parse_json_reply(text))
    except JsonReplyError as exc:
        raise _Unrepairable(f"aggregation reply is not JSON ({exc})") from None
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(p) for p in first["loc"]) or "reply"
        raise _Unrepairable(f"aggregation reply invalid at {where}: {first['msg']}") from None
