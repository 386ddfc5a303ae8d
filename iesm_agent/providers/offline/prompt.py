"""Read a rendered prompt the way an LLM would: which task, the fenced query, candidates,
experts, the expert's focus line and the ranking length."""

from __future__ import annotations

import json
import re
from bisect import bisect_left
from dataclasses import dataclass, field
from functools import lru_cache

from ... import contract
from ..base import Message

_AT_MOST = re.compile(r"at most\s+(\d+)", re.I)
_ROLE_WORDS = {
    "obj": ("category", "categories", "label", "object name", "object type", "class"),
    "room": ("room", "spatial", "location", "located", "where "),
    "desc": ("colour", "color", "material", "appearance", "visual", "caption", "descript",
             "attribute", "texture", "shape", "size", "style"),
    "abs": ("function", "intent", "purpose", "abstract", "implicit", "afford", "used for", "what it is for"),
}


@dataclass
class Prompt:
    """What the offline model understood from the messages."""

    task: str                                  # a `contract` task name, or "unknown"
    query: str = ""
    candidate_lines: tuple[str, ...] = ()      # one JSON object per line
    reference_lines: tuple[str, ...] = ()      # landmarks outside the candidates (spatial.j2)
    instructions: str = ""                     # the prompt text outside the fenced data
    experts: list[dict] = field(default_factory=list)
    focus: str = ""
    hint: str = ""
    kappa: int = 2


def read_prompt(messages: list[Message]) -> Prompt:
    """Parse the rendered prompt; missing pieces stay empty, nothing raises."""
    text = "\n".join(m.text() for m in messages if m.role != "assistant")
    tags = _Tags(text)
    instructions = _without_fences(text, tags)  # fenced data is data: it never sets the task
    task = contract.read_task(instructions) or _task_from_format(instructions)
    prompt = Prompt(task=task, query=_fenced_string(tags, "query"), hint=_fenced_string(tags, "hint"))
    prompt.focus = (_between(tags, "focus") or "").strip()
    kappa = _AT_MOST.match(instructions, max(0, instructions.lower().rfind("at most")))
    if kappa:
        prompt.kappa = max(1, int(kappa.group(1)))
    prompt.candidate_lines = _lines(tags, "candidates")
    prompt.reference_lines = _lines(tags, "references")
    prompt.instructions = instructions
    prompt.experts = [e for e in _json_objects(_lines(tags, "experts")) if isinstance(e.get("name"), str)]
    return prompt


def _task_from_format(instructions: str) -> str:
    """The task of a prompt without a task line (a user template), from the reply format it asks
    for, as a reader would infer it."""
    if contract.RANKING_KEY in instructions:
        return contract.RANK
    if '"scores"' in instructions:
        return contract.GATE
    if '"object"' in instructions and '"room"' in instructions:
        return contract.KEYWORD
    return "unknown"


@lru_cache(maxsize=256)
def focus_role(focus: str) -> str:
    """The expert role a focus line asks for: the role whose keyword comes first; "all" if none.
    Memoised by the line: an expert's focus is the same from query to query."""
    low = focus.lower()
    best, best_pos = "all", len(low) + 1
    for role, words in _ROLE_WORDS.items():
        for w in words:
            pos = low.find(w)
            if 0 <= pos < best_pos:
                best, best_pos = role, pos
    return best


_FENCE_TAGS = ("query", "hint", "candidates", "references", "experts")
#: the opening and closing tag of each fence and of the expert's focus line
_OPEN = {tag: f"<{tag}>" for tag in (*_FENCE_TAGS, "focus")}
_CLOSE = {tag: f"</{tag}>" for tag in (*_FENCE_TAGS, "focus")}
_MARKERS = frozenset(_OPEN.values()) | frozenset(_CLOSE.values())
_LONGEST_MARKER = max(map(len, _MARKERS))
_OPENS_FENCE = {_OPEN[tag]: tag for tag in _FENCE_TAGS}


class _Tags:
    """A prompt's text and where each tag of `_MARKERS` occurs in it, found in one pass over the
    text's '<' characters (fenced data has none: `fence` escapes them). `find` then answers as
    `str.find` would for those tags without scanning the text again: each scan past a query's
    12 kB candidate block cost about 5 us, and reading one prompt took about 20 of them.
    `openings`: (position, tag) of each fence's opening tag, in order."""

    def __init__(self, text: str):
        self.text = text
        self._at: dict[str, list[int]] = {}
        self.openings: list[tuple[int, str]] = []
        i = text.find("<")
        while i >= 0:
            end = text.find(">", i + 1, i + _LONGEST_MARKER)
            if end >= 0 and (marker := text[i:end + 1]) in _MARKERS:
                self._at.setdefault(marker, []).append(i)
                if marker in _OPENS_FENCE:
                    self.openings.append((i, _OPENS_FENCE[marker]))
            i = text.find("<", i + 1)

    def find(self, marker: str, start: int = 0) -> int:
        """`self.text.find(marker, start)` for a marker of `_MARKERS` (-1: none from `start` on)."""
        at = self._at.get(marker, ())
        k = bisect_left(at, start)
        return at[k] if k < len(at) else -1


def _without_fences(text: str, tags: _Tags | None = None) -> str:
    """`text` with the fenced data blocks (query, hint, candidates, references, experts) cut
    out, each replaced by a space: the leftmost `<tag>` that has a `</tag>` after it, up to
    that closing tag, again and again (`tags`: `text`'s tag positions, found when not given;
    a regular expression took 0.12 ms on a prompt whose candidate block is shared by the gate
    and every expert). A tag never closed after its leftmost opening fences nothing more."""
    tags = _Tags(text) if tags is None else tags
    out, pos, unclosed = [], 0, set()
    for start, tag in tags.openings:
        if start < pos or tag in unclosed:
            continue
        end = tags.find(_CLOSE[tag], start + len(tag) + 2)
        if end < 0:
            unclosed.add(tag)
            continue
        out += [text[pos:start], " "]
        pos = end + len(tag) + 3
    out.append(text[pos:])
    return "".join(out)


def _between(tags: _Tags, tag: str) -> str | None:
    """The text between the first `<tag>` and the first `</tag>` after it (None: no such pair)."""
    start = tags.find(_OPEN[tag])
    if start < 0:
        return None
    start += len(tag) + 2
    end = tags.find(_CLOSE[tag], start)
    return tags.text[start:end] if end >= 0 else None


def _fenced_string(tags: _Tags, name: str) -> str:
    raw = (_between(tags, name) or "").strip()
    if not raw:
        return ""
    try:
        value = json.loads(raw)
    except ValueError:
        return raw
    return value if isinstance(value, str) else raw


def _lines(tags: _Tags, name: str) -> tuple[str, ...]:
    return _block_lines(_between(tags, name) or "")


@lru_cache(maxsize=64)
def _block_lines(body: str) -> tuple[str, ...]:
    """The non-empty lines of a fenced block, stripped of spaces and a trailing comma. Memoised
    by the block's text: a query's expert prompts all carry the same candidate block (about
    12 kB on the apartment map; splitting it costs about 0.05 ms), and a hit returns the same
    tuple, whose parse the ranking experts memoise in turn."""
    return tuple(ln for ln in (raw.strip().rstrip(",") for raw in body.splitlines()) if ln)


def _json_objects(lines: list[str]) -> list[dict]:
    try:
        items = json.loads("[" + ",".join(lines) + "]")
    except ValueError:
        items = []
        for line in lines:
            try:
                items.append(json.loads(line))
            except ValueError:
                continue
    return [item for item in items if isinstance(item, dict)]
