"""Retriever mechanics with scripted models: routing, validation of replies, failure handling,
concurrency, cost-saving mode, ablations and baselines (no offline model involved)."""

import asyncio
import json
import time

import pytest

from iesm_agent.config import RetrievalConfig
from iesm_agent.errors import IesmError, ProviderError
from iesm_agent.providers import FunctionModel
from iesm_agent.retrieval import Retriever, fuse
from iesm_agent.store.mapstore import MapStore
from iesm_agent.store.model import GridSpec, Instance, Room, SceneMap

EXPERTS = {
    "obj": ["label", "alt_labels"],
    "room": ["label", "room"],
    "desc": ["label", "caption", "tags"],
    "abs": ["label", "caption"],
}


@pytest.fixture()
def store():
    rooms = [Room(id=1, label="office"), Room(id=2, label="kitchen")]
    specs = [(10, "chair", 1, "a red leather chair", {"color": "red"}),
             (11, "chair", 2, "a wooden chair", {"color": "brown"}),
             (12, "table", 2, "a white dining table", {"color": "white"}),
             (13, "sofa", 1, "a grey fabric sofa", {"color": "grey"}),
             (14, "lamp", 1, "a tall floor lamp", {}),
             (15, "mug", 2, "a blue mug on the table", {"color": "blue"})]
    instances = [Instance(id=i, label=label, room_id=r, room_label=rooms[r - 1].label, caption=cap, tags=tags)
                 for i, label, r, cap, tags in specs]
    return MapStore(SceneMap(scene_id="tiny", grid=GridSpec(cell_size=0.1, height=10, width=10),
                             instances=instances, rooms=rooms))


@pytest.fixture()
def experts_dir(tmp_path):
    """The four experts with a marker focus line, so a scripted model can tell them apart."""
    d = tmp_path / "experts"
    d.mkdir()
    for name, fields in EXPERTS.items():
        (d / f"{name}.toml").write_text(
            f'name = "{name}"\ntitle = "{name} expert"\ngate_description = "judges {name}"\n'
            f'focus = "FOCUS:{name}"\nfields = {json.dumps(fields)}\n')
    return d


class Script:
    """A scripted model: `replies[name]` is the reply text (or an exception / callable) for the
    gate ("gate"), an expert (by focus marker), "spr" or "keyword". Records every prompt."""

    def __init__(self, **replies):
        self.replies = replies
        self.prompts = {}

    def route(self, messages, options):
        text = "\n".join(m.text() for m in messages)
        props = (options.json_schema or {}).get("properties", {})
        if "scores" in props:
            return "gate", text
        if "object" in props:
            return "keyword", text
        for name in self.replies:
            if f"FOCUS:{name}" in text:
                return name, text
        return "spr", text

    def __call__(self, messages, options):
        name, text = self.route(messages, options)
        self.prompts[name] = text
        reply = self.replies.get(name, '{"ranked_instance_ids": []}')
        if isinstance(reply, Exception):
            raise reply
        return reply


def gate(**scores):
    return json.dumps({"scores": scores, "hints": {}})


def ranked(*ids):
    return json.dumps({"ranked_instance_ids": list(ids)})


def make(store, experts_dir, script, **kwargs):
    kwargs.setdefault("method", "experts:" + ",".join(sorted(EXPERTS)))  # the scripted four, not the shipped spatial
    return Retriever(store, provider=FunctionModel(script), experts_dirs=[experts_dir], **kwargs)


def test_mtefr_fuses_gate_weights_and_expert_rankings(store, experts_dir):
    script = Script(gate=gate(obj=4, room=2, desc=2, abs=0), obj=ranked(10, 11), room=ranked(11, 14),
                    desc=ranked(11, 10), abs=ranked(13))
    res = make(store, experts_dir, script).ask("the red chair in the office")
    w = {"obj": 0.5, "room": 0.25, "desc": 0.25, "abs": 0.0}
    assert res.gate == pytest.approx(w)
    expected = fuse(w, {"obj": [10, 11], "room": [11, 14], "desc": [11, 10], "abs": [13]})
    assert res.scores == pytest.approx(expected.scores)
    # obj alone gives 10 its peak 0.5 * 2 = 1.0; 11 has S = 0.5 + 0.5 + 0.5 but P = 0.5
    assert res.instance_id == expected.best == 10
    assert (res.label, res.room, res.caption) == ("chair", "office", "a red leather chair")
    assert res.experts == {"obj": [10, 11], "room": [11, 14], "desc": [11, 10], "abs": [13]}
    assert res.ranking[:3] == [10, 11, 14] and sorted(res.ranking) == [10, 11, 12, 13, 14, 15]
    assert [c.name for c in res.calls] == ["gate", "abs", "desc", "obj", "room"]
    assert all(len(c.prompt_sha256) == 64 and c.template_hash and c.error is None for c in res.calls)
    assert res.failures == [] and res.deciding_expert == "obj"
    assert res.candidate_ids == [10, 11, 12, 13, 14, 15] and res.instances_considered == 6
    # every call saw one candidate block: the fields any expert asks for (obj asks for labels
    # only, desc for captions), so the prompts share a prefix a server can cache
    for field, text in (("caption", '"a red leather chair"'), ("room", '"kitchen"')):
        fenced = f'"{field}": {text}'
        assert all(fenced in script.prompts[name] for name in ("gate", "obj", "desc", "room"))
    text = res.explain()
    assert "obj 0.50" in text and "deciding expert: obj" in text and "chair (office)" in text


@pytest.mark.parametrize("reply", ["I think the object expert matters most.", '{"scores": {"size": 3}}',
                                   ProviderError("HTTP 500", "test", retryable=True)])
def test_gate_failure_falls_back_to_uniform_weights(store, experts_dir, reply):
    script = Script(gate=reply, obj=ranked(13), room=ranked(10, 14), desc=ranked(10), abs=ranked(10))
    res = make(store, experts_dir, script).ask("the sofa")
    assert res.gate == pytest.approx({"obj": 0.25, "room": 0.25, "desc": 0.25, "abs": 0.25})
    assert len(res.failures) == 1 and res.failures[0].startswith("gate:")
    assert res.calls[0].name == "gate" and res.calls[0].error
    assert res.instance_id == 10  # three experts agree under uniform weights


def test_a_gate_that_finds_no_expert_useful_means_uniform_weights(store, experts_dir):
    script = Script(gate=gate(obj=0, room=0), obj=ranked(13), room=ranked(10, 14), desc=ranked(10), abs=ranked(10))
    res = make(store, experts_dir, script).ask("the sofa")
    assert res.gate == pytest.approx({"obj": 0.25, "room": 0.25, "desc": 0.25, "abs": 0.25})
    assert res.failures == [] and res.instance_id == 10


def test_bad_expert_replies_are_dropped_and_recorded(store, experts_dir):
    script = Script(gate=gate(obj=1, room=1, desc=1, abs=1),
                    obj="Sorry, I cannot rank these.",
                    room=ranked(999, "13", 13, 12.0, "x"),   # unknown id, numeric string, dup, float
                    desc=RuntimeError("connection reset"),
                    abs=json.dumps({"ranked_instance_ids": "13"}))
    res = make(store, experts_dir, script).ask("a sofa in the office")
    assert res.experts == {"room": [13, 12]}
    assert res.instance_id == 13
    failures = "\n".join(res.failures)
    assert "obj: unusable reply" in failures and "abs: unusable reply" in failures
    assert "desc: call failed: RuntimeError: connection reset" in failures
    assert "room: dropped entries" in failures and "999" in failures
    by_name = {c.name: c for c in res.calls}
    assert by_name["desc"].error and by_name["obj"].error and by_name["obj"].reply.startswith("Sorry")
    assert by_name["room"].error is None


def test_every_expert_failing_returns_no_instance(store, experts_dir):
    script = Script(gate="{}", obj="nope", room="nope", desc="nope", abs="nope")
    res = make(store, experts_dir, script).ask("anything")
    assert res.instance_id is None and res.scores == {} and len(res.failures) == 5
    assert res.ranking == res.candidate_ids  # nothing scored: candidate order
    assert "chosen: nothing" in res.explain()


def test_positive_weight_experts_failing_falls_back_to_uniform(store, experts_dir):
    script = Script(gate=gate(obj=4), obj="garbage", room=ranked(14), desc=ranked(13), abs=ranked(13))
    res = make(store, experts_dir, script).ask("the lamp")
    assert res.instance_id == 13
    assert any(f.startswith("fusion:") for f in res.failures)


async def test_gate_and_experts_run_concurrently(store, experts_dir):
    spans = []

    async def slow(messages, options):
        start = time.perf_counter()
        await asyncio.sleep(0.2)
        spans.append((start, time.perf_counter()))
        if options.json_schema and "scores" in options.json_schema["properties"]:
            return gate(obj=4)
        return ranked(10)

    retriever = make(store, experts_dir, slow)
    res = await retriever.aask("a chair")
    assert len(spans) == 5 and res.instance_id == 10
    assert max(s for s, _ in spans) < min(e for _, e in spans)  # every call started before any ended


def test_cost_saving_mode_calls_only_heavy_experts_with_hints(store, experts_dir):
    script = Script(gate=json.dumps({"scores": {"obj": 4, "room": 1, "desc": 0, "abs": 0},
                                     "hints": {"obj": "HINT-look-for-chairs"}}),
                    obj=ranked(11, 10), room=ranked(10), desc=ranked(12), abs=ranked(12))
    cfg = RetrievalConfig(skip_below=0.5)
    res = make(store, experts_dir, script, config=cfg).ask("a chair")
    assert [c.name for c in res.calls] == ["gate", "obj"]
    assert "HINT-look-for-chairs" in script.prompts["obj"]
    assert res.gate == pytest.approx({"obj": 0.8, "room": 0.2, "desc": 0.0, "abs": 0.0})
    assert res.instance_id == 11 and res.hints == {"obj": "HINT-look-for-chairs"}


class OneAtATime(FunctionModel):
    """A scripted model that serves one call at a time (a llama-cpp-python server)."""

    async def aparallel_calls(self):
        return 1


def test_one_call_at_a_time_asks_the_gate_first_and_skips_experts_it_gives_no_weight(store, experts_dir):
    script = Script(gate=gate(obj=4, room=2, desc=0, abs=0), obj=ranked(10, 11), room=ranked(11, 14),
                    desc=ranked(12), abs=ranked(13))
    res = Retriever(store, provider=OneAtATime(script), experts_dirs=[experts_dir],
                    method="experts:abs,desc,obj,room").ask("the red chair in the office")
    assert [c.name for c in res.calls] == ["gate", "obj", "room"]
    assert "not asked, gate weight 0: abs, desc" in res.notes and res.abstained == {}
    # the fusion of every expert: those without weight had no say in it
    both = make(store, experts_dir, script).ask("the red chair in the office")
    assert len(both.calls) == 5 and (res.instance_id, res.ranking, res.scores) == (
        both.instance_id, both.ranking, both.scores)
    assert res.deciding_expert == both.deciding_expert and '"hints": {' not in script.prompts["gate"]


def test_one_call_at_a_time_asks_the_others_when_no_weighted_expert_ranks(store, experts_dir):
    script = Script(gate=gate(obj=4, room=0, desc=0, abs=0), obj=ranked(), room=ranked(11, 14),
                    desc=ranked(12), abs=ProviderError("HTTP 500", "test", retryable=False))
    res = Retriever(store, provider=OneAtATime(script), experts_dirs=[experts_dir],
                    method="experts:abs,desc,obj,room").ask("the red chair in the office")
    assert [c.name for c in res.calls] == ["gate", "obj", "abs", "desc", "room"]
    assert any("asked after all" in n for n in res.notes)
    both = make(store, experts_dir, script).ask("the red chair in the office")
    assert (res.instance_id, res.ranking, res.abstained) == (both.instance_id, both.ranking, both.abstained)
    assert res.instance_id == 12  # room and desc under uniform weights: a tie, broken by name (desc first)


def test_expert_subsets(store, experts_dir):
    script = Script(gate=gate(obj=1, desc=3), obj=ranked(11), desc=ranked(10), room=ranked(12), abs=ranked(12))
    res = make(store, experts_dir, script, method="experts:obj, desc").ask("a red chair")
    assert res.method == "experts:obj,desc"
    assert sorted(c.name for c in res.calls) == ["desc", "gate", "obj"]
    assert res.gate == pytest.approx({"obj": 0.25, "desc": 0.75}) and res.instance_id == 10
    single = make(store, experts_dir, script, method="experts:obj").ask("a red chair")
    assert [c.name for c in single.calls] == ["obj"] and single.gate == {"obj": 1.0}
    assert single.instance_id == 11


@pytest.mark.parametrize("method", ["best", "experts:obj,colour", "experts:"])
def test_unknown_method_or_expert_is_an_error(store, experts_dir, method):
    with pytest.raises(IesmError):
        make(store, experts_dir, Script(), method=method)


def test_spr_takes_the_single_pass_top1(store, experts_dir):
    script = Script(spr=ranked(15, 12, 11))
    res = make(store, experts_dir, script, method="spr").ask("the blue mug")
    assert [c.name for c in res.calls] == ["spr"] and res.instance_id == 15
    assert res.experts == {"spr": [15, 12]}  # truncated to kappa
    for fenced in ('"caption": "a blue mug on the table"', '"room": "kitchen"', '"color": "blue"'):
        assert fenced in script.prompts["spr"]  # all fields are shown


def test_keyword_matches_labels_in_the_room_and_ignores_descriptions(store, experts_dir):
    script = Script(keyword=json.dumps({"object": "chair", "room": "kitchen"}))
    res = make(store, experts_dir, script, method="keyword").ask("the red chair in the kitchen")
    assert res.instance_id == 11 and res.room == "kitchen"  # the red one is in the office
    anywhere = make(store, experts_dir, Script(keyword=json.dumps({"object": "sofa", "room": "garage"})),
                    method="keyword").ask("sofa in the garage")
    assert anywhere.instance_id == 13
    broken = make(store, experts_dir, Script(keyword="no idea"), method="keyword").ask("x")
    assert broken.instance_id is None and broken.failures[0].startswith("keyword:")


def test_candidates_limited_by_store_search_and_recall_recorded(store, experts_dir):
    script = Script(gate=gate(obj=1), obj=ranked(13, 10), room=ranked(), desc=ranked(), abs=ranked())
    retriever = make(store, experts_dir, script, config=RetrievalConfig(max_candidates=2))
    res = retriever.ask("grey sofa", target=13)
    assert len(res.candidate_ids) == 2 and 13 in res.candidate_ids
    assert res.candidate_ids == [i for i, _ in store.search("grey sofa", 2)]
    assert res.candidate_recall is True and res.instances_considered == 6
    assert res.instance_id == 13
    miss = retriever.ask("grey sofa", target=15)
    assert miss.candidate_recall is False
    assert retriever.ask("grey sofa").candidate_recall is None


def test_result_json_has_string_keys(store, experts_dir):
    script = Script(gate=gate(obj=1), obj=ranked(12), room=ranked(), desc=ranked(), abs=ranked())
    data = json.loads(make(store, experts_dir, script).ask("table").model_dump_json())
    assert data["instance_id"] == 12 and "12" in data["scores"] and data["experts"]["obj"] == [12]


async def test_sync_ask_works_inside_a_running_loop(store, experts_dir):
    script = Script(gate=gate(obj=1), obj=ranked(14), room=ranked(), desc=ranked(), abs=ranked())
    retriever = make(store, experts_dir, script)
    assert retriever.ask("the lamp").instance_id == (await retriever.aask("the lamp")).instance_id == 14


def test_candidate_pick_keeps_what_the_query_implies_by_function():
    """On a map larger than G, the lexical search alone would fill C with instances sharing the
    query's words; the concept fit keeps the keyboard ("something I can type on") in C."""
    from iesm_agent.retrieval.candidates import select_candidates
    from iesm_agent.understanding import analyse_query
    from iesm_agent.store import MapStore
    from iesm_agent.store.model import GridSpec, Instance, SceneMap

    fillers = [Instance(id=i, label="chair", caption="something you can sit on, of any type")
               for i in range(1, 131)]
    keyboard = Instance(id=500, label="keyboard", caption="white plastic keys")
    store = MapStore(SceneMap(scene_id="big", grid=GridSpec(cell_size=0.05, height=1, width=1),
                              instances=[*fillers, keyboard]))
    lexical_top = [i for i, _ in store.search("something I can type on", 100)]
    assert 500 not in lexical_top  # what the pick has to overcome
    picked = select_candidates(store, "something I can type on", analyse_query("something I can type on"), 100, target=500)
    assert picked.recall is True and picked.ids[0] == 500 and len(picked.ids) == 100
    assert picked.considered == 131
    plain = select_candidates(store, "a chair", analyse_query("a chair"), 100, target=500)
    assert plain.recall is False and len(plain.ids) == 100


def test_the_experts_not_chosen_keep_their_order_and_are_found_by_identity():
    """`mtefr._others`: the specs outside a selection made from them, in order (found by identity,
    not by comparing the pydantic models field by field)."""
    from iesm_agent.retrieval.experts import load_experts
    from iesm_agent.retrieval.mtefr import _others

    specs = list(load_experts([]).values())
    chosen = specs[1::2]
    assert _others(specs, chosen) == [s for s in specs if s not in chosen] == specs[0::2]
    assert _others(specs, []) == specs and _others(specs, specs) == []
