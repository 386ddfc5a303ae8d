"""Tiny valid recordings in each layout `iesm segment` reads (7-Scenes, Replica, ScanNet, TUM), for
the recording fuzz tests and the memory benchmark of bad recordings: a camera 1.4 m above a floor
facing a wall 2.5 m away, a few frames each."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

H, W = 48, 64                       # tiny frames (TUM's intrinsics are fixed: 640 x 480)
K = (50.0, 50.0, 31.5, 23.5)        # fx fy cx cy (pixels)


def _depth_m(h: int, w: int, fy: float, cy: float) -> np.ndarray:
    """Depth (h, w) metres: a wall 2.5 m ahead above the horizon, the floor 1.4 m below it."""
    v = np.arange(h, dtype=np.float64)[:, None] - cy
    floor = np.where(v > 0, 1.4 * fy / np.maximum(v, 1e-6), np.inf)
    return np.broadcast_to(np.minimum(floor, 2.5), (h, w)).astype(np.float32)


def _colour(h: int, w: int, i: int) -> np.ndarray:
    rgb = np.full((h, w, 3), 90, np.uint8)
    rgb[: h // 2, : w // 3] = (200, 40, 40)
    rgb[h // 2:, w // 2:] = (40, 160, (60 + 10 * i) % 256)
    return rgb


def _pose(i: int) -> np.ndarray:
    pose = np.eye(4)
    pose[:3, 3] = [0.05 * i, 0.0, 0.0]
    return pose


def _png(path: Path, image: np.ndarray) -> None:
    import cv2

    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(cv2.imencode(path.suffix, image[..., ::-1] if image.ndim == 3 else image)[1].tobytes())


def _matrix_text(m: np.ndarray) -> str:
    return "\n".join(" ".join(f"{v:.9g}" for v in row) for row in m) + "\n"


def seven_scenes(d: Path, n: int = 3) -> Path:
    d.mkdir(parents=True, exist_ok=True)
    fx, fy, cx, cy = K
    (d / "camera-intrinsics.txt").write_text(_matrix_text(np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]])))
    for i in range(n):
        _png(d / f"frame-{i:06d}.color.png", _colour(H, W, i))
        _png(d / f"frame-{i:06d}.depth.png", np.rint(_depth_m(H, W, fy, cy) * 1000).astype(np.uint16))
        (d / f"frame-{i:06d}.pose.txt").write_text(_matrix_text(_pose(i)))
    return d


def replica(d: Path, n: int = 3) -> Path:
    fx, fy, cx, cy = K
    (d / "results").mkdir(parents=True, exist_ok=True)
    (d / "cam_params.json").write_text(json.dumps(
        {"camera": {"w": W, "h": H, "fx": fx, "fy": fy, "cx": cx, "cy": cy, "scale": 6553.5}}))
    lines = []
    for i in range(n):
        _png(d / "results" / f"frame{i:06d}.jpg", _colour(H, W, i))
        _png(d / "results" / f"depth{i:06d}.png", np.rint(_depth_m(H, W, fy, cy) * 6553.5).astype(np.uint16))
        lines.append(" ".join(f"{v:.9g}" for v in _pose(i).ravel()))
    (d / "traj.txt").write_text("\n".join(lines) + "\n")
    return d


def scannet(d: Path, n: int = 3) -> Path:
    fx, fy, cx, cy = K
    for sub in ("color", "depth", "pose", "intrinsic"):
        (d / sub).mkdir(parents=True, exist_ok=True)
    k = np.eye(4)
    k[0, 0], k[1, 1], k[0, 2], k[1, 2] = fx, fy, cx, cy
    (d / "intrinsic" / "intrinsic_depth.txt").write_text(_matrix_text(k))
    for i in range(n):
        _png(d / "color" / f"{i}.jpg", _colour(2 * H, 2 * W, i))  # colour larger than depth, as ScanNet's
        _png(d / "depth" / f"{i}.png", np.rint(_depth_m(H, W, fy, cy) * 1000).astype(np.uint16))
        (d / "pose" / f"{i}.txt").write_text(_matrix_text(_pose(i)))
    return d


def tum(d: Path, n: int = 2) -> Path:
    """TUM RGB-D at its own 640 x 480 (the layout fixes the intrinsics); default camera."""
    fy, cy = 525.0, 239.5
    rgb, depth, gt = ["# colour images"], ["# depth images"], ["# timestamp tx ty tz qx qy qz qw"]
    for i in range(n):
        t = 1000.0 + i / 30
        _png(d / "rgb" / f"{t:.6f}.png", _colour(480, 640, i))
        _png(d / "depth" / f"{t:.6f}.png", np.rint(_depth_m(480, 640, fy, cy) * 5000).astype(np.uint16))
        rgb.append(f"{t:.6f} rgb/{t:.6f}.png")
        depth.append(f"{t + 0.001:.6f} depth/{t:.6f}.png")
        gt.append(f"{t:.6f} {0.05 * i} 0 0 0 0 0 1")
    (d / "rgb.txt").write_text("\n".join(rgb) + "\n")
    (d / "depth.txt").write_text("\n".join(depth) + "\n")
    (d / "groundtruth.txt").write_text("\n".join(gt) + "\n")
    return d


WRITERS = {"7scenes": seven_scenes, "replica": replica, "scannet": scannet, "tum": tum}


def png_claiming(width: int, height: int) -> bytes:
    """A tiny 16-bit PNG whose header claims `width` x `height` pixels (a decompression bomb's
    header: only a reader that checks the header before decoding stays small)."""
    import struct
    import zlib

    import cv2

    data = bytearray(cv2.imencode(".png", np.zeros((4, 4), np.uint16))[1].tobytes())
    data[16:24] = struct.pack(">II", width, height)
    data[29:33] = struct.pack(">I", zlib.crc32(bytes(data[12:29])))
    return bytes(data)


def jpeg_claiming(width: int, height: int) -> bytes:
    """A tiny JPEG whose frame header claims `width` x `height` pixels."""
    import struct

    import cv2

    data = bytearray(cv2.imencode(".jpg", np.zeros((8, 8, 3), np.uint8))[1].tobytes())
    at = 2
    while data[at + 1] not in (0xC0, 0xC1, 0xC2):
        at += 2 + struct.unpack(">H", data[at + 2:at + 4])[0]
    data[at + 5:at + 9] = struct.pack(">HH", height, width)
    return bytes(data)
