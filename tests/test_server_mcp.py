"""The MCP server in-process, through the official SDK's client."""

from __future__ import annotations

import json

import numpy as np
import pytest

pytest.importorskip("mcp")

from mcp import Client  # noqa: E402

from iesm_agent.retrieval import Retriever  # noqa: E402
from iesm_agent.server import MapService, tool_specs  # noqa: E402
from iesm_agent.server.app import build_server  # noqa: E402
from iesm_agent.store import InstanceGrid, MapStore  # noqa: E402


@pytest.fixture(autouse=True)
def _no_embeddings(monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")


@pytest.fixture()
def two_maps(apartment_store) -> MapService:
    """The apartment, and a copy of it as 'flat' without its chairs."""
    scene = apartment_store.scene
    kept = [i for i in scene.instances if i.label != "chair"]
    cells, ids, top = scene.occupancy.entries()
    keep = np.isin(ids, [i.id for i in kept])
    flat = scene.model_copy(update={"scene_id": "flat", "instances": kept, "embeddings": None,
                                    "occupancy": InstanceGrid.from_entries(cells[keep], ids[keep], top[keep])})
    return MapService({"apartment": apartment_store, "flat": MapStore(flat)})


def _payload(result) -> object:
    assert not result.is_error, result.content[0].text
    return json.loads(result.content[0].text)


async def test_list_tools_and_find_goal(apartment_store):
    server = build_server(MapService({"apartment": apartment_store}))
    async with Client(server) as client:
        listed = (await client.list_tools()).tools
        specs = tool_specs()
        assert [t.name for t in listed] == [s["name"] for s in specs]
        assert [t.input_schema for t in listed] == [s["parameters"] for s in specs]
        assert {"find_goal", "get_instance", "list_rooms", "instances_near", "stacked_with"} <= {t.name for t in listed}

        query = "the red chair in the office"
        found = _payload(await client.call_tool("find_goal", {"query": query}))
        expected = Retriever(apartment_store).ask(query)
        assert found["instance_id"] == expected.instance_id
        assert (found["label"], found["room"]) == ("chair", "office")
        assert set(found["gate"]) == set(expected.gate) and found["experts"]

        inst = _payload(await client.call_tool("get_instance", {"instance_id": found["instance_id"]}))
        assert inst["caption"] == found["caption"]
        rooms = _payload(await client.call_tool("list_rooms", {}))
        assert [r["label"] for r in rooms] == [r["label"] for r in apartment_store.list_rooms()]


@pytest.mark.parametrize("name, arguments, message", [
    ("get_instance", {"instance_id": 987654}, "unknown instance id 987654"),
    ("get_instance", {"instance_id": "seven"}, "instance_id"),
    ("find_goal", {"query": "q" * 100_000}, "100000 characters"),
    ("find_goal", {"query": 42}, "query"),
    ("find_goal", {"query": "chair", "map": "castle"}, "unknown map 'castle'"),
    ("instances_near", {"x": "left", "y": 0.0}, "x"),
    ("stacked_with", {}, "instance_id"),
])
async def test_bad_calls_are_tool_errors_and_the_server_stays_up(apartment_store, name, arguments, message):
    async with Client(build_server(MapService({"apartment": apartment_store}))) as client:
        bad = await client.call_tool(name, arguments)
        assert bad.is_error and message in bad.content[0].text
        assert _payload(await client.call_tool("list_maps", {}))[0]["name"] == "apartment"


async def test_each_map_is_a_resource_and_tools_pick_the_map(two_maps):
    async with Client(build_server(two_maps)) as client:
        resources = {str(r.uri): r for r in (await client.list_resources()).resources}
        assert set(resources) == {"iesm://maps/apartment", "iesm://maps/flat"}
        content = (await client.read_resource("iesm://maps/flat")).contents[0]
        summary = json.loads(content.text)
        assert summary["scene_id"] == "flat"
        assert len(summary["instances"]) == len(two_maps.maps["flat"].scene.instances)
        assert all(i["label"] != "chair" for i in summary["instances"])

        in_apartment = _payload(await client.call_tool("find_instances", {"category": "chair"}))
        in_flat = _payload(await client.call_tool("find_instances", {"category": "chair", "map": "flat"}))
        assert any(i["label"] == "chair" for i in in_apartment)
        assert all(i["label"] != "chair" for i in in_flat)
        goal = _payload(await client.call_tool("find_goal", {"query": "the red chair in the office", "map": "flat"}))
        assert goal["map"] == "flat" and goal["label"] != "chair"


async def test_plan_path_to_the_found_goal(apartment_store):
    from iesm_agent.server.tools import navigation_available

    if not navigation_available():
        pytest.skip("navigation extra (OpenCV, pyastar2d) not installed")
    async with Client(build_server(MapService({"apartment": apartment_store}))) as client:
        goal = _payload(await client.call_tool("find_goal", {"query": "the red chair in the office"}))
        path = _payload(await client.call_tool("plan_path", {"instance_id": goal["instance_id"], "start": [0.5, 0.5]}))
        assert path["status"] == "ok" and path["reachable"] and path["waypoints"][0] == [0.5, 0.5]
        centroid = np.array(apartment_store.get_instance(goal["instance_id"])["centroid"][:2])
        end = np.array(path["waypoints"][-1])
        assert np.linalg.norm(end - centroid) < 1.5
        steps = np.diff(np.array(path["waypoints"]), axis=0)
        assert path["length_m"] == pytest.approx(np.hypot(*steps.T).sum(), rel=1e-6)

        outside = _payload(await client.call_tool("plan_path", {"instance_id": goal["instance_id"], "start": [-50, 0]}))
        assert outside["status"] == "start_outside_map" and not outside["reachable"]
        for arguments, message in [({"instance_id": 4242, "start": [0.5, 0.5]}, "no instance with id 4242"),
                                   ({"instance_id": 1, "start": [0.5]}, "start"),
                                   ({"instance_id": 1, "start": "kitchen"}, "start")]:
            bad = await client.call_tool("plan_path", arguments)
            assert bad.is_error and message in bad.content[0].text


async def test_find_goal_is_structured_content_under_its_output_schema(apartment_store):
    from iesm_agent.server.results import FindGoalResult

    async with Client(build_server(MapService({"apartment": apartment_store}))) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        schema = tools["find_goal"].output_schema
        assert schema["type"] == "object" and {"position", "box", "ranking"} <= set(schema["properties"])
        assert tools["list_rooms"].output_schema is None  # text only
        result = await client.call_tool("find_goal", {"query": "the red chair in the office"})
        assert result.structured_content == _payload(result)  # the text block says the same
        goal = FindGoalResult.model_validate(result.structured_content)
        assert goal.position == goal.box.center and len(goal.position) == 3
        assert goal.ranking[0].id == goal.instance_id and all(r.score > 0 for r in goal.ranking)


async def test_listed_output_schema_accepts_and_refuses_what_the_model_schema_does(apartment_store):
    """The compact schema listed for find_goal (references inlined, nullable types as type lists,
    no titles) means the same as pydantic's: on real results and on each of them broken in one
    place, jsonschema says valid or invalid alike."""
    from jsonschema.validators import validator_for

    from iesm_agent.server.results import FindGoalResult, output_schema

    service = MapService({"apartment": apartment_store})
    results = [await service.find_goal(q) for q in ("the red chair in the office", "somewhere to sleep",
                                                    "a xylophone in the garage")]
    broken = []
    for result in results:
        for field, value in [("instance_id", "48"), ("position", [1.0, "2"]), ("position", None),
                             ("box", {"center": [1.0, 2.0, 3.0]}), ("box", None), ("label", 3),
                             ("gate", {"obj": "high"}), ("experts", {"obj": [{"id": 1}]}),
                             ("ranking", [{"id": 1, "name": "x", "score": 1.0, "box": None}]),
                             ("ranking", [{"id": 1, "name": "x", "score": 1.0, "box": {"center": [0], "size": [True]}}]),
                             ("failures", [None]), ("latency_ms", None), ("found", None)]:
            broken.append({**result, field: value})
        broken.append({k: v for k, v in result.items() if k != "ranking"})
    listed, model = output_schema(FindGoalResult), FindGoalResult.model_json_schema()
    assert "$defs" not in listed and "anyOf" not in json.dumps(listed)
    listed_ok, model_ok = validator_for(listed)(listed), validator_for(model)(model)
    verdicts = [(listed_ok.is_valid(r), model_ok.is_valid(r)) for r in results + broken]
    assert all(a == b for a, b in verdicts)
    assert all(a for a, _ in verdicts[:3]) and sum(not a for a, _ in verdicts) >= 30


@pytest.mark.parametrize("arguments, message", [
    ({"instance_id": 1, "start": "kitchen"}, "bad argument for plan_path: start (input should be a valid tuple)"),
    ({"start": [0.5, 0.5]}, "bad argument for plan_path: instance_id is missing"),
    ({"instance_id": "one", "start": [0.5, 0.5]},
     "bad argument for plan_path: instance_id (input should be a valid integer, unable to parse string as an integer)"),
])
async def test_argument_errors_are_one_sentence_naming_the_argument(apartment_store, arguments, message):
    from iesm_agent.server.tools import navigation_available

    if not navigation_available():
        pytest.skip("navigation extra (OpenCV, pyastar2d) not installed")
    async with Client(build_server(MapService({"apartment": apartment_store}))) as client:
        bad = await client.call_tool("plan_path", arguments)
        assert bad.is_error and bad.content[0].text == message
