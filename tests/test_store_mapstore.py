"""MapStore tools over the shipped apartment, embedding-aware search and tool schemas."""

from __future__ import annotations

import sys
import types
from typing import Literal, Optional

import numpy as np
import pytest

from iesm_agent.errors import IesmError
from iesm_agent.store import MapStore
from iesm_agent.store.tools import function_schema


def test_list_categories_and_rooms(apartment_store):
    cats = apartment_store.list_categories()
    assert cats["chair"] == 3 and cats["sink"] == 2 and cats["sofa"] == 2
    assert sum(cats.values()) == len(apartment_store.scene.instances)
    rooms = {r["label"]: r for r in apartment_store.list_rooms()}
    assert set(rooms) == {"living room", "kitchen", "bedroom", "bathroom", "office", "hallway"}
    assert rooms["bathroom"]["instances"] == 7 and rooms["kitchen"]["area_m2"] == pytest.approx(22.5, abs=0.5)


def test_find_by_category_and_room(apartment_store):
    chairs = apartment_store.find_instances(category="chair")
    assert {c["id"] for c in chairs[:3]} == {23, 24, 48}
    assert chairs[0]["score"] >= chairs[-1]["score"]
    assert [c["id"] for c in apartment_store.find_instances(category="chair", room="office")] == [48]
    assert [c["id"] for c in apartment_store.find_instances(category="sink", room=4)] == [41]
    assert apartment_store.find_instances(category="fridge")[0]["id"] == 16  # via alt label
    assert apartment_store.find_instances(category="helicopter") == []


def test_find_by_text(apartment_store):
    hits = apartment_store.find_instances(text="red leather")
    assert hits[0]["id"] == 48
    hits = apartment_store.find_instances(category="chair", text="green cushion")
    assert hits[0]["id"] == 23


@pytest.fixture(scope="module")
def lexical_store(apartment_store):
    """The apartment without embeddings, so lexical ranking is tested whatever the shipped map holds."""
    return MapStore(apartment_store.scene.model_copy(update={"embeddings": None, "embedding_model": None}))


@pytest.mark.parametrize("query, expected", [
    ("the red leather office chair", 48), ("kettle", 27), ("the sink in the bathroom", 41),
    ("kitchen sink", 17), ("fridge", 16), ("yellow pillow", 14), ("lamp in the bedroom", 34),
    ("the mirror in the hallway", 30), ("a white mug", 15), ("brown leather sofa", 2),
    ("the book on the office shelf", 52), ("chair in the kitchen with a green cushion", 23),
])
def test_search_ranks_the_target_first(lexical_store, query, expected):
    assert lexical_store.search(query, limit=5)[0][0] == expected


def test_search_limit_order_and_ties(lexical_store):
    res = lexical_store.search("kettle", limit=10)
    assert len(res) == 10 and res[0][0] == 27
    scores = [s for _, s in res]
    assert scores == sorted(scores, reverse=True)
    zero_ids = [i for i, s in res if s == 0]
    assert zero_ids == sorted(zero_ids)
    assert len(lexical_store.search("the", limit=100)) == len(lexical_store.scene.instances)


def test_get_instance_and_unknown_id(apartment_store):
    inst = apartment_store.get_instance(48)
    assert inst["label"] == "chair" and inst["room"] == "office" and inst["tags"]["color"] == "red"
    with pytest.raises(IesmError, match="unknown instance id 999"):
        apartment_store.get_instance(999)


def test_instances_at_orders_by_top(apartment_store):
    cup = apartment_store.scene.instance(15)
    at = apartment_store.instances_at(*cup.centroid[:2])
    assert [d["id"] for d in at] == [15, 3, 9]  # cup, coffee table, rug
    assert at[0]["top"] > at[1]["top"] > at[2]["top"]
    assert apartment_store.instances_at(-100.0, -100.0) == []


def test_stacked_with(apartment_store):
    sofa = apartment_store.stacked_with(1)
    assert {d["id"] for d in sofa["above"]} == {6, 14} and sofa["below"] == []
    desk = apartment_store.stacked_with(47)
    assert {d["id"] for d in desk["above"]} == {49, 50, 56}
    cup = apartment_store.stacked_with(15)
    assert [d["id"] for d in cup["below"]] == [3, 9]  # nearest below first
    assert apartment_store.stacked_with(40) == {"id": 40, "above": [], "below": []}


def test_instances_near(apartment_store):
    fridge = apartment_store.scene.instance(16)
    near = apartment_store.instances_near(fridge.centroid[0], fridge.centroid[1], radius=0.5)
    assert near[0]["id"] == 16 and near[0]["distance"] < 0.05
    assert all(d["distance"] <= 0.5 for d in near)
    assert [d["distance"] for d in near] == sorted(d["distance"] for d in near)
    assert len(apartment_store.instances_near(5.0, 4.5, radius=20.0, limit=5)) == 5


def test_candidate_view(apartment_store):
    view = apartment_store.candidate_view(48, ["label", "room"])
    assert view == {"id": 48, "label": "chair", "room": "office"}
    full = apartment_store.candidate_view(48)
    assert set(full) == {"id", "label", "alt_labels", "room", "caption", "tags"}
    full["tags"]["color"] = "blue"  # a copy: the store is not modified
    assert apartment_store.candidate_view(48, ["tags"])["tags"]["color"] == "red"
    with pytest.raises(IesmError, match="unknown candidate field"):
        apartment_store.candidate_view(48, ["secret"])


def test_tool_specs_and_call(apartment_store):
    specs = {s["name"]: s for s in apartment_store.tool_specs()}
    assert {"list_categories", "find_instances", "instances_near", "stacked_with", "search"} <= set(specs)
    near = specs["instances_near"]["parameters"]
    assert near["properties"]["x"]["type"] == "number" and near["required"] == ["x", "y"]
    assert near["properties"]["radius"]["default"] == 1.0
    assert specs["get_instance"]["parameters"]["properties"]["instance_id"]["type"] == "integer"
    assert all(s["description"] and "\n" not in s["description"] for s in specs.values())
    assert apartment_store.call_tool("get_instance", {"instance_id": 27})["label"] == "kettle"
    with pytest.raises(IesmError, match="bad arguments"):
        apartment_store.call_tool("get_instance", {"nope": 1})
    with pytest.raises(IesmError, match="unknown tool"):
        apartment_store.call_tool("rm", {})


def test_function_schema_types():
    def tool(names: list[str], mode: Literal["a", "b"], k: Optional[int] = None, flag: bool = True,
             opts: dict[str, str] | None = None) -> None:
        """Do a thing.

        More text.

        Args:
            names: the names
                to use
            k: how many
        """

    schema = function_schema(tool)
    props = schema["parameters"]["properties"]
    assert schema["description"] == "Do a thing."
    assert props["names"] == {"type": "array", "items": {"type": "string"}, "description": "the names to use"}
    assert props["mode"] == {"type": "string", "enum": ["a", "b"]}
    assert props["k"] == {"type": "integer", "description": "how many"}
    assert props["flag"] == {"type": "boolean", "default": True}
    assert props["opts"] == {"type": "object"}
    assert schema["parameters"]["required"] == ["names", "mode"]


class FakeEncoder:
    """Maps known texts to fixed unit vectors; anything else to a constant vector."""

    def __init__(self, name, table, dim):
        self.name, self.dim, self.table = name, dim, table
        self.calls = 0

    def encode(self, texts):
        self.calls += 1
        out = np.zeros((len(texts), self.dim), np.float32)
        for i, t in enumerate(texts):
            out[i] = self.table.get(t, np.full(self.dim, 1 / np.sqrt(self.dim)))
        return out


def _with_encoder(monkeypatch, encoder):
    module = types.ModuleType("iesm_agent.embeddings")
    module.get_encoder = lambda: encoder
    monkeypatch.setitem(sys.modules, "iesm_agent.embeddings", module)


def test_search_adds_embedding_similarity(apartment_store, monkeypatch):
    scene = apartment_store.scene
    n = len(scene.instances)
    target = [inst.id for inst in scene.instances].index(54)  # the printer
    emb = np.eye(n, dtype=np.float32)
    encoder = FakeEncoder("fake-enc", {"zqx device": emb[target]}, n)
    _with_encoder(monkeypatch, encoder)
    store = MapStore(scene.model_copy(update={"embeddings": emb, "embedding_model": "fake-enc"}))
    assert store.search("zqx device", limit=3)[0][0] == 54
    store.search("zqx device")
    assert encoder.calls == 1  # query embeddings are cached
    other = MapStore(scene.model_copy(update={"embeddings": emb, "embedding_model": "another-model"}))
    assert other.search("zqx device", limit=3)[0][1] == 0.0  # different model: lexical only


def test_search_without_embeddings_module(apartment_store, monkeypatch):
    monkeypatch.setitem(sys.modules, "iesm_agent.embeddings", None)  # import raises ImportError
    n = len(apartment_store.scene.instances)
    store = MapStore(apartment_store.scene.model_copy(
        update={"embeddings": np.eye(n, dtype=np.float32), "embedding_model": "x"}))
    assert store.search("kettle")[0][0] == 27
