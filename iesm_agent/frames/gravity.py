"""Gravity alignment of a recording: our maps have z up and the floor at z = 0, recordings
(7-Scenes, 3DMatch, ScanNet, TUM) do not. From a sample of frames: a first guess of "up" from the
cameras (held upright: up ~ -mean camera y axis), refined by the normals of up-facing depth surfaces;
the floor is the lowest up-facing plane holding enough points, accepted when the cameras stand
0.5-2.5 m above it (else z = 0 is put `ASSUMED_CAMERA_HEIGHT` below the median camera, and we say
so); walls (vertical normals) set the yaw so they run along x and y."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .ours import Frame, Intrinsics

STRIDE = 8                    # pixels between sampled depth points
HORIZONTAL_DEG = 10.0         # an up-facing normal is within this of "up"
BIN_M = 0.02                  # height histogram bin
ASSUMED_CAMERA_HEIGHT = 1.4   # m, used only when no floor is seen
CAMERA_HEIGHT_RANGE = (0.5, 2.5)


@dataclass
class Alignment:
    """`transform` (4, 4) maps the recording's world to ours (z up, floor z = 0, walls on x/y);
    `description` says in one line what was done; `method` "floor plane", "camera height" or "none"."""

    transform: np.ndarray
    description: str
    method: str
    tilt_deg: float = 0.0
    yaw_deg: float = 0.0
    camera_height: float = 0.0

    def apply(self, pose: np.ndarray) -> np.ndarray:
        return self.transform @ pose


def identity(reason: str) -> Alignment:
    return Alignment(np.eye(4), reason, "none")


def _points_normals(frame: Frame, k: Intrinsics, stride: int) -> tuple[np.ndarray, np.ndarray]:
    """World points (n, 3) and unit normals (n, 3) facing the camera, from a strided depth grid."""
    d = frame.depth[::stride, ::stride].astype(np.float64)
    v, u = np.mgrid[0:frame.depth.shape[0]:stride, 0:frame.depth.shape[1]:stride]
    p = np.stack([(u - k.cx) / k.fx * d, (v - k.cy) / k.fy * d, d], axis=-1)
    dx = p[1:-1, 2:] - p[1:-1, :-2]
    dy = p[2:, 1:-1] - p[:-2, 1:-1]
    n = np.cross(dx, dy)
    c = p[1:-1, 1:-1]
    zc = d[1:-1, 1:-1]
    ok = (zc > 0) & (d[1:-1, 2:] > 0) & (d[1:-1, :-2] > 0) & (d[2:, 1:-1] > 0) & (d[:-2, 1:-1] > 0)
    jump = np.maximum(np.abs(d[1:-1, 2:] - d[1:-1, :-2]), np.abs(d[2:, 1:-1] - d[:-2, 1:-1]))
    ok &= jump < 0.1 * zc * stride / 4
    n, c = n[ok], c[ok]
    norm = np.linalg.norm(n, axis=1)
    good = norm > 0
    n, c = n[good] / norm[good, None], c[good]
    n[np.einsum("ij,ij->i", n, c) > 0] *= -1           # face the camera
    r, t = frame.pose[:3, :3], frame.pose[:3, 3]
    return c @ r.T + t, n @ r.T


def estimate_alignment(frames: list[Frame], k: Intrinsics, stride: int = STRIDE,
                       up: np.ndarray | None = None) -> Alignment:
    """The `Alignment` of a recording from a sample of its frames (poses already checked); `up`
    (3,) is the format's known up direction (Replica, ScanNet: +z), else estimated."""
    if not frames:
        return identity("no frame to align with: poses kept as they are")
    pts, nrm = zip(*(_points_normals(f, k, stride) for f in frames))
    pts, nrm = np.concatenate(pts), np.concatenate(nrm)
    if up is not None:
        up = np.asarray(up, np.float64) / np.linalg.norm(up)
        source = "the format's convention (world z up)"
    else:
        up = up0 = -np.mean([f.pose[:3, 1] for f in frames], axis=0) / np.linalg.norm(
            np.mean([f.pose[:3, 1] for f in frames], axis=0))
        for deg in (25.0, HORIZONTAL_DEG):
            facing = nrm @ up > np.cos(np.radians(deg))
            if facing.sum() < 50:
                break
            refined = nrm[facing].mean(axis=0)
            refined /= np.linalg.norm(refined)
            if refined @ up0 < np.cos(np.radians(30.0)):
                break                      # too few level surfaces to trust: keep the cameras' guess
            up = refined
        source = f"{int((nrm @ up > np.cos(np.radians(HORIZONTAL_DEG))).sum())} up-facing depth normals"
    facing = nrm @ up > np.cos(np.radians(HORIZONTAL_DEG))
    heights = pts[facing] @ up
    cams = np.array([f.pose[:3, 3] for f in frames]) @ up
    floor, method, n_floor = None, "camera height", 0
    if len(heights) >= 50:
        lo = heights.min()
        counts = np.bincount(((heights - lo) / BIN_M).astype(np.int64))
        need = max(50, int(0.02 * len(heights)))
        first = int(np.flatnonzero(counts >= need)[0]) if (counts >= need).any() else None
        if first is not None:
            centre = lo + (first + 0.5) * BIN_M
            near = np.abs(heights - centre) <= 1.5 * BIN_M
            candidate = float(np.median(heights[near]))
            cam_h = float(np.median(cams) - candidate)
            if CAMERA_HEIGHT_RANGE[0] <= cam_h <= CAMERA_HEIGHT_RANGE[1]:
                floor, method, n_floor = candidate, "floor plane", int(near.sum())
    if floor is None:
        floor = float(np.median(cams)) - ASSUMED_CAMERA_HEIGHT
    # yaw from vertical surfaces: the dominant wall direction mod 90 degrees
    e1 = np.eye(3)[int(np.argmin(np.abs(up)))]
    e1 = e1 - (e1 @ up) * up
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(up, e1)
    vertical = np.abs(nrm @ up) < 0.15
    yaw = 0.0
    if vertical.sum() >= 50:
        theta = np.arctan2(nrm[vertical] @ e2, nrm[vertical] @ e1)
        yaw = float(np.arctan2(np.sin(4 * theta).mean(), np.cos(4 * theta).mean()) / 4)
    x_axis = np.cos(yaw) * e1 + np.sin(yaw) * e2
    y_axis = np.cross(up, x_axis)
    transform = np.eye(4)
    transform[:3, :3] = np.stack([x_axis, y_axis, up])
    transform[2, 3] = -floor
    tilt = float(np.degrees(np.arccos(np.clip(up[2], -1, 1))))
    cam_h = float(np.median(cams) - floor)
    if method == "floor plane":
        what = (f"floor plane from depth ({n_floor} points of {len(heights)} up-facing) set to z = 0, "
                f"median camera height {cam_h:.2f} m")
    else:
        what = (f"no floor in view (lowest up-facing surface not 0.5-2.5 m below the cameras): z = 0 put "
                f"{ASSUMED_CAMERA_HEIGHT} m below the median camera (assumed hand-held); heights are approximate")
    desc = (f"gravity: up from {source}, recording's z axis was {tilt:.1f} deg "
            f"from up; {what}; yaw {np.degrees(yaw):.1f} deg so walls run along x/y")
    return Alignment(transform, desc, method, tilt, float(np.degrees(yaw)), cam_h)
