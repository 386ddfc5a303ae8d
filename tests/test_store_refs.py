"""Map references: files, importable JSON maps and shipped map names resolve to one SceneMap."""

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.resources import resource_dir, shipped_map
from iesm_agent.store import load_map, open_map, resolve_map_path


def test_shipped_name_and_path_resolve_to_the_same_file(tmp_path):
    assert resolve_map_path("apartment") == shipped_map("apartment")
    assert resolve_map_path("apartment.iesm") == shipped_map("apartment")
    assert resolve_map_path(shipped_map("apartment").name, shipped_map("apartment").parent) == shipped_map("apartment")


def test_json_map_is_imported_in_memory():
    imported = open_map(resource_dir("map_store") / "apartment.json")
    shipped = load_map(shipped_map("apartment"))
    assert [i.model_dump() for i in imported.instances] == [i.model_dump() for i in shipped.instances]
    assert imported.occupancy == shipped.occupancy


def test_unknown_reference_is_a_clear_error(tmp_path):
    with pytest.raises(IesmError, match="unknown map 'nowhere/x.iesm'"):
        open_map("nowhere/x.iesm", tmp_path)
