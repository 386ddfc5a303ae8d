"""No test and no code comment quotes an evaluation query: a string literal in `iesm_agent/` or `tests/` must
not equal, word for word (case and punctuation aside), a query of a shipped suite, a blind round or (when present
beside the repository) the referring development corpus. A rule or test written from a suite's wording fits that
suite; these are written in our own words (docs/evaluation-discipline.md)."""

from __future__ import annotations

import json
import re
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO.parent / "shared" / "data" / "referring_dev"
#: a literal this short ("the red chair") says nothing particular to a suite
MIN_WORDS = 3


def _words(text: str) -> str:
    return " ".join(re.findall(r"[a-z0-9']+", text.lower()))


def _queries() -> set[str]:
    files = [*REPO.glob("evals/*.jsonl"), *REPO.glob("evals/blind/*.jsonl"), *CORPUS.glob("*.jsonl")]
    out = set()
    for path in files:
        for line in path.read_text(encoding="utf-8").splitlines():
            try:
                row = json.loads(line)
            except ValueError:
                continue
            text = row.get("query") or row.get("utterance") or row.get("description") if isinstance(row, dict) else None
            if isinstance(text, str) and len(_words(text).split()) >= MIN_WORDS:
                out.add(_words(text))
    return out


def quoted_queries(paths: list[Path], queries: set[str]) -> list[str]:
    """`file:line: literal` for each double-quoted literal of `paths` that is one of `queries`."""
    hits = []
    for path in paths:
        source = path.read_text(encoding="utf-8")
        for m in re.finditer(r'"([^"\n]{8,})"', source):
            if _words(m.group(1)) in queries:
                hits.append(f"{path.relative_to(REPO)}:{source.count(chr(10), 0, m.start()) + 1}: {m.group(1)}")
    return hits


def test_no_literal_is_a_suite_query():
    queries = _queries()
    assert len(queries) > 1000  # the shipped suites and blind rounds are read
    paths = sorted([*REPO.glob("iesm_agent/**/*.py"), *REPO.glob("tests/*.py")])
    assert quoted_queries(paths, queries) == []


def test_the_check_finds_a_quoted_query(tmp_path, monkeypatch):
    source = tmp_path / "sample.py"
    source.write_text('# "The Green Kettle, on the hob!"\nx = "a green kettle on a hob"\n', encoding="utf-8")
    monkeypatch.setattr(f"{__name__}.REPO", tmp_path)
    assert quoted_queries([source], {"the green kettle on the hob"}) == ["sample.py:1: The Green Kettle, on the hob!"]
