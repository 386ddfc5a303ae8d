"""The regression gate (`iesm eval-check`, `make eval-suites`): comparison on synthetic verdict
files, suite discovery, and one real run on a tiny suite."""

import json
from pathlib import Path

from iesm_agent.cli import run
from iesm_agent.evals.regression import (SuiteSpec, Verdict, check, compare, disagreement, discover_suites,
                                         missing_maps, read_verdicts, write_verdicts)

APARTMENT_SUITE = Path(__file__).resolve().parents[1] / "evals" / "apartment_suite.jsonl"


def _verdicts(method: str, right: list[bool], predicted: int = 1, type_: str = "o") -> list[Verdict]:
    return [Verdict(id=f"q{k}", method=method, type=type_, correct=ok, predicted=predicted if ok else 99,
                    query=f"query {k}") for k, ok in enumerate(right)]


def _write_reference(tmp_path: Path, suite: str, verdicts: list[Verdict]) -> Path:
    refs = tmp_path / "refs"
    write_verdicts(refs / f"{suite}.jsonl", verdicts)
    return refs


def test_a_drop_beyond_one_per_hundred_fails_and_names_the_queries(tmp_path):
    before = _verdicts("mtefr", [True] * 50)
    after = _verdicts("mtefr", [True] * 48 + [False, False])
    (delta,) = compare("s", before, after)
    assert (delta.n, delta.before, delta.after, delta.delta) == (50, 50, 48, -2)
    assert delta.failed  # 2 lost > 0.5 allowed
    assert [(c.id, c.query, c.before_predicted, c.after_predicted) for c in delta.changes] == [
        ("q48", "query 48", 1, 99), ("q49", "query 49", 1, 99)]
    report = check([SuiteSpec("s", tmp_path / "s.jsonl")], {"s": after}, _write_reference(tmp_path, "s", before))
    assert not report.passed and [d.suite for d in report.failed] == ["s"]


def test_a_drop_within_the_tolerance_passes_and_lists_gains_and_losses(tmp_path):
    # 200 queries: 3 lost, 1 gained, net -2 = 1 per hundred, not more
    before = _verdicts("spr", [True] * 197 + [False] * 3)
    after_right = [True] * 197 + [False] * 3
    after_right[0] = after_right[1] = after_right[2] = False
    after_right[197] = True
    after = _verdicts("spr", after_right)
    report = check([SuiteSpec("s", tmp_path / "s.jsonl")], {"s": after}, _write_reference(tmp_path, "s", before))
    (delta,) = report.deltas
    assert delta.delta == -2 and not delta.failed and report.passed
    assert {c.id: c.after_correct for c in delta.changes} == {"q0": False, "q1": False, "q2": False, "q197": True}
    # one more loss crosses the line
    after_right[3] = False
    (delta,) = compare("s", before, _verdicts("spr", after_right))
    assert delta.delta == -3 and delta.failed


def test_methods_are_judged_separately_and_only_shared_queries_count():
    before = _verdicts("mtefr", [True] * 100) + _verdicts("spr", [True] * 100)
    after = _verdicts("mtefr", [True] * 100 + [False]) + _verdicts("spr", [True] * 98 + [False] * 2)
    deltas = {d.method: d for d in compare("s", before, after)}
    assert not deltas["mtefr"].failed and deltas["mtefr"].n == 100 and deltas["mtefr"].new_ids == ["q100"]
    assert deltas["spr"].failed and deltas["spr"].delta == -2


def test_missing_data_is_skipped_and_a_suite_without_reference_fails(tmp_path):
    evals = tmp_path / "evals"
    (evals / "blind").mkdir(parents=True)
    line = {"id": "a", "map": "apartment", "query": "the bed", "type": "o", "target": 1}
    (evals / "here.jsonl").write_text(json.dumps(line) + "\n")
    (evals / "blind" / "round9.jsonl").write_text(json.dumps({**line, "id": "b", "map": "../nowhere/x.json"}) + "\n")
    specs = discover_suites(evals, tmp_path / "no_corpus")
    by_name = {s.name: s for s in specs}
    assert set(by_name) == {"here", "blind-round9", "scanrefer_dev", "nr3d_dev"}
    assert by_name["here"].missing is None
    assert "nowhere/x.json is not present" in by_name["blind-round9"].missing
    assert by_name["nr3d_dev"].missing.startswith("no file") and not by_name["nr3d_dev"].keep_text
    # a bare map name is a shipped map: a typo there is the suite loader's error, not missing data
    (evals / "typo.jsonl").write_text(json.dumps({**line, "map": "apartmnt"}) + "\n")
    assert missing_maps(evals / "typo.jsonl") is None

    results = {"here": _verdicts("mtefr", [True])}
    report = check(specs, results, tmp_path / "refs")
    assert set(report.skipped) == {"blind-round9", "scanrefer_dev", "nr3d_dev"}
    assert report.unreferenced == ["here"] and not report.passed
    # --update writes the missing reference; the next check passes
    assert check(specs, results, tmp_path / "refs", update=True).updated == ["here"]
    assert check(specs, results, tmp_path / "refs").passed


def test_update_keeps_the_references_of_methods_not_run(tmp_path):
    spec = SuiteSpec("s", tmp_path / "s.jsonl")
    refs = _write_reference(tmp_path, "s", _verdicts("mtefr", [True, True]) + _verdicts("keyword", [False, True]))
    report = check([spec], {"s": _verdicts("mtefr", [True, False])}, refs, update=True)
    assert report.deltas[0].delta == -1  # what the update accepts is still shown
    stored = {(v.method, v.id): v.correct for v in read_verdicts(refs / "s.jsonl")}
    assert stored == {("mtefr", "q0"): True, ("mtefr", "q1"): False, ("keyword", "q0"): False,
                      ("keyword", "q1"): True}


def test_corpus_references_keep_no_query_text(tmp_path):
    spec = SuiteSpec("nr3d_dev", tmp_path / "nr3d_dev.jsonl", keep_text=False)
    verdicts = _verdicts("mtefr", [True, False])
    check([spec], {"nr3d_dev": verdicts}, tmp_path / "refs", update=True)
    written = (tmp_path / "refs" / "nr3d_dev.jsonl").read_text()
    assert "query" not in written
    assert [(v.id, v.correct, v.predicted) for v in read_verdicts(tmp_path / "refs" / "nr3d_dev.jsonl")] == [
        ("q0", True, 1), ("q1", False, 99)]
    # a changed corpus query is still named with its text from the run
    now = _verdicts("mtefr", [False, False])
    (delta,) = check([spec], {"nr3d_dev": now}, tmp_path / "refs").deltas
    assert delta.changes[0].query == "query 0"


def test_disagreement_counts_who_is_right_on_non_spatial_queries():
    mtefr = _verdicts("mtefr", [True, True, False, True]) + [Verdict(id="s0", method="mtefr", type="s", correct=True)]
    spr = _verdicts("spr", [True, False, True, True]) + [Verdict(id="s0", method="spr", type="s", correct=False)]
    spr[3] = spr[3].model_copy(update={"predicted": 2})  # right too, another accepted id
    counts = disagreement(mtefr + spr)
    assert counts == {"methods": ["mtefr", "spr"], "n": 4, "verdicts_differ": 2, "share_differ": 0.5,
                      "mtefr_wins": 1, "spr_wins": 1, "picks_differ": 3}
    assert disagreement(mtefr + spr, non_spatial=False)["mtefr_wins"] == 2
    assert disagreement(mtefr) is None


def test_disagreement_on_queries_without_a_relation_counts_them_whatever_their_type():
    # a corpus typed spatial as a whole: only the queries in which no relation is read count;
    # verdicts from before the field was recorded (None) are left out
    relation = [False, True, False, None]
    mtefr = [Verdict(id=f"q{k}", method="mtefr", type="s", correct=c, relation=r)
             for k, (c, r) in enumerate(zip([True, True, False, True], relation))]
    spr = [Verdict(id=f"q{k}", method="spr", type="s", correct=c, relation=r)
           for k, (c, r) in enumerate(zip([False, False, True, False], relation))]
    assert disagreement(mtefr + spr)["n"] == 0
    counts = disagreement(mtefr + spr, non_spatial=False, without_relation=True)
    assert (counts["n"], counts["mtefr_wins"], counts["spr_wins"]) == (2, 1, 1)


def test_end_to_end_on_a_tiny_suite(tmp_path, capsys):
    evals = tmp_path / "evals"
    evals.mkdir()
    lines = APARTMENT_SUITE.read_text().splitlines()[:4]
    (evals / "tiny.jsonl").write_text("\n".join(lines) + "\n")
    refs, out = evals / "reference_verdicts", tmp_path / "out"
    args = ["eval-check", "--evals", str(evals), "--referring", str(tmp_path / "absent"),
            "--references", str(refs), "-o", str(out)]
    assert run([*args, "--update"]) == 0
    reference = read_verdicts(refs / "tiny.jsonl")
    assert sorted({v.method for v in reference}) == ["mtefr", "spr"] and len(reference) == 8
    assert all(v.query for v in reference)
    assert run(args) == 0
    printed = capsys.readouterr().out
    assert f"skipped: nr3d_dev (no file {tmp_path / 'absent' / 'nr3d_dev.jsonl'})" in printed and "tiny" in printed

    # move the first query's target to an instance MTEFR did not pick: its verdict flips to wrong
    first = json.loads(lines[0])
    picked = next(v.predicted for v in reference if v.id == first["id"] and v.method == "mtefr")
    assert next(v.correct for v in reference if v.id == first["id"] and v.method == "mtefr")
    other = next(i for i in range(1, 100) if i != picked and i not in first["accept"])
    (evals / "tiny.jsonl").write_text("\n".join([json.dumps({**first, "target": other, "accept": [other]}),
                                                 *lines[1:]]) + "\n")
    assert run(args) == 1
    captured = capsys.readouterr()
    assert f"LOST   tiny mtefr {first['id']} {first['query']!r}: predicted {picked} ->" in captured.out
    assert "tiny mtefr dropped 1 of 4" in captured.err
    stored = json.loads((out / "regression.json").read_text())
    assert not stored["passed"] and {s["method"] for s in stored["suites"] if s["failed"]} >= {"mtefr"}
    assert stored["disagreement"]["tiny"]["non_spatial"]["n"] == 4


def test_a_damaged_reference_is_one_line_before_the_run(tmp_path, capsys):
    evals = tmp_path / "evals"
    evals.mkdir()
    (evals / "tiny.jsonl").write_text(APARTMENT_SUITE.read_text().splitlines()[0] + "\n")
    (evals / "refs").mkdir()
    (evals / "refs" / "tiny.jsonl").write_text('{"id": "x", "method": "mtefr"}\n')
    assert run(["eval-check", "--evals", str(evals), "--referring", str(tmp_path), "--references",
                str(evals / "refs"), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.strip() == f"iesm: error: {evals / 'refs' / 'tiny.jsonl'}:line 1: correct: Field required"
    assert not (tmp_path / "out").exists()
