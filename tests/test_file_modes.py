"""Files written by `iesm` follow the umask (issue 30): the atomic writes (`fileio.atomic_write`:
mkstemp, mode 0600) give the file the mode an ordinary `open` would, so a map, its page and its
picture are readable by a web server or a colleague under the usual umask 022."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from fuzzing import write_tiny_frames
from recordings import seven_scenes

from iesm_agent.cli import run

pytest.importorskip("cv2")


@pytest.fixture()
def umask():
    """Set the process umask for the test (restored after)."""
    old = os.umask(0o022)
    os.umask(old)
    yield lambda mask: os.umask(mask)
    os.umask(old)


def _mode(path: Path) -> int:
    return stat.S_IMODE(path.stat().st_mode)


@pytest.mark.parametrize("mask, file_mode, dir_mode", [(0o022, 0o644, 0o755), (0o077, 0o600, 0o700),
                                                      (0o002, 0o664, 0o775)])
def test_written_files_follow_the_umask(mask, file_mode, dir_mode, umask, tmp_path, capsys):
    umask(mask)
    frames = write_tiny_frames(tmp_path / "frames")
    assert run(["build-map", str(frames), "-o", str(tmp_path / "scene.iesm")]) == 0, capsys.readouterr().err
    assert run(["view", str(tmp_path / "scene.iesm"), "-o", str(tmp_path / "map.html")]) == 0
    assert run(["render", str(tmp_path / "scene.iesm"), "-o", str(tmp_path / "instance_map.png")]) == 0
    assert run(["segment", str(seven_scenes(tmp_path / "rec")), "-o", str(tmp_path / "seg"), "--segmenter",
                "geometric"]) == 0
    written = [tmp_path / "scene.iesm", tmp_path / "map.html", tmp_path / "instance_map.png",
               frames / "scene.json", frames / "frames" / "000000.rgb.png", tmp_path / "seg" / "scene.json",
               tmp_path / "seg" / "frames" / "000000.depth.png", tmp_path / "seg" / "frames" / "000000.seg.npz"]
    assert {p.name: oct(_mode(p)) for p in written} == {p.name: oct(file_mode) for p in written}
    assert oct(_mode(tmp_path / "seg")) == oct(dir_mode)  # the staged folder renamed into place
