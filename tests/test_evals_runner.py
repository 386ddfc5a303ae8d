"""The eval runner with a scripted model: journal, summary shape, report, refusal and resume."""

from __future__ import annotations

import json
import re

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.evals.generate import generate_suite
from iesm_agent.evals.journal import read_journal
from iesm_agent.evals.runner import (make_config, make_variants, run_eval, split_methods,
                                     write_run_outputs)
from iesm_agent.providers import FunctionModel

_QUERY = re.compile(r"<query>(.*?)</query>", re.S)
_CANDIDATES = re.compile(r"<candidates>(.*?)</candidates>", re.S)


def word_overlap(messages, options):
    """SPR: rank candidates by words shared with the query; keyword: extracts nothing."""
    text = "\n".join(m.text() for m in messages)
    if "object" in (options.json_schema or {}).get("properties", {}):
        return json.dumps({"object": None, "room": None})
    words = set(re.findall(r"[a-z]+", json.loads(_QUERY.search(text).group(1)).lower()))
    scored = []
    for line in _CANDIDATES.search(text).group(1).strip().splitlines():
        c = json.loads(line)
        fields = " ".join([c.get("label", ""), c.get("room") or "", c.get("caption", "")]).lower()
        scored.append((-len(words & set(re.findall(r"[a-z]+", fields))), c["id"]))
    return json.dumps({"ranked_instance_ids": [i for _, i in sorted(scored)[:2]]})


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    import asyncio

    path = tmp_path_factory.mktemp("suite") / "suite.jsonl"
    asyncio.run(generate_suite(["apartment"], path, per_type=3, seed=1))
    return path


def _config(suite, methods="spr,keyword"):
    return make_config([suite], make_variants(split_methods([methods]), []), "scripted")


def test_split_methods_keeps_expert_lists_together():
    assert split_methods(["mtefr,spr,keyword,experts:obj,experts:obj,desc,experts:obj,room"]) == [
        "mtefr", "spr", "keyword", "experts:obj", "experts:obj,desc", "experts:obj,room"]
    assert split_methods(["spr", "experts:obj,desc"]) == ["spr", "experts:obj,desc"]
    assert split_methods(["experts:obj,room,mtefr-uniform"]) == ["experts:obj,room", "mtefr-uniform"]


def test_prompt_dirs_make_one_variant_per_method_and_dir(tmp_path):
    (tmp_path / "v2").mkdir()
    variants = make_variants(["spr", "mtefr"], [tmp_path / "v2"])
    assert [v.name for v in variants] == ["spr@v2", "mtefr@v2"]
    with pytest.raises(IesmError, match="prompt directory does not exist"):
        make_variants(["spr"], [tmp_path / "missing"])


async def test_run_writes_journal_summary_and_report(tmp_path, suite):
    config, run = _config(suite), tmp_path / "run"
    outcome = await run_eval(config, run, model=FunctionModel(word_overlap), concurrency=3)
    summary = write_run_outputs(run, config, outcome)

    records = read_journal(run / "results.jsonl")
    n_queries = len(suite.read_text().splitlines())
    assert len(records) == 2 * n_queries == len({r.key for r in records})
    accept = {q["id"]: q["accept"] for q in map(json.loads, suite.read_text().splitlines())}
    for r in records:
        assert r.correct == (r.predicted in accept[r.id])
        # rank is within the full candidate ranking (runner._rank): past the scored ids the target
        # was not scored and sits among the tied rest
        assert r.rank is None or r.rank > len(r.ranking) or r.ranking[r.rank - 1] in accept[r.id]
    assert all(not r.correct for r in records if r.variant == "keyword")  # it extracts nothing

    assert list(summary["methods"]) == ["spr", "keyword"]
    for m in summary["methods"].values():
        assert {"n", "osr", "mrr", "top3"} <= set(m["overall"])
        assert set(m["by_type"]) == {"o", "or", "od", "ord", "ard"}
        assert all(set(t) >= {"n", "osr"} and t["n"] == 3 for t in m["by_type"].values())
    spr = [r for r in records if r.variant == "spr"]
    assert summary["methods"]["spr"]["overall"]["osr"] == pytest.approx(sum(r.correct for r in spr) / len(spr))
    assert {t["type"] for t in summary["significance"]} == {"overall", "o", "or", "od", "ord", "ard"}
    assert json.loads((run / "summary.json").read_text()) == summary
    report = (run / "report.md").read_text()
    assert "| Method | (o) | (o,r) | (o,d) | (o,r,d) | (a,r,d) |" in report
    assert "![O-SR by query type](osr_by_type.png)" in report and (run / "osr_by_type.png").stat().st_size > 0
    assert "exact McNemar" in report


async def test_non_empty_run_dir_is_refused_without_resume(tmp_path, suite):
    run = tmp_path / "run"
    run.mkdir()
    (run / "notes.txt").write_text("mine")
    with pytest.raises(IesmError, match="run directory is not empty: pass --resume"):
        await run_eval(_config(suite), run, model=FunctionModel(word_overlap))
    assert (run / "notes.txt").read_text() == "mine"


async def test_resume_asks_only_the_missing_pairs(tmp_path, suite):
    config, run = _config(suite), tmp_path / "run"
    await run_eval(config, run, model=FunctionModel(word_overlap))
    journal = run / "results.jsonl"
    lines = journal.read_text().splitlines(keepends=True)
    journal.write_text("".join(lines[:7]) + lines[7][:25])  # killed while writing line 8
    model = FunctionModel(word_overlap)
    outcome = await run_eval(config, run, model=model, resume=True)
    assert outcome.done_before == 7 and outcome.new == len(lines) - 7
    keys = [r.key for r in read_journal(journal)]
    assert len(keys) == len(set(keys)) == len(lines)
    assert set(keys) == {(json.loads(x)["id"], json.loads(x)["variant"]) for x in lines}
    assert model.calls == len(lines) - 7  # spr and keyword make one call per query


async def test_resume_with_another_configuration_is_refused(tmp_path, suite):
    run = tmp_path / "run"
    await run_eval(_config(suite), run, model=FunctionModel(word_overlap))
    with pytest.raises(IesmError, match="different variants"):
        await run_eval(_config(suite, "spr"), run, model=FunctionModel(word_overlap), resume=True)


async def test_experts_dir_adds_an_expert_to_every_variant(suite, tmp_path):
    experts = tmp_path / "experts"
    experts.mkdir()
    (experts / "size.toml").write_text(
        'name = "size"\ntitle = "Size expert"\ngate_description = "sizes: big, small, tall"\n'
        'focus = "Size words"\nfields = ["id", "label"]\ntemplate = "expert.j2"\n')
    gate_prompts = []

    def model(messages, options):
        text = "\n".join(m.text() for m in messages)
        if '"scores"' in text and "<experts>" in text:
            gate_prompts.append(text)
            return json.dumps({"scores": {}, "hints": {}})
        return word_overlap(messages, options)

    config = make_config([suite], make_variants(["mtefr"], []), "scripted", experts_dirs=[experts])
    assert config.experts_dirs == [str(experts.resolve())]
    await run_eval(config, tmp_path / "run", model=FunctionModel(model))
    assert gate_prompts and all('"size"' in p for p in gate_prompts)
