"""Readers of the recording layouts people have; each `open_*(dir, depth_scale)` returns a
`Recording` with the format's depth scale, intrinsics and pose convention, and each `is_*(dir)`
tells whether a directory looks like that layout.

- 7-Scenes / 3DMatch: `frame-%06d.color.{jpg,png}`, `frame-%06d.depth.png` (uint16 mm),
  `frame-%06d.pose.txt` (4 x 4 camera-to-world, m), `camera-intrinsics.txt` (3 x 3), in DIR or in
  `seq-*/` folders under it (3DMatch). World: the first camera's frame (y down), not gravity-aligned.
- Replica (NICE-SLAM / ConceptGraphs / HOV-SG): `results/frame%06d.jpg`, `results/depth%06d.png`
  (uint16, metres = value / scale, scale 6553.5), `traj.txt` (16 numbers per line, camera-to-world,
  OpenCV axes; line i = frame i), `cam_params.json` (in DIR or its parent). World z up.
- ScanNet exported frames (SensReader): `color/N.jpg`, `depth/N.png` (uint16 mm), `pose/N.txt`
  (4 x 4 camera-to-world; "-inf" where tracking was lost), `intrinsic/intrinsic_depth.txt` (4 x 4).
  Colour (1296 x 968) is resized to the depth image (640 x 480). World z up, floor not at z = 0.
- TUM RGB-D: `rgb.txt`, `depth.txt` (timestamp file), `groundtruth.txt` (timestamp tx ty tz qx qy
  qz qw, camera-to-world); depth frames associated with the nearest colour frame and pose within
  `MAX_DT` s; depth uint16 / 5000 m; intrinsics of freiburg 1/2/3 from the folder name.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Optional

import numpy as np

from ..errors import IesmError
from ..fileio import load_json
from .checks import BadFrame, check_depth_scale
from .ours import Intrinsics
from .recording import (FrameRef, Recording, frame_size, intrinsics_from_matrix, make_intrinsics, numbered,
                        read_list, read_matrix)

MAX_DT = 0.02  # s, TUM association tolerance (as the benchmark's associate.py)
SEVEN_SCENES_K = (585.0, 585.0, 320.0, 240.0)
REPLICA_DEFAULT = {"w": 1200, "h": 680, "fx": 600.0, "fy": 600.0, "cx": 599.5, "cy": 339.5, "scale": 6553.5}
TUM_K = {"freiburg1": (517.3, 516.5, 318.6, 255.3), "freiburg2": (520.9, 521.0, 325.1, 249.7),
         "freiburg3": (535.4, 539.2, 320.1, 247.6)}
TUM_DEFAULT_K = (525.0, 525.0, 319.5, 239.5)
#: largest cam_params.json read (bytes)
MAX_PARAMS_BYTES = 1024 * 1024


def _pose_or_error(path: Path, shape=(4, 4)) -> tuple[Optional[np.ndarray], str]:
    try:
        return read_matrix(path, shape), ""
    except BadFrame as exc:
        return None, exc.message


# ---------------------------------------------------------------------------- 7-Scenes / 3DMatch

def _seven_dirs(directory: Path) -> list[Path]:
    if any(directory.glob("frame-*.color.*")):
        return [directory]
    return sorted(p for p in directory.glob("seq-*") if p.is_dir() and any(p.glob("frame-*.color.*")))


def is_sevenscenes(directory: Path) -> bool:
    return bool(_seven_dirs(directory))


def open_sevenscenes(directory: Path, depth_scale: float | None = None) -> Recording:
    notes, refs = [], []
    seqs = _seven_dirs(directory)
    k_path = next((p / "camera-intrinsics.txt" for p in (*seqs[:1], directory, directory.parent)
                   if (p / "camera-intrinsics.txt").is_file()), None)
    for seq in seqs:
        for number, color in numbered(seq.iterdir(), r"frame-(\d+)\.color\.(?:jpg|png)"):
            stem = seq / f"frame-{number:06d}"
            pose, err = _pose_or_error(Path(f"{stem}.pose.txt"))
            name = f"{seq.name}/frame-{number:06d}" if seq != directory else f"frame-{number:06d}"
            refs.append(FrameRef(name, color, Path(f"{stem}.depth.png"), pose, f"{stem}.pose.txt", err))
    if not refs:
        raise IesmError("no 7-Scenes frames: colour images must be named frame-NNNNNN.color.jpg or .png", directory)
    width, height = frame_size(refs)
    if k_path is not None:
        try:
            k = read_matrix(k_path, (3, 3))
        except BadFrame as exc:
            raise IesmError(exc.message, k_path) from None
        intr = intrinsics_from_matrix(k, width, height, k_path)
        notes.append(f"intrinsics from {k_path.name}")
    else:
        fx, fy, cx, cy = SEVEN_SCENES_K
        intr = Intrinsics(width=width, height=height, fx=fx, fy=fy, cx=cx, cy=cy)
        notes.append("no camera-intrinsics.txt: 7-Scenes' published intrinsics (fx = fy = 585) assumed")
    notes.append("depth uint16 millimetres" if depth_scale is None else f"depth scale {depth_scale:g} per metre")
    return Recording("7scenes", directory, intr, depth_scale or 1000.0, refs, notes=notes)


# ------------------------------------------------------------------------------------- Replica

def is_replica(directory: Path) -> bool:
    return (directory / "traj.txt").is_file() and any((directory / "results").glob("frame*.jpg"))


def open_replica(directory: Path, depth_scale: float | None = None) -> Recording:
    notes = []
    params_path = next((p / "cam_params.json" for p in (directory, directory.parent)
                        if (p / "cam_params.json").is_file()), None)
    cam = dict(REPLICA_DEFAULT)
    if params_path is not None:
        params = load_json(params_path, max_bytes=MAX_PARAMS_BYTES, allow_nan=False)
        if not isinstance(params, dict) or not isinstance(params.get("camera"), dict):
            raise IesmError("cam_params.json must hold a 'camera' object", params_path)
        cam.update(params["camera"])
        notes.append(f"intrinsics and depth scale from {params_path}")
    else:
        notes.append("no cam_params.json: Replica's usual 1200 x 680, f = 600, scale 6553.5 assumed")
    traj_path = directory / "traj.txt"
    lines = [line for line in read_list(traj_path) if line.strip()]  # each split only when its frame is read
    refs = []
    for number, color in numbered((directory / "results").iterdir(), r"frame(\d+)\.jpg"):
        depth = directory / "results" / f"depth{number:06d}.png"
        source = f"{traj_path}:{number + 1}"
        pose, err = None, ""
        row = lines[number].split() if number < len(lines) else None
        if row is None:
            err = f"traj.txt has {len(lines)} lines, none for frame {number}"
        elif len(row) != 16:
            err = f"a pose line must hold 16 numbers, found {len(row)}"
        else:
            try:
                pose = np.array([float(v) for v in row], np.float64).reshape(4, 4)
            except ValueError:
                err = "a pose line must hold 16 numbers"
        refs.append(FrameRef(f"frame{number:06d}", color, depth, pose, source, err))
    source = params_path or directory
    intr = make_intrinsics(cam.get("w"), cam.get("h"), cam.get("fx"), cam.get("fy"), cam.get("cx"), cam.get("cy"),
                           source)
    scale = check_depth_scale(depth_scale if depth_scale is not None else cam.get("scale"), source, "scale")
    return Recording("replica", directory, intr, scale, refs, notes=notes, up=(0.0, 0.0, 1.0))


# ------------------------------------------------------------------------------------- ScanNet

def is_scannet(directory: Path) -> bool:
    return all((directory / d).is_dir() for d in ("color", "depth", "pose"))


def open_scannet(directory: Path, depth_scale: float | None = None) -> Recording:
    refs = []
    for number, depth in numbered((directory / "depth").iterdir(), r"(\d+)\.png"):
        color = next((p for p in (directory / "color" / f"{number}.jpg", directory / "color" / f"{number}.png")
                      if p.is_file()), directory / "color" / f"{number}.jpg")
        pose_path = directory / "pose" / f"{number}.txt"
        pose, err = _pose_or_error(pose_path)
        refs.append(FrameRef(f"frame {number}", color, depth, pose, str(pose_path), err))
    if not refs:
        raise IesmError("no ScanNet frames: depth images must be named depth/N.png", directory)
    width, height = frame_size(refs)
    k_path = directory / "intrinsic" / "intrinsic_depth.txt"
    if not k_path.is_file():
        raise IesmError("ScanNet export without intrinsic/intrinsic_depth.txt (4 x 4 depth camera matrix)", k_path)
    try:
        k = read_matrix(k_path, (4, 4))
    except BadFrame as exc:
        raise IesmError(exc.message, k_path) from None
    notes = ["intrinsics from intrinsic/intrinsic_depth.txt; colour resized to the depth image",
             "depth uint16 millimetres" if depth_scale is None else f"depth scale {depth_scale:g} per metre"]
    return Recording("scannet", directory, intrinsics_from_matrix(k, width, height, k_path),
                     depth_scale or 1000.0, refs, notes=notes, up=(0.0, 0.0, 1.0))


# ----------------------------------------------------------------------------------------- TUM

def is_tum(directory: Path) -> bool:
    return (directory / "rgb.txt").is_file() and (directory / "depth.txt").is_file()


def _stamped(path: Path, min_fields: int = 2) -> list[tuple[float, list[str]]]:
    """(timestamp s, remaining fields) of every non-comment line of a TUM list file, each holding
    at least `min_fields` fields (the timestamp and a file name, or the 8 of a ground-truth pose)."""
    out = []
    for n, line in enumerate(read_list(path), 1):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        try:
            stamp = float(fields[0])
        except ValueError:
            stamp = math.nan
        if not math.isfinite(stamp):
            raise IesmError(f"line must start with a timestamp (a finite number): {line[:60]!r}", path,
                            f"line {n}")
        if len(fields) < min_fields:
            raise IesmError(f"line must hold a timestamp and {min_fields - 1} more fields, found "
                            f"{len(fields) - 1}: {line[:60]!r}", path, f"line {n}")
        out.append((stamp, fields[1:]))
    return out


def _nearest(stamps: np.ndarray, t: float) -> int:
    j = int(np.searchsorted(stamps, t))
    cands = [c for c in (j - 1, j) if 0 <= c < len(stamps)]
    return min(cands, key=lambda c: abs(stamps[c] - t)) if cands else -1


def quaternion_pose(values: list[str]) -> np.ndarray:
    """4 x 4 pose from TUM's tx ty tz qx qy qz qw (NaN stays NaN for the pose check)."""
    tx, ty, tz, qx, qy, qz, qw = (float(v) for v in values[:7])
    q = np.array([qw, qx, qy, qz])
    q = q / np.linalg.norm(q) if np.linalg.norm(q) > 0 else q * np.nan
    w, x, y, z = q
    pose = np.eye(4)
    pose[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                    [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                    [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    pose[:3, 3] = [tx, ty, tz]
    return pose


def open_tum(directory: Path, depth_scale: float | None = None) -> Recording:
    rgb = _stamped(directory / "rgb.txt")
    depth = _stamped(directory / "depth.txt")
    gt_path = directory / "groundtruth.txt"
    gt = _stamped(gt_path, 8) if gt_path.exists() else []
    rgb.sort(key=lambda row: row[0])  # _nearest bisects
    gt.sort(key=lambda row: row[0])
    rgb_t = np.array([t for t, _ in rgb])
    gt_t = np.array([t for t, _ in gt])
    refs = []
    for t, fields in depth:
        i = _nearest(rgb_t, t)
        if i < 0 or abs(rgb_t[i] - t) > MAX_DT:
            continue  # a depth frame without a colour frame is not a frame
        g = _nearest(gt_t, t)
        pose, err = None, ""
        if g < 0 or abs(gt_t[g] - t) > MAX_DT:
            err = f"no ground-truth pose within {MAX_DT * 1000:.0f} ms"
        else:
            try:
                pose = quaternion_pose(gt[g][1])
            except (ValueError, IndexError):
                err = "groundtruth.txt line must be: timestamp tx ty tz qx qy qz qw"
        refs.append(FrameRef(f"depth {t:.6f}", directory / rgb[i][1][0], directory / fields[0], pose,
                             f"{gt_path}:{t:.6f}", err))
    key = next((k for k in TUM_K if k in directory.name or k in str(directory)), None)
    fx, fy, cx, cy = TUM_K.get(key, TUM_DEFAULT_K)
    if not refs:
        raise IesmError(f"no TUM frame: no depth.txt entry has a colour frame within {MAX_DT * 1000:.0f} ms",
                        directory)
    width, height = frame_size(refs)
    notes = [f"{len(refs)} depth frames associated with colour and pose within {MAX_DT * 1000:.0f} ms",
             f"intrinsics of {key}" if key else "intrinsics: TUM's default 525 / 319.5 / 239.5 (folder name "
             "names no freiburg camera)", "depth uint16 / 5000 m" if depth_scale is None else
             f"depth scale {depth_scale:g} per metre"]
    return Recording("tum", directory, Intrinsics(width=width, height=height, fx=fx, fy=fy, cx=cx, cy=cy),
                     depth_scale or 5000.0, refs, notes=notes)
