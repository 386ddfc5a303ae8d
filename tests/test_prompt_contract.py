"""The prompt contract is declared once: templates render the task line and reply format from
`iesm_agent.contract`, the offline model dispatches on the task line, and one expert's template
can be overridden alone (`expert_<name>.j2`)."""

from __future__ import annotations

import json
import os

import pytest

from iesm_agent import contract
from iesm_agent.evals.runner import make_variants
from iesm_agent.prompting import PromptLibrary
from iesm_agent.providers.base import Model
from iesm_agent.providers.offline import OfflineModel
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
    text = "\n".join(m.text() for m in messages)
    assert text.count(contract.task_line(task)) == 1 and contract.task_line(task) in text.splitlines()
    assert contract.reply_format(task, 3, hints=False) in text  # the gate asks for hints only when told to
    assert read_prompt(messages).task == task


def test_the_gate_asks_for_hints_only_when_the_experts_get_them():
    plain, hinted = ("\n".join(m.text() for m in PromptLibrary().render("gate.j2", **VARS, **extra))
                     for extra in ({}, {"hints": True}))
    assert '"hints"' not in plain and contract.reply_format(contract.GATE, hints=True) in hinted
    assert "hints" not in contract.gate_schema(("obj", "room"), hints=False)["properties"]
    assert contract.gate_schema(("obj", "room"))["required"] == ["scores", "hints"]
    assert (contract.max_reply_tokens(contract.gate_schema(("obj", "room"), hints=False))
            < contract.max_reply_tokens(contract.gate_schema(("obj", "room"))) / 3)


class _Recorder(Model):
    """The offline model, keeping every prompt it is sent (in the order the calls are made)."""

    def __init__(self):
        self.inner, self.seen = OfflineModel(use_embeddings=False), []
        self.capabilities = self.inner.capabilities

    async def acomplete(self, messages, options=None):
        self.seen.append(messages)
        return await self.inner.acomplete(messages, options)


def test_the_six_prompts_of_a_query_share_one_byte_identical_prefix():
    """Gate and five experts: the same system message, then a user message whose first part
    (candidates, query) is identical; the task, focus and references come after it."""
    model = _Recorder()
    res = Retriever(MapStore(open_map("apartment")), provider=model).ask("that lamp next to the sofa")
    assert len(model.seen) == 6 and not res.failures
    systems = {m[0].text() for m in model.seen}
    users = [m[1].text() for m in model.seen]
    assert len(systems) == 1 and all(m[0].role == "system" for m in model.seen)
    shared = os.path.commonprefix(users)
    assert shared.count("</query>") == 1 and shared.split("</query>")[1].strip() in ("", "Task:")
    assert shared.count("<candidates>") == 1 and '"center"' in shared and '"alt_labels"' in shared
    head = shared[:shared.index("</query>")]
    assert sorted(contract.read_task(u[len(head):]) for u in users) == sorted(
        [contract.GATE] + [contract.RANK] * 4 + [contract.RANK_GEOMETRY])
    # what differs is short next to what is shared (a server's prompt cache reads the rest once)
    assert max(len(u) - len(shared) for u in users) < 0.5 * len(shared)
    # the four experts of expert.j2 share their task, rules and reply format too: only the focus differs
    experts = [u for u in users if contract.read_task(u[len(head):]) == contract.RANK]
    tails = [u[len(os.path.commonprefix(experts)):] for u in experts]
    assert os.path.commonprefix(experts).endswith("<focus>") and all(t.count("\n") <= 3 for t in tails)


def test_hashing_the_shared_prefix_once_gives_each_prompt_its_whole_hash():
    """`PromptHasher` (the shared part hashed once per query, then each tail) equals
    `prompt_sha256` on the six prompts of two queries in turn, on prompts whose system text or
    shared part differs from the one before, and on messages of another shape."""
    from iesm_agent.providers.base import Message
    from iesm_agent.retrieval.calls import PromptHasher, prompt_sha256

    model = _Recorder()
    retriever = Retriever(MapStore(open_map("apartment")), provider=model)
    retriever.ask("the lamp beside the armchair")
    retriever.ask("somewhere to sleep")
    system, user = model.seen[0]
    other = [[system, Message(role="user", content=user.text().replace("lamp", "lamps", 1))],
             [Message(role="system", content=system.text() + " "), user],
             [Message(role="user", content="<query>\"x\"</query> rank")], [system],
             [system, Message(role="user", content="no fenced query here")], [user, system]]
    hasher = PromptHasher()
    for messages in model.seen + other + model.seen[:2]:
        assert hasher(messages) == prompt_sha256(messages)
    assert len({prompt_sha256(m) for m in model.seen}) == len(model.seen) == 11


def test_a_query_without_a_spatial_relation_sends_no_geometry():
    """The spatial expert would abstain: it is not asked, and no prompt carries the geometry."""
    model = _Recorder()
    res = Retriever(MapStore(open_map("apartment")), provider=model).ask("somewhere to sleep")
    assert len(model.seen) == 5 and not res.failures and "spatial" not in res.gate
    assert not any('"center"' in m[1].text() or "<references>" in m[1].text() for m in model.seen)
    assert "spatial: not asked (the query states no spatial relation, comparison, order or viewpoint)" in res.notes


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


def test_each_reply_kind_is_one_model_giving_schema_validation_and_bound():
    names = ["obj", "room"]
    gate = contract.gate_schema(tuple(names))
    # every key required: a grammar-constrained server gets a straight-line grammar
    assert gate["required"] == ["scores", "hints"]
    assert all(gate["properties"][k]["required"] == names for k in ("scores", "hints"))
    # the same model reads a reply leniently: numeric strings, over-long hints cut to the schema's bound
    reply = contract.GateReply.model_validate({"scores": {"obj": "3", "room": True},
                                               "hints": {"obj": "x" * 500, "room": 7}})
    assert reply.scores == {"obj": 3.0, "room": None} and reply.hints == {"obj": "x" * contract.HINT_CHARS}
    # the bound: the longest reply the schema allows, at 2 characters a token or better
    longest = json.dumps({"scores": dict.fromkeys(names, 4), "hints": dict.fromkeys(names, "x" * contract.HINT_CHARS)})
    assert len(longest) / 2 <= contract.max_reply_tokens(gate) < len(longest)
    ranking = contract.ranking_schema(3)
    assert ranking["properties"][contract.RANKING_KEY]["maxItems"] == 3
    assert contract.max_reply_tokens(contract.ranking_schema(1)) < contract.max_reply_tokens(ranking)
    with pytest.raises(ValueError, match="neither 'object' nor 'room'"):
        contract.KeywordReply.model_validate({"thing": "mug"})


def test_the_offline_reader_cuts_fences_as_the_regular_expression_would():
    """`_without_fences` (str.find, fast on the long shared prefix) cuts exactly what
    `<(tag)>.*?</tag>` would, on random mixes of tags, stray brackets and text."""
    import random
    import re

    from iesm_agent.providers.offline.prompt import _without_fences

    pattern = re.compile(r"<(query|hint|candidates|references|experts)>.*?</\1>", re.S)
    parts = ["<query>", "</query>", "<hint>", "</hint>", "<candidates>", "</candidates>", "<experts>",
             "</experts>", "<references>", "</references>", "a", "b c", "\n", "<", ">", "</", "<quer", "y>"]
    rng = random.Random(7)
    for _ in range(3000):
        text = "".join(rng.choice(parts) for _ in range(rng.randint(0, 14)))
        assert _without_fences(text) == pattern.sub(" ", text), text


def test_the_offline_reader_finds_tags_as_str_find_would():
    """`_Tags.find` (tag positions found once per prompt) answers as `str.find` on the text
    would, for every tag and start, on random mixes of tags, near-tags, stray brackets and text."""
    import random

    from iesm_agent.providers.offline.prompt import _MARKERS, _Tags

    parts = [*_MARKERS, "a", "b c", "\n", "<", ">", "</", "<<", "<quer", "y>", "<focu", "s>", "</references"]
    rng = random.Random(11)
    for _ in range(2000):
        text = "".join(rng.choice(parts) for _ in range(rng.randint(0, 16)))
        tags = _Tags(text)
        for marker in _MARKERS:
            for start in range(len(text) + 2):
                assert tags.find(marker, start) == text.find(marker, start), (text, marker, start)


def test_the_task_line_is_read_as_the_pattern_searched_everywhere_would():
    """`read_task` (tried only where a line starts with "Task:") finds what `_TASK_LINE.search`
    finds, on random mixes of task lines, near-task lines, spaces and newlines."""
    import random

    parts = ["Task:", "Task: ", "task:", "rank", "gate", "rank-geometry", "rerank", " ", "\n", "\t", "x",
             "Task:rank", "TTask:", "-", "Task: gate\n"]
    rng = random.Random(3)
    for _ in range(5000):
        text = "".join(rng.choice(parts) for _ in range(rng.randint(0, 12)))
        match = contract._TASK_LINE.search(text)
        expected = match.group(1) if match and match.group(1) in contract.TASKS else None
        assert contract.read_task(text) == expected, text
