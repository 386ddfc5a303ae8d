"""`iesm path` and `iesm rooms` in-process: JSON output, PNG, exit codes and one-line errors."""

from __future__ import annotations

import json

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.sim.layouts import grid_layout, noisy_labels
from iesm_agent.store import load_map, save_map


@pytest.fixture()
def layout_map(tmp_path):
    layout = grid_layout(2, 1, labels=("bedroom", "kitchen"))
    path = tmp_path / "grid.iesm"
    save_map(layout.scene, path)
    labels = noisy_labels(layout, 0.7)
    np.savez(tmp_path / "labels.npz", labels=labels.labels, names=np.array(labels.names))
    return layout, path, tmp_path / "labels.npz"


def one_error_line(capsys) -> str:
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("iesm: error: ")
    return err[0]


def test_path_json_and_png(layout_map, tmp_path, capsys):
    layout, path, _ = layout_map
    fridge = next(i.id for i in layout.scene.instances if i.label == "refrigerator")
    png = tmp_path / "path.png"
    assert run(["path", str(path), "--to", str(fridge), "--start", "1.0,0.5", "--json", "--png", str(png)]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["reachable"] and result["length_m"] > 4.0 and result["waypoints"][0] == [1.0, 0.5]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_path_answers_for_bad_requests(layout_map, capsys):
    layout, path, _ = layout_map
    bed = next(i.id for i in layout.scene.instances if i.label == "bed")
    assert run(["path", str(path), "--to", "999", "--start", "1,1"]) == 2
    assert "no instance with id 999" in one_error_line(capsys)
    assert run(["path", str(path), "--to", str(bed), "--start", "1;1"]) == 2
    assert "expected X,Y" in one_error_line(capsys)
    assert run(["path", str(path), "--to", str(bed), "--start", "1.5,1.5"]) == 1
    assert "not reachable (start_in_obstacle)" in capsys.readouterr().out


def test_rooms_command_writes_rooms_into_the_map(layout_map, tmp_path, capsys):
    layout, path, labels = layout_map
    out = tmp_path / "rooms.iesm"
    assert run(["rooms", str(path), "--cell-labels", str(labels), "-o", str(out)]) == 0
    assert "2 rooms" in capsys.readouterr().out
    scene = load_map(out)
    assert sorted(r.label for r in scene.rooms) == ["bedroom", "kitchen"]
    assert scene.obstacles is not None and scene.room_map.shape == layout.rooms.shape
    assert next(i for i in scene.instances if i.label == "refrigerator").room_label == "kitchen"


def test_rooms_command_refuses_bad_label_sources(layout_map, tmp_path, capsys):
    _, path, labels = layout_map
    out = tmp_path / "rooms.iesm"
    assert run(["rooms", str(path), "-o", str(out)]) == 2
    assert "exactly one of --frames" in one_error_line(capsys)
    np.savez(tmp_path / "bad.npz", labels=np.zeros((3, 3), np.int32), names=np.array(["kitchen"]))
    assert run(["rooms", str(path), "--cell-labels", str(tmp_path / "bad.npz"), "-o", str(out)]) == 2
    assert "the map grid" in one_error_line(capsys)
    assert not out.exists()
