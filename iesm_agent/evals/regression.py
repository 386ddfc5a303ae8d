"""The regression gate: every suite's per-query verdicts against committed reference verdicts.

`discover_suites` lists the shipped suites (`evals/*.jsonl`), the blind rounds
(`evals/blind/round*.jsonl`) and, where present, the referring development corpus; a suite whose
maps are not on this machine is skipped with a reason. `run_suites` scores them with the eval
runner (one run, the runner's concurrency) and keeps one compact `Verdict` per (query, method).
`compare` sets them against the references (`evals/reference_verdicts/<suite>.jsonl`): a method
fails a suite when its correct count drops by more than `TOLERANCE` (one query per hundred) of the
queries both hold; every query whose verdict changed is named, both directions. `disagreement`
counts how often two methods (MTEFR and SPR) disagree on non-spatial queries and who is right then.
"""

from __future__ import annotations

import asyncio
import json
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Optional

from pydantic import BaseModel, ConfigDict, ValidationError

from ..errors import IesmError
from ..fileio import load_json, validation_message, write_text
from ..store.refs import resolve_map_path
from ..understanding.spatial import parse_query

#: a suite fails when its correct count drops by more than this share of its queries
TOLERANCE = 0.01
#: the query type of spatial referring expressions, left out of the disagreement counts
SPATIAL_TYPE = "s"
#: the methods the gate scores unless told otherwise
DEFAULT_METHODS = ("mtefr", "spr")


class Verdict(BaseModel):
    """One query under one method: right or wrong and the id picked (None: nothing picked).
    `query` is left out for suites whose text may not be committed (the referring corpus)."""

    model_config = ConfigDict(extra="forbid")

    id: str
    method: str
    type: Optional[str] = None
    correct: bool
    predicted: Optional[int] = None
    query: Optional[str] = None
    #: whether the spatial reading finds a relation in the query (the spatial expert is asked);
    #: None in references written before it was recorded
    relation: Optional[bool] = None


@dataclass
class SuiteSpec:
    """A suite the gate knows: its name (the reference file's stem), its file, whether its query
    text may be written into the repository, and why it cannot run here (None: it can)."""

    name: str
    path: Path
    keep_text: bool = True
    missing: Optional[str] = None


def missing_maps(path: Path) -> Optional[str]:
    """Why the suite at `path` cannot run on this machine (its file or a map file it names by a
    path is not present), or None. Bare map names (shipped maps) and lines that are not JSON
    objects are left to the suite loader, which reports what is wrong with them."""
    if not path.is_file():
        return f"no file {path}"
    refs = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            ref = json.loads(line).get("map") if line.strip() else None
        except (json.JSONDecodeError, AttributeError):
            continue
        if isinstance(ref, str) and ("/" in ref or "\\" in ref):
            refs[ref] = None
    for ref in refs:
        try:
            resolve_map_path(ref, path.parent)
        except IesmError:
            return f"map {ref} is not present"
    return None


def discover_suites(evals_dir: Path, referring_dir: Path) -> list[SuiteSpec]:
    """The shipped suites, the blind rounds (named `blind-<stem>`) and the referring corpus's
    `scanrefer_dev` and `nr3d_dev` (text never kept), each with `missing` set when it cannot run."""
    specs = [SuiteSpec(p.stem, p) for p in sorted(evals_dir.glob("*.jsonl"))]
    specs += [SuiteSpec(f"blind-{p.stem}", p) for p in sorted((evals_dir / "blind").glob("round*.jsonl"))]
    specs += [SuiteSpec(stem, referring_dir / f"{stem}.jsonl", keep_text=False) for stem in ("scanrefer_dev", "nr3d_dev")]
    for spec in specs:
        spec.missing = missing_maps(spec.path)
    return specs


async def run_suites(specs: list[SuiteSpec], methods: Iterable[str], *, concurrency: int = 4,
                     on_start=None, on_result=None) -> dict[str, list[Verdict]]:
    """Score every runnable suite of `specs` with `methods` on the offline model in one eval run
    (its journal in a temporary directory); suite name -> its verdicts (with the query text) in
    file order. `on_start(n)` and `on_result(record)` drive a progress display."""
    from .runner import make_config, make_variants, run_eval

    runnable = [s for s in specs if s.missing is None]
    if not runnable:
        return {}
    config = make_config([s.path for s in runnable], make_variants(list(methods), []), "offline")
    with tempfile.TemporaryDirectory(prefix="iesm-eval-check-") as tmp:
        outcome = await run_eval(config, Path(tmp) / "run", concurrency=concurrency,
                                 on_start=on_start, on_result=on_result)
    by_source = {s.path.resolve(): s for s in runnable}
    suite_of = {e.query.id: by_source[e.source.resolve()] for e in outcome.suite.entries}
    order = {e.query.id: k for k, e in enumerate(outcome.suite.entries)}
    out: dict[str, list[Verdict]] = {s.name: [] for s in runnable}
    for r in sorted(outcome.records, key=lambda r: (order[r.id], r.method)):
        out[suite_of[r.id].name].append(Verdict(id=r.id, method=r.method, type=r.type, correct=r.correct,
                                                predicted=r.predicted, query=r.query,
                                                relation=bool(parse_query(r.query).relations)))
    return out


def committable(spec: SuiteSpec, verdicts: list[Verdict]) -> list[Verdict]:
    """`verdicts` as they may be written to a file: without the query text when `spec` may not keep it."""
    return verdicts if spec.keep_text else [v.model_copy(update={"query": None}) for v in verdicts]


def read_verdicts(path: Path) -> list[Verdict]:
    """The verdicts of a JSONL file; a bad line is an `IesmError` naming file and line."""
    verdicts = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if not line.strip():
            continue
        try:
            verdicts.append(Verdict.model_validate(load_json(line, path, f"line {number}")))
        except ValidationError as exc:
            message, where = validation_message(exc)
            raise IesmError(f"{where}: {message}" if where else message, path, f"line {number}") from None
    return verdicts


def write_verdicts(path: Path, verdicts: Iterable[Verdict]) -> None:
    """Write `verdicts` as JSONL (one compact line each, unset fields left out), atomically."""
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text(path, "".join(v.model_dump_json(exclude_none=True) + "\n" for v in verdicts))


class Change(BaseModel):
    """A query whose verdict changed between the reference and now."""

    id: str
    query: Optional[str] = None
    before_correct: bool
    after_correct: bool
    before_predicted: Optional[int] = None
    after_predicted: Optional[int] = None


class MethodDelta(BaseModel):
    """One method on one suite, over the queries both the reference and the run hold: correct
    counts before and after, the changed verdicts, and the ids only one side has."""

    suite: str
    method: str
    n: int
    before: int
    after: int
    changes: list[Change] = []
    new_ids: list[str] = []  # in the run, not in the reference
    gone_ids: list[str] = []  # in the reference, not in the run

    @property
    def delta(self) -> int:
        return self.after - self.before

    @property
    def allowed_drop(self) -> float:
        """Queries this suite may lose: `TOLERANCE` of n."""
        return TOLERANCE * self.n

    @property
    def failed(self) -> bool:
        return -self.delta > self.allowed_drop


def compare(suite: str, reference: list[Verdict], current: list[Verdict]) -> list[MethodDelta]:
    """Per method present in both, `current` against `reference` on their shared query ids; a
    changed query carries the current text, else the reference's (None when neither keeps it)."""
    deltas = []
    for method in dict.fromkeys(v.method for v in current):
        before = {v.id: v for v in reference if v.method == method}
        if not before:
            continue
        after = {v.id: v for v in current if v.method == method}
        shared = [i for i in after if i in before]
        changes = [Change(id=i, query=after[i].query or before[i].query, before_correct=before[i].correct,
                          after_correct=after[i].correct, before_predicted=before[i].predicted,
                          after_predicted=after[i].predicted)
                   for i in shared if before[i].correct != after[i].correct]
        deltas.append(MethodDelta(suite=suite, method=method, n=len(shared),
                                  before=sum(before[i].correct for i in shared),
                                  after=sum(after[i].correct for i in shared), changes=changes,
                                  new_ids=[i for i in after if i not in before],
                                  gone_ids=[i for i in before if i not in after]))
    return deltas


def disagreement(verdicts: list[Verdict], a: str = "mtefr", b: str = "spr", *,
                 non_spatial: bool = True, without_relation: bool = False) -> Optional[dict]:
    """How often methods `a` and `b` disagree on the queries of type other than `SPATIAL_TYPE`
    (every query when `non_spatial` is False; with `without_relation`, the queries in which the
    reading finds no spatial relation, whatever their type): `n` queries both answered,
    `verdicts_differ` (one right, the other wrong) split into `a_wins` and `b_wins`, `picks_differ`
    (different ids, whatever the verdicts) and `share_differ` = verdicts_differ / n. None when a
    method is absent."""
    first = {v.id: v for v in verdicts if v.method == a}
    second = {v.id: v for v in verdicts if v.method == b}
    if not first or not second:
        return None
    ids = [i for i, v in first.items() if i in second and not (non_spatial and v.type == SPATIAL_TYPE)
           and not (without_relation and v.relation is not False)]
    a_wins = sum(first[i].correct and not second[i].correct for i in ids)
    b_wins = sum(second[i].correct and not first[i].correct for i in ids)
    return {"methods": [a, b], "n": len(ids), "verdicts_differ": a_wins + b_wins,
            "share_differ": round((a_wins + b_wins) / len(ids), 4) if ids else None,
            f"{a}_wins": a_wins, f"{b}_wins": b_wins,
            "picks_differ": sum(first[i].predicted != second[i].predicted for i in ids)}


@dataclass
class CheckReport:
    """What one gate run found: per-suite deltas, skipped suites (name -> reason), suites run
    without a reference, the disagreement counts, and whether the gate passed."""

    deltas: list[MethodDelta] = field(default_factory=list)
    skipped: dict[str, str] = field(default_factory=dict)
    unreferenced: list[str] = field(default_factory=list)
    disagreements: dict[str, dict] = field(default_factory=dict)
    updated: list[str] = field(default_factory=list)

    @property
    def failed(self) -> list[MethodDelta]:
        return [d for d in self.deltas if d.failed]

    @property
    def passed(self) -> bool:
        return not self.failed and not self.unreferenced

    def to_json(self) -> dict:
        return {"passed": self.passed, "tolerance": TOLERANCE,
                "suites": [{**d.model_dump(), "delta": d.delta, "failed": d.failed} for d in self.deltas],
                "skipped": self.skipped, "unreferenced": self.unreferenced,
                "disagreement": self.disagreements, "updated": self.updated}


def reference_path(references_dir: Path, suite: str) -> Path:
    return references_dir / f"{suite}.jsonl"


def check(specs: list[SuiteSpec], results: dict[str, list[Verdict]], references_dir: Path, *,
          update: bool = False) -> CheckReport:
    """Compare each suite's `results` with its reference verdicts (or, with `update`, rewrite the
    references of the suites and methods that ran, still reporting what changed against the old ones)."""
    report = CheckReport(skipped={s.name: s.missing for s in specs if s.missing is not None})
    for spec in specs:
        if spec.name not in results:
            continue
        current = results[spec.name]
        ref_file = reference_path(references_dir, spec.name)
        reference = read_verdicts(ref_file) if ref_file.exists() else None
        if reference is not None:
            report.deltas += compare(spec.name, reference, current)
        elif not update:
            report.unreferenced.append(spec.name)
        report.disagreements[spec.name] = {"non_spatial": disagreement(current),
                                           "no_relation": disagreement(current, non_spatial=False,
                                                                       without_relation=True),
                                           "all": disagreement(current, non_spatial=False)}
        if update:  # the references of methods this run did not score are kept
            ran = {v.method for v in current}
            kept = [v for v in reference or [] if v.method not in ran]
            write_verdicts(ref_file, committable(spec, current) + kept)
            report.updated.append(spec.name)
    return report


def run_check(evals_dir: Path, referring_dir: Path, references_dir: Path, out_dir: Path, *,
              methods: Iterable[str] = DEFAULT_METHODS, only: Iterable[str] = (), update: bool = False,
              concurrency: int = 4, on_start=None, on_result=None) -> tuple[CheckReport, list[SuiteSpec]]:
    """The whole gate: discover, run, compare (or update); writes `out_dir/verdicts.jsonl` (every
    suite's verdicts, with a `suite` field; no corpus text) and `out_dir/regression.json` (the
    report). `only` restricts it to the named suites."""
    specs = discover_suites(evals_dir, referring_dir)
    wanted = set(only)
    if wanted:
        unknown = sorted(wanted - {s.name for s in specs})
        if unknown:
            raise IesmError(f"unknown suite {unknown[0]!r} (known: {', '.join(s.name for s in specs)})", None,
                            "--suite")
        specs = [s for s in specs if s.name in wanted]
    for spec in specs:  # a damaged reference is reported before the run, not after it
        if spec.missing is None and reference_path(references_dir, spec.name).exists():
            read_verdicts(reference_path(references_dir, spec.name))
    results = asyncio.run(run_suites(specs, methods, concurrency=concurrency, on_start=on_start,
                                     on_result=on_result))
    report = check(specs, results, references_dir, update=update)
    out_dir.mkdir(parents=True, exist_ok=True)
    by_name = {s.name: s for s in specs}
    write_text(out_dir / "verdicts.jsonl", "".join(
        json.dumps({"suite": name, **v.model_dump(exclude_none=True)}) + "\n"
        for name, verdicts in results.items() for v in committable(by_name[name], verdicts)))
    write_text(out_dir / "regression.json", json.dumps(report.to_json(), indent=1) + "\n")
    return report, specs
