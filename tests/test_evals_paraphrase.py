"""Paraphrase consistency: groups of wordings scored per method (all wordings correct, same pick),
overall and per type, worst groups in summary, report and terminal table; suites without groups
keep the old summary."""

from __future__ import annotations

import json
import re

import pytest

from iesm_agent.cli.eval_cmds import _print_table
from iesm_agent.evals.journal import read_journal
from iesm_agent.evals.runner import make_config, make_variants, run_eval, write_run_outputs
from iesm_agent.providers import FunctionModel

_QUERY = re.compile(r"<query>(.*?)</query>", re.S)

# (group, type, query, target, accept, what the scripted single pass picks)
LINES = [
    ("sofa", "o", "the sofa", 1, [2], 1),
    ("sofa", "o", "the couch", 1, [2], 2),           # the other sofa: accepted, but another pick
    ("sofa", "o", "a sofa please", 1, [2], 1),
    ("cup", "o", "the cup", 15, [], 15),
    ("cup", "o", "a mug", 15, [], 15),
    ("cup", "o", "my teacup", 15, [], 15),
    ("lamp", "od", "the black lamp", 7, [], 7),
    ("lamp", "od", "the dark lamp", 7, [], 34),      # wrong
    ("lamp", "od", "the lamp that is black", 7, [], 7),
    ("book", "od", "the red book", 12, [], 13),      # wrong twice, the same wrong pick
    ("book", "od", "the crimson book", 12, [], 13),
    ("lonely", "o", "the towel", 44, [], 44),        # one wording: not a paraphrase group
    (None, "o", "the toilet", 40, [], 40),           # no group
]
PICKS = {query: pick for _, _, query, _, _, pick in LINES}


def scripted(messages, options):
    """SPR answers from the table above; the keyword method extracts nothing."""
    text = "\n".join(m.text() for m in messages)
    if "object" in (options.json_schema or {}).get("properties", {}):
        return json.dumps({"object": None, "room": None})
    return json.dumps({"ranked_instance_ids": [PICKS[json.loads(_QUERY.search(text).group(1))]]})


def write_suite(path, with_groups=True):
    lines = []
    for k, (group, qtype, query, target, accept, _) in enumerate(LINES):
        line = {"id": f"q{k:02d}", "map": "apartment", "query": query, "type": qtype, "target": target,
                "accept": accept}
        if with_groups and group:
            line["group"] = group
        lines.append(json.dumps(line))
    path.write_text("\n".join(lines) + "\n")
    return path


async def _run(tmp_path, with_groups=True):
    suite = write_suite(tmp_path / "suite.jsonl", with_groups)
    config = make_config([suite], make_variants(["spr", "keyword"], []), "scripted")
    outcome = await run_eval(config, tmp_path / "run", model=FunctionModel(scripted))
    return write_run_outputs(tmp_path / "run", config, outcome)


async def test_group_shares_follow_the_hand_arithmetic(tmp_path):
    summary = await _run(tmp_path)
    spr = summary["methods"]["spr"]
    # 13 lines, wrong: "the dark lamp", "the red book", "the crimson book" -> 10/13
    assert spr["overall"]["osr"] == pytest.approx(10 / 13)
    g = spr["groups"]
    # groups with two or more wordings: sofa, cup, lamp, book (the towel stands alone)
    assert g["overall"]["n"] == 4 and g["overall"]["wordings"] == 11
    # every wording right: sofa, cup -> 2/4; one pick in every wording: cup (15), book (13) -> 2/4
    assert g["overall"]["all_correct"] == pytest.approx(2 / 4)
    assert g["overall"]["consistent_pick"] == pytest.approx(2 / 4)
    # (o): sofa and cup both right, only cup one pick; (o,d): neither right, book one (wrong) pick
    assert g["by_type"]["o"] == {"n": 2, "wordings": 6, "all_correct": 1.0, "consistent_pick": 0.5}
    assert g["by_type"]["od"] == {"n": 2, "wordings": 5, "all_correct": 0.0, "consistent_pick": 0.5}
    # worst first: book 0/2, then lamp 2/3; groups without a wrong wording are not listed
    assert [(w["group"], w["correct"], w["n"]) for w in g["worst"]] == [("book", 0, 2), ("lamp", 2, 3)]
    assert [(r["query"], r["predicted"], r["correct"]) for r in g["worst"][1]["wordings"]] == [
        ("the black lamp", 7, True), ("the dark lamp", 34, False), ("the lamp that is black", 7, True)]
    # the keyword method picks nothing: no group right, and no pick is not a consistent pick
    kw = summary["methods"]["keyword"]["groups"]["overall"]
    assert (kw["all_correct"], kw["consistent_pick"]) == (0.0, 0.0)


async def test_records_report_and_table_carry_the_groups(tmp_path, capsys):
    summary = await _run(tmp_path)
    records = read_journal(tmp_path / "run" / "results.jsonl")
    assert {r.query: r.group for r in records if r.variant == "spr"}["the couch"] == "sofa"
    assert {r.group for r in records if r.query == "the toilet"} == {None}
    assert json.loads((tmp_path / "run" / "summary.json").read_text())["methods"]["spr"]["groups"]["worst"]
    report = (tmp_path / "run" / "report.md").read_text()
    assert "## Paraphrase consistency (%)" in report
    assert "| spr | 76.9 | 50.0 | 50.0 | 100.0 / 50.0 | 0.0 / 50.0 |" in report
    assert "- `book` (o,d): 0/2 correct" in report and "MISS `q07` 'the dark lamp' -> 34" in report
    _print_table(summary)
    out = capsys.readouterr().out
    assert "Paraphrase groups" in out and "worst spr book 0/2" in out
    assert "'the red book' -> 13 (wrong)" in out


async def test_suites_without_groups_keep_the_old_summary(tmp_path, capsys):
    summary = await _run(tmp_path, with_groups=False)
    assert all("groups" not in m for m in summary["methods"].values())
    assert "Paraphrase" not in (tmp_path / "run" / "report.md").read_text()
    _print_table(summary)
    assert "Paraphrase" not in capsys.readouterr().out
