"""Store geometry for the spatial expert: box fields in candidate views, `relate`, tool schema."""

import json

import numpy as np
import pytest

from iesm_agent.errors import IesmError
from iesm_agent.retrieval.experts import ExpertSpec
from iesm_agent.store import MapStore
from iesm_agent.store import geometry as geo
from iesm_agent.store.importers.objects import import_objects


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    path = tmp_path_factory.mktemp("geo") / "tiny.json"
    objects = [
        {"id": 1, "label": "table", "center": [1.0, 1.0, 0.375], "size": [1.0, 0.6, 0.75]},
        {"id": 2, "label": "cup", "center": [1.2, 1.0, 0.8], "size": [0.1, 0.1, 0.1]},
        {"id": 3, "label": "box", "center": [0.8, 1.0, 0.15], "size": [0.3, 0.3, 0.3]},
        {"id": 4, "label": "chair", "center": [3.0, 1.0, 0.45], "size": [0.4, 0.4, 0.9]},
    ]
    path.write_text(json.dumps({"scene_id": "tiny", "objects": objects}))
    return MapStore(import_objects(path, cell_size=0.05))


def test_candidate_view_geometry_fields(store):
    cup = store.candidate_view(2, ["label", "center", "size", "z_range", "on", "under"])
    assert cup["center"] == pytest.approx([1.2, 1.0, 0.8], abs=0.03)
    assert cup["size"][:2] == pytest.approx([0.1, 0.1], abs=0.06) and cup["size"][2] == pytest.approx(0.1)
    assert cup["z_range"] == pytest.approx([0.75, 0.85]) and cup["on"] == [1] and cup["under"] == []
    table = store.candidate_view(1, ["on", "under", "z_range"])
    assert table == {"id": 1, "on": [], "under": [2], "z_range": [0.0, 0.75]}
    assert store.candidate_view(3, ["under"])["under"] == [1]  # the box stands under the table
    assert store.candidate_view(4, ["on", "under"]) == {"id": 4, "on": [], "under": []}


def test_unknown_field_is_an_error(store):
    with pytest.raises(IesmError, match="unknown candidate field"):
        store.candidate_view(1, ["centre"])


def test_relate_describes_the_pair(store):
    rel = store.relate(2, 1)
    assert rel["vertical"] == "on" and rel["shared_cells"] > 0 and rel["near"] and rel["gap"] == 0
    assert store.relate(1, 2)["vertical"] == "supports"
    assert store.relate(3, 1)["vertical"] == "under"
    far = store.relate(4, 1)
    assert far["vertical"] == "level" and far["direction"] == "east" and far["gap"] == pytest.approx(1.3, abs=0.06)
    assert not far["near"] and far["shared_cells"] == 0


def test_relate_is_a_tool_and_rejects_unknown_ids(store):
    assert "relate" in {t["name"] for t in store.tool_specs()}
    assert store.call_tool("relate", {"a": 2, "b": 1})["vertical"] == "on"
    with pytest.raises(IesmError, match="unknown instance id"):
        store.relate(2, 99)


def test_expert_specs_may_request_geometry_but_not_unknown_fields():
    spec = ExpertSpec(name="g", title="t", gate_description="d", focus="f", fields=["label", "center", "on"])
    assert spec.fields == ("id", "label", "center", "on")
    with pytest.raises(ValueError):
        ExpertSpec(name="g", title="t", gate_description="d", focus="f", fields=["elevation"])


def test_boxes_from_views_skip_views_without_geometry():
    boxes = geo.Boxes.from_views([{"id": 1, "center": [0, 0, 1], "size": [2, 2, 2]},
                                  {"id": 2, "center": "nowhere"}, {"id": 3, "label": "x"},
                                  {"id": 4, "center": [1, 1, 0.5], "size": [1, 1, 1], "z_range": [0.2, 0.9]}])
    assert boxes.ids.tolist() == [1, 4]
    assert np.allclose(boxes.lo[1], [0.5, 0.5, 0.2]) and np.allclose(boxes.hi[1], [1.5, 1.5, 0.9])


def test_segment_distance_skips_segments_ending_at_the_object():
    three = geo.Boxes(np.array([1, 2, 3]), np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0]], float),
                      np.array([[0.2, 0.2, 1], [1.2, 0.2, 1], [2.2, 0.2, 1]], float))
    cost = geo.segment_distance(three, three, three)
    assert cost[1] == pytest.approx(0.0) and cost[0] > 0.9 and cost[2] > 0.9
