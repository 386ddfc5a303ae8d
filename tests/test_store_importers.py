"""Object-list and IESM (caption JSON + PLY) importers, caption repair and colour names."""

from __future__ import annotations

import json

import numpy as np
import pytest

from iesm_agent.errors import MapFormatError
from iesm_agent.colours import colour_family, colour_name
from iesm_agent.store.importers import detect_format, import_map
from iesm_agent.store.importers.iesm import parse_inner_caption

ROOMS = [{"id": 1, "label": "office", "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]]},
         {"id": 2, "label": "kitchen", "polygon": [[2, 0], [4, 0], [4, 2], [2, 2]]}]


def objects_file(tmp_path, objects, rooms=ROOMS, **extra):
    path = tmp_path / "objs.json"
    data = {"scene_id": "s", "objects": objects, **extra}
    if rooms is not None:
        data["rooms"] = rooms
    path.write_text(json.dumps(data))
    return path


def chair(**kw):
    return {"id": 1, "label": "chair", "center": [1.0, 1.0, 0.45], "size": [0.5, 0.4, 0.9], **kw}


def test_box_rasterisation_and_heights(tmp_path):
    desk = {"id": 2, "label": "desk", "center": [1.0, 1.0, 0.375], "size": [1.0, 1.0, 0.75]}
    scene = import_map(objects_file(tmp_path, [chair(), desk]), cell_size=0.05)
    assert scene.grid.cell_size == 0.05
    inst = scene.instance(1)
    assert inst.footprint_cells == 10 * 8
    assert inst.mean_height == 0.45 and inst.centroid == (1.0, 1.0, 0.45)
    cells, ids, top = scene.occupancy.entries()
    assert np.allclose(top[ids == 1], 0.9) and np.allclose(top[ids == 2], 0.75)
    assert scene.occupancy.multi_occupancy_cells == 80  # the chair footprint lies inside the desk's
    rows, cols = np.divmod(cells[ids == 2], scene.grid.width)
    xs = scene.grid.origin[0] + (cols + 0.5) * 0.05
    assert xs.min() > 0.5 and xs.max() < 1.5
    # grid covers the room polygons plus margin
    assert scene.grid.origin[0] <= -0.25 + 1e-9 and scene.grid.width * 0.05 >= 4.5 - 1e-9


def test_room_map_from_polygons_and_inferred_room(tmp_path):
    obj = {"id": 5, "label": "kettle", "center": [3.0, 1.0, 1.0], "size": [0.2, 0.2, 0.25]}
    scene = import_map(objects_file(tmp_path, [chair(room="office"), obj]))
    r, c = scene.grid.cell_of(3.0, 1.0)
    assert scene.room_map[r, c] == 2 and scene.room_map.dtype == np.int32
    assert scene.instance(5).room_label == "kitchen"  # inferred from the polygon
    assert scene.instance(1).room_id == 1
    assert (scene.room_map == -1).any()  # margin outside the rooms


def test_caption_built_from_attributes(tmp_path):
    obj = chair(color_rgb=[200, 30, 35], tags={"material": "wood"}, room="office")
    scene = import_map(objects_file(tmp_path, [obj]))
    inst = scene.instance(1)
    assert inst.tags == {"material": "wood", "color": "red"}
    assert inst.caption == "a red wooden chair in the office, about 0.9 m tall and 0.5 m wide"


def test_given_caption_and_color_tag_win(tmp_path):
    obj = chair(color_rgb=[200, 30, 35], tags={"color": "crimson"}, caption="My chair.")
    inst = import_map(objects_file(tmp_path, [obj])).instance(1)
    assert inst.caption == "My chair." and inst.tags["color"] == "crimson"


def test_rooms_derived_from_object_labels(tmp_path):
    objs = [chair(room="study"), {**chair(room="hall"), "id": 2}, {**chair(room="study"), "id": 3}]
    scene = import_map(objects_file(tmp_path, objs, rooms=None))
    assert [(r.id, r.label) for r in scene.rooms] == [(1, "study"), (2, "hall")]
    assert scene.instance(3).room_id == 1
    assert (scene.room_map == -1).all()


@pytest.mark.parametrize("objects, rooms, where", [
    ([{"id": 1, "label": "chair", "size": [1, 1, 1]}], ROOMS, "objects[0].center"),
    ([chair(), {**chair(), "id": 2, "size": [0.5, -0.1, 0.9]}], ROOMS, "objects[1].size"),
    ([chair(), {**chair(), "id": 2, "size": [0.5, 0.0, 0.9]}], ROOMS, "objects[1].size"),
    ([chair(), chair()], ROOMS, "objects[1].id"),
    ([chair(room="garage")], ROOMS, "objects[0].room"),
    ([chair(room=9)], ROOMS, "objects[0].room"),
    ([chair(room=1)], None, "objects[0].room"),
    ([chair(color_rgb=[300, 0, 0])], ROOMS, "objects[0].color_rgb"),
    ([chair(center=[float("nan"), 1.0, 0.45])], ROOMS, "objects[0].center[0]"),
    ([chair(size=[0.5, float("inf"), 0.9])], ROOMS, "objects[0].size[1]"),
    ([chair()], [{"id": 1, "label": "office", "polygon": [[0, 0], [float("inf"), 0], [0, 2]]}],
     "rooms[0].polygon[1][0]"),
])
def test_object_list_errors_name_the_field(tmp_path, objects, rooms, where):
    path = objects_file(tmp_path, objects, rooms=rooms)
    with pytest.raises(MapFormatError) as info:
        import_map(path)
    assert str(info.value).startswith(f"{path}:{where}")


def test_invalid_json_and_unknown_format(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{oops")
    with pytest.raises(MapFormatError, match="invalid JSON"):
        import_map(bad)
    other = tmp_path / "other.json"
    other.write_text(json.dumps({"foo": 1}))
    with pytest.raises(MapFormatError, match="unrecognised input"):
        detect_format(other)


@pytest.mark.parametrize("text, status, caption", [
    ('{"color": "red", "captions": "A red chair."}', "ok", "A red chair."),
    ('{\n "color": "red",\n "captions": "A red chair.",\n}', "repaired", "A red chair."),
    ('{"color": "red" "captions": "A \\"red\\" chair."', "repaired", 'A "red" chair.'),
    ("Just a plain caption.", "plain", "Just a plain caption."),
    ('{"color": "red", broken', "unrecovered", None),
    ("", "empty", None),
])
def test_inner_caption_repair(text, status, caption):
    fields, got = parse_inner_caption(text)
    assert got == status
    assert fields.get("captions") == caption


def write_ply(path, verts, declared=None):
    dtype = np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("red", "u1"), ("green", "u1"),
                      ("blue", "u1"), ("instance_id", "<i4")])
    arr = np.array(verts, dtype)
    header = ("ply\nformat binary_little_endian 1.0\ncomment test\n"
              f"element vertex {declared if declared is not None else len(arr)}\n"
              "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
              "property uchar green\nproperty uchar blue\nproperty int instance_id\nend_header\n")
    path.write_bytes(header.encode() + arr.tobytes())


def caption_entry(cat, room_id, room_cat, inner):
    return {"category": cat, "room_cat": room_cat, "room_id": room_id, "category_idx": 1,
            "top5_categories": [cat, "seat", cat], "caption": inner}


@pytest.fixture
def tiny_iesm(tmp_path):
    caps = {
        "3": caption_entry("chair", 1, "office", '{"color": "red", "material": "wood", "captions": "A red chair.",}'),
        "4": caption_entry("cup", 1, "office", '{"color": "white", "captions": "A cup."}'),
        "5": caption_entry("lamp", None, None, '{"color": "black", broken'),
    }
    cap_path = tmp_path / "scene_t_caption.json"
    cap_path.write_text(json.dumps(caps))
    # chair in cells (0,0),(1,0) at z 20; cup stacked in (1,0) at z 32; lamp at (3,2); background id 1
    write_ply(tmp_path / "scene_t_ours_map_with_id.ply", [
        (0, 0, 20, 1, 2, 3, 3), (1, 0, 20, 1, 2, 3, 3), (1, 0, 32, 1, 2, 3, 4), (3, 2, 40, 0, 0, 0, 5),
        (2, 2, 10, 0, 0, 0, 1), (1, 0, 10, 0, 0, 0, 1)])
    return cap_path


def test_iesm_import_with_ply(tiny_iesm):
    assert detect_format(tiny_iesm) == "iesm"
    scene = import_map(tiny_iesm)
    assert scene.scene_id == "t" and scene.grid.height == 3 and scene.grid.width == 4
    assert [r.label for r in scene.rooms] == ["office"]
    chair_ = scene.instance(3)
    assert chair_.caption == "A red chair." and chair_.tags == {"color": "red", "material": "wood"}
    assert chair_.alt_labels == ["seat"] and chair_.footprint_cells == 2
    assert chair_.mean_height == pytest.approx(0.5) and chair_.centroid == pytest.approx((0.025, 0.0125, 0.5))
    assert scene.instance(5).room_id is None and scene.instance(5).caption == ""
    assert scene.occupancy.multi_occupancy_cells == 1  # background id 1 does not count
    assert set(scene.occupancy.ids.tolist()) == {3, 4, 5}
    assert scene.meta["captions_repaired"] == "1" and scene.meta["captions_unrecovered"] == "1"
    assert scene.meta["background_points"] == "2"
    assert scene.room_map[0, 1] == 1 and scene.room_map[2, 3] == -1


def test_iesm_import_without_ply(tiny_iesm, tmp_path):
    (tmp_path / "scene_t_ours_map_with_id.ply").unlink()
    scene = import_map(tiny_iesm)
    assert len(scene.instances) == 3 and scene.grid.height == 0 and len(scene.occupancy.cells) == 0


def test_ply_with_lying_header(tiny_iesm, tmp_path):
    ply = tmp_path / "scene_t_ours_map_with_id.ply"
    write_ply(ply, [(0, 0, 20, 1, 2, 3, 3)] * 4, declared=9)
    with pytest.raises(MapFormatError) as info:
        import_map(tiny_iesm)
    assert str(ply) in str(info.value) and "declares 9 vertices" in str(info.value)


def test_ply_not_a_ply(tiny_iesm, tmp_path):
    bad = tmp_path / "bad.ply"
    bad.write_bytes(b"hello")
    with pytest.raises(MapFormatError, match="not a PLY"):
        import_map(tiny_iesm, ply=bad)


def test_iesm_caption_entry_error_names_key(tmp_path):
    path = tmp_path / "scene_x_caption.json"
    path.write_text(json.dumps({"7": {"category": 5, "caption": ""}}))
    with pytest.raises(MapFormatError) as info:
        import_map(path, "iesm")
    assert "7.category" in str(info.value)
    path.write_text(json.dumps({"7": {"category": "chair"}, "07": {"category": "cup"}}))
    with pytest.raises(MapFormatError, match="duplicate instance id 7") as info:
        import_map(path, "iesm")
    assert str(info.value).startswith(f"{path}:'07'")


@pytest.mark.slow
def test_published_scene_00829(iesm_maps_dir):
    cap = iesm_maps_dir / "scene_00829_caption.json"
    scene = import_map(cap)
    assert len(scene.instances) == 112
    assert {r.label for r in scene.rooms} == {"living room", "kitchen", "bathroom", "bedroom"}
    assert sum(1 for i in scene.instances if i.caption) == 112
    assert int(scene.meta["captions_repaired"]) > 0 and scene.meta["captions_unrecovered"] == "0"
    # independent multi-occupancy count from the raw PLY
    raw = (iesm_maps_dir / "scene_00829_ours_map_with_id.ply").read_bytes()
    body = raw[raw.index(b"end_header\n") + 11:]
    v = np.frombuffer(body, np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("r", "u1"), ("g", "u1"),
                                      ("b", "u1"), ("id", "<i4")]))
    captioned = np.isin(v["id"], [int(k) for k in json.loads(cap.read_text())])
    per_cell: dict[tuple[int, int], set[int]] = {}
    for x, y, i in zip(v["x"][captioned].astype(int), v["y"][captioned].astype(int), v["id"][captioned]):
        per_cell.setdefault((x, y), set()).add(int(i))
    assert scene.occupancy.multi_occupancy_cells == sum(len(s) > 1 for s in per_cell.values())
    assert scene.meta["background_points"] == str(int((~captioned).sum()))


@pytest.mark.parametrize("rgb, name", [((255, 0, 0), "red"), ((250, 250, 250), "white"), ((10, 10, 10), "black"),
                                       ((30, 60, 200), "blue"), ((40, 160, 60), "green"), ((139, 69, 19), "brown")])
def test_color_names_fall_in_the_family_people_expect(rgb, name):
    assert colour_family(colour_name(rgb)) == name


def test_color_name_range():
    with pytest.raises(ValueError):
        colour_name((0, 0, 256))


def test_far_apart_objects_are_refused_before_allocating_the_grid(tmp_path):
    from iesm_agent.errors import MapFormatError
    from iesm_agent.store.importers import import_map

    objs = {"scene_id": "far", "objects": [
        {"id": 1, "label": "chair", "center": [0, 0, 0.4], "size": [0.5, 0.5, 0.8]},
        {"id": 2, "label": "chair", "center": [5000, 5000, 0.4], "size": [0.5, 0.5, 0.8]}]}
    path = tmp_path / "far.json"
    path.write_text(json.dumps(objs))
    with pytest.raises(MapFormatError, match=r"far.json:grid: .*larger --cell-size"):
        import_map(path)
    assert import_map(path, cell_size=2.0).grid.width < 3000  # a coarser grid fits


def test_simulator_ground_truth_fields_import(tmp_path):
    # gt/objects.json from `iesm sim` marks walls as structural and what stands on what
    wall = {"id": 3, "label": "wall", "center": [2.0, 1.0, 1.25], "size": [0.1, 2.0, 2.5], "structural": True}
    cup = {"id": 4, "label": "cup", "center": [1.0, 1.0, 0.95], "size": [0.1, 0.1, 0.1], "on": 1}
    scene = import_map(objects_file(tmp_path, [chair(), wall, cup]), cell_size=0.05)
    assert sorted(i.id for i in scene.instances) == [1, 3, 4]
    with pytest.raises(MapFormatError, match="on"):
        import_map(objects_file(tmp_path, [chair(on="the table")]), cell_size=0.05)
