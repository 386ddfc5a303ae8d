"""Expert plugins: shipped specs, user directories, entry points, overrides and errors."""

import json
from types import SimpleNamespace

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.providers import FunctionModel
from iesm_agent.retrieval import Retriever
from iesm_agent.retrieval import experts as registry_mod
from iesm_agent.retrieval.experts import ExpertSpec, load_experts, load_spec
from iesm_agent.store.mapstore import MapStore
from iesm_agent.store.model import GridSpec, Instance, Room, SceneMap

SPEC = """name = "{name}"
title = "{title}"
gate_description = "{desc}"
focus = "{focus}"
fields = {fields}
"""


def write_spec(directory, name, desc="", focus="", fields=("label",), title="T"):
    directory.mkdir(exist_ok=True)
    path = directory / f"{name}.toml"
    path.write_text(SPEC.format(name=name, title=title, desc=desc or f"about {name}",
                                focus=focus or f"FOCUS:{name}", fields=json.dumps(list(fields))))
    return path


def test_shipped_experts_are_the_papers_four_and_spatial():
    specs = load_experts(plugins=False)
    assert set(specs) == {"obj", "room", "desc", "abs", "spatial"}
    # one ranking skeleton: every paper expert sees every field, the focus line tells them apart
    assert all(set(s.fields) >= {"id", "label", "room", "caption", "tags"} for n, s in specs.items() if n != "spatial")
    assert {"center", "size", "z_range", "on", "under"} <= set(specs["spatial"].fields)
    assert len({s.focus for s in specs.values()}) == 5
    assert all(s.fields[0] == "id" and s.gate_description and s.focus for s in specs.values())


def test_user_directory_overrides_by_name_and_adds(tmp_path):
    d = tmp_path / "mine"
    write_spec(d, "obj", focus="my own object focus", fields=["label", "tags"])
    write_spec(d, "height", fields=["label"])
    specs = load_experts([d], plugins=False)
    assert specs["obj"].focus == "my own object focus" and specs["obj"].fields == ("id", "label", "tags")
    assert list(specs)[-1] == "height" and len(specs) == 6


@pytest.mark.parametrize("body, field", [
    ('name = "x"\ntitle = "t"\ngate_description = "g"\nfocus = "f"\nfields = ["colour"]\n', "fields"),
    ('name = "x"\ntitle = "t"\ngate_description = "g"\nfields = ["label"]\n', "focus"),
    ('name = "two words"\ntitle = "t"\ngate_description = "g"\nfocus = "f"\nfields = []\n', "name"),
    ('name = "x"\ntitle = "t"\ngate_description = "g"\nfocus = "f"\nfields = []\nsize = 3\n', "size"),
])
def test_invalid_spec_names_file_and_field(tmp_path, body, field):
    path = tmp_path / "bad.toml"
    path.write_text(body)
    with pytest.raises(IesmError) as err:
        load_spec(path)
    assert err.value.source == str(path) and err.value.where == field


def test_unreadable_spec_and_missing_directory(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text("name = [unterminated")
    with pytest.raises(IesmError, match="cannot read expert spec"):
        load_spec(path)
    with pytest.raises(IesmError, match="does not exist"):
        load_experts([tmp_path / "nope"], plugins=False)


def test_entry_points_resolve_spec_dict_or_path(tmp_path, monkeypatch):
    path = write_spec(tmp_path / "ep", "from_path")
    objects = {
        "a": ExpertSpec(name="from_spec", title="t", gate_description="g", focus="f", fields=["label"]),
        "b": {"name": "from_dict", "title": "t", "gate_description": "g", "focus": "f", "fields": ["caption"]},
        "c": str(path),
        "d": {"name": "broken", "title": "t"},
    }
    eps = [SimpleNamespace(name=k, value=f"pkg:{k}", load=lambda k=k: objects[k]) for k in "abc"]
    monkeypatch.setattr(registry_mod, "entry_points", lambda group: eps if group == "iesm_agent.experts" else [])
    specs = load_experts()
    assert {"from_spec", "from_dict", "from_path"} <= set(specs)
    assert specs["from_dict"].fields == ("id", "caption")
    eps.append(SimpleNamespace(name="d", value="pkg:d", load=lambda: objects["d"]))
    with pytest.raises(IesmError) as err:
        load_experts()
    assert "entry point d" in err.value.source and err.value.where == "gate_description"


def test_a_fifth_expert_from_a_file_joins_gate_and_fusion(tmp_path):
    rooms = [Room(id=1, label="hall")]
    insts = [Instance(id=1, label="shelf", room_id=1, room_label="hall", caption="tall shelf", mean_height=1.8),
             Instance(id=2, label="shelf", room_id=1, room_label="hall", caption="low shelf", mean_height=0.4)]
    store = MapStore(SceneMap(scene_id="s", grid=GridSpec(cell_size=0.1, height=4, width=4),
                              instances=insts, rooms=rooms))
    d = tmp_path / "plugins"
    write_spec(d, "height", desc="HEIGHT-EXPERT judges how high objects are", fields=["label", "caption"])
    seen = {}

    def model(messages, options):
        text = "\n".join(m.text() for m in messages)
        if "scores" in (options.json_schema or {}).get("properties", {}):
            seen["gate"] = text
            return json.dumps({"scores": {"height": 4, "obj": 1}})
        if "FOCUS:height" in text:
            seen["height"] = text
            return json.dumps({"ranked_instance_ids": [2]})
        return json.dumps({"ranked_instance_ids": [1, 2]})

    without = Retriever(store, provider=FunctionModel(model)).ask("the low shelf")
    assert without.instance_id == 1 and "HEIGHT-EXPERT" not in seen["gate"]
    res = Retriever(store, provider=FunctionModel(model), experts_dirs=[d]).ask("the low shelf")
    assert "height" in seen["gate"] and "HEIGHT-EXPERT judges how high objects are" in seen["gate"]
    assert "low shelf" in seen["height"]
    assert res.experts["height"] == [2] and res.gate["height"] == pytest.approx(0.8)
    assert res.instance_id == 2 and res.deciding_expert == "height"
