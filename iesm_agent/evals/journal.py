"""The run journal `results.jsonl`: one `ResultRecord` per (query, variant), appended and flushed.

A record counts once its newline is written: a run killed mid-write leaves a last line without
one, which `read_journal` ignores and `repair_journal` cuts, so a resumed run re-asks that query.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import IO, Optional

from pydantic import BaseModel, ConfigDict, ValidationError

from ..errors import IesmError
from ..retrieval.result import CallTrace

#: a run directory's journal and its configuration (file names)
RESULTS, RUN_CONFIG = "results.jsonl", "run.json"


class KeptCall(CallTrace):
    """A model call as journaled: the trace, plus the rendered prompt messages
    ([{"role", "content"}]) when the run kept prompts."""

    messages: Optional[list[dict[str, str]]] = None


class ResultRecord(BaseModel):
    """Outcome of one query under one variant. `rank` is the 1-based position of the first
    accepted id in the full ranking (None when no accepted id was ranked)."""

    model_config = ConfigDict(extra="ignore")

    id: str
    variant: str
    method: str
    type: Optional[str] = None
    group: Optional[str] = None  # the suite line's paraphrase group
    map: str
    query: str
    target: int
    predicted: Optional[int] = None
    correct: bool
    rank: Optional[int] = None
    ranking: list[int]
    latency_ms: float
    tokens: int = 0
    prompt_tokens: int = 0
    cached_tokens: int = 0  # prompt tokens the server read from its prompt cache
    completion_tokens: int = 0
    cache_hits: int = 0
    candidates_cut: int = 0  # instances of the map not sent to the model (budget, window)
    failures: list[str] = []
    failed_calls: int = 0  # model calls that got no reply (a resume asks this query again)
    candidate_recall: Optional[bool] = None
    nav_success: Optional[bool] = None  # reached within 1 m of the ground-truth instance (N-SR)
    path_length_m: Optional[float] = None
    # the evidence of the answer, for the HTML report (records of older runs lack it)
    accept: list[int] = []
    start: Optional[tuple[float, float]] = None  # the robot's start (m), N-SR
    nav_path: list[tuple[float, float]] = []  # the planned path to the prediction (m), N-SR
    gate: dict[str, float] = {}  # normalised gate weight per expert
    hints: dict[str, str] = {}
    experts: dict[str, list[int]] = {}  # each expert's validated top-kappa
    abstained: dict[str, float] = {}  # gate weight of each expert that returned no ranking
    scores: dict[int, float] = {}  # U of the scored ids in `ranking`
    sum_scores: dict[int, float] = {}  # S
    peak_scores: dict[int, float] = {}  # P
    lam: Optional[float] = None
    kappa: Optional[int] = None
    deciding_expert: Optional[str] = None
    notes: list[str] = []
    names: dict[int, str] = {}  # "label (room)" of the ids mentioned
    #: every model call: template and its hash, prompt sha256, cost, error; `reply` is "" and
    #: `messages` None unless the run kept prompts (`iesm eval --keep-prompts`)
    calls: list[KeptCall] = []

    @property
    def key(self) -> tuple[str, str]:
        return self.id, self.variant


def _no_constant(name: str):
    raise ValueError(f"{name} is not a number a record may hold")


def read_journal(path: Path) -> list[ResultRecord]:
    """All complete (newline-terminated) records of `path` (missing file -> []). A damaged
    complete line (not JSON, NaN / Infinity, nested too deep, a wrong field) is an error naming
    the line."""
    if not path.exists():
        return []
    lines = path.read_text(encoding="utf-8", errors="replace").split("\n")[:-1]  # the last piece has no newline
    records = []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            records.append(ResultRecord.model_validate(json.loads(line, parse_constant=_no_constant)))
        except ValidationError as exc:
            raise IesmError(f"damaged journal record: {exc.errors()[0]['msg']}", path, f"line {number}") from None
        except (ValueError, RecursionError) as exc:  # not JSON (JSONDecodeError), NaN, too deep
            raise IesmError(f"damaged journal record: {' '.join(str(exc).split())[:200]}", path,
                            f"line {number}") from None
    return records


def repair_journal(path: Path) -> None:
    """Cut a truncated last line so that appends start on a fresh line."""
    if not path.exists():
        return
    data = path.read_bytes()
    if data and not data.endswith(b"\n"):
        path.write_bytes(data[: data.rfind(b"\n") + 1])


def append_record(handle: IO[str], record: ResultRecord) -> None:
    """Write one record as a line and flush it to the OS."""
    handle.write(json.dumps(record.model_dump(mode="json"), ensure_ascii=False) + "\n")
    handle.flush()
