"""The contract between the prompt templates and the models that answer them, declared once.

Every retrieval template opens its system message with a task line (`task_line`), and shows the
reply format from `reply_format`; the same names and JSON schemas are what the retrieval code
sends as structured-output schemas and what the offline model reads (`read_task`). A real LLM
sees an ordinary header line and an ordinary format example.

Tasks: `gate` (weights experts), `rank` (an expert or the single pass ranks candidates from
their fields), `rank-geometry` (an expert ranks candidates from their geometry: spatial
relations), `keyword` (object and room keywords).
"""

from __future__ import annotations

import re
from typing import Any

GATE, RANK, RANK_GEOMETRY, KEYWORD = "gate", "rank", "rank-geometry", "keyword"
TASKS = (GATE, RANK, RANK_GEOMETRY, KEYWORD)

#: the gate scores each expert on this scale
GATE_MAX = 4
#: key of the ranked ids in a ranking reply, and of the reason an expert abstains
RANKING_KEY, ABSTAIN_KEY = "ranked_instance_ids", "abstain"

_TASK_LINE = re.compile(r"^Task:\s*([a-z-]+)\s*$", re.M)


def task_line(task: str) -> str:
    """The header line a template renders first ("Task: rank")."""
    if task not in TASKS:
        raise ValueError(f"unknown task {task!r}; known: {', '.join(TASKS)}")
    return f"Task: {task}"


def read_task(text: str) -> str | None:
    """The task a rendered prompt declares (its first task line), None when it declares none."""
    match = _TASK_LINE.search(text)
    return match.group(1) if match and match.group(1) in TASKS else None


def gate_schema() -> dict[str, Any]:
    """JSON schema of a gate reply."""
    return {"type": "object", "required": ["scores"], "properties": {
        "scores": {"type": "object", "additionalProperties": {"type": "integer", "minimum": 0, "maximum": GATE_MAX}},
        "hints": {"type": "object", "additionalProperties": {"type": "string"}}}}


def ranking_schema(kappa: int) -> dict[str, Any]:
    """JSON schema of a ranking reply: an empty list with a reason in `abstain` says the query
    holds nothing of the expert's kind."""
    return {"type": "object", "required": [RANKING_KEY], "properties": {
        RANKING_KEY: {"type": "array", "items": {"type": "integer"}, "maxItems": kappa},
        ABSTAIN_KEY: {"type": "string"}}}


def keyword_schema() -> dict[str, Any]:
    """JSON schema of a keyword reply."""
    return {"type": "object", "required": ["object", "room"], "properties": {
        "object": {"type": ["string", "null"]}, "room": {"type": ["string", "null"]}}}


def reply_format(task: str, kappa: int = 2) -> str:
    """The reply format a template shows for `task` (one JSON example and its rules)."""
    if task == GATE:
        return ('{"scores": {"<expert name>": <integer 0-%d>, ...}, "hints": {"<expert name>": '
                '"<a few words from the query this expert should use>", ...}}' % GATE_MAX)
    if task in (RANK, RANK_GEOMETRY):
        return (f'{{"{RANKING_KEY}": [<id>, <id>, ...]}}\nbest first, using only ids from the candidate list. '
                f'Return at most {kappa} ids. To abstain:\n{{"{RANKING_KEY}": [], "{ABSTAIN_KEY}": "<why, in a few words>"}}')
    if task == KEYWORD:
        return '{"object": "<object keyword or null>", "room": "<room keyword or null>"}'
    raise ValueError(f"unknown task {task!r}; known: {', '.join(TASKS)}")
