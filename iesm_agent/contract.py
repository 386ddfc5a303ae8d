"""The contract between the prompt templates and the models that answer them, declared once.

Every retrieval template states its task line (`task_line`) and shows the reply format from
`reply_format`; the offline model reads both (`read_task`). Each reply kind is one pydantic model
(`GateReply`, `RankingReply`, `KeywordReply`): it validates a model's reply leniently (numeric
strings, missing wrappers and over-long text are tolerated, as a reader would) and gives the
strict JSON schema sent as structured output, from which `max_reply_tokens` bounds the reply.
A real LLM sees an ordinary header line and an ordinary format example.

Tasks: `gate` (weights experts), `rank` (an expert or the single pass ranks candidates from
their fields), `rank-geometry` (an expert ranks candidates from their geometry: spatial
relations), `keyword` (object and room keywords).
"""

from __future__ import annotations

import functools
import json
import math
import re
from typing import Annotated, Any, Optional

from pydantic import BaseModel, BeforeValidator, ConfigDict, WithJsonSchema, model_validator

GATE, RANK, RANK_GEOMETRY, KEYWORD = "gate", "rank", "rank-geometry", "keyword"
TASKS = (GATE, RANK, RANK_GEOMETRY, KEYWORD)

#: the gate scores each expert on this scale
GATE_MAX = 4
#: key of the ranked ids in a ranking reply, and of the reason an expert abstains
RANKING_KEY, ABSTAIN_KEY = "ranked_instance_ids", "abstain"
#: longest text kept (characters) of a gate hint, an abstain reason and a keyword; the schemas
#: say so (`maxLength`), so a grammar-constrained model cannot ramble past them
HINT_CHARS, ABSTAIN_CHARS, KEYWORD_CHARS = 80, 200, 100

_TASK_LINE = re.compile(r"^Task:\s*([a-z-]+)\s*$", re.M)


def task_line(task: str) -> str:
    """The header line a template renders ("Task: rank")."""
    if task not in TASKS:
        raise ValueError(f"unknown task {task!r}; known: {', '.join(TASKS)}")
    return f"Task: {task}"


def read_task(text: str) -> str | None:
    """The task a rendered prompt declares (its first task line), None when it declares none.
    The first match of `_TASK_LINE`, tried only where a line starts with "Task:" (`str.find`;
    the pattern's search tried every position of a 3 kB prompt, about 8 us)."""
    start = text.find("Task:")
    while start >= 0:
        match = _TASK_LINE.match(text, start) if start == 0 or text[start - 1] == "\n" else None
        if match:
            return match.group(1) if match.group(1) in TASKS else None
        start = text.find("Task:", start + 1)
    return None


# -- lenient readers of reply values ------------------------------------------------------------
def number(value: Any) -> float | None:
    """A finite number from a JSON value (numeric strings accepted, booleans not), else None."""
    if isinstance(value, bool):
        return None
    if isinstance(value, str):
        try:
            value = float(value.strip())
        except ValueError:
            return None
    if isinstance(value, (int, float)) and math.isfinite(value):
        return float(value)
    return None


def _text(limit: int):
    """A validator keeping a string's first `limit` characters (stripped); anything else -> ""."""
    return BeforeValidator(lambda v: v.strip()[:limit] if isinstance(v, str) else "")


def _texts(limit: int):
    """A validator keeping the non-empty string values of a dict (first `limit` characters)."""
    return BeforeValidator(lambda v: {str(k): s[:limit] for k, s in v.items() if isinstance(s, str) and s}
                           if isinstance(v, dict) else {})


_Score = Annotated[Optional[float], BeforeValidator(number),
                   WithJsonSchema({"type": "integer", "minimum": 0, "maximum": GATE_MAX})]
_Hints = Annotated[dict[str, str], _texts(HINT_CHARS),
                   WithJsonSchema({"type": "object", "additionalProperties": {"type": "string",
                                                                              "maxLength": HINT_CHARS}})]


class GateReply(BaseModel):
    """{"scores": {expert: 0-4}, "hints": {expert: a few words}}; scores that are not numbers
    read as None, a reply without the "scores" wrapper is read as the scores themselves."""

    model_config = ConfigDict(extra="ignore", title="gate_reply")

    scores: dict[str, _Score]
    hints: _Hints = {}

    @model_validator(mode="before")
    @classmethod
    def _unwrapped(cls, data: Any) -> Any:
        if isinstance(data, dict) and not isinstance(data.get("scores"), dict):
            return {"scores": data, "hints": data.get("hints")}
        return data


class RankingReply(BaseModel):
    """{"ranked_instance_ids": [id, ...], "abstain": reason}; the entries are checked against the
    candidates by the caller (`retrieval.replies.parse_ranking`)."""

    model_config = ConfigDict(extra="ignore", title="ranking_reply")

    ranked_instance_ids: Annotated[list[Any], WithJsonSchema({"type": "array", "items": {"type": "integer"}})]
    abstain: Annotated[str, _text(ABSTAIN_CHARS),
                       WithJsonSchema({"type": "string", "maxLength": ABSTAIN_CHARS})] = ""


_Keyword = Annotated[Optional[str], BeforeValidator(lambda v: v.strip()[:KEYWORD_CHARS] or None
                                                    if isinstance(v, str) else None),
                     WithJsonSchema({"type": ["string", "null"], "maxLength": KEYWORD_CHARS})]


class KeywordReply(BaseModel):
    """{"object": keyword or null, "room": keyword or null}; blank keywords read as None."""

    model_config = ConfigDict(extra="ignore", title="keyword_reply")

    object: _Keyword
    room: _Keyword

    @model_validator(mode="before")
    @classmethod
    def _either(cls, data: Any) -> Any:
        if not isinstance(data, dict) or ("object" not in data and "room" not in data):
            raise ValueError("reply has neither 'object' nor 'room'")
        return {"object": data.get("object"), "room": data.get("room")}


@functools.cache
def _schema_text(kind: type[BaseModel]) -> str:
    """The JSON schema of reply model `kind` as text, without its docstring (made once:
    pydantic takes about 0.6 ms to generate it)."""
    schema = kind.model_json_schema()
    schema.pop("description", None)
    return json.dumps(schema)


def _schema(kind: type[BaseModel]) -> dict[str, Any]:
    """A fresh copy of `kind`'s JSON schema."""
    return json.loads(_schema_text(kind))


# the schema functions are memoised: the dicts they return are shared, never to be changed
@functools.lru_cache(maxsize=64)
def gate_schema(experts: tuple[str, ...] = (), hints: bool = True) -> dict[str, Any]:
    """JSON schema of a gate reply; with `experts` (names), every one of them gets a score and, with
    `hints`, a hint (which may be empty), in that order: a grammar with no optional key is a straight
    line (llama-cpp-python sampled a gate reply with five optional hints at 0.57 tokens/s, 1.8 s a
    token, against 41 ms for an expert's reply). Without `hints` the reply holds the scores only
    (hints are read only when the experts get them: the cost-saving mode)."""
    schema = _schema(GateReply)
    if not hints:
        del schema["properties"]["hints"]
    if experts:
        for key in schema["properties"]:
            value = schema["properties"][key].pop("additionalProperties")
            schema["properties"][key].update(properties=dict.fromkeys(experts, value), required=list(experts),
                                             additionalProperties=False)
            schema["properties"][key].pop("default", None)
        schema["required"] = list(schema["properties"])
    return schema


@functools.lru_cache(maxsize=64)
def ranking_schema(kappa: int) -> dict[str, Any]:
    """JSON schema of a ranking reply of at most `kappa` ids: an empty list with a reason in
    `abstain` says the query holds nothing of the expert's kind."""
    schema = _schema(RankingReply)
    schema["properties"][RANKING_KEY]["maxItems"] = kappa
    return schema


@functools.cache
def keyword_schema() -> dict[str, Any]:
    """JSON schema of a keyword reply."""
    return _schema(KeywordReply)


#: characters assumed for a JSON value the schema does not bound (an integer id, a bare string)
_UNBOUNDED_CHARS = 12
#: a reply's worst-case tokens: this many per character of its longest compact JSON (digits and
#: punctuation are one token each in Gemma's and Llama's vocabularies; words take fewer), plus slack
_TOKENS_PER_CHAR, _SLACK_TOKENS = 0.5, 16


def _max_chars(schema: dict[str, Any]) -> int:
    """Characters of the longest compact JSON value `schema` allows (`_UNBOUNDED_CHARS` where
    it sets no bound; an object's unnamed keys as long as the text allows)."""
    kind = schema.get("type")
    kind = kind[0] if isinstance(kind, list) else kind
    if kind == "object":
        named = schema.get("properties", {})
        chars = 2 + sum(len(k) + 4 + _max_chars(v) for k, v in named.items())
        extra = schema.get("additionalProperties")
        if isinstance(extra, dict) and not named:
            chars += 8 * (_UNBOUNDED_CHARS + 4 + _max_chars(extra))  # eight unnamed entries
        return chars
    if kind == "array":
        return 2 + schema.get("maxItems", 8) * (2 + _max_chars(schema.get("items", {})))
    if kind == "string":
        return 2 + schema.get("maxLength", _UNBOUNDED_CHARS)
    if kind == "integer" and "maximum" in schema:
        return len(str(schema["maximum"]))
    return _UNBOUNDED_CHARS


def max_reply_tokens(schema: dict[str, Any]) -> int:
    """The `max_tokens` a reply to `schema` can need: its longest compact JSON in tokens, with
    slack for whitespace. A reply cut at this bound is a bad reply, not one to wait for."""
    return math.ceil(_max_chars(schema) * _TOKENS_PER_CHAR) + _SLACK_TOKENS


def reply_format(task: str, kappa: int = 2, hints: bool = True) -> str:
    """The reply format a template shows for `task` (one JSON example and its rules; a gate's
    without hints when `hints` is False)."""
    if task == GATE:
        scores = '"scores": {"<expert name>": <integer 0-%d>, ...}' % GATE_MAX
        return ('{%s, "hints": {"<expert name>": "<a few words from the query this expert should use>", ...}}'
                % scores if hints else '{%s}' % scores)
    if task in (RANK, RANK_GEOMETRY):
        return (f'{{"{RANKING_KEY}": [<id>, <id>, ...]}}\nbest first, using only ids from the candidate list. '
                f'Return at most {kappa} ids. To abstain:\n{{"{RANKING_KEY}": [], "{ABSTAIN_KEY}": "<why, in a few words>"}}')
    if task == KEYWORD:
        return '{"object": "<object keyword or null>", "room": "<room keyword or null>"}'
    raise ValueError(f"unknown task {task!r}; known: {', '.join(TASKS)}")
