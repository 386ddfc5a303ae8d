"""Pull one JSON object out of a model's reply text, never by evaluating it.

Models wrap JSON in code fences, add prose before or after, leave trailing commas, write
Python-style single-quoted strings or `True`/`None`, and reasoning models prepend a
`<think>...</think>` block. `parse_json_reply` tolerates all of these with a small
string-aware scanner; anything else raises `JsonReplyError` (a `ValueError`).
"""

from __future__ import annotations

import json
import re
from typing import Any

from ..errors import IesmError
from ..fileio import load_json

_THINK = re.compile(r"<think>.*?</think>", re.DOTALL | re.IGNORECASE)
_FENCE = re.compile(r"```[ \t]*(?:json[a-z0-9]*)?[ \t]*\n?(.*?)```", re.DOTALL | re.IGNORECASE)
_BARE_WORDS = {"True": "true", "False": "false", "None": "null"}
#: largest reply parsed (bytes) and deepest nesting in it
MAX_REPLY_BYTES = 8 * 1024 * 1024
MAX_REPLY_DEPTH = 32
#: at most this many `{` positions are tried, so a hostile reply cannot cost quadratic time
_MAX_ATTEMPTS = 64


class JsonReplyError(ValueError):
    """The reply holds no JSON object."""


def parse_json_reply(text: str) -> dict[str, Any]:
    """The first JSON object in `text`, tried in order: the whole text, each fenced block,
    then each balanced `{...}` span. Raises `JsonReplyError` if none parses to a dict."""
    if not isinstance(text, str):
        raise JsonReplyError(f"expected reply text, got {type(text).__name__}")
    text = _THINK.sub("", text).strip()
    if not text:
        raise JsonReplyError("empty reply")
    candidates = [text] + [m.group(1) for m in _FENCE.finditer(text)]
    for candidate in candidates:
        found = _loads_dict(candidate.strip())
        if found is not None:
            return found
    starts = [m.start() for _, m in zip(range(_MAX_ATTEMPTS), re.finditer(r"\{", text))]
    for start in starts:
        end = _matching_brace(text, start)
        if end is not None:
            found = _loads_dict(text[start:end + 1])
            if found is not None:
                return found
    snippet = text[:80].replace("\n", " ")
    raise JsonReplyError(f"no JSON object in reply: {snippet!r}")


def _loads_dict(candidate: str) -> dict[str, Any] | None:
    """`candidate` parsed as a dict, directly or, when strict JSON fails, after `_normalise`
    (which costs a scan, so valid replies skip it); None otherwise."""
    if not candidate.startswith("{"):
        return None
    value = _strict_loads(candidate)
    if not isinstance(value, dict):
        repaired = _normalise(candidate)
        value = None if repaired is None else _strict_loads(repaired)
    return value if isinstance(value, dict) else None


def _strict_loads(text: str) -> Any:
    """`text` as strict JSON (no NaN), bounded in size and depth (`fileio.load_json`: a hostile
    reply nested 100,000 deep is no reply, not a RecursionError); None when it is not."""
    try:
        return load_json(text, max_bytes=MAX_REPLY_BYTES, max_depth=MAX_REPLY_DEPTH, allow_nan=False)
    except IesmError:
        return None


def _matching_brace(text: str, start: int) -> int | None:
    """Index of the `}` closing the `{` at `start`, skipping quoted strings; None if unbalanced."""
    depth = 0
    i = start
    while i < len(text):
        ch = text[i]
        if ch in "\"'":
            end = _string_end(text, i)
            if end is None:
                return None
            i = end
        elif ch in "{[":
            depth += 1
            if depth > MAX_REPLY_DEPTH:  # deeper than a reply may be: stop scanning here
                return None
        elif ch in "}]":
            depth -= 1
            if depth == 0:
                return i if ch == "}" else None
        i += 1
    return None


def _normalise(src: str) -> str | None:
    """Rewrite lenient JSON to strict JSON token by token: single-quoted strings become
    double-quoted, trailing commas before `}`/`]` are dropped, `True`/`False`/`None` become
    JSON literals. Returns None when a string is left unterminated."""
    out: list[str] = []
    i, n = 0, len(src)
    while i < n:
        ch = src[i]
        if ch in "\"'":
            end = _string_end(src, i)
            if end is None:
                return None
            body = src[i + 1:end]
            if ch == '"':
                out.append(src[i:end + 1])
            else:
                out.append(json.dumps(_unescape_single(body)))
            i = end + 1
        elif ch == ",":
            j = i + 1
            while j < n and src[j].isspace():
                j += 1
            if j >= n or src[j] not in "}]":
                out.append(ch)
            i += 1
        elif ch.isalpha() or ch == "_":
            j = i
            while j < n and (src[j].isalnum() or src[j] == "_"):
                j += 1
            word = src[i:j]
            out.append(_BARE_WORDS.get(word, word))
            i = j
        else:
            out.append(ch)
            i += 1
    return "".join(out)


def _string_end(src: str, start: int) -> int | None:
    quote = src[start]
    i = start + 1
    while i < len(src):
        if src[i] == "\\":
            i += 2
            continue
        if src[i] == quote:
            return i
        i += 1
    return None


def _unescape_single(body: str) -> str:
    """Content of a single-quoted string: `\\'` -> `'`; other escapes read as JSON escapes."""
    body = body.replace("\\'", "'")
    try:
        return json.loads('"' + body.replace('"', '\\"') + '"')
    except ValueError:
        return body
