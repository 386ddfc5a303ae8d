"""What a captioner produces for one instance, and the replies the vision prompts ask for."""

from __future__ import annotations

from typing import Optional

from pydantic import BaseModel, ConfigDict, Field, field_validator

#: longest caption kept in the map (characters); longer model replies are cut at a word
MAX_CAPTION_CHARS = 300
#: longest tag value kept (characters)
MAX_TAG_CHARS = 60
#: structured tag keys a captioner may write (besides "size" and "height" from geometry)
TAG_KEYS = ("color", "material", "texture", "shape", "parts")


def _clean(value: object) -> Optional[str]:
    """A tag value as one short lowercase line; None for empty / "null" / "unknown"."""
    if value is None:
        return None
    text = " ".join(str(value).split()).strip(" .").lower()
    if text in ("", "null", "none", "unknown", "n/a", "not visible"):
        return None
    return text[:MAX_TAG_CHARS]


class CaptionTags(BaseModel):
    """Structured attributes of one instance (all optional, lowercase everyday words)."""

    model_config = ConfigDict(extra="ignore")

    color: Optional[str] = None
    material: Optional[str] = None
    texture: Optional[str] = None
    shape: Optional[str] = None
    parts: list[str] = Field(default_factory=list, max_length=12)

    @field_validator("color", "material", "texture", "shape", mode="before")
    @classmethod
    def _text(cls, value: object) -> Optional[str]:
        return _clean(value)

    @field_validator("parts", mode="before")
    @classmethod
    def _parts(cls, value: object) -> list[str]:
        if value is None:
            return []
        items = value.split(",") if isinstance(value, str) else value
        if not isinstance(items, list):
            raise ValueError("parts must be a list of strings")
        return [p for p in (_clean(i) for i in items) if p]


class CaptionReply(BaseModel):
    """The aggregation prompt's reply: one compact caption plus structured tags."""

    model_config = ConfigDict(extra="ignore")

    caption: str = Field(min_length=3)
    tags: CaptionTags = Field(default_factory=CaptionTags)

    @field_validator("caption", mode="before")
    @classmethod
    def _caption(cls, value: object) -> str:
        if not isinstance(value, str):
            raise ValueError("caption must be a string")
        text = " ".join(value.split())
        if len(text) > MAX_CAPTION_CHARS:
            text = text[:MAX_CAPTION_CHARS].rsplit(" ", 1)[0]
        return text


class FrameDescription(CaptionTags):
    """The per-keyframe prompt's reply: a free description plus the same attribute slots."""

    description: str = ""

    @field_validator("description", mode="before")
    @classmethod
    def _description(cls, value: object) -> str:
        return " ".join(str(value or "").split())[:MAX_CAPTION_CHARS * 2]


class CaptionResult(BaseModel):
    """One instance's caption and tags as written into the map (`tags` values are strings;
    `parts` joined with ", "). `failure` says why a fallback was used, else None."""

    caption: str
    tags: dict[str, str] = Field(default_factory=dict)
    failure: Optional[str] = None

    @classmethod
    def from_reply(cls, reply: CaptionReply, extra_tags: dict[str, str]) -> "CaptionResult":
        fields = reply.tags.model_dump()
        tags = {k: v for k, v in fields.items() if k != "parts" and v}
        if fields["parts"]:
            tags["parts"] = ", ".join(fields["parts"])
        return cls(caption=reply.caption, tags={**extra_tags, **tags})
