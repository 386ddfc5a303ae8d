"""Read a rendered prompt the way an LLM would: which task, the fenced query, candidates,
experts, the expert's focus line and the ranking length."""

from __future__ import annotations

import json
import re
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
    candidate_lines: list[str] = field(default_factory=list)  # one JSON object per line
    reference_lines: list[str] = field(default_factory=list)  # landmarks outside the candidates (spatial.j2)
    instructions: str = ""                     # the prompt text outside the fenced data
    experts: list[dict] = field(default_factory=list)
    focus: str = ""
    hint: str = ""
    kappa: int = 2


def read_prompt(messages: list[Message]) -> Prompt:
    """Parse the rendered prompt; missing pieces stay empty, nothing raises."""
    text = "\n".join(m.text() for m in messages if m.role != "assistant")
    instructions = _without_fences(text)  # fenced data is data: it never sets the task
    task = contract.read_task(instructions) or _task_from_format(instructions)
    prompt = Prompt(task=task, query=_fenced_string(text, "query"), hint=_fenced_string(text, "hint"))
    prompt.focus = (_between(text, "focus") or "").strip()
    kappa = _AT_MOST.match(instructions, max(0, instructions.lower().rfind("at most")))
    if kappa:
        prompt.kappa = max(1, int(kappa.group(1)))
    prompt.candidate_lines = _lines(text, "candidates")
    prompt.reference_lines = _lines(text, "references")
    prompt.instructions = instructions
    prompt.experts = [e for e in _json_objects(_lines(text, "experts")) if isinstance(e.get("name"), str)]
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


def focus_role(focus: str) -> str:
    """The expert role a focus line asks for: the role whose keyword comes first; "all" if none."""
    low = focus.lower()
    best, best_pos = "all", len(low) + 1
    for role, words in _ROLE_WORDS.items():
        for w in words:
            pos = low.find(w)
            if 0 <= pos < best_pos:
                best, best_pos = role, pos
    return best


_FENCE_TAGS = ("query", "hint", "candidates", "references", "experts")


def _without_fences(text: str) -> str:
    """`text` with the fenced data blocks (query, hint, candidates, references, experts) cut
    out, each replaced by a space: the leftmost `<tag>` that has a `</tag>` after it, up to
    that closing tag, again and again (`str.find`: a regular expression took 0.12 ms on a
    prompt whose candidate block is shared by the gate and every expert)."""
    out, pos, tags = [], 0, list(_FENCE_TAGS)
    while tags:
        found = [(i, tag) for tag in tags if (i := text.find(f"<{tag}>", pos)) >= 0]
        if not found:
            break
        start, tag = min(found)
        end = text.find(f"</{tag}>", start + len(tag) + 2)
        if end < 0:  # never closed after here: this tag fences nothing more
            tags.remove(tag)
            continue
        out += [text[pos:start], " "]
        pos = end + len(tag) + 3
    out.append(text[pos:])
    return "".join(out)


def _between(text: str, tag: str) -> str | None:
    start = text.find(f"<{tag}>")
    if start < 0:
        return None
    start += len(tag) + 2
    end = text.find(f"</{tag}>", start)
    return text[start:end] if end >= 0 else None


def _fenced_string(text: str, name: str) -> str:
    raw = (_between(text, name) or "").strip()
    if not raw:
        return ""
    try:
        value = json.loads(raw)
    except ValueError:
        return raw
    return value if isinstance(value, str) else raw


def _lines(text: str, name: str) -> list[str]:
    return list(_block_lines(_between(text, name) or ""))


@lru_cache(maxsize=64)
def _block_lines(body: str) -> tuple[str, ...]:
    """The non-empty lines of a fenced block, stripped of spaces and a trailing comma. Memoised
    by the block's text: a query's expert prompts all carry the same candidate block (about
    12 kB on the apartment map; splitting it costs about 0.05 ms)."""
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
