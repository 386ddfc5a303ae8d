"""A size word said of the target: a caption's measurements are not size words, and a bare
"little"/"tall" compares the target with the others of its kind by their boxes where no caption
of that kind speaks of size."""

import json

from iesm_agent.config import RetrievalConfig
from iesm_agent.providers.offline import OfflineModel
from iesm_agent.retrieval import Retriever
from iesm_agent.store import MapStore
from iesm_agent.store.importers.objects import import_objects
from iesm_agent.understanding import candidate_from_line
from iesm_agent.understanding.spatial import parse_query


def _store(tmp_path, objects):
    path = tmp_path / "flat.json"
    path.write_text(json.dumps({"scene_id": "flat", "rooms": [{"id": 1, "label": "hall"}], "objects": objects}))
    return MapStore(import_objects(path))


def _obj(i, label, center, size, **extra):
    return {"id": i, "label": label, "center": list(center), "size": list(size), "room": "hall", **extra}


def test_a_measured_dimension_is_not_a_size_word():
    line = json.dumps({"id": 3, "label": "wardrobe",
                       "caption": "a wardrobe in the hall, about 1.9 m tall and 1.2 m wide, 25 cm above the floor"})
    record = candidate_from_line(line)[1]
    assert not any(k == "size" for k, _ in record.attrs)
    assert not any(s.kind == "size" for s in record.slots)
    described = candidate_from_line(json.dumps({"id": 4, "label": "wardrobe", "caption": "a tall narrow wardrobe"}))[1]
    assert {("size", "tall"), ("size", "small")} <= described.attrs


def test_a_bare_size_word_on_a_named_kind_is_a_comparison():
    (rel,) = parse_query("walk over to the little wardrobe").relations
    assert (rel.kind, rel.value, rel.said) == ("extreme", "small", True)
    # one detail among others of a description, or said of a class noun: no comparison
    assert parse_query("walk over to the little oak wardrobe").relations == []
    assert parse_query("walk over to the tiny container").relations == []
    # with an indefinite article it says what kind of wardrobe will do
    assert parse_query("walk over to a little wardrobe").relations == []


def test_boxes_decide_a_size_word_where_no_caption_speaks_of_size(tmp_path):
    # two wardrobes and a bookcase, imported from an object list: their captions state measurements only
    store = _store(tmp_path, [_obj(1, "wardrobe", (1.0, 1.0, 1.0), (1.2, 0.6, 2.0)),
                              _obj(2, "wardrobe", (4.0, 1.0, 0.6), (0.6, 0.5, 1.2)),
                              _obj(3, "bookcase", (2.5, 3.0, 0.9), (0.8, 0.3, 1.8))])
    ask = Retriever(store, provider=OfflineModel(use_embeddings=False), method="mtefr",
                    config=RetrievalConfig(kappa=2)).ask
    assert ask("walk over to the little wardrobe").instance_id == 2
    assert ask("walk over to the big wardrobe").instance_id == 1


def test_a_caption_that_speaks_of_size_keeps_the_word(tmp_path):
    # the captions call the wardrobe with the smaller box the large one: the words are the
    # description's to match, the spatial expert is not weighed for them
    store = _store(tmp_path, [_obj(1, "wardrobe", (1.0, 1.0, 1.0), (1.2, 0.6, 2.0), caption="A compact white wardrobe."),
                              _obj(2, "wardrobe", (4.0, 1.0, 0.6), (0.6, 0.5, 1.2), caption="A large oak wardrobe.")])
    result = Retriever(store, provider=OfflineModel(use_embeddings=False), method="mtefr",
                       config=RetrievalConfig(kappa=2)).ask("walk over to the little wardrobe")
    assert result.instance_id == 1 and not result.gate.get("spatial")
