"""`iesm import | info | render` end to end in a subprocess, including bad input."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]


def iesm(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", "from iesm_agent.cli import main; main()", *map(str, args)],
                          capture_output=True, text=True, cwd=REPO, timeout=120)


def assert_user_error(proc: subprocess.CompletedProcess, *fragments: str) -> None:
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("iesm: error: "), proc.stderr
    assert "Traceback" not in proc.stderr
    for fragment in fragments:
        assert fragment in lines[0], lines[0]


def test_import_then_info_json(tmp_path):
    out = tmp_path / "apt.iesm"
    proc = iesm("import", REPO / "map_store" / "apartment.json", "-o", out)
    assert proc.returncode == 0, proc.stderr
    assert "56 instances" in proc.stdout and out.is_file()
    proc = iesm("info", out, "--json")
    assert proc.returncode == 0, proc.stderr
    info = json.loads(proc.stdout)
    assert info["instances"] == 56 and info["rooms"] == 6 and info["categories"]["chair"] == 3
    assert info["grid"]["cell_size"] == 0.05 and info["bytes"] == out.stat().st_size
    assert info["multi_occupancy_cells"] > 0 and info["schema_version"] == 1 and info["scene_id"] == "apartment"
    assert "embedding_model" in info


def test_shipped_apartment_is_current(tmp_path, apartment_path):
    """map_store/apartment.iesm must be regenerated whenever apartment.json changes."""
    from iesm_agent.store import load_map
    from iesm_agent.store.importers import import_map

    shipped = load_map(apartment_path)
    fresh = import_map(REPO / "map_store" / "apartment.json")
    assert shipped.model_copy(update={"embeddings": None, "embedding_model": None}) == fresh


def test_info_reads_a_json_map():
    """Like every command, info takes an importable JSON map (imported in memory)."""
    proc = iesm("info", REPO / "map_store" / "apartment.json", "--json")
    assert proc.returncode == 0, proc.stderr
    info = json.loads(proc.stdout)
    assert info["instances"] == 56 and info["scene_id"] == "apartment"
    assert info["bytes"] == (REPO / "map_store" / "apartment.json").stat().st_size


def test_info_human_output(apartment_path):
    proc = iesm("info", apartment_path)
    assert proc.returncode == 0 and "multi-occupancy cells" in proc.stdout


@pytest.mark.slow
def test_render_png(tmp_path, apartment_path):
    out = tmp_path / "apt.png"
    proc = iesm("render", apartment_path, "-o", out)
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20_000
    assert [p.name for p in tmp_path.iterdir()] == ["apt.png"]


def test_truncated_map(tmp_path, apartment_path):
    bad = tmp_path / "trunc.iesm"
    bad.write_bytes(apartment_path.read_bytes()[:500])
    assert_user_error(iesm("info", bad), str(bad), "truncated")
    assert_user_error(iesm("render", bad, "-o", tmp_path / "x.png"), str(bad))
    assert not (tmp_path / "x.png").exists()


def test_corrupted_zip(tmp_path):
    bad = tmp_path / "garbage.iesm"
    bad.write_bytes(b"PK\x03\x04" + bytes(range(256)) * 4)
    assert_user_error(iesm("info", bad), str(bad))


@pytest.mark.parametrize("obj, where", [
    ({"id": 1, "label": "chair", "size": [1, 1, 1]}, "objects[0].center"),
    ({"id": 1, "label": "chair", "center": [0, 0, 0], "size": [1, -1, 1]}, "objects[0].size"),
])
def test_bad_object_list(tmp_path, obj, where):
    src = tmp_path / "objs.json"
    src.write_text(json.dumps({"scene_id": "s", "objects": [obj]}))
    out = tmp_path / "out.iesm"
    assert_user_error(iesm("import", src, "-o", out), f"{src}:{where}")
    assert list(tmp_path.iterdir()) == [src]  # no output, no temp file


def test_lying_ply_header(tmp_path):
    cap = tmp_path / "scene_z_caption.json"
    cap.write_text(json.dumps({"3": {"category": "chair", "room_cat": None, "room_id": None,
                                     "top5_categories": ["chair"], "caption": "{}"}}))
    ply = tmp_path / "scene_z_ours_map_with_id.ply"
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty double x\n"
              "property double y\nproperty double z\nproperty uchar red\nproperty uchar green\n"
              "property uchar blue\nproperty int instance_id\nend_header\n").encode()
    ply.write_bytes(header + bytes(31 * 10))
    out = tmp_path / "out.iesm"
    assert_user_error(iesm("import", cap, "-o", out), str(ply), "declares 1000 vertices")
    assert not out.exists()


def test_missing_output_directory(tmp_path):
    assert_user_error(iesm("import", REPO / "map_store" / "apartment.json", "-o", tmp_path / "no" / "x.iesm"),
                      "output directory does not exist")
