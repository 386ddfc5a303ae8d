"""The assistant tools defined once (`iesm_agent.server.tools`): specs, formats, errors, concurrency."""

from __future__ import annotations

import asyncio
import json

import pytest

from iesm_agent.cli import run
from iesm_agent.errors import IesmError
from iesm_agent.retrieval import Retriever
from iesm_agent.server import MapService, format_specs, tool_specs
from iesm_agent.retrieval.retriever import MAX_QUERY_CHARS
from iesm_agent.server.tools import MAX_ARGUMENT_CHARS
from iesm_agent.store import MapStore
from iesm_agent.store import mapstore as mapstore_module


@pytest.fixture(autouse=True)
def _no_embeddings(monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")


@pytest.fixture()
def service(apartment_store) -> MapService:
    return MapService({apartment_store.scene.scene_id: apartment_store})


def test_store_tool_specs_are_the_store_schemas_plus_map(apartment_store):
    specs = {s["name"]: s for s in tool_specs()}
    assert list(specs)[:2] == ["find_goal", "list_maps"]
    store_specs = apartment_store.tool_specs()
    assert [s["name"] for s in store_specs] == list(mapstore_module.TOOLS)
    for spec in store_specs:
        served = specs[spec["name"]]
        assert served["description"] == spec["description"]
        props = dict(served["parameters"]["properties"])
        assert props.pop("map")["type"] == "string"
        assert props == spec["parameters"]["properties"]
        assert served["parameters"].get("required") == spec["parameters"].get("required")
    goal = specs["find_goal"]["parameters"]
    assert goal["required"] == ["query"] and set(goal["properties"]) == {"query", "map", "method", "provider"}


def test_a_new_store_tool_is_served_without_server_edits(monkeypatch, service):
    def count_in_room(self, room: str) -> int:
        """Number of instances in a room.

        Args:
            room: room label
        """
        return len(self.find_instances(room=room, limit=1000))

    monkeypatch.setattr(MapStore, "count_in_room", count_in_room, raising=False)
    monkeypatch.setattr(mapstore_module, "TOOLS", mapstore_module.TOOLS + ("count_in_room",))
    spec = next(s for s in tool_specs() if s["name"] == "count_in_room")
    assert spec["parameters"]["required"] == ["room"]
    assert spec["parameters"]["properties"]["room"] == {"type": "string", "description": "room label"}
    tool = next(t for t in service.tools() if t.__name__ == "count_in_room")
    kitchen = next(r for r in service.store().list_rooms() if r["label"] == "kitchen")
    assert asyncio.run(tool(room="kitchen")) == kitchen["instances"]


def test_formats_wrap_the_same_schemas():
    specs = tool_specs()
    openai = format_specs(specs, "openai")
    assert [t["type"] for t in openai] == ["function"] * len(specs)
    assert [t["function"] for t in openai] == specs
    mcp = format_specs(specs, "mcp")
    assert [(t["name"], t["inputSchema"]) for t in mcp] == [(s["name"], s["parameters"]) for s in specs]
    with pytest.raises(IesmError, match="unknown tool spec format"):
        format_specs(specs, "yaml")


def test_iesm_tools_prints_the_specs(capsys):
    assert run(["tools", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out) == tool_specs()
    assert run(["tools", "--format", "bogus"]) == 2
    assert "unknown tool spec format" in capsys.readouterr().err


def test_find_goal_matches_the_retriever(service, apartment_store):
    query = "the red chair in the office"
    out = asyncio.run(service.find_goal(query))
    direct = Retriever(apartment_store).ask(query)
    assert out["instance_id"] == direct.instance_id and out["found"]
    assert (out["label"], out["room"]) == ("chair", "office")
    assert out["gate"] == {e: round(w, 3) for e, w in direct.gate.items()}
    assert {e: [p["id"] for p in picks] for e, picks in out["experts"].items()} == direct.experts
    assert out["ranking"][0]["id"] == direct.instance_id


@pytest.mark.parametrize("kwargs, message", [
    ({"query": "chair", "map": "castle"}, "unknown map 'castle'; served: apartment"),
    ({"query": "x" * 100_000}, f"100000 characters; at most {MAX_QUERY_CHARS}"),
    ({"query": "   "}, "the query is empty"),
    ({"query": "?! @@@"}, "the query has no word"),
    ({"query": "chair", "provider": "openai:gpt-4o"}, "not enabled on this server"),
    ({"query": "chair", "method": "vote"}, "unknown retrieval method"),
])
def test_find_goal_bad_input(service, kwargs, message):
    with pytest.raises(IesmError, match=message.replace("(", r"\(").replace(")", r"\)")):
        asyncio.run(service.find_goal(**kwargs))


def test_retrievers_stay_warm_per_map_method_provider(service):
    first = service.retriever(None, "mtefr", None)
    assert service.retriever("apartment", "mtefr", "offline") is first
    assert service.retriever(None, "spr", None) is not first
    obj = service.retriever(None, "experts:obj", None)
    for spelling in ("experts: obj", "experts:obj,obj", "experts:obj,,obj "):
        assert service.retriever(None, spelling, None) is obj
    assert len(service._retrievers) == 3


def test_long_text_arguments_of_store_tools_are_refused(service):
    with pytest.raises(IesmError, match=f"text: 100000 characters; at most {MAX_ARGUMENT_CHARS}"):
        asyncio.run(service.call_tool("find_instances", {"text": "lamp " * 20_000}))
    assert asyncio.run(service.call_tool("find_instances", {"text": "lamp"}))[0]["label"] == "lamp"


def test_concurrent_calls_agree_with_sequential_ones(service):
    queries = ["the red chair in the office", "something to sit on in the living room", "the lamp next to the bed",
               "a wooden table", "the fridge", "the plant in the kitchen"] * 4

    async def both():
        sequential = [await service.find_goal(q) for q in queries]
        concurrent = await asyncio.gather(*(service.find_goal(q) for q in queries))
        return sequential, concurrent

    sequential, concurrent = asyncio.run(both())
    assert [r["instance_id"] for r in concurrent] == [r["instance_id"] for r in sequential]
    assert len({r["instance_id"] for r in sequential}) >= 4


def test_duplicate_scene_ids_are_refused():
    with pytest.raises(IesmError, match="share the scene id 'apartment'"):
        MapService.open(["apartment", "apartment"])


def test_call_tool_validates_and_dispatches(service, apartment_store):
    rooms = asyncio.run(service.call_tool("list_rooms", {}))
    assert rooms == apartment_store.list_rooms()
    near = asyncio.run(service.call_tool("instances_near", {"x": "1.5", "y": 2, "radius": 3}))
    assert near == apartment_store.instances_near(1.5, 2.0, radius=3.0)
    goal = asyncio.run(service.call_tool("find_goal", {"query": "the lamp next to the bed"}))
    assert (goal["label"], goal["room"]) == ("lamp", "bedroom")
    for name, arguments, message in [
        ("teleport", {}, "unknown tool 'teleport'"),
        ("get_instance", {"instance_id": "seven"},
         r"^bad argument for get_instance: instance_id \(input should be a valid integer, unable to parse"),
        ("get_instance", {}, r"^bad argument for get_instance: instance_id is missing$"),
        ("list_rooms", {"floor": 2}, r"^bad argument for list_rooms: floor is not an argument of list_rooms$"),
        ("instances_near", {"x": "left", "y": 1.0, "radius": [2]},
         r"^bad arguments for instances_near: x \(input should be a valid number.*\); "
         r"radius \(input should be a valid number\)$"),
        ("get_instance", {"instance_id": 4242}, "unknown instance id 4242"),
    ]:
        with pytest.raises(IesmError, match=message):
            asyncio.run(service.call_tool(name, arguments))
