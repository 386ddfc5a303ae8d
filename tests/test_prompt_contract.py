"""The prompt contract is declared once: templates render the task line and reply format from
`iesm_agent.contract`, the offline model dispatches on the task line, and one expert's template
can be overridden alone (`expert_<name>.j2`)."""

from __future__ import annotations

import pytest

from iesm_agent import contract
from iesm_agent.evals.runner import make_variants
from iesm_agent.prompting import PromptLibrary
from iesm_agent.providers.offline.prompt import read_prompt
from iesm_agent.resources import resource_dir
from iesm_agent.retrieval import Retriever
from iesm_agent.store import MapStore, open_map

TEMPLATES = {"gate.j2": contract.GATE, "expert.j2": contract.RANK, "spr.j2": contract.RANK,
             "spatial.j2": contract.RANK_GEOMETRY, "keyword.j2": contract.KEYWORD}
VARS = dict(query="the lamp", experts=[], focus="x", hint="", candidates=[], references=[], kappa=3,
            expert="obj", expert_title="Object expert")


@pytest.mark.parametrize("name, task", TEMPLATES.items())
def test_every_retrieval_template_declares_its_task_and_reply_format(name, task):
    messages = PromptLibrary().render(name, **VARS)
    system = messages[0].text()
    assert system.splitlines()[0] == contract.task_line(task)
    assert contract.reply_format(task, 3) in system
    assert read_prompt(messages).task == task


def test_a_user_template_without_a_task_line_is_read_from_its_reply_format(tmp_path):
    (tmp_path / "expert.j2").write_text(
        '{% block system %}Rank them. Reply {"ranked_instance_ids": [..]}, at most {{ kappa }} ids.'
        '{% endblock %}{% block user %}<query>{{ query | fence }}</query>{% endblock %}')
    messages = PromptLibrary([tmp_path]).render("expert.j2", **VARS)
    assert contract.read_task(messages[0].text()) is None and read_prompt(messages).task == contract.RANK


def test_unknown_task_names_are_refused():
    with pytest.raises(ValueError):
        contract.task_line("rerank")
    assert contract.read_task("Task: rerank") is None


def test_one_expert_template_overrides_only_that_expert(tmp_path):
    shipped = (resource_dir("prompts") / "expert.j2").read_text()
    (tmp_path / "expert_desc.j2").write_text(shipped.replace("You are one expert ranker",
                                                             "You are the {{ expert_title }} ({{ expert }})"))
    retriever = Retriever(MapStore(open_map("apartment")), prompts_dir=tmp_path)
    res = retriever.ask("the grey fabric sofa")
    templates = {c.name: c.template for c in res.calls}
    assert templates["desc"] == "expert_desc.j2" and templates["obj"] == "expert.j2"
    assert res.label == "sofa"


def test_prompts_default_names_the_shipped_templates(tmp_path):
    variants = make_variants(["mtefr"], ["default", tmp_path])
    assert [(v.name, v.prompts_dir) for v in variants] == [("mtefr@default", None),
                                                            (f"mtefr@{tmp_path.name}", str(tmp_path))]
