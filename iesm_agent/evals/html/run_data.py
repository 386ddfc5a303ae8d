"""What the HTML report shows, read from one or two eval run directories: the run facts, the
metrics tables with Wilson intervals, the paired tests, the paraphrase groups, every record (its
evidence trimmed to a bounded size) and the maps the queries were asked on.

Bounds (so a page stays under `MAX_PAGE_BYTES`): at most `MAX_ROWS` records, kept prompts and
replies at most `MESSAGE_CHARS` each and `PROMPT_BUDGET` in all (later ones are left out, and the
page says so), maps drawn at most `shapes.MAX_SIDE` cells a side.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from pydantic import BaseModel, ConfigDict, ValidationError

from ...errors import IesmError
from ...fileio import load_json, validation_message
from ...store.refs import open_map, resolve_map_path
from ..journal import RESULTS, RUN_CONFIG, ResultRecord, read_journal
from ..query_types import UNTYPED, ordered_types, type_title
from ..significance import paired_test
from ..summary import build_summary
from .shapes import map_layers

#: the most (query, variant) rows one page shows
MAX_ROWS = 5000
#: characters of one kept prompt message or reply shown
MESSAGE_CHARS = 6000
#: characters of kept prompts and replies in one page
PROMPT_BUDGET = 3_000_000
#: the largest page written (bytes): rows of about 2 KB, the prompt budget and a few maps fit
MAX_PAGE_BYTES = 24_000_000


@dataclass
class Run:
    """One run directory: its label ("A", "B" when two are compared), configuration, summary
    and the latest record of each (query, variant)."""

    label: str
    directory: Path
    config: dict
    facts: dict
    records: list[ResultRecord]
    variants: list[str] = field(default_factory=list)


class VariantView(BaseModel):
    """One variant of `run.json` as the page reads it: its name."""

    model_config = ConfigDict(extra="ignore")

    name: str


class RunFileView(BaseModel):
    """The fields of a run's `run.json` the page shows (others ignored; a file written by an older
    version may lack some): wrong types are refused by name."""

    model_config = ConfigDict(extra="ignore", allow_inf_nan=False)

    provider: Optional[str] = None
    suites: list[str] = []
    variants: list[VariantView] = []
    prompt_hashes: dict[str, dict[str, str]] = {}


class RunFacts(BaseModel):
    """`summary.json`'s `run` facts the page's header shows."""

    model_config = ConfigDict(extra="ignore", allow_inf_nan=False)

    queries: Optional[int] = None
    wall_s: Optional[float] = None


def _read_model(path: Path, model: type[BaseModel], part: str | None = None) -> dict:
    """`model` validated from the JSON file `path` (or its member `part`), as a dict; a missing
    file is an empty one. NaN / Infinity, wrong types or a file that is no JSON object are one
    `IesmError` naming the file and field."""
    if not path.is_file():
        return {}
    data = load_json(path, allow_nan=False)
    if part is not None:
        data = data.get(part, {}) if isinstance(data, dict) else None
    if not isinstance(data, dict):
        raise IesmError("expected a JSON object", path, part)
    try:
        return model.model_validate(data).model_dump(exclude_none=True)
    except ValidationError as exc:
        message, field = validation_message(exc)
        raise IesmError(message, path, f"{part}.{field}" if part and field else part or field) from None


def load_run(directory: str | Path, label: str = "") -> Run:
    """Read `directory` (run.json, results.jsonl, summary.json when present); one `IesmError`
    naming the file when it is not an eval run directory or a file in it is damaged."""
    directory = Path(directory)
    if not directory.is_dir():
        raise IesmError("not a directory (expected an eval run directory)", directory)
    if not (directory / RESULTS).is_file():
        raise IesmError(f"not an eval run directory: no {RESULTS}", directory)
    config = _read_model(directory / RUN_CONFIG, RunFileView)
    facts = _read_model(directory / "summary.json", RunFacts, "run")
    latest = {r.key: r for r in read_journal(directory / RESULTS)}
    if not latest:
        raise IesmError(f"the run has no results yet ({RESULTS} is empty)", directory)
    named = [v["name"] for v in config.get("variants", [])]
    seen = list(dict.fromkeys(r.variant for r in latest.values()))
    variants = [v for v in named if v in seen] + [v for v in seen if v not in named]
    return Run(label, directory, config, facts, list(latest.values()), variants)


def wilson(k: int, n: int, z: float = 1.96) -> tuple[float, float]:
    """95 % Wilson score interval of a proportion k / n ((0, 1) when n is 0)."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def _cell(records: list[ResultRecord]) -> dict:
    k, n = sum(r.correct for r in records), len(records)
    lo, hi = wilson(k, n)
    return {"n": n, "k": k, "osr": k / n if n else None, "lo": lo, "hi": hi}


def metric_rows(runs: list[Run], names: dict[tuple[str, str], str], types: list[str]) -> list[dict]:
    """Per shown variant: O-SR with n and Wilson interval per type and overall, MRR, top-3,
    N-SR and failures, from the records."""
    rows = []
    for run in runs:
        summary = build_summary(run.records, run.variants)
        for variant in run.variants:
            mine = [r for r in run.records if r.variant == variant]
            overall = summary["methods"][variant]["overall"]
            rows.append({"variant": names[run.label, variant], "overall": _cell(mine),
                         "types": {t: _cell([r for r in mine if (r.type or UNTYPED) == t]) for t in types},
                         "mrr": overall["mrr"], "top3": overall["top3"], "nsr": overall.get("nsr"),
                         "failures": overall["queries_with_failures"], "latency": overall["latency_ms_p50"],
                         "groups": summary["methods"][variant].get("groups")})
    return rows


def significance_rows(runs: list[Run], names: dict[tuple[str, str], str]) -> list[dict]:
    """Exact McNemar tests: within each run the first variant against the others (as
    summary.json), and across two runs each variant against the same-named one (else the
    first variants), on the queries both answered, overall and per type."""
    out = []
    for run in runs:
        summary = build_summary(run.records, run.variants)
        out += [{**t, "a": names[run.label, t["a"]], "b": names[run.label, t["b"]]} for t in summary["significance"]]
    if len(runs) == 2:
        a, b = runs
        pairs = [(v, v) for v in a.variants if v in b.variants] or [(a.variants[0], b.variants[0])]
        for va, vb in pairs:
            ra = {r.id: r for r in a.records if r.variant == va}
            rb = {r.id: r for r in b.records if r.variant == vb}
            types = {q: (ra[q].type or UNTYPED) for q in ra}
            for group in ["overall", *ordered_types(set(types.values()) - {UNTYPED})]:
                ids = {q for q in ra if group == "overall" or types[q] == group}
                test = paired_test({q: ra[q].correct for q in ids}, {q: r.correct for q, r in rb.items() if q in ids})
                out.append({"a": names[a.label, va], "b": names[b.label, vb], "type": group, **test})
    return out


class MapCache:
    """Maps of the records, each loaded and traced once; a map that cannot be found is noted
    and drawn as missing."""

    def __init__(self) -> None:
        self.keys: dict[Path, str] = {}
        self.layers: dict[str, dict] = {}
        self.missing: dict[str, str] = {}

    def key(self, ref: str, bases: list[Path]) -> str | None:
        for base in [*bases, Path.cwd()]:
            try:
                path = resolve_map_path(ref, base)
            except IesmError:
                continue
            if path not in self.keys:
                key = f"m{len(self.keys)}"
                self.keys[path] = key
                try:
                    self.layers[key] = map_layers(open_map(path))
                except IesmError as exc:
                    self.missing[key] = str(exc)
            return self.keys[path]
        self.missing.setdefault(ref, "map file not found")
        return None


class Texts:
    """Kept prompt messages and replies, each distinct text stored once (system prompts and
    candidate blocks repeat across calls and queries): records refer to them by index. A text is
    cut to MESSAGE_CHARS; once PROMPT_BUDGET characters are stored, new texts are left out (None)."""

    def __init__(self) -> None:
        self.texts: list[str] = []
        self.index: dict[str, int] = {}
        self.left = PROMPT_BUDGET

    def ref(self, text: str | None) -> int | None:
        if text is None:
            return None
        if text not in self.index:
            if self.left <= 0:
                return None
            cut = text[:MESSAGE_CHARS] + (f"\n... [{len(text) - MESSAGE_CHARS} more characters]"
                                          if len(text) > MESSAGE_CHARS else "")
            self.left -= len(cut)
            self.index[text] = len(self.texts)
            self.texts.append(cut)
        return self.index[text]


def record_data(record: ResultRecord, variant: str, map_key: str | None, texts: Texts) -> dict:
    """One record as the page's JSON: the query, outcome and evidence; kept prompts and replies
    as indices into `texts`."""
    calls = []
    for c in record.calls:
        call = c.model_dump(exclude={"messages", "reply", "prompt_sha256"})
        call["prompt_sha256"] = c.prompt_sha256[:12]
        if c.messages is not None:
            call["messages"] = [{"role": m.get("role", ""), "content": texts.ref(m.get("content", ""))}
                                for m in c.messages]
            call["reply"] = texts.ref(c.reply)
        calls.append(call)
    data = record.model_dump(mode="json", exclude={"calls", "variant"})
    data.update(variant=variant, map_key=map_key, calls=calls)
    return data


def report_data(run_dirs: list[str | Path]) -> dict:
    """Everything the report page needs from one run (or two compared: variants prefixed
    "A:" and "B:")."""
    if not 1 <= len(run_dirs) <= 2:
        raise IesmError("give one run directory, or two to compare", "RUN_DIR")
    runs = [load_run(d, "AB"[i] if len(run_dirs) == 2 else "") for i, d in enumerate(run_dirs)]
    names = {(run.label, v): f"{run.label}:{v}" if run.label else v for run in runs for v in run.variants}
    types = ordered_types({r.type or UNTYPED for run in runs for r in run.records} - {UNTYPED})
    if any(r.type is None for run in runs for r in run.records):
        types.append(UNTYPED)
    maps, texts = MapCache(), Texts()
    records, dropped = [], 0
    for run in runs:
        bases = [Path(s).parent for s in run.config.get("suites", []) if isinstance(s, str)]
        order = {v: i for i, v in enumerate(run.variants)}
        for record in sorted(run.records, key=lambda r: (order.get(r.variant, 0), r.id)):
            if len(records) >= MAX_ROWS:
                dropped += 1
                continue
            records.append(record_data(record, names[run.label, record.variant], maps.key(record.map, bases), texts))
    kept = any(c.messages is not None for run in runs for r in run.records for c in r.calls)
    return {
        "runs": [{"label": run.label, "directory": str(run.directory), "provider": run.config.get("provider"),
                  "suites": run.config.get("suites", []), "variants": [names[run.label, v] for v in run.variants],
                  "prompt_hashes": {names[run.label, v]: h for v, h in run.config.get("prompt_hashes", {}).items()
                                    if (run.label, v) in names},
                  "facts": run.facts} for run in runs],
        "variants": list(names.values()),
        "types": [{"id": t, "title": type_title(t)} for t in types],
        "metrics": metric_rows(runs, names, types),
        "significance": significance_rows(runs, names),
        "records": records,
        "texts": texts.texts,
        "maps": maps.layers,
        "missing_maps": maps.missing,
        "limits": {"rows": MAX_ROWS, "rows_left_out": dropped, "message_chars": MESSAGE_CHARS,
                   "prompt_budget": PROMPT_BUDGET, "prompts_kept": kept,
                   "prompts_left_out": kept and texts.left <= 0, "page_bytes": MAX_PAGE_BYTES},
    }
