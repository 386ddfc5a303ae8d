"""Which layout a directory is in, and `open_recording` for the readers in `layouts`."""

from __future__ import annotations

from pathlib import Path

from ..errors import IesmError
from . import layouts
from .checks import check_depth_scale
from .recording import Recording

#: layout name -> (detector, opener); "ours" is our frame directory (scene.json), read by `FrameSet`
LAYOUTS = {
    "7scenes": (layouts.is_sevenscenes, layouts.open_sevenscenes),
    "3dmatch": (layouts.is_sevenscenes, layouts.open_sevenscenes),
    "replica": (layouts.is_replica, layouts.open_replica),
    "scannet": (layouts.is_scannet, layouts.open_scannet),
    "tum": (layouts.is_tum, layouts.open_tum),
}
EXPECTED = ("expected one of: our frame directory (scene.json), 7-Scenes/3DMatch (frame-NNNNNN.color.jpg, "
            ".depth.png, .pose.txt), Replica (results/frameNNNNNN.jpg, traj.txt), ScanNet (color/, depth/, pose/, "
            "intrinsic/), TUM RGB-D (rgb.txt, depth.txt, groundtruth.txt)")


def matching_layouts(directory: str | Path) -> list[str]:
    """Every layout name `directory` looks like, in `detect_layout`'s order of preference ("3dmatch"
    is 7-Scenes' other name and not listed apart)."""
    directory = Path(directory)
    if not directory.is_dir():
        raise IesmError("not a directory", directory)
    found = ["ours"] if (directory / "scene.json").is_file() else []
    return found + [name for name, (detect, _open) in LAYOUTS.items() if name != "3dmatch" and detect(directory)]


def detect_layout(directory: str | Path) -> str:
    """The layout name of `directory` ("ours", "7scenes", "replica", "scannet", "tum"): the first
    of `matching_layouts` (callers warn when there are several; --layout chooses)."""
    found = matching_layouts(directory)
    if not found:
        raise IesmError(f"no frames found ({EXPECTED})", directory)
    return found[0]


def open_recording(directory: str | Path, layout: str | None = None, depth_scale: float | None = None) -> Recording:
    """The recording in `directory` read as `layout` (detected when None); refuses a directory
    without frames. Our own layout is read with `FrameSet.open`, not here."""
    directory = Path(directory)
    layout = layout or detect_layout(directory)
    if layout == "ours":
        raise IesmError("our own frame directory is read with FrameSet.open", directory)
    if layout not in LAYOUTS:
        raise IesmError(f"unknown layout {layout!r} (choose from ours, {', '.join(LAYOUTS)})", None, "--layout")
    if depth_scale is not None:
        depth_scale = check_depth_scale(depth_scale, None, "--depth-scale")
    detect, opener = LAYOUTS[layout]
    if not directory.is_dir():
        raise IesmError("not a directory", directory)
    if not detect(directory):
        raise IesmError(f"not a {layout} recording: no frames found ({EXPECTED})", directory)
    recording = opener(directory, depth_scale)
    if not recording.refs:
        raise IesmError(f"no frames found in this {layout} recording", directory)
    return recording
