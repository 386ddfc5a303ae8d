"""McNemar against hand-computed values; metrics from ranks; the run journal."""

from __future__ import annotations

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.evals.journal import ResultRecord, append_record, read_journal, repair_journal
from iesm_agent.evals.metrics import mrr, summarize, top_k
from iesm_agent.evals.significance import compare_to_first, mcnemar_exact, paired_test


@pytest.mark.parametrize("b, c, expected", [
    (0, 0, 1.0),
    (1, 0, 1.0),                    # 2 * 1/2 = 1
    (5, 0, 0.0625),                 # 2 * (1/32)
    (0, 6, 0.03125),                # 2 * (1/64)
    (2, 8, 0.109375),               # 2 * (1 + 10 + 45) / 1024
    (3, 3, 1.0),                    # symmetric: capped at 1
    (1, 9, 0.021484375),            # 2 * (1 + 10) / 1024
])
def test_mcnemar_exact_matches_hand_computation(b, c, expected):
    assert mcnemar_exact(b, c) == pytest.approx(expected, abs=1e-12)


def test_mcnemar_is_symmetric_and_rejects_negative_counts():
    assert mcnemar_exact(4, 11) == mcnemar_exact(11, 4)
    with pytest.raises(ValueError):
        mcnemar_exact(-1, 2)


def test_paired_test_counts_only_shared_discordant_queries():
    a = {"q1": True, "q2": True, "q3": False, "q4": True, "only_a": True}
    b = {"q1": True, "q2": False, "q3": True, "q4": False, "only_b": False}
    out = paired_test(a, b)
    assert out == {"n": 4, "a_only": 2, "b_only": 1, "p": pytest.approx(1.0)}


def test_compare_to_first_groups_by_type():
    correct = {"A": {"1": True, "2": True, "3": True}, "B": {"1": False, "2": False, "3": True}}
    tests = compare_to_first(correct, {"1": "o", "2": "o", "3": "ard"}, ["A", "B"])
    by_type = {t["type"]: t for t in tests}
    assert set(by_type) == {"overall", "o", "ard"}
    assert (by_type["o"]["a_only"], by_type["o"]["b_only"], by_type["o"]["p"]) == (2, 0, 0.5)
    assert by_type["ard"]["n"] == 1 and by_type["ard"]["p"] == 1.0
    assert compare_to_first(correct, {"1": "o"}, ["A"]) == []


def _record(qid, variant="mtefr", qtype="o", correct=True, rank=1, latency=10.0):
    return ResultRecord(id=qid, variant=variant, method=variant, type=qtype, map="m", query="q",
                        target=1, predicted=1 if correct else 2, correct=correct, rank=rank,
                        ranking=[1, 2], latency_ms=latency)


def test_mrr_and_top_k_from_ranks():
    assert mrr([1, 2, None, 4]) == pytest.approx((1 + 0.5 + 0 + 0.25) / 4)
    assert top_k([1, 3, 4, None], 3) == 0.5
    assert mrr([]) == 0.0


def test_summary_shape_per_variant_and_type():
    records = [_record("a", qtype="o"), _record("b", qtype="o", correct=False, rank=2),
               _record("c", qtype="ard", correct=False, rank=None),
               _record("a", variant="spr", qtype="o", correct=False, rank=3)]
    summary = summarize(records, ["spr", "mtefr"])
    assert list(summary["methods"]) == ["spr", "mtefr"]
    m = summary["methods"]["mtefr"]
    assert m["overall"]["n"] == 3
    assert m["overall"]["osr"] == pytest.approx(1 / 3)
    assert m["overall"]["mrr"] == pytest.approx(0.5)
    assert m["overall"]["top3"] == pytest.approx(2 / 3)
    assert m["by_type"]["o"] == {"n": 2, "osr": 0.5, "mrr": 0.75}
    assert m["overall"]["osr_type_mean"] == pytest.approx(0.25)  # mean of (o) 0.5 and (a,r,d) 0.0
    assert summary["methods"]["spr"]["by_type"]["o"]["osr"] == 0.0


def test_journal_ignores_truncated_last_line_and_repairs_it(tmp_path):
    path = tmp_path / "results.jsonl"
    with path.open("w") as handle:
        append_record(handle, _record("a"))
        append_record(handle, _record("b"))
    full = path.read_bytes()
    path.write_bytes(full + full[:40])  # a kill in the middle of the third write
    assert [r.id for r in read_journal(path)] == ["a", "b"]
    repair_journal(path)
    assert path.read_bytes() == full


def test_journal_damaged_complete_line_names_the_line(tmp_path):
    path = tmp_path / "results.jsonl"
    with path.open("w") as handle:
        append_record(handle, _record("a"))
    with path.open("a") as handle:
        handle.write("{not json}\n")
    with pytest.raises(IesmError, match=r"results.jsonl:line 2"):
        read_journal(path)
