"""`render_rooms`: the room map picture (one colour per room) and its errors."""

import cv2
import numpy as np
import pytest

from iesm_agent.errors import IesmError
from iesm_agent.store import GridSpec, Instance, Room, SceneMap
from iesm_agent.store.render import render_rooms


def _scene(with_rooms: bool) -> SceneMap:
    room_map = np.full((20, 40), -1, np.int32)
    room_map[:, :18], room_map[:, 22:] = 1, 2
    obstacles = np.zeros((20, 40), bool)
    obstacles[:, 18:22] = True  # the wall between them
    return SceneMap(scene_id="two", grid=GridSpec(cell_size=0.1, height=20, width=40),
                    instances=[Instance(id=1, label="bed")],
                    rooms=[Room(id=1, label="bedroom"), Room(id=2, label="kitchen")] if with_rooms else [],
                    room_map=room_map if with_rooms else None, obstacles=obstacles)


def test_each_room_gets_its_own_colour(tmp_path):
    out = tmp_path / "rooms.png"
    render_rooms(_scene(True), out)
    image = cv2.imread(str(out))[:, :, ::-1].reshape(-1, 3) / 255.0
    tab20 = [(0.1216, 0.4667, 0.7059), (0.6824, 0.7804, 0.9098)]  # colours 0 and 1 of tab20
    for colour in tab20:
        assert (np.abs(image - colour).max(1) < 0.02).sum() > 500, colour
    assert (np.abs(image - 0.3).max(1) < 0.02).sum() > 100  # the obstacle wall


def test_a_map_without_rooms_is_a_clear_error(tmp_path):
    with pytest.raises(IesmError, match="no rooms"):
        render_rooms(_scene(False), tmp_path / "rooms.png")
    assert not (tmp_path / "rooms.png").exists()
